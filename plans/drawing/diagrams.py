"""Kinematic diagrams over the driver's cycle, from an analytic sweep.

Three figures (A4 portrait, the size of a handout page):

* links — φ (unwrapped, in degrees), ω and ε of every link (slider blocks
  turn with their guides and are left out);
* points — |v| and |a| of every reported point, and with ``components=True``
  their x and y components;
* sliders — travel s, relative velocity vʳ = ṡ and relative acceleration
  aʳ = s̈ along the guide, and the magnitude of the Coriolis acceleration |aᵏ|
  of every prismatic pair (only when the
  mechanism has one).

Conventions, the same as :mod:`plans.positions` and ``plans sweep``:

* The horizontal axis is the angle the crank has turned from position 0 *in
  the sense of its ω* (so 0, 1, 2 … of the marked positions run left to
  right), or the linear driver's position.
* An angle φ is unwrapped continuously along the whole sweep (across an
  interval without assembly too) and starts in [0°, 360°): it differs from
  the CSV's angle in [0, 360) by whole turns only.  The crank's own φ is the
  horizontal axis and is not drawn again: the panel says how it relates.
  Each angle is drawn over its own swing: links whose swings are alike share a
  panel, each as its change from the middle of its swing (``φ₄ − 112,3°`` in
  the legend); a link that swings less than :data:`SHARE` of the panel's range
  gets a panel of its own, drawn as it is (see :func:`_angle_panels`).  A
  rocker input's swing: every angle (the input's too) drawn as it is, the
  middle of its range within (−180°, 180°], without offsets.
* A cycle that repeats (a crank's turn at constant ω, a swing there and
  back) is closed: its first sample drawn again at 360° (or T).
* Positions 0 and 0′ (the output's extreme positions) are marked and said
  in the legend; a Coriolis panel that would be zero everywhere is left out,
  a line under the title says so.
* Every text of a diagram (ticks, legends, notes, position numbers) is
  :data:`TEXT` pt; the positions' lines are one thin width (:data:`MARK`).
* A quantity constant by the scene (the crank's ω and ε, the angle of a
  linear driver) is not drawn as a flat curve but written beside the panel,
  under its legend (never over the data; a single diagram: above it); curves equal at every position (links
  that turn together: ω₃ ≡ ω₄) are drawn once, with both names.
* Near a dead centre the values run off to infinity: each panel's vertical
  range is that of the well-conditioned positions (not near a dead centre);
  values beyond it are clipped, marked with ▲/▼ at the edge, and their
  extremes written in the panel.
* Intervals where the mechanism cannot assemble are grey and hatched ``///``;
  those near a dead centre (|sin| of the angle between a group's
  construction lines below :data:`NEAR_DEAD_CENTRE`, and the positions beside
  an interval without assembly, which is entered through a dead centre) are
  hatched ``\\\\`` in black: both read in black and white.  The positions that
  have sheets are marked with dashed vertical lines, a ▼ and their numbers;
  the grid has horizontal lines only, so the marks are never taken for it.
* Curves differ in colour, line style and marker, so they read without
  colour too.  Numbers use the decimal comma in sr, ru, bg and sl, and a true
  minus sign; the scene's title is drawn as plain text.

Only the drawing happens here: every value comes from the
:class:`~plans.analytic.AnalyticSolution`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.ticker import ScalarFormatter

from .._files import replace_all
from .._text import math_name, subscript, user_text
from ..i18n import term
from .numerals import MINUS, localised
from .style import A4
from .svg import drawing_rc

__all__ = ["NEAR_DEAD_CENTRE", "QUANTITIES", "draw_cycle_diagrams", "write_cycle_diagrams", "plot_cycle", "cycle_axis", "marks_shown"]

#: |sin| of the angle between construction lines below which a position counts as near a dead centre.
NEAR_DEAD_CENTRE = 0.1
#: Positions where every group's |sin| is at least this are well-conditioned: they set a panel's vertical range
#: when the others reach beyond it by more than :data:`CLIP_BEYOND` times its span.
WELL_CONDITIONED = 0.3
CLIP_BEYOND = 0.5
#: The near-dead-centre band is drawn at least this share of the horizontal axis wide, so that it can be seen.
BAND_MIN = 0.008

COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#8C6D31")
STYLES = ("-", "--", "-.", ":")
MARKERS = ("o", "s", "^", "D", "v", "x", "+", "*")
NO_ASSEMBLY = {"facecolor": "#d4d4d4", "edgecolor": "#6e6e6e", "hatch": "///"}
NEAR = {"facecolor": "none", "edgecolor": "#6a6a6a", "hatch": "\\\\"}
#: The positions' lines: thin (ISO 128's 0.18 mm), so that a screen or pdftoppm up to 150 dpi draws every one a
#: single pixel wide (0.7 pt fell one or two pixels wide by where it lay: the line at 90° read heavier).
MARK = {"color": "#202020", "lw": 0.45, "ls": "--"}
#: Size [pt] of every text in a diagram but the page's title and subtitle: tick labels, legends, notes, position numbers.
TEXT = 8.0
#: The label of the output's other extreme position (the course's 0′), marked dotted beside the numbered positions.
OTHER_EXTREME = "0′"


def _number(value: float, lang: str, digits: int = 3) -> str:
    """A number for a panel note: ordinary magnitudes without exponent, a true minus, the language's decimal mark."""
    value = float(value)
    if value == 0 or not math.isfinite(value):
        return "0" if value == 0 else "?"
    if 1e-3 <= abs(value) < 1e6:
        decimals = max(0, digits - 1 - int(math.floor(math.log10(abs(value)))))
        text = _grouped(f"{value:.{decimals}f}")
    else:
        mantissa, exponent = f"{value:.{digits - 1}e}".split("e")
        text = f"{mantissa}·10" + str(int(exponent)).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))
    return localised(text, lang)


def _stated(value: float, lang: str) -> str:
    """A value of the scene (the crank's ω) as the driver's law states it: four significant digits, trailing zeros
    dropped (``209,4``, ``−10``), so that the panel and the law under the title read the same."""
    text = _number(value, lang, 4)
    mark = "," if lang in ("sr", "ru", "bg", "sl") else "."
    if mark in text and "·" not in text:
        text = text.rstrip("0").rstrip(mark)
    return text


def _grouped(text: str) -> str:
    """Digits of a whole part of five or more grouped by three with a thin space (ISO 80000-1): ``15 000``."""
    import re

    return re.sub(r"(?<![\d.,])(\d{5,})", lambda m: f"{int(m.group(1)):,}".replace(",", "\u2009"), text)


class _Ticks(ScalarFormatter):
    """Tick labels without an offset or exponent for ordinary magnitudes, a true minus, the decimal comma in sr, ru, bg, sl."""

    def __init__(self, lang: str):
        super().__init__(useOffset=False)
        self.set_powerlimits((-4, 6))
        self.lang = lang

    def __call__(self, x, pos=None):
        return localised(_grouped(super().__call__(x, pos).replace(MINUS, "-")), self.lang)

    def get_offset(self):
        return localised(super().get_offset().replace(MINUS, "-"), self.lang)


def _sense(scene) -> float:
    """+1 when the crank turns counter-clockwise (or stands still), −1 clockwise; +1 for a linear driver."""
    omega = getattr(scene.driver, "omega", 0.0)
    return -1.0 if omega < 0 else 1.0


def _swing(cycle) -> bool:
    """The sweep is a rocker input's swing and back (:mod:`plans.motion`): drawn against time."""
    return cycle is not None and cycle.law.kind == "harmonic"


def cycle_axis(analytic, marked=None, cycle=None) -> tuple[np.ndarray, str, list[tuple[int, float]]]:
    """The x values of a sweep, the axis label, and the marked positions as (number, x).

    For a crank, x is the angle turned from the sweep's first position in the
    sense of the crank's ω [°] (the sense :mod:`plans.positions` and ``plans
    sweep`` number and run positions in); for a linear driver, the position
    [m] (s in m on every diagram).  *marked* are driver positions (rad or m), numbered 0, 1, 2 … in the
    order given, or a :class:`plans.motion.Cycle` of them.  A rocker input's
    swing (*cycle*, the :class:`plans.motion.Cycle` the sweep was solved
    under, with a harmonic law) runs there and back over the same angles:
    x is then the time t [s] from the first position, and *marked* a Cycle.
    """
    scene = analytic.scene
    driver = np.asarray(analytic.driver, dtype=float)
    marks = []
    if _swing(cycle):
        x = np.asarray(cycle.t, dtype=float)
        if hasattr(marked, "phase"):
            omega = cycle.law.frequency
            for k, psi in enumerate(np.asarray(marked.phase, dtype=float)):
                marks.append((k, float(((psi - cycle.phase[0]) % (2 * math.pi)) / omega)))
        return x, "t [s]", marks
    if hasattr(marked, "positions"):
        marked = list(marked.positions)
    if hasattr(scene.driver, "omega"):
        sense = _sense(scene)
        start = driver[0]
        x = np.degrees(sense * (driver - start))
        label = "Δφ [°]"
        for k, p in enumerate(marked or ()):
            marks.append((k, float(np.degrees(sense * (p - start)) % 360.0)))
    else:
        x = driver.copy()  # [m]: s in m on every diagram, as the kinematic diagrams' μ_s [m/mm] gives it
        label = "s [m]"
        for k, p in enumerate(marked or ()):
            marks.append((k, float(p)))
    return x, label, marks


def marks_shown(analytic, marked, cycle=None) -> list[tuple[int, float]]:
    """Where the diagrams of :func:`plot_cycle` (with the same *cycle*) show each marked position: (number, x)
    on their horizontal axis, for those they show (a crank's sweep that assembles over one short arc is shown
    over that arc only; a rocker input's swing against time; see :func:`cycle_axis`).  A cursor that follows
    the positions is drawn at these x."""
    return list(_cycle_view(analytic, marked, cycle)[3])


#: A crank's sweep that assembles over at most this arc [°] is drawn over that arc (and a margin), not the whole turn.
WINDOW_ARC = 240.0


def _window(x: np.ndarray, valid: np.ndarray) -> tuple[np.ndarray, np.ndarray, tuple[float, float]] | None:
    """Where a crank's full-turn sweep assembles over one arc of at most :data:`WINDOW_ARC`: the order that runs
    through that arc first, the angles turned in that order (the arc unbroken, negative before position 0),
    and the axis limits (the arc and a margin either side, hatched as not assembling).  None otherwise."""
    n = len(x)
    if n < 3 or not valid.any() or valid.all() or float(x[-1] - x[0]) < 300.0:
        return None
    closed = abs(float(x[-1] - x[0]) - 360.0) < 1e-6  # the last position is the first one a turn on
    m = n - 1 if closed else n
    ring = np.concatenate([valid[:m], valid[:m]])
    best, end, run = 0, 0, 0
    for k, ok in enumerate(ring):  # the longest run of positions that do not assemble, round the turn
        run = 0 if ok else run + 1
        if best < run <= m:
            best, end = run, k
    covered = m - best
    step = 360.0 / m
    if covered * step > WINDOW_ARC or not valid[:m][[(end + 1 + t) % m for t in range(covered)]].all():
        return None  # the mechanism assembles over more than one arc, or over most of the turn
    first = (end + 1) % m
    order = np.array([(first + t) % m for t in range(m)])
    turned = float(x[first]) + step * np.arange(m)
    if turned[covered - 1] > 360.0 - 1e-9:  # the arc runs through position 0: before it is negative
        turned -= 360.0
    lo, hi = float(turned[0]), float(turned[covered - 1])
    margin = max(10.0, 0.15 * (hi - lo))
    return order, turned, (lo - margin, hi + margin)


def _cycle_view(analytic, marked, cycle=None):
    """(solution, x, axis label, marks, x limits, ticks, rolled) of a cycle diagram: a crank's sweep that
    assembles over one short arc is shown over that arc, its positions taken in the order the arc runs
    through (*rolled*: its first and last positions are neighbours on the turn)."""
    x, xlabel, marks = cycle_axis(analytic, marked, cycle)
    crank = hasattr(analytic.scene.driver, "omega") and not _swing(cycle)
    limits, ticks = (float(np.nanmin(x)), float(np.nanmax(x))), None
    if crank and float(np.nanmax(x) - np.nanmin(x)) >= 300.0:
        limits = (0.0, 360.0)  # a whole turn: its axis ends at 360°
    window = _window(x, np.asarray(analytic.valid, dtype=bool)) if crank else None
    rolled = window is not None
    if window is not None:
        order, x, limits = window
        analytic = analytic.at(order)
        lo, hi = float(x.min()), float(x.max())
        # each marked position where the window shows it (a turn before, when it lies there)
        marks = [(k, min((xm + t for t in (-360.0, 0.0, 360.0) if lo - 1e-9 <= xm + t <= hi + 1e-9),
                         key=lambda v: abs(v - (limits[0] + limits[1]) / 2), default=xm)) for k, xm in marks]
        marks = [(k, xm) for k, xm in marks if limits[0] <= xm <= limits[1]]  # (the others lie where it does not assemble)
    if crank and limits[1] - limits[0] >= 90.0:
        span = limits[1] - limits[0]
        every = 30.0 if span > 150.0 else 15.0
        ticks = np.arange(math.ceil(limits[0] / every) * every, limits[1] + 1e-9, every)
    return analytic, x, xlabel, marks, limits, ticks, rolled


def _spans(x: np.ndarray, mask: np.ndarray) -> list[tuple[float, float]]:
    """Intervals of x where mask holds (each sample stands for half the step either side)."""
    spans = []
    n = len(x)
    k = 0
    while k < n:
        if mask[k]:
            j = k
            while j + 1 < n and mask[j + 1]:
                j += 1
            left = x[k] - (x[k] - x[k - 1]) / 2 if k > 0 else x[k]
            right = x[j] + (x[j + 1] - x[j]) / 2 if j + 1 < n else x[j]
            spans.append((float(min(left, right)), float(max(left, right))))
            k = j + 1
        else:
            k += 1
    return spans


def _near_dead(analytic, ring: bool = False) -> np.ndarray:
    """Positions near a dead centre: a group's |sin| below the threshold, or beside a position that
    cannot assemble (the assembly is lost through a dead centre, between the two).  *ring*: the first
    and last positions are neighbours (a turn taken from where the mechanism starts to assemble)."""
    near = np.zeros(len(analytic.driver), dtype=bool)
    for sines in analytic.sines.values():
        s = np.asarray(sines, dtype=float)
        near |= np.isfinite(s) & (s < NEAR_DEAD_CENTRE)
    invalid = ~np.asarray(analytic.valid, dtype=bool)
    beside = np.zeros_like(invalid)
    beside[1:] |= invalid[:-1]
    beside[:-1] |= invalid[1:]
    if ring and len(invalid) > 1:
        beside[0] |= invalid[-1]
        beside[-1] |= invalid[0]
    return near | (beside & ~invalid)


def _decorate(ax, x, invalid, near, marks, lang, *, numbers: bool, limits: tuple[float, float] | None = None) -> None:
    limits = limits or (float(np.nanmin(x)), float(np.nanmax(x)))
    spans = _spans(x, invalid)
    # beyond the sweep's own ends, inside the limits (the margin of an arc, a turn's last step): not assembling
    # where the sweep's end does not assemble or the margin runs into the turn's gap
    if len(x) and limits[0] < float(np.nanmin(x)) and invalid.any():
        spans.append((limits[0], float(np.nanmin(x))))
    if len(x) and limits[1] > float(np.nanmax(x)) and (invalid[-1] or limits[1] - float(np.nanmax(x)) > 2 * abs(float(x[-1] - x[-2]))):
        spans.append((float(np.nanmax(x)), limits[1]))
    for a, b in spans:
        ax.axvspan(a, b, linewidth=0.0, zorder=0.5, **NO_ASSEMBLY)
    widest = BAND_MIN * (limits[1] - limits[0])  # of the axis shown
    for a, b in _spans(x, near & ~invalid):
        grow = max(0.0, widest - (b - a)) / 2
        ax.axvspan(a - grow, b + grow, linewidth=0.0, zorder=0.4, **NEAR)
    for k, xm in marks:
        ax.axvline(xm, zorder=0.6, **(MARK if k != OTHER_EXTREME else {**MARK, "ls": ":"}))
        ax.plot([xm], [1.0], marker="v", ms=3.5, color=MARK["color"], transform=ax.get_xaxis_transform(), clip_on=False, zorder=3, label="_mark")
        if numbers:
            ax.text(xm, 1.025, str(k), transform=ax.get_xaxis_transform(), ha="center", va="bottom", fontsize=TEXT, color="#202020")
    ax.grid(True, axis="y", lw=0.3, color="#d8d8d8")
    # the zero line where the range holds 0, without pulling 0 into the range (a φ from 140° to 155° stays readable)
    ax.add_artist(Line2D([0.0, 1.0], [0.0, 0.0], transform=ax.get_yaxis_transform(), color="#000000", lw=0.5, zorder=0.7, label="_zero"))
    ax.tick_params(labelsize=TEXT)
    ax.xaxis.set_major_formatter(_Ticks(lang))
    ax.yaxis.set_major_formatter(_Ticks(lang))
    ax.set_xlim(*limits)


def _finite(values, valid) -> np.ndarray:
    v = np.array(values, dtype=float)
    v[~valid] = np.nan
    return v


def _page(title: str, subtitle: str, rows: int, size=A4, heading: bool = True) -> tuple[Figure, list]:
    """A page of *size* [mm] (A4 by default; a handout passes its text area, so that the page prints at 100 %).

    *heading*: the title and the subtitle's lines drawn at the top; without, they are the figure's
    ``plans_heading`` (title, lines) for a typesetter to set above it, and the axes start at the top."""
    fig = Figure(figsize=(size[0] / 25.4, size[1] / 25.4), dpi=72)
    fig.plans_size = tuple(size)
    from matplotlib.backends.backend_svg import FigureCanvasSVG

    FigureCanvasSVG(fig)
    import textwrap

    if heading:
        fig.text(11 / size[0], 1 - 11 / size[1], title, fontsize=13.5, weight="bold", ha="left", va="top")
        lines = [w for line in subtitle.split("\n") for w in textwrap.wrap(line, 95)]
        fig.text(11 / size[0], 1 - 19 / size[1], "\n".join(lines), fontsize=9, ha="left", va="top", linespacing=1.3)
        # the axes below the subtitle's lines (9 pt at 1.3 line spacing, 4.13 mm a line) and the positions' numbers
        top = 1 - max(36.0, 19.0 + 4.13 * len(lines) + 9.0) / size[1]
    else:
        fig.plans_heading = (title, subtitle.split("\n"))
        top = 1 - 9.0 / size[1]  # the positions' numbers above the first panel
    bottom = 26 / size[1]
    axes = fig.subplots(rows, 1, sharex=True, gridspec_kw={"left": 24 / size[0], "right": 1 - 40 / size[0], "top": top, "bottom": bottom, "hspace": 0.2})
    return fig, list(np.atleast_1d(axes))


def _legend_note(fig, lang: str, has_invalid: bool, has_near: bool, has_marks: bool, has_clipped: bool, has_extremes: bool = False) -> None:
    from matplotlib.patches import Patch

    handles = []
    if has_invalid:
        handles.append(Patch(label=term("no_assembly", lang), **NO_ASSEMBLY))
    if has_near:
        handles.append(Patch(label=f"{term('near_dead_centre', lang)}: |sin γ| < {localised(f'{NEAR_DEAD_CENTRE:g}', lang)},\n"
                                   f"γ — {term('construction_lines_angle', lang)}", **NEAR))
    if has_marks:
        handles.append(Line2D([], [], marker="v", ms=3.5, label=term("sheet_positions", lang), **MARK))
    if has_extremes:
        handles.append(Line2D([], [], marker="v", ms=3.5, label=f"0, {OTHER_EXTREME} — {term('output_extremes', lang)}", **{**MARK, "ls": ":"}))
    if has_clipped:
        handles.append(Line2D([], [], color="#000000", ls="none", marker="^", ms=3.5, label=term("clipped", lang)))
    if handles:
        size = getattr(fig, "plans_size", A4)
        fig.legend(handles=handles, loc="lower left", bbox_to_anchor=(24 / size[0], 5 / size[1]), ncol=2, fontsize=TEXT, frameon=False)


@dataclass
class _Panel:
    """What one panel shows: curves (names, values), and notes for what is not drawn as a curve."""

    curves: list
    notes: list
    #: each curve's colour, line style and marker by number (the angles split over panels keep their link's)
    styles: list | None = None


def _panel(series, valid, lang: str, unit: str, extra_notes=()) -> _Panel:
    """Constant series become notes, equal series one curve with all their names."""
    curves, notes = [], list(extra_notes)
    for name, y in series:
        y = np.asarray(y, dtype=float)
        ok = valid & np.isfinite(y)
        if not ok.any():
            continue
        values = y[ok]
        scale = max(float(np.max(np.abs(values))), 1e-300)
        if float(np.ptp(values)) <= 1e-9 * scale:
            value = float(values[0]) if abs(float(values[0])) > 1e-12 * scale else 0.0
            # (no-break spaces: a note wrapped into the legend's column never breaks inside "|a_A| = 0")
            if unit == "°":
                # a link that does not turn: its angle is its own frame's, not a line's on the page ("φ₂ = 0" was read
                # against the linear-arm's arm AF drawn at 56°), so it is said constant
                notes.append(f"{name}\u00a0=\u00a0const")
            else:
                notes.append(f"{name}\u00a0=\u00a0{_stated(value, lang)}{(chr(0xa0) + unit) if unit and value else ''}")
            continue
        for curve in curves:
            other = curve[1]
            if np.array_equal(np.isfinite(other), np.isfinite(y)) and np.allclose(other[ok], values, rtol=1e-9, atol=1e-12 * scale):
                curve[0].append(name)
                break
        else:
            curves.append(([name], y))
    if notes:
        notes = [f"{', '.join(notes)}  ({term('constant', lang)})"] if not extra_notes else [", ".join(notes)]
    return _Panel([(" = ".join(names), y) for names, y in curves], notes)


#: Angles share a panel only where each one's swing is at least this share of the panel's data range.
SHARE = 0.5


def _angle_panels(panel: _Panel, lang: str, offsets: bool = True) -> list[_Panel]:
    """The angle panel split so that every angle's swing is readable: links whose swings are alike share a
    panel, each drawn as its change from the middle of its swing (named ``φ₄ − 112,3°``); a link that
    swings much less (or much more) than the others gets a panel of its own, drawn as it is.  The notes
    (the crank's φ, constant angles) go into the first panel.

    Without *offsets* (a swing: every angle, the driver's too, within a half turn of 0) each angle is drawn
    as it is, and links share a panel where their angles themselves lie alike."""
    if len(panel.curves) < 2:
        return [panel]

    def swing(y):
        return float(np.nanmax(y) - np.nanmin(y))

    groups: list[list[tuple[str, np.ndarray, float]]] = []
    for name, y in sorted(panel.curves, key=lambda c: -swing(c[1])):
        middle = round((float(np.nanmax(y)) + float(np.nanmin(y))) / 2, 1) if offsets else 0.0
        entry = (name, y, middle)
        for group in groups:
            trial = group + [entry]
            lo = min(float(np.nanmin(v - m)) for _, v, m in trial)
            hi = max(float(np.nanmax(v - m)) for _, v, m in trial)
            if all(swing(v) >= SHARE * (hi - lo) for _, v, _ in trial):
                group.append(entry)
                break
        else:
            groups.append([entry])
    order = [name for name, _ in panel.curves]  # the links' order within each panel
    out = []
    for group in sorted(groups, key=lambda g: min(order.index(n) for n, _, _ in g)):
        group.sort(key=lambda e: order.index(e[0]))
        if len(group) == 1:
            out.append(_Panel([(group[0][0], group[0][1])], [], [order.index(group[0][0])]))
        else:
            curves: list = []  # links that turn together swing alike: one curve with both names
            styles = []
            for name, y, m in group:
                label = f"{name} {MINUS if m >= 0 else '+'} {localised(f'{abs(m):.1f}', lang)}°" if offsets else name
                d = y - m
                same = [c for c in curves if np.array_equal(np.isfinite(c[1]), np.isfinite(d)) and np.allclose(c[1][np.isfinite(d)], d[np.isfinite(d)], atol=1e-9)]
                if same:
                    same[0][0].append(label)
                else:
                    curves.append(([label], d))
                    styles.append(order.index(name))
            out.append(_Panel([("\n= ".join(names), d) for names, d in curves], [], styles))  # (a long name: a line each)
    out[0].notes = list(panel.notes)
    # styles numbered over all the angle panels in the links' order, links drawn as one counted once (as in ω, ε)
    ranks = {n: r for r, n in enumerate(sorted({n for p in out for n in p.styles}))}
    for p in out:
        p.styles = [ranks[n] for n in p.styles]
    return out


def _well_conditioned(analytic) -> np.ndarray:
    """Positions where every group's |sin| is at least :data:`WELL_CONDITIONED`."""
    good = np.asarray(analytic.valid, dtype=bool).copy()
    for sines in analytic.sines.values():
        s = np.asarray(sines, dtype=float)
        good &= np.isfinite(s) & (s >= WELL_CONDITIONED)
    return good


def _clip(ax, x, panel: _Panel, good, lang: str, unit: str) -> bool:
    """Limit the vertical range to the well-conditioned positions; mark and write what lies beyond. True if clipped."""
    if not panel.curves:
        return False
    ys = np.array([y for _, y in panel.curves], dtype=float)
    if not good.any():
        return False
    inside = ys[:, good]
    lo, hi = float(np.nanmin(inside)), float(np.nanmax(inside))
    full_lo, full_hi = float(np.nanmin(ys)), float(np.nanmax(ys))
    span = max(hi - lo, 1e-12 * max(abs(hi), abs(lo), 1e-300))
    if full_lo >= lo - CLIP_BEYOND * span and full_hi <= hi + CLIP_BEYOND * span:
        return False
    bottom, top = lo - 0.12 * span, hi + 0.12 * span
    if full_lo >= lo - CLIP_BEYOND * span:
        bottom = min(bottom, full_lo - 0.05 * span)
    if full_hi <= hi + CLIP_BEYOND * span:
        top = max(top, full_hi + 0.05 * span)
    ax.set_ylim(bottom, top)
    extremes: dict[str, list[str]] = {}
    for name, y in panel.curves:
        for edge, over, marker in ((top, y > top, "^"), (bottom, y < bottom, "v")):
            over = np.where(np.isfinite(y), over, False)
            if not over.any():
                continue
            # one mark per run of clipped positions, at its extreme
            k = 0
            while k < len(y):
                if over[k]:
                    j = k
                    while j + 1 < len(y) and over[j + 1]:
                        j += 1
                    run = slice(k, j + 1)
                    extreme = k + int(np.argmax(np.abs(y[run])))
                    ax.plot([x[extreme]], [edge], marker=marker, ms=4, color="#000000", clip_on=False, zorder=3.5, label="_clipped")
                    k = j + 1
                else:
                    k += 1
            extreme = float(np.nanmax(y[over])) if marker == "^" else float(np.nanmin(y[over]))
            extremes.setdefault(name, []).append(_number(extreme, lang))
    beyond = [f"{name}: {' / '.join(values)}" for name, values in extremes.items()]
    if beyond:  # in the legend's column beside the axes, under the panel's other notes: never over the data
        note = _wrapped(f"{term('clipped', lang)}: " + ", ".join(beyond) + (f" {unit}" if unit else ""))
        notes = _side_notes(ax)
        if notes:
            notes[0].set_text(notes[0].get_text() + "\n" + note)
        else:
            ax.text(1.015, 0.0, note, transform=ax.transAxes, ha="left", va="bottom", fontsize=TEXT, linespacing=1.25)
    return bool(beyond)


def _plot_panel(ax, x, panel: _Panel, ylabel: str, marks=()) -> None:
    """The curves, told apart by colour, line style and marker shape.

    With marked positions, each curve's markers sit on the marked positions' lines
    (a marker between them would be read as a position); otherwise about ten a curve.
    """
    step = max(1, len(x) // 10)
    on_marks = sorted({int(np.nanargmin(np.abs(x - xm))) for _, xm in marks}) if len(marks) else None
    for k, (label, y) in enumerate(panel.curves):
        n = panel.styles[k] if panel.styles else k
        ax.plot(
            x, y, color=COLOURS[n % len(COLOURS)], ls=STYLES[n % len(STYLES)], lw=1.1, label=label,
            marker=MARKERS[n % len(MARKERS)], ms=3.2,
            markevery=on_marks if on_marks is not None else ((k * step) // max(1, len(panel.curves)), step),
            mfc="white" if n % 2 else COLOURS[n % len(COLOURS)],
        )
    ax.set_ylabel(ylabel, fontsize=TEXT)
    if panel.curves:
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=TEXT, frameon=False, borderaxespad=0.0, handlelength=3.0)
    if panel.notes:  # (a quantity constant by the scene) in the legend's column beside the axes, at its foot: never over the data
        ax.text(1.015, 0.0, "\n".join(_wrapped(n) for n in panel.notes), transform=ax.transAxes, ha="left", va="bottom",
                fontsize=TEXT, linespacing=1.25)


#: Characters a line of a note in the legend's column holds (the column beside the axes is about 38 mm wide).
NOTE_LINE = 22


def _wrapped(note: str) -> str:
    """A panel's note broken into the legend column's lines."""
    import textwrap

    return "\n".join(textwrap.wrap(note, NOTE_LINE, break_long_words=False))


def _side_notes(ax) -> list:
    """The panel's notes beside the axes (see :func:`_plot_panel`): texts placed in axes coordinates right of them."""
    return [t for t in ax.texts if t.get_transform() == ax.transAxes and t.get_position()[0] > 1.0]


def _notes_above(ax, raised: bool = False) -> None:
    """A single diagram's notes (see :func:`_plot_panel`) moved from beside the axes to above them, as wide as the
    axes: a diagram of a page (the lecture's) has no legend column to hold them; never over the data.
    *raised*: above the positions' numbers too."""
    import textwrap

    from matplotlib.transforms import offset_copy

    width_mm = ax.get_position().width * ax.figure.get_figwidth() * 25.4
    for note in _side_notes(ax):
        words = "; ".join(" ".join(part.split("\n")) for part in note.get_text().split("\n\n"))
        lines = textwrap.wrap(" ".join(words.split("\n")), max(20, int(width_mm / 1.55)), break_long_words=False)
        note.set_text("\n".join(lines))
        note.set_position((0.0, 1.02))
        if raised:
            note.set_transform(offset_copy(ax.transAxes, ax.figure, y=TEXT * 1.4, units="points"))
        note.set_horizontalalignment("left")
        note.set_verticalalignment("bottom")


def _name(symbol: str, sub: str) -> str:
    """A symbol with a subscript, typeset: digits as Unicode subscripts (``ω₃``), a name in mathtext (``$v_{\\mathrm{M}}$``).

    The name comes from the scene: characters mathtext would read as commands are escaped.
    """
    if sub.isdigit() and "^" not in symbol:
        return symbol + subscript(sub)
    return rf"${symbol}_{{\mathrm{{{math_name(sub)}}}}}$"


def _other_extreme(cycle, extremes, x, start: float) -> list[tuple[str, float]]:
    """The mark of the output's other extreme position 0′ (:class:`plans.motion.Strokes`) on the axis x of a cycle."""
    if cycle is None or extremes is None or cycle.start != "output" or not len(x):
        return []
    if _swing(cycle):
        at = ((extremes.other_phase - float(cycle.phase[0])) % (2 * math.pi)) / cycle.law.frequency
    elif cycle.law.crank:
        at = math.degrees(cycle.law.sense * (extremes.other_position - start)) % 360.0
    else:
        at = float(extremes.other_position)
    return [(OTHER_EXTREME, float(at))] if float(np.nanmin(x)) <= at <= float(np.nanmax(x)) else []


def draw_cycle_diagrams(analytic, *, marked=None, lang: str = "en", components: bool = False, cycle=None, extremes=None, size=A4,
                        signed_elsewhere=(), heading: bool = True) -> list[tuple[str, Figure]]:
    """The cycle diagrams as (name, Figure) pairs: ``links``, ``points`` and, if any, ``sliders``.

    Parameters
    ----------
    analytic : plans.analytic.AnalyticSolution
        A sweep over the cycle (``allow_partial=True`` is fine: invalid
        positions are shaded and not plotted).
    marked : sequence of float, optional
        Driver positions with sheets (rad or m), numbered 0, 1, 2 …
    lang : str
        Language of headings and axis words (see :mod:`plans.i18n`).
    components : bool
        Also plot the x and y components of every point's v and a.
    cycle : plans.motion.Cycle, optional
        The law the sweep was solved under (``cycle.solve()``): stated under
        the title; a rocker input's swing is drawn against time.
    extremes : plans.motion.Strokes, optional
        With a cycle that starts at the output's extreme position: its other
        extreme position is marked 0′ (dotted).
    size : (float, float)
        The page [mm]: A4 portrait by default; a handout gives its text area.
    signed_elsewhere : sequence of str
        Points whose |v|, |a| are not drawn on the points page: those of the output slider, whose signed
        v and a the kinematic diagrams beside these pages give (the page says so; without another point
        it is not drawn).
    heading : bool
        Draw each page's title and words at its top; without, each figure carries them as ``plans_heading``
        ``(title, lines)`` (the first line the scene's title, as written) for a typesetter to set above it.
    """
    scene = analytic.scene
    omit = tuple(p for p in signed_elsewhere if p in analytic.points)
    start = float(analytic.driver[0])  # position 0's angle, for the note φ₂ = start + Δφ
    analytic, x, xlabel, marks, limits, ticks, rolled = _cycle_view(analytic, marked, cycle)
    others = [] if rolled else _other_extreme(cycle, extremes, x, start)
    drawn = bool(marks)  # positions with sheets
    if others and not marks:  # no positions drawn: position 0 (the output's first extreme) marked beside 0′
        marks = [(0, float(x[0]))]
    if not rolled:  # 0′ dotted, unless it falls on a numbered position's line (within 1.2 % of the axis: it reads as that)
        span = limits[1] - limits[0]
        marks = marks + [m for m in others if all(abs(m[1] - xm) > 0.012 * span for _, xm in marks)]
    period = None if rolled else _period(x, cycle, hasattr(scene.driver, "omega"))
    valid = np.asarray(analytic.valid, dtype=bool)
    invalid = ~valid
    near = _near_dead(analytic, ring=rolled)
    good = _well_conditioned(analytic)
    crank = hasattr(scene.driver, "omega")
    xwords = term("time", lang) if _swing(cycle) else term("turned_from_0", lang) if crank else term("driver_position", lang)
    title = term("cycle_diagrams" if crank or _swing(cycle) else "stroke_diagrams", lang)  # a sliding driver: one stroke
    subtitle = user_text(scene.title_in(lang) if hasattr(scene, "title_in") else scene.title)
    if cycle is not None:
        subtitle += "\n" + cycle.law.describe(lang, scene.driver.link, **({"phase": float(cycle.phase[0])} if _swing(cycle) else {}))
    out = []

    xs, invalid_s, near_s, good_s = (x, invalid, near, good) if period is None else (
        np.append(x, x[0] + period), *(np.append(a, a[0]) for a in (invalid, near, good)))

    def page(name, words, quantities):
        panels, dropped = [], []
        for quantity, ylabel, unit in quantities:
            panel = _quantity_panel(analytic, quantity, valid, lang, unit, start=start, swing=_swing(cycle), omit=omit if name == "points" else ())
            if quantity == "coriolis" and not panel.curves:  # a slider on a guide that does not turn: no panel of zeros
                dropped.append(term("coriolis_zero", lang))
                continue
            if period is not None:
                panel = _closed(panel, quantity)
            panels += [(p, ylabel, unit) for p in (_angle_panels(panel, lang, offsets=not _swing(cycle)) if quantity == "phi" else [panel])]
        if dropped and name == "sliders":  # the page's words without the Coriolis acceleration it does not draw
            words = term("sliders_motion_relative", lang)
        fig, axes = _page(title, subtitle + "\n" + words + "".join("\n" + d for d in dropped), len(panels), size, heading)
        clipped = False
        for ax, (panel, ylabel, unit) in zip(axes, panels):
            _plot_panel(ax, xs, panel, ylabel, marks)
            _decorate(ax, xs, invalid_s, near_s, marks, lang, numbers=ax is axes[0], limits=limits)
            clipped |= _clip(ax, xs, panel, good_s, lang, unit)
        axes[-1].set_xlabel(f"{xlabel}  —  {xwords}", fontsize=TEXT + 1)
        if ticks is not None:
            axes[-1].set_xticks(ticks)
            axes[-1].set_xlim(*limits)
        extremes_marked = any(k == OTHER_EXTREME for k, _ in marks)
        _legend_note(fig, lang, bool(invalid.any()), bool((near & ~invalid).any()), drawn, clipped, extremes_marked)
        out.append((name, fig))

    with drawing_rc():
        panels = [("phi", f"φ [°]\n({term('angle', lang)})", "°"), ("omega", f"ω [rad/s]\n({term('angular_velocity', lang)})", "rad/s")]
        if scene.accelerations:
            panels.append(("epsilon", f"ε [rad/s²]\n({term('angular_acceleration', lang)})", "rad/s²"))
        page("links", term("links_motion", lang), panels)

        panels = [("v", f"|v| [m/s]\n({term('velocity', lang)})", "m/s")]
        if components:
            panels += [("vx", "$v_x$ [m/s]", "m/s"), ("vy", "$v_y$ [m/s]", "m/s")]
        if scene.accelerations:
            panels.append(("a", f"|a| [m/s²]\n({term('acceleration', lang)})", "m/s²"))
            if components:
                panels += [("ax", "$a_x$ [m/s²]", "m/s²"), ("ay", "$a_y$ [m/s²]", "m/s²")]
        if omit:
            words = term("points_motion", lang) + "\n" + term("signed_elsewhere", lang).format(points=", ".join(omit))
            if any(p not in omit for p in scene.report if p in analytic.points):
                page("points", words, panels)
        else:
            page("points", term("points_motion", lang), panels)

        if any(p.name in analytic.sliders for p in scene.prismatics):
            panels = [("s", f"s [m]\n({term('guide_position', lang)})", "m"), ("v_rel", f"vʳ [m/s]\n({term('relative_velocity_short', lang)})", "m/s")]
            if scene.accelerations:
                panels += [
                    ("a_rel", f"aʳ [m/s²]\n({term('relative_acceleration_short', lang)})", "m/s²"),
                    ("coriolis", f"|aᵏ| [m/s²]\n({term('coriolis_acceleration', lang)})", "m/s²"),
                ]
            page("sliders", term("sliders_motion", lang), panels)
    return out


def _period(x: np.ndarray, cycle, crank: bool) -> float | None:
    """The period of the horizontal axis when the sweep is one whole cycle that repeats, its last sample one
    step before the first one again (a crank's turn at constant ω: 360°; a swing there and back: T); else None.
    The diagrams are then closed: the first sample drawn again one period on."""
    if len(x) < 3:
        return None
    step = float(x[1] - x[0])
    if _swing(cycle):
        period = float(cycle.period)
    elif crank and (cycle is None or cycle.law.kind == "constant"):
        period = 360.0
    else:
        return None
    steps = np.diff(x)
    if _swing(cycle):  # (its limit positions may lie between the equal steps): the last step short of T at most one step
        rest = float(x[0]) + period - float(x[-1])
        return period if 1e-9 * period < rest <= float(steps.max()) * (1 + 1e-6) else None
    if not np.allclose(steps, step, rtol=1e-6, atol=1e-9) or abs(float(x[-1]) + step - float(x[0]) - period) > 1e-6 * period:
        return None
    return period


def _closed(panel: _Panel, quantity: str) -> _Panel:
    """The panel with each curve's first value appended, one period on (an angle: whole turns added where
    the link turned them over the cycle)."""
    curves = []
    for name, y in panel.curves:
        first = float(y[0])
        if quantity == "phi" and np.isfinite(first) and np.isfinite(y[-1]):
            first += 360.0 * round((float(y[-1]) - first) / 360.0)
        curves.append((name, np.append(y, first)))
    return _Panel(curves, panel.notes, panel.styles)


def _unwrap_nan(phi, valid, centred: bool = False) -> np.ndarray:
    """φ in degrees, unwrapped continuously over every valid position (across gaps too), starting in [0°, 360°)
    (*centred*, a swing's angles: the middle of its range within (−180°, 180°]).

    It differs from the angle in [0, 360) of the CSV by whole turns only.
    """
    phi = np.array(phi, dtype=float)
    out = np.full_like(phi, np.nan)
    ok = valid & np.isfinite(phi)
    if ok.any():
        turned = np.degrees(np.unwrap(phi[ok]))
        if centred:
            middle = (float(turned.max()) + float(turned.min())) / 2
            out[ok] = turned - 360.0 * math.ceil((middle - 180.0) / 360.0)
        else:
            out[ok] = turned - 360.0 * math.floor(turned[0] / 360.0)
    return out


def write_cycle_diagrams(analytic, directory, *, marked=None, lang: str = "en", components: bool = False, cycle=None, extremes=None) -> list[Path]:
    """Write ``links.svg``, ``points.svg`` and (with prismatic pairs) ``sliders.svg`` into *directory*, atomically.

    Parameters are those of :func:`draw_cycle_diagrams`.

    Returns
    -------
    list of pathlib.Path
    """
    from .svg import render_svg

    directory = Path(directory)
    contents = {directory / f"{name}.svg": render_svg(fig) for name, fig in draw_cycle_diagrams(analytic, marked=marked, lang=lang, components=components, cycle=cycle, extremes=extremes)}
    return replace_all(contents)  # creates the directory


#: quantity -> label of its axis; see :func:`plot_cycle`.
QUANTITIES = {
    "phi": "φ [°]",
    "omega": "ω [rad/s]",
    "epsilon": "ε [rad/s²]",
    "v": "|v| [m/s]",
    "a": "|a| [m/s²]",
    "s": "s [m]",
    "v_rel": "vʳ [m/s]",
    "a_rel": "aʳ [m/s²]",
    "coriolis": "|aᵏ| [m/s²]",
}
_UNITS = {"phi": "°", "omega": "rad/s", "epsilon": "rad/s²", "v": "m/s", "a": "m/s²", "s": "m", "v_rel": "m/s", "a_rel": "m/s²", "coriolis": "m/s²"}


def _quantity_panel(analytic, quantity: str, valid, lang: str, unit: str, start: float | None = None, swing: bool = False,
                    omit=()) -> _Panel:
    """*start*: position 0's driver angle [rad] (the sweep's first, unless its order was changed); *swing*: a rocker
    input's swing drawn against time, its own angle a curve like the others; *omit*: points not drawn."""
    scene = analytic.scene
    extra = []
    series = _series(analytic, quantity, valid, swing, lang, omit)
    if quantity == "phi" and hasattr(scene.driver, "omega") and not swing:
        link = scene.driver.link
        start = _number(math.degrees(float(analytic.driver[0] if start is None else start)) % 360.0, lang, 4)
        sign = "−" if _sense(scene) < 0 else "+"
        extra.append(f"φ{subscript(link)} = {start}° {sign} Δφ")
        series = [(n, y) for n, y in series if n != f"φ{subscript(link)}"]
    return _panel(series, valid, lang, unit, extra)


def _series(analytic, quantity: str, valid, swing: bool = False, lang: str = "en", omit=()) -> list[tuple[str, np.ndarray]]:
    scene = analytic.scene
    if quantity in ("phi", "omega", "epsilon"):
        links = [n for n in scene.links if not scene.bodies[n].block]
        symbol = {"phi": "φ", "omega": "ω", "epsilon": "ε"}[quantity]
        if quantity == "phi":
            return [(_name(symbol, n), _unwrap_nan(analytic.links[n].phi, valid, centred=swing)) for n in links]
        return [(_name(symbol, n), _finite(getattr(analytic.links[n], quantity), valid)) for n in links]
    points = [p for p in scene.report if p in analytic.points and p not in omit]
    if quantity in ("v", "a"):
        return [(_abs(_name(quantity, p)), _finite(np.abs(getattr(analytic.points[p], quantity)), valid)) for p in points]
    if quantity in ("vx", "vy", "ax", "ay"):
        part = "real" if quantity[1] == "x" else "imag"
        return [(_name(quantity[0], f"{p},{quantity[1]}"), _finite(getattr(getattr(analytic.points[p], quantity[0]), part), valid)) for p in points]
    pairs = [p.name for p in scene.prismatics if p.name in analytic.sliders]
    # a pair by its coincident points (F3F4) where the scene names it in words (a sleeve): no word in a subscript
    called = {n: scene.pair_label(n) for n in pairs}
    if quantity == "s":
        return [(_name("s", called[n]), _finite(np.asarray(analytic.sliders[n].s, dtype=float), valid)) for n in pairs]
    if quantity == "coriolis":
        return [(_abs(_name("a^k", called[n])), _finite(np.abs(analytic.sliders[n].coriolis), valid)) for n in pairs]
    symbol = {"v_rel": "v^r", "a_rel": "a^r"}[quantity]
    return [(_name(symbol, called[n]), _finite(getattr(analytic.sliders[n], quantity), valid)) for n in pairs]


def _abs(name: str) -> str:
    return f"$|{name[1:-1]}|$" if name.startswith("$") else f"|{name}|"


def plot_cycle(analytic, quantity: str = "omega", ax=None, *, marked=None, lang: str = "en", cycle=None) -> list:
    """One diagram over the cycle into *ax* (a new figure when None): ``"phi"``, ``"omega"``, ``"epsilon"``
    of the links, ``"v"``, ``"a"`` of the points, ``"s"``, ``"v_rel"``, ``"a_rel"``, ``"coriolis"`` of the
    prismatic pairs.  Returns the curves (Line2D).
    """
    if quantity not in QUANTITIES:
        raise ValueError(f"no diagram of {quantity!r}; choose one of {', '.join(QUANTITIES)}")
    start = float(analytic.driver[0])
    analytic, x, xlabel, marks, limits, ticks, rolled = _cycle_view(analytic, marked, cycle)
    valid = np.asarray(analytic.valid, dtype=bool)
    near = _near_dead(analytic, ring=rolled)
    with drawing_rc():
        if ax is None:
            fig = Figure(figsize=(160 / 25.4, 90 / 25.4), dpi=72)
            from matplotlib.backends.backend_svg import FigureCanvasSVG

            FigureCanvasSVG(fig)
            ax = fig.add_axes([0.12, 0.16, 0.72, 0.68])  # (room above for the positions' numbers and a note)
        panel = _quantity_panel(analytic, quantity, valid, lang, _UNITS[quantity], start=start, swing=_swing(cycle))
        _plot_panel(ax, x, panel, QUANTITIES[quantity], marks)
        _decorate(ax, x, ~valid, near, marks, lang, numbers=True, limits=limits)
        _clip(ax, x, panel, _well_conditioned(analytic), lang, _UNITS[quantity])
        _notes_above(ax, raised=bool(marks))
        if ticks is not None:
            ax.set_xticks(ticks)
            ax.set_xlim(*limits)
        ax.set_xlabel(xlabel, fontsize=TEXT + 1)
    return [line for line in ax.get_lines() if not line.get_label().startswith("_")]
