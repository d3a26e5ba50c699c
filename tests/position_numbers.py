"""Reading a plan of positions' numbers back from a figure: a number is set as its letter and its index (two Text
artists, ``pos-…`` and ``pos-…-index``, see plans.drawing.positions_plan.number_parts); these helpers read them as one
label, ``A₁₀``, with one box."""

from __future__ import annotations

from matplotlib.transforms import Bbox

_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


class Number:
    """A number's letter and index read as one label (the methods of a Text the tests use)."""

    def __init__(self, letter, index):
        self.letter, self.index = letter, index
        self.parts = [letter] + ([index] if index is not None else [])
        self.figure = letter.figure
        self.head = letter.get_gid()
        self.group = [self]

    def get_gid(self):
        return self.letter.get_gid()

    def get_text(self):
        return self.letter.get_text() + (self.index.get_text().translate(_SUB) if self.index is not None else "")

    def get_window_extent(self, renderer=None):
        return Bbox.union([t.get_window_extent(renderer) for t in self.parts])

    def get_position(self):
        """The centre of the label's box, in data units [mm]."""
        bb = self.get_window_extent(self.figure.canvas.get_renderer()).transformed(self.letter.axes.transData.inverted())
        return ((bb.x0 + bb.x1) / 2, (bb.y0 + bb.y1) / 2)

    def label_position(self):
        """The centre [mm] of the whole label it is part of (numbers set side by side: one label)."""
        renderer = self.figure.canvas.get_renderer()
        bb = Bbox.union([n.get_window_extent(renderer) for n in self.group]).transformed(self.letter.axes.transData.inverted())
        return ((bb.x0 + bb.x1) / 2, (bb.y0 + bb.y1) / 2)

    def get_fontsize(self):
        return self.letter.get_fontsize()


def read_texts(texts):
    """*texts* (Text artists with gids) with each number's letter and index read as one :class:`Number` (a comma
    between numbers set side by side left out)."""
    by_gid = {t.get_gid(): t for t in texts}
    out, head, after_comma, group = [], None, False, []
    for t in texts:  # (in the order drawn: letter, index, comma, letter, index of numbers set side by side)
        gid = t.get_gid() or ""
        if gid.endswith(("-index", "-comma")) and (gid.rsplit("-", 1)[0] in by_gid):
            after_comma = after_comma or gid.endswith("-comma")
            continue
        index = by_gid.get(f"{gid}-index")
        if index is not None:
            number = Number(t, index)
            if not (after_comma and head is not None):
                head, group = gid, []
            number.head = head  # (the first of numbers set side by side: its leader serves them all)
            group.append(number)
            number.group = group
            out.append(number)
        else:
            out.append(t)
        after_comma = False
    return out


def leader_of(fig, gid: str):
    """The leader line of the number *gid*: (start, end) [mm], or None (a number beside its mark)."""
    lines = fig.findobj(lambda a: (a.get_gid() or "") == f"{gid}-leader" and hasattr(a, "get_xydata"))
    if not lines:
        return None
    xy = lines[0].get_xydata()
    return complex(*xy[0]), complex(*xy[-1])


def leader_says(number, own: complex, mark_r: float = 0.45) -> bool:
    """Whether *number*'s leader line comes from *own* (the mark [mm]) and ends at the number's box."""
    ends = leader_of(number.figure, getattr(number, "head", number.get_gid()))
    if ends is None:
        return False
    start, end = ends
    renderer = number.figure.canvas.get_renderer()
    parts = getattr(number, "group", [number])  # (numbers set side by side: one label, one leader)
    bb = Bbox.union([n.get_window_extent(renderer) for n in parts]).transformed(
        (number.letter if isinstance(number, Number) else number).axes.transData.inverted())
    gap = abs(complex(max(bb.x0 - end.real, 0.0, end.real - bb.x1), max(bb.y0 - end.imag, 0.0, end.imag - bb.y1)))
    # (numbers side by side name marks all but on one another, within 1 mm: their leader starts amid them)
    reach = mark_r + 0.5 + (1.0 if len(parts) > 1 else 0.0)
    return abs(start - own) <= reach and gap <= 1.5  # (the glyphs' box, a little inside the line's)
