"""The handout's kinetostatic page of a position (``plans handout … --forces``).

One A4 page after a position's pages: the free bodies of the groups and the
driver with their loads and reactions (at a page k_l), then every force plan
in construction order (the last group first, the driver's last), all at the
page's one round μ_F (the smallest with which every plan fits its box, so the
largest fills it), stated once in the heading, with its readings and M_b; a
reaction carried to the next plan is stated there as R_ji = −R_ij with the value found;
Joukowski's lever, when one is given, on a page of its own at its velocity plan's k_v.

The force plans are constructed here at the page's μ_F (so that what the
page states, drawn length × μ_F, is what is read); nothing is drawn that the
construction did not find.  Words from :mod:`plans.i18n`, decimal comma in
sr, ru, bg, sl.
"""

from __future__ import annotations

from .._text import decimal_comma
from ..graphical.scales import round_down, round_up
from ..i18n import term
from .blocks import Block
from .force_drawing import draw_force_legend_into, draw_force_plan_into, draw_free_bodies_into, draw_lever_into, legend_kinds
from .layout import A4, GAP, PAGE_MARGIN, footer as page_footer, header, header_height, new_page
from .numerals import scale_caption
from ._canvas import fmt_number
from .svg import drawing_rc
from ._canvas import sketch_on

__all__ = ["draw_forces_pages", "FREE_BODIES_SHARE", "CRAMPED"]

#: The free bodies take at most this share of the page's height under the header.
FREE_BODIES_SHARE = 0.4


def _block(fig, tag: str, draw) -> Block:
    """A drawing made now into new axes of *fig* (one data unit = 1 mm), placed later by moving the axes."""
    ax = fig.add_axes([0, 0, 0.01, 0.01])
    sketch_on(ax, tag, draw)
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    width, height = x1 - x0, y1 - y0

    def place(sketch, x: float, y: float, page) -> None:
        pw, ph = page
        ax.set_aspect("auto")
        ax.set_position([x / pw, y / ph, width / pw, height / ph])

    block = Block(width, height, place, kind="mechanism")
    block.axes = ax
    return block


def _fits(block: Block, box: tuple[float, float]) -> bool:
    return block.width <= box[0] + 0.5 and block.height <= box[1] + 0.5


def _largest_fitting(make, box: tuple[float, float], guess: float, extent, steps: int = 14):
    """The block of the smallest round scale (the largest drawing) that fits *box*: (scale, block).

    ``make(scale)`` draws at a scale (k_l or μ_F: larger draws smaller);
    ``extent(scale)`` is the size [mm] (across, up) of the part that scales
    (the mechanism, the polygon).  The first drawing, at *guess*, tells the
    fixed part (labels, captions, arrows); the scale it then needs is tried
    and corrected a round step at a time, measured, never extrapolated.
    Blocks tried and not kept are taken off the page.
    """
    block = make(guess)
    needs = []
    for drawn, scaled, room in zip((block.width, block.height), extent(guess), box):
        fixed = drawn - scaled
        if scaled > 0:
            needs.append(guess * scaled / (room - fixed) if room - fixed > 5.0 else 4 * guess)
    block.axes.remove()
    k = round_up(max(needs, default=guess))
    block = make(k)
    if _fits(block, box):
        for _ in range(steps):
            smaller = round_down(k * 0.999)
            trial = make(smaller)
            if not _fits(trial, box):
                trial.axes.remove()
                break
            block.axes.remove()
            k, block = smaller, trial
        return k, block
    for _ in range(steps):
        block.axes.remove()
        k = round_up(k * 1.001)
        block = make(k)
        if _fits(block, box):
            break
    return k, block


def _span(points) -> tuple[float, float]:
    xs = [z.real for z in points] or [0.0]
    ys = [z.imag for z in points] or [0.0]
    return max(xs) - min(xs), max(ys) - min(ys)


class _Measured:
    """A drawing's size [mm], measured once and taken off the page (it stands in for a Block while fitting)."""

    class _Gone:
        def remove(self) -> None:
            pass

    def __init__(self, width: float, height: float):
        self.width, self.height = width, height
        self.axes = self._Gone()


def _plan_scales(fig, plans_at, first, items, box, lang: str, sizes: dict) -> dict[str, float]:
    """Group -> the page's one round μ_F [N/mm]: the smallest with which every plan fits *box*.

    Each plan is fitted alone (the round μ_F that draws it largest within *box*); the largest of
    those is the page's, so that the plan that needs it fills its box and the others fit
    (a plan of small forces is then drawn small: that is what it is at the page's μ_F).
    *sizes* keeps every plan drawing measured, by (group, μ_F), for the next layout tried.
    """
    groups = [item for item in items if item != "lever"]

    def measured(group: str, mu: float) -> "_Measured":
        key = (group, mu, box[0])
        if key not in sizes:
            plans = plans_at(mu)
            plan = next(p for p in plans.plans if p.group == group)
            moment = plans.balancing_moment if group == "driver" else None
            block = _block(fig, "fplan", lambda s: draw_force_plan_into(s, plan, lang=lang, legend=False, balancing_moment=moment, known=False, scale=False,
                                                                  caption_width=box[0] - 2.0))
            block.axes.remove()
            sizes[key] = (block.width, block.height)
        return _Measured(*sizes[key])

    # the round values upwards from half the largest plan's own μ_F (which draws it 60–120 mm long): the first with which
    # every plan fits is the page's (measured at each; a plan's captions are not monotonic in μ_F: short vectors get notes)
    mu = round_down(max(p.scale for p in first.plans if p.group in groups) / 2.0)
    for _ in range(24):
        if all(_fits(measured(group, mu), box) for group in groups):
            break
        mu = round_up(mu * 1.001)
    return {group: mu for group in groups}


#: A plan drawn at more than this times its own round μ_F on a shared page (under a third of its
#: natural 60–120 mm) gets a page of its own with the other plans: the free bodies stay on the first.
CRAMPED = 2.5


def _natural(fig, first, lang: str) -> dict[str, tuple[float, float, float, float, float]]:
    """Group -> (width, height [mm] of its drawing, of its polygon, its own μ_F [N/mm]): the fixed part of each plan's size."""
    out = {}
    for plan in first.plans:
        moment = first.balancing_moment if plan.group == "driver" else None
        block = _block(fig, "fplan", lambda s, plan=plan, moment=moment: draw_force_plan_into(s, plan, lang=lang, legend=False, balancing_moment=moment, known=False, scale=False))
        block.axes.remove()
        out[plan.group] = (block.width, block.height, *_span([z for v in plan.vectors for z in (v.tail, v.tip)]), plan.scale)
    return out


def _shrink(natural, box) -> float:
    """How many times the largest plan's own μ_F the page's one μ_F must be for every plan to fit *box*, by the size model (inf: never)."""
    largest = max(mu for *_, mu in natural.values())
    worst = 1.0
    for w, h, pw, ph, mu in natural.values():
        for drawn, scaled, room in ((w, pw, box[0]), (h, ph, box[1])):
            if scaled > 0:
                fixed = drawn - scaled
                need = scaled / (room - fixed) if room - fixed > 1.0 else float("inf")
                worst = max(worst, need * mu / largest)
    return worst


def _layout(fig, plans_at, first, items, room: float, width: float, lang: str, sizes: dict, natural=None, limit: float = float("inf")):
    """(worst shrink, columns, box, scales): the column count that draws the plans largest in *room* [mm].

    Layouts whose boxes the size model says shrink a plan more than *limit* (given *natural*) are not tried; None if none is left.
    """
    best = None
    for columns in ([1, 2] if len(items) <= 2 else [2]):
        if columns > len(items):
            continue
        rows = -(-len(items) // columns)
        box = ((width - (columns - 1) * GAP) / columns, (room - GAP * (rows - 1)) / rows)
        if box[1] < 25.0 or (natural is not None and _shrink(natural, box) > limit):
            continue
        scales = _plan_scales(fig, plans_at, first, items, box, lang, sizes)
        growth = 1.0
        for plan in first.plans:
            growth *= plan.scale / scales[plan.group]
        worst = max(scales.values()) / max(plan.scale for plan in first.plans)  # the largest plan against its own μ_F
        if best is None or growth > best[0] * 1.0001:
            best = (growth, worst, columns, box, scales)
    if best is None:
        return None
    return best[1:]


def _place_plans(fig, sketch, plans_at, items, columns, box, scales, y_top: float, width: float, size, lang: str, lever) -> None:
    final = plans_at(next(iter(scales.values())) if scales else None)
    for n, item in enumerate(items):
        column, row = n % columns, n // columns
        if item == "lever":
            block = _block(fig, "lever", lambda s: draw_lever_into(s, lever, lang=lang))
        else:
            plan = next(p for p in final.plans if p.group == item)
            moment = final.balancing_moment if item == "driver" else None
            block = _block(fig, "fplan", lambda s, plan=plan, moment=moment: draw_force_plan_into(s, plan, lang=lang, legend=False, balancing_moment=moment, known=False, scale=False,
                                                                                      caption_width=box[0] - 2.0))
        x = PAGE_MARGIN + column * (box[0] + GAP) + (box[0] - block.width) / 2
        y = y_top - row * (box[1] + GAP) - block.height
        block.place(sketch, x, y, size)


def draw_forces_pages(graphical, plans_at, *, lang: str = "en", header_lines=(), title: str | None = None, footer: str = "", lever=None) -> list:
    """The kinetostatic pages of one position, A4 portrait, from its graphical solution.

    One page: the free bodies across the top, the force plans under them,
    one legend at the foot.  Where the plans would be drawn too small there
    (the page's μ_F more than :data:`CRAMPED` times the largest plan's own), two: the free
    bodies and the legend, then the plans on a page of their own.

    Parameters
    ----------
    graphical : plans.graphical.GraphicalSolution
        The position's graphical solution (its scene has masses or loads).
    plans_at : callable
        μ_F [N/mm] (None: each plan's own round value) -> the position's force plans constructed at it
        (:func:`plans.forces.force_plans.construct_force_plans`): the page tries scales, drawing never constructs.
    lang : str
    header_lines : sequence of str
        The page header's data lines (the position, as the other pages).
    title, footer : str
    lever : plans.forces.lever.JoukowskiLever, optional
        Joukowski's lever of the position, drawn after the force plans.

    Returns
    -------
    list of matplotlib.figure.Figure
        Each with ``force_scales``: group -> the μ_F [N/mm] its plan is drawn at (on that page; one value for all).
    """
    size = A4
    width = size[0] - 2 * PAGE_MARGIN
    where = [decimal_comma(line, lang) for line in header_lines]
    first = plans_at(None)
    items = [plan.group for plan in first.plans]
    with drawing_rc():
        fig, sketch = new_page(size)
        # the header is drawn once the page's μ_F is known (it states it); its height is the same
        top = size[1] - header_height(where + [_heading(lang, ("free_bodies", "force_plans"), 1.0)])
        bottom = PAGE_MARGIN + 4.0
        # one legend for every plan, at the foot of the page
        kinds, closing = legend_kinds(first.plans)
        legend = _block(fig, "flegend", lambda s: draw_force_legend_into(s, kinds, closing, lang))
        legend.place(sketch, PAGE_MARGIN, bottom, size)
        room = top - bottom - legend.height - GAP
        # the free bodies across the page, at the k_l that draws them largest within their share
        w, h = _span(list(graphical.positions.values()))

        def free_bodies(share: float, page=None):
            """The free bodies in one row, or (when larger so) in two, as large as fit (width × share of the room)."""
            page = page or fig
            best = None
            counts = [len(first.plans)] + ([-(-len(first.plans) // 2)] if len(first.plans) >= 3 and share > FREE_BODIES_SHARE else [])
            for per_row in counts:
                rows = -(-len(first.plans) // per_row)
                k, block = _largest_fitting(lambda k, per_row=per_row: _block(page, "fbody", lambda s: draw_free_bodies_into(s, first, lang=lang, k_l=k, per_row=per_row)),
                                            (width, room * share), graphical.scales["k_l"], lambda k, rows=rows, per_row=per_row: (w * per_row / k, h * rows / k))
                if best is None or k < best[0]:
                    if best is not None:
                        best[1].axes.remove()
                    best = (k, block)
                else:
                    block.axes.remove()
            return best[1]

        free = free_bodies(FREE_BODIES_SHARE)
        sizes: dict = {}
        natural = _natural(fig, first, lang)
        shared = _layout(fig, plans_at, first, items, room - free.height - GAP, width, lang, sizes, natural, limit=CRAMPED * 1.5)
        if shared is not None and shared[0] <= CRAMPED:
            _, columns, box, scales = shared
            header(sketch, size, title or graphical.scene.title_in(lang), where + [_heading(lang, ("free_bodies", "force_plans"), _one(scales))])
            free.place(sketch, PAGE_MARGIN + (width - free.width) / 2, top - free.height, size)
            _place_plans(fig, sketch, plans_at, items, columns, box, scales, top - free.height - GAP, width, size, lang, lever)
            page_footer(sketch, footer)
            fig.force_scales = dict(scales)
            return [fig] + _lever_page(graphical, lever, lang, title, where, footer)
        # two pages: the free bodies larger on the first, the plans and their legend on the second
        free.axes.remove()
        legend.axes.remove()
        header(sketch, size, title or graphical.scene.title_in(lang), where + [_heading(lang, ("free_bodies",))])
        top = size[1] - header_height(where + [_heading(lang, ("free_bodies",))])
        room = top - bottom
        free = free_bodies(1.0)
        free.place(sketch, PAGE_MARGIN + (width - free.width) / 2, top - free.height, size)
        page_footer(sketch, footer)
        fig.force_scales = {}
        second, sketch2 = new_page(size)
        top2 = size[1] - header_height(where + [_heading(lang, ("force_plans",), 1.0)])
        legend = _block(second, "flegend", lambda s: draw_force_legend_into(s, kinds, closing, lang))
        legend.place(sketch2, PAGE_MARGIN, bottom, size)
        room2 = top2 - bottom - legend.height - GAP
        _, columns, box, scales = _layout(second, plans_at, first, items, room2, width, lang, sizes)
        header(sketch2, size, title or graphical.scene.title_in(lang), where + [_heading(lang, ("force_plans",), _one(scales))])
        _place_plans(second, sketch2, plans_at, items, columns, box, scales, top2, width, size, lang, lever)
        page_footer(sketch2, footer)
        second.force_scales = dict(scales)
    return [fig, second] + _lever_page(graphical, lever, lang, title, where, footer)


def _one(scales: dict) -> float | None:
    """The page's one μ_F [N/mm] (every plan's)."""
    values = set(scales.values())
    if len(values) > 1:
        raise ValueError(f"the force plans of one page are drawn at one μ_F, got {sorted(values)}")
    return values.pop() if values else None


def _heading(lang: str, parts, mu: float | None = None) -> str:
    """The page's bold heading: "Kinetostatic analysis — <what the page holds>" and, with plans, their one μ_F [N/mm]."""
    words = "; ".join(_lower(term(part, lang)) if n else term(part, lang) for n, part in enumerate(parts))
    line = f"§{term('kinetostatics', lang)} — {words}"
    if mu is not None:
        line += "; " + scale_caption(r"\mu_F", fmt_number(mu), "N/mm", lang)
    return line


def _lower(words: str) -> str:
    """A term's first letter in lower case (it continues a line), unless the second is a capital too."""
    return words[:1].lower() + words[1:] if words[1:2].islower() else words


def _lever_page(graphical, lever, lang: str, title, lines, footer: str) -> list:
    """Joukowski's lever on a page of its own, at its velocity plan's k_v (none without a lever)."""
    if lever is None:
        return []
    size = A4
    width = size[0] - 2 * PAGE_MARGIN
    with drawing_rc():
        fig, sketch = new_page(size)
        top = header(sketch, size, title or graphical.scene.title_in(lang), list(lines) + [_heading(lang, ("joukowski_lever",))])
        block = _block(fig, "lever", lambda s: draw_lever_into(s, lever, lang=lang))
        block.place(sketch, PAGE_MARGIN + max(0.0, (width - block.width) / 2), top - block.height, size)
        page_footer(sketch, footer)
    fig.force_scales = {}
    return [fig]
