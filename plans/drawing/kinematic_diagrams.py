"""The output link's kinematic diagrams by graphical differentiation, drawn as a plate shows them.

Three drawings (:func:`diagram_svgs`), each an SVG block true to scale (one
data unit one millimetre of paper) that a page places at 100 %, over one time
axis (their origins one above the other):

* **s–t** (a rocker: ψ–t): the points of the positions, the smooth curve
  through them, and the chords between neighbouring points;
* **v–t** (ω–t): the pole P₁ at H₁ [mm] to the left of the origin, the rays
  from it parallel to the chords, each ray's intercept on the ordinate carried
  across to the middle of its interval (a point of the v–t curve), and the
  smooth curve through those points; the chords between them, for the next;
* **a–t** (ε–t): the same from the v–t curve, pole P₂ at H₂.

The analytic curves are drawn thin and dashed beside the constructed ones, for
comparison.  The ordinates' values are written on the right of each diagram
(the rays of the pole fill the left), the positions' numbers under it.  The
drawings carry no words: the page (Typst, :mod:`plans.pages.handout`) sets
each diagram's title and scales (:func:`diagram_title`), the data lines
(:func:`header_lines`), the legend (:func:`legend_items`), the comparison
table (:func:`diagrams_table`, :func:`table_header`) and the notes
(:func:`notes`) in the reader's language.  A rate constant over the cycle is
said in a line (:func:`flat_line`) instead of drawn.

:func:`draw_kinematic_figure` is the same as one matplotlib figure with a
short caption: the drawing file of ``plans sweep --plot`` and of
:meth:`plans.differentiation.KinematicDiagrams.save`.

Only the drawing happens here: every number comes from a
:class:`plans.differentiation.KinematicDiagrams`.
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.ticker import MaxNLocator

from .._text import subscript
from ..differentiation import KinematicDiagrams, flat, readable, smooth
from ..i18n import term
from ._canvas import Sketch, fit_axes, text_size
from .numerals import localised
from .svg import drawing_rc, new_figure, render_svg

__all__ = ["diagram_svgs", "diagram_title", "flat_line", "legend_items", "diagrams_table", "table_header", "header_lines",
           "origin_line", "scales_line", "page_heading", "notes", "unavailable_reason", "diagram_words", "page_diagrams", "draw_kinematic_figure",
           "block_room", "table_heading", "KEYS", "TEXT_PT", "DIAGRAM_GAP", "PAGE_ROOM", "PEAK_NOTE", "analytic_cut"]

#: Size [pt] of every text in the diagrams and their table.
TEXT_PT = 8.0
#: The diagrams, in their order down the page.
KEYS = ("s", "v", "a")
#: Room [mm] between diagrams (in the figure of :func:`draw_kinematic_figure`).
DIAGRAM_GAP = 4.5
#: Room [mm] under a diagram for the positions' numbers and the pole distance's dimension.
NUMBER_ROOM = 5.0
#: Room [mm] on the right of a diagram for its ordinate's values.
RIGHT_ROOM = 16.0
#: Room [mm] left of the longer pole for its label.
POLE_ROOM = 6.0
#: The margin [mm] of a drawing's SVG round what it draws.
MARGIN = 1.0
#: The height [mm] of the three drawings together that an A4 page's text area has room for under the data lines
#: and the diagrams' titles: beyond it the analytic curves widen no diagram.
PAGE_ROOM = 204.0
CURVE = "#0072B2"
CHORD = "#D55E00"
RAY = "#404040"
ANALYTIC = "#808080"
GRID = "#b0b0b0"
#: How far [share of its constructed range] the analytic curve may widen a diagram; beyond, it is cut off at the
#: frame, the cut marked (a page's scales, :func:`plans.differentiation.readable`, leave it that room)
REFERENCE_ROOM = 0.25


def _num(value: float, lang: str, digits: int = 4) -> str:
    """*value* to *digits* significant digits, without exponent for ordinary magnitudes, localised."""
    if value is None or not math.isfinite(value):
        return "—"
    if value == 0:
        return "0"
    exponent = int(math.floor(math.log10(abs(value))))
    if -4 <= exponent < 6:
        decimals = max(0, digits - 1 - exponent)
        text = f"{value:.{decimals}f}"
    else:
        mantissa, e = f"{value:.{digits - 1}e}".split("e")
        text = f"{mantissa}·10" + str(int(e)).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))
    return localised(text, lang)


def _short(value: float, lang: str) -> str:
    """A scale or a length to four significant digits, without trailing zeros: ``320``, ``1.6``, ``0.005``, ``120``."""
    text = f"{value:.4g}"
    return _num(value, lang) if "e" in text else localised(text, lang)


def diagram_words(d: KinematicDiagrams, lang: str = "en") -> dict[str, str]:
    """Symbols, units and titles of the three diagrams (a slider: s, v, a; a rocker: ψ, ω, ε)."""
    slider = d.motion.kind == "slider"
    sub = "" if slider else subscript(d.motion.name)
    return {
        "s": "s" if slider else f"ψ{sub}",
        "v": "v" if slider else f"ω{sub}",
        "a": "a" if slider else f"ε{sub}",
        "s_tex": "s" if slider else "\\psi",
        "v_tex": "v" if slider else "\\omega",
        "a_tex": "a" if slider else "\\varepsilon",
        "s_unit": "m" if slider else "rad",
        "v_unit": "m/s" if slider else "rad/s",
        "a_unit": "m/s²" if slider else "rad/s²",
        "s_title": term("displacement" if slider else "angle", lang),
        "v_title": term("velocity" if slider else "angular_velocity", lang),
        "a_title": term("acceleration" if slider else "angular_acceleration", lang),
        "output": f"{term('output_slider' if slider else 'output_rocker', lang)} {d.motion.name}",
    }


def _ticks(lo: float, hi: float, drawn: float) -> np.ndarray:
    """Round values between *lo* and *hi* (physical units) for an ordinate *drawn* mm tall, at least 7 mm apart."""
    bins = max(1, min(6, int(drawn / 7.0)))
    best = None
    for more in range(0, 7):  # finer, until a range on both sides of 0 has a tick on each (as long as they stay 4 mm apart)
        values = MaxNLocator(nbins=bins + more, steps=[1, 2, 2.5, 5, 10]).tick_values(lo, hi)
        values = values[(values >= lo - 1e-12 * abs(hi - lo)) & (values <= hi + 1e-12 * abs(hi - lo))]
        if best is not None and len(values) > 1 and float(np.min(np.diff(values))) / (hi - lo) * drawn < 4.0:
            break
        best = values
        if (hi <= 0 or (values > 0).any()) and (lo >= 0 or (values < 0).any()):
            break
    return best


def _range(*arrays, pad: float = 2.0) -> tuple[float, float]:
    """The drawn range [mm] of a diagram: its data and the abscissa, with *pad* mm above and below."""
    values = np.concatenate([np.asarray(a, dtype=float).ravel() for a in arrays] + [np.zeros(1)])
    values = values[np.isfinite(values)]
    return float(values.min()) - pad, float(values.max()) + pad


def _runs(xs, ys) -> list[list[tuple[float, float]]]:
    """The stretches of a curve where its values are finite (a curve cut at the diagram's edge, or not assembled)."""
    runs, run = [], []
    for x, y in zip(xs, ys):
        if math.isfinite(y):
            run.append((float(x), float(y)))
        elif run:
            runs.append(run)
            run = []
    if run:
        runs.append(run)
    return [r for r in runs if len(r) >= 2]


def _clipped(xs, ys, length: float) -> list:
    """The segments between neighbouring points (xs, ys) [mm], cut to the abscissa 0 ≤ x ≤ *length*."""
    out = []
    for k in range(len(xs) - 1):
        (xa, ya), (xb, yb) = (float(xs[k]), float(ys[k])), (float(xs[k + 1]), float(ys[k + 1]))
        if xb <= 0.0 or xa >= length:
            continue
        if xa < 0.0:
            ya, xa = ya + (yb - ya) * (0.0 - xa) / (xb - xa), 0.0
        if xb > length:
            yb, xb = ya + (yb - ya) * (length - xa) / (xb - xa), length
        out.append(((xa, ya), (xb, yb)))
    return out


def _dense(d: KinematicDiagrams, samples: int = 241) -> np.ndarray:
    return np.linspace(0.0, d.motion.duration, samples) + float(d.motion.t[0])


def block_room(text_width: float) -> float:
    """What a page *text_width* [mm] wide leaves the abscissa L and the longer pole H together [mm]
    (:func:`plans.differentiation.readable`'s *room*): the rest is the poles' label, the arrow past L, the
    ordinate's values and the drawings' margins."""
    return text_width - POLE_ROOM - 8.0 - RIGHT_ROOM - 2 * MARGIN


def page_diagrams(d: KinematicDiagrams, text_width: float) -> KinematicDiagrams:
    """The diagrams at the round scales that print them readably on a page *text_width* [mm] wide
    (:func:`plans.differentiation.readable`)."""
    return readable(d, block_room(text_width))


def _scale_words(d: KinematicDiagrams, key: str, lang: str) -> str:
    sc = d.scales
    words = diagram_words(d, lang)
    unit = words[f"{key}_unit"]
    ms, mv, ma = (f"$\\mu_{{{words[k + '_tex']}}}$" for k in KEYS)
    if key == "s":
        return f"{ms} = {_short(sc.mu_s, lang)} {unit}/mm"
    if key == "v":
        return (f"{mv} = {ms}/($\\mu_{{t}}$·$H_{{1}}$) = {_short(sc.mu_v, lang)} ({unit})/mm,  "
                f"$H_{{1}}$ = {_short(sc.pole_v, lang)} mm")
    return (f"{ma} = {mv}/($\\mu_{{t}}$·$H_{{2}}$) = {_short(sc.mu_a, lang)} ({unit})/mm,  "
            f"$H_{{2}}$ = {_short(sc.pole_a, lang)} mm")


def diagram_title(d: KinematicDiagrams, key: str, lang: str = "en") -> str:
    """The line over diagram *key* (``"s"``, ``"v"``, ``"a"``): what it shows, its unit and its scale (``$…$`` math)."""
    words = diagram_words(d, lang)
    return f"{words[key]}–t: {words[f'{key}_title']} [{words[f'{key}_unit']}];  {_scale_words(d, key, lang)}"


def flat_line(d: KinematicDiagrams, key: str, lang: str = "en") -> str | None:
    """For a rate *key* constant over the cycle (:func:`plans.differentiation.flat`), the line that says so
    instead of its diagram; None for a rate that varies (drawn)."""
    value = flat(d, key)
    if value is None:
        return None
    words = diagram_words(d, lang)
    head = f"{words[key]}–t: {words[f'{key}_title']}: "
    if value == 0.0:
        return head + term("kd_zero", lang).format(q=words[key])
    return head + term("kd_constant", lang).format(q=words[key], value=_num(value, lang), unit=words[f"{key}_unit"])


def legend_items(d: KinematicDiagrams, lang: str = "en", *, analytic: bool = True) -> list[tuple[str, float, bool, str]]:
    """The legend of the drawn lines: (colour, width [pt], dashed, words)."""
    items = [(CURVE, 1.0, False, term("chords_curve", lang)), (CHORD, 0.7, False, term("chord", lang))]
    if flat(d, "v") is None:  # a constant rate is not drawn: no rays
        items.append((RAY, 0.35, False, term("ray", lang)))
    if analytic and d.reference is not None:
        items.append((ANALYTIC, 0.6, True, term("analytic_curve", lang)))
    return items


class _Prepared:
    """The drawn ordinates [mm] of the three diagrams of *d* at its scales, and their ranges."""

    def __init__(self, d: KinematicDiagrams, analytic: bool, widen: float = REFERENCE_ROOM):
        sc = d.scales
        motion = d.motion
        self.d, self.sc = d, sc
        period = motion.period
        self.t0 = t0 = float(motion.t[0])
        self.tt = _dense(d)
        vel, acc = d.velocity, d.acceleration
        self.s_mm = motion.s / sc.mu_s
        self.te, self.se = motion.points()  # an open turn's points beyond its ends are not drawn: their chords are cut
        self.curves = {
            "s": smooth(self.te, self.se, self.tt, period=period) / sc.mu_s,
            "v": smooth(vel.middles, vel.rates, self.tt, period=period) / sc.mu_v,
            "a": smooth(acc.middles, acc.rates, self.tt, period=period) / sc.mu_a,
        }
        points = {"s": self.s_mm, "v": vel.intercepts(), "a": acc.intercepts()}
        self.ranges = {key: _range(points[key], self.curves[key]) for key in KEYS}
        self.ref = None
        self.cuts = {key: [] for key in KEYS}
        if analytic and d.reference is not None:
            rt, rs, rv, ra = d.reference
            inside = (rt >= t0 - 1e-12) & (rt <= t0 + motion.duration * (1 + 1e-9))
            ref = {"s": rs[inside] / sc.mu_s, "v": rv[inside] / sc.mu_v, "a": ra[inside] / sc.mu_a}
            # the analytic curve widens a diagram by at most REFERENCE_ROOM of its constructed range; beyond, it is cut
            for key in KEYS:
                lo, hi = self.ranges[key]
                room = widen * (hi - lo)
                r_lo, r_hi = _range(ref[key])
                self.ranges[key] = lo, hi = (max(min(lo, r_lo), lo - room), min(max(hi, r_hi), hi + room))
                outside = ~((ref[key] >= lo) & (ref[key] <= hi)) & np.isfinite(ref[key])
                # where the curve leaves the frame: a mark on its edge (the cut is seen, and said in the notes)
                xs = self.x_of(rt[inside])
                for k in np.flatnonzero(outside[1:] != outside[:-1]):
                    j = k + 1 if outside[k + 1] else k  # the point outside, at the crossing
                    self.cuts[key].append((float(xs[j]), hi if ref[key][j] > hi else lo))
                ref[key] = np.where(outside, np.nan, ref[key])
            self.ref = (self.x_of(rt[inside]), ref)
        self.length = sc.length
        self.left = max(sc.pole_v if flat(d, "v") is None else 0.0, sc.pole_a if flat(d, "a") is None else 0.0) + POLE_ROOM
        self.right = self.length + 8.0 + RIGHT_ROOM
        self.closing = [self.length] if period is not None else []
        self.numbers = list(motion.numbers) + ([motion.numbers[0]] if period is not None else [])
        self.pos_x = list(self.x_of(motion.t)) + self.closing

    def x_of(self, t):
        return (np.asarray(t, dtype=float) - self.t0) / self.sc.mu_t

    def height(self, key: str) -> float:
        lo, hi = self.ranges[key]
        return (hi - lo) + NUMBER_ROOM + 1.0 + 2 * MARGIN


def _draw(sketch: Sketch, p: _Prepared, key: str, y0: float, lang: str) -> None:
    """Diagram *key* with its origin at (0, *y0*) [mm]: the positions' lines and numbers, the axes, the ordinate's
    values on the right, the construction and the curves."""
    d, sc = p.d, p.sc
    words = diagram_words(d, lang)
    lo, hi = p.ranges[key]
    mu = {"s": sc.mu_s, "v": sc.mu_v, "a": sc.mu_a}[key]
    length = p.length

    def P(px, py):  # noqa: N802 — a point of the diagram [mm]
        return complex(px, y0 + py)

    def label(at, text, ha="left", gid=None):
        sketch.text(at, text, size=TEXT_PT, ha=ha, gid=gid, obstacle=False)

    for px in p.pos_x:
        sketch.line([P(px, lo), P(px, hi)], color=GRID, lw=0.35, gid=f"{key}-position", obstacle=False)
    sketch.arrow(P(0, 0), P(length + 5.0, 0), lw=0.6, head=2.2, gid=f"{key}-abscissa")
    sketch.arrow(P(0, lo), P(0, hi + 1.5), lw=0.6, head=2.2, gid=f"{key}-ordinate")
    label(P(length + 4.0, 2.4), "t", ha="center", gid=f"{key}-t")
    label(P(1.2, hi + 0.5), words[key], gid=f"{key}-symbol")
    right = length + 8.0
    sketch.line([P(right, lo), P(right, hi)], lw=0.4, gid=f"{key}-scale", obstacle=False)
    for value in _ticks(lo * mu, hi * mu, hi - lo):
        py = value / mu
        sketch.line([P(right, py), P(right + 1.5, py)], lw=0.4, gid=f"{key}-tick", obstacle=False)
        label(P(right + 2.3, py), _tick(float(value), lang), gid=f"{key}-value")
    for px, number in zip(p.pos_x, p.numbers):
        label(P(px, lo - 3.0), str(number), ha="center", gid=f"{key}-number")
    tx = p.x_of(p.tt)
    if p.ref is not None:
        for run in _runs(p.ref[0], p.ref[1][key]):
            sketch.line([P(a, b) for a, b in run], color=ANALYTIC, lw=0.6, dashes=(3, 2), gid=f"{key}-analytic", obstacle=False)
        for x, edge in p.cuts[key]:  # the analytic curve cut at the frame: a small wedge pointing out of it
            tip = 1.4 if edge == hi else -1.4
            sketch.polygon([P(x - 0.9, edge), P(x + 0.9, edge), P(x, edge + tip)], fc=ANALYTIC, ec=ANALYTIC, lw=0.3,
                           gid=f"{key}-analytic-cut", obstacle=False)
    period = d.motion.period
    if key == "s":
        sketch.line([P(a, b) for a, b in zip(tx, p.curves["s"])], color=CURVE, lw=1.0, gid="s-curve", obstacle=False)
        chord_x = list(p.x_of(p.te)) + p.closing
        chord_y = list(p.se / sc.mu_s) + ([p.s_mm[0]] if period is not None else [])
        for first, second in _clipped(chord_x, chord_y, length):
            sketch.line([P(*first), P(*second)], color=CHORD, lw=0.7, gid="s-chord", obstacle=False)
        for px, py in zip(p.pos_x, list(p.s_mm) + ([p.s_mm[0]] if period is not None else [])):
            sketch.circle(P(px, py), 0.6, fc=CURVE, ec=CURVE, lw=0.3, gid="s-point", obstacle=False)
        return
    diff, pole, name = (d.velocity, sc.pole_v, "1") if key == "v" else (d.acceleration, sc.pole_a, "2")
    pole_at = P(-pole, 0)
    sketch.circle(pole_at, 0.7, fc="black", ec="black", lw=0.3, gid=f"{key}-pole", obstacle=False)
    label(pole_at + complex(-1.0, 2.6), "P" + subscript(name), ha="right", gid=f"{key}-pole-label")
    # H: a dimension under the diagram, from the pole to the origin
    dim = lo - 0.6
    for end in (0.0, -pole):
        sketch.line([P(end, dim - 1.0), P(end, 0)], color=RAY, lw=0.3, dashes=(2, 1.5), gid=f"{key}-H-extension", obstacle=False)
    sketch.arrow(P(-pole / 2, dim), P(-pole, dim), lw=0.4, head=1.8, gid=f"{key}-H-dimension")
    sketch.arrow(P(-pole / 2, dim), P(0, dim), lw=0.4, head=1.8, gid=f"{key}-H-dimension")
    label(P(-pole / 2, lo - 3.0), "H" + subscript(name), ha="center", gid=f"{key}-H")
    for middle, intercept in zip(diff.middles, diff.intercepts()):
        if not -1.0 <= float(p.x_of(middle)) <= length + 1.0:  # beyond an open turn's ends: not drawn
            continue
        axis_at = P(0, intercept)
        sketch.line([pole_at, axis_at], color=RAY, lw=0.35, gid=f"{key}-ray", obstacle=False)
        sketch.line([axis_at, P(float(p.x_of(middle)), intercept)], color=RAY, lw=0.35, dashes=(1, 1.5), gid=f"{key}-carry", obstacle=False)
        sketch.circle(P(float(p.x_of(middle)), intercept), 0.6, fc=CURVE, ec=CURVE, lw=0.3, gid=f"{key}-point", obstacle=False)
    sketch.line([P(a, b) for a, b in zip(tx, p.curves[key])], color=CURVE, lw=1.0, gid=f"{key}-curve", obstacle=False)
    if key == "v":  # the chords of the v–t points, from which the a–t rays are drawn
        mx, my = p.x_of(d.velocity.middles), d.velocity.intercepts()
        if period is not None:  # the chord across the end of the cycle, drawn at both ends of the abscissa
            mx, my = np.concatenate([[mx[-1] - length], mx, [mx[0] + length]]), np.concatenate([[my[-1]], my, [my[0]]])
        for first, second in _clipped(mx, my, length):
            sketch.line([P(*first), P(*second)], color=CHORD, lw=0.7, gid="v-chord", obstacle=False)


def _fixed(sketch: Sketch, p: _Prepared, y_lo: float, y_hi: float) -> None:
    """The drawing's left and right edges fixed, whatever it draws: the three diagrams' origins one above the other."""
    sketch.bounds.add(-p.left, y_lo)
    sketch.bounds.add(p.right, y_hi)


def diagram_svgs(d: KinematicDiagrams, lang: str = "en", *, analytic: bool = True) -> dict:
    """Each drawn diagram of *d* (at its scales: see :func:`page_diagrams`) as an SVG block true to scale:
    ``{"s": SvgBlock, "v": …, "a": …}``, without a rate constant over the cycle (:func:`flat_line`).

    All three are as wide, their origins at the same distance from their left edge: placed one under another,
    their time axes line up.  *analytic*: the analytic curves, thin and dashed, beside the constructed ones.
    """
    from .svgblocks import SvgBlock

    p = _Prepared(d, analytic)
    drawn = [key for key in KEYS if key == "s" or flat(d, key) is None]
    if sum(p.height(key) for key in drawn) > PAGE_ROOM:  # the analytic curves cut at the construction's range
        p = _Prepared(d, analytic, widen=0.0)
    out = {}
    for key in KEYS:
        if key != "s" and flat(d, key) is not None:
            continue
        with drawing_rc():
            fig = new_figure()
            ax = fig.add_axes([0, 0, 1, 1])
            sketch = Sketch(ax, "kd")
            _draw(sketch, p, key, 0.0, lang)
            lo, hi = p.ranges[key]
            _fixed(sketch, p, lo - NUMBER_ROOM, hi + 1.0)
            width, height = fit_axes(ax, sketch.bounds, MARGIN)
            out[key] = SvgBlock(render_svg(fig), width, height)
    return out


def analytic_cut(d: KinematicDiagrams) -> bool:
    """Whether the analytic curves of :func:`diagram_svgs` (drawn at *d*'s scales) leave a frame somewhere (cut there,
    the cut marked with a wedge on the frame's edge)."""
    p = _Prepared(d, True)
    drawn = [key for key in KEYS if key == "s" or flat(d, key) is None]
    if sum(p.height(key) for key in drawn) > PAGE_ROOM:
        p = _Prepared(d, True, widen=0.0)
    return any(p.cuts[key] for key in drawn)


def draw_kinematic_figure(d: KinematicDiagrams, *, title: str = "", lang: str = "en", analytic: bool = True):
    """The diagrams of *d* (at its own scales) as one matplotlib figure true to scale, with a short caption
    (the title, the method, the time scale) and each diagram's line over it: a drawing file, not a page."""
    p = _Prepared(d, analytic)
    with drawing_rc():
        fig = new_figure()
        ax = fig.add_axes([0, 0, 1, 1])
        sketch = Sketch(ax, "kd")
        sc = d.scales
        caption = [title, page_heading(lang),
                   f"{diagram_words(d, lang)['output']};  T = {_short(d.motion.duration, lang)} s,  L = {_short(sc.length, lang)} mm,  "
                   f"μt = T/L = {_short(sc.mu_t, lang)} s/mm"]
        top = 0.0
        for k, line in enumerate(x for x in caption if x):
            sketch.text(complex(-p.left, top), line, size=TEXT_PT + (1.5 if k == 0 else 0.0), ha="left", va="top",
                        weight="bold" if k == 0 else "normal", gid="caption", obstacle=False)
            top -= 5.0 if k == 0 else 4.2
        top -= 2.0
        for key in KEYS:
            line = flat_line(d, key, lang) if key != "s" else None
            words = line if line is not None else diagram_title(d, key, lang)
            sketch.text(complex(-p.left, top), _plain(words), size=TEXT_PT, ha="left", va="top", gid=f"{key}-title", obstacle=False)
            top -= 4.5
            if line is not None:
                continue
            lo, hi = p.ranges[key]
            y0 = top - 2.0 - hi
            _draw(sketch, p, key, y0, lang)
            top = y0 + lo - NUMBER_ROOM - DIAGRAM_GAP
        x = -p.left
        for colour, lw, dashed, words in legend_items(d, lang, analytic=analytic):
            sketch.line([complex(x, top), complex(x + 6, top)], color=colour, lw=lw, dashes=(3, 2) if dashed else None, gid="legend-line", obstacle=False)
            sketch.text(complex(x + 7.5, top), words, size=TEXT_PT, ha="left", gid="legend", obstacle=False)
            x += 7.5 + text_size(words, TEXT_PT)[0] + 5.0
        _fixed(sketch, p, top - 2.0, 0.0)
        fit_axes(ax, sketch.bounds, 3.0)
    return fig


def _plain(line: str) -> str:
    """A line's ``$…$`` parts as plain Unicode (μ_s → μs, H_{1} → H₁) for a figure's caption."""
    import re

    greek = {"\\psi": "ψ", "\\omega": "ω", "\\varepsilon": "ε", "\\mu": "μ", "\\mathrm": ""}

    def part(m):
        body = m.group(1)
        for k, v in greek.items():
            body = body.replace(k, v)
        body = re.sub(r"_\{([^{}]*)\}", lambda s: s.group(1) if not s.group(1).isdigit() else subscript(s.group(1)), body)
        return body.replace("{", "").replace("}", "")

    return re.sub(r"\$([^$]*)\$", part, line)


def diagrams_table(d: KinematicDiagrams, lang: str = "en") -> list[list[str]]:
    """The comparison at every position, as rows of text (the first the header).

    Columns: position, t [s], s, then v and a each from the diagrams, the
    plans and analytic, and the errors δ [%] of the diagrams and the plans
    (see :meth:`KinematicDiagrams.errors`).
    """
    words = diagram_words(d, lang)
    e = d.errors()
    diagram, plans, analytic = term("from_diagram", lang), term("from_plans", lang), term("from_analytic", lang)
    head = [term("position_no", lang), "t [s]", f"{words['s']} [{words['s_unit']}]"]
    for key in ("v", "a"):
        symbol = words[key]
        head += [f"{symbol} {diagram}", f"{symbol} {plans}", f"{symbol} {analytic}", f"δ {diagram}", f"δ {plans}"]
    rows = [head]

    # round-off of a zero (6·10⁻¹⁶ where v passes through 0 at an extreme, 4·10⁻¹⁴ for the a of a uniform motion)
    # printed as 0: below 10⁻⁹ of the output's natural scale, its span over the cycle time (squared)
    duration = d.motion.duration or 1.0
    span = float(np.ptp(d.motion.s)) if len(d.motion.s) else 0.0

    def clean(values, floor):
        values = np.array(values, dtype=float)
        finite = values[np.isfinite(values)]
        largest = float(np.max(np.abs(finite))) if len(finite) else 0.0
        values[np.abs(values) < max(1e-9 * largest, floor)] = 0.0
        return values

    floors = {"v": 1e-9 * span / duration, "a": 1e-9 * span / duration**2}
    d = type(d)(**{**d.__dict__, **{k: clean(getattr(d, k), floors[k[0]]) for k in ("v", "a", "v_plans", "a_plans", "v_analytic", "a_analytic")}})
    steps = {"v": d.v_plans_step, "a": d.a_plans_step}
    for k, number in enumerate(d.motion.numbers):
        row = [str(number), _num(float(d.motion.t[k]), lang, 3), _num(float(d.motion.s[k]), lang, 4)]
        for key, ours, theirs, exact in (("v", d.v, d.v_plans, d.v_analytic), ("a", d.a, d.a_plans, d.a_analytic)):
            step = float(steps[key][k]) if steps[key] is not None else math.nan
            row += [_num(float(ours[k]), lang), _plan_number(float(theirs[k]), step, lang), _num(float(exact[k]), lang),
                    _percent(e[f"{key}_diagram"][k], lang), _percent(e[f"{key}_plans"][k], lang)]
        rows.append(row)
    return rows


def _plan_number(value: float, step: float, lang: str) -> str:
    """A value read off a plan: to the digits its resolution *step* gives (as the plan's readings print it,
    :func:`plans.report.reading_number`), else four significant digits; "—" where there is no plan."""
    from ..report import reading_number

    if not math.isfinite(value):
        return "—"
    if value == 0 or not math.isfinite(step):
        return _num(value, lang)
    return localised(reading_number(value, step), lang)


def table_header(d: KinematicDiagrams, lang: str = "en") -> tuple[list[str], list[tuple[int, str]], list[str]]:
    """The comparison table's two header rows (so that it fits an A4 page's width in every language): the first
    (position, t, s, then a cell per group), the groups (first column, ``v [m/s]`` over its five columns) and the
    second row (units of the first three, the methods under each group)."""
    words = diagram_words(d, lang)
    diagram, plans, analytic = term("from_diagram", lang), term("from_plans", lang), term("from_analytic", lang)
    methods = [diagram, plans, analytic, f"δ {diagram}", f"δ {plans}"]
    second = ["", "[s]", f"[{words['s_unit']}]"] + methods + methods
    first = [term("position_no", lang), "t", words["s"]]
    groups = [(3, f"{words['v']} [{words['v_unit']}]"), (8, f"{words['a']} [{words['a_unit']}]")]
    return first, groups, second


def table_heading(lang: str = "en") -> str:
    """The comparison table's heading: what it compares, and that δ is in per cent."""
    return f"{term('diagrams_table', lang)} (δ [%])"


def _percent(value: float, lang: str) -> str:
    if not math.isfinite(value):
        return "—"
    if abs(value) < 0.005:
        return "0,00" if lang != "en" else "0.00"
    return localised(f"{value:+.2f}", lang)


def _tick(value: float, lang: str) -> str:
    """A round value of an ordinate, as short as it is: ``0.05``, ``−2500``."""
    return localised(f"{value:.6g}" if abs(value) >= 1e-12 else "0", lang)


#: Above this largest |δ| [%] of the diagrams, the notes say where the chords flatten a peak and ask for more positions.
PEAK_NOTE = 5.0


def notes(d: KinematicDiagrams, lang: str = "en") -> list[str]:
    """The lines under the table: what δ is, the largest errors, where the "plans" values come from and their sign
    rule, why a "—", the order of the chords (and, where the diagrams' error exceeds :data:`PEAK_NOTE` %, which
    peak they flatten), the reading at an extreme position."""
    e = d.errors()
    words = diagram_words(d, lang)
    largest = lambda x: float(np.nanmax(np.abs(x))) if np.any(np.isfinite(x)) else math.nan  # noqa: E731
    pct = lambda x: localised(f"{x:.2f}", lang) + " %" if math.isfinite(x) else "—"  # noqa: E731
    v, a = words["v"], words["a"]
    out = [
        term("diagram_error_note", lang) + ".",
        f"max |δ|:  {v} {term('from_diagram', lang)} {pct(largest(e['v_diagram']))},  {a} {term('from_diagram', lang)} {pct(largest(e['a_diagram']))};  "
        f"{v} {term('from_plans', lang)} {pct(largest(e['v_plans']))},  {a} {term('from_plans', lang)} {pct(largest(e['a_plans']))}.",
    ]
    sense = term("positive_along_guide" if d.motion.kind == "slider" else "positive_ccw", lang)
    out.append(term("kd_plans_signs", lang).format(v=v, a=a, plan=term("from_plans", lang), sense=sense) + ".")
    numbers = list(d.motion.numbers)
    v_plans, a_plans = np.asarray(d.v_plans, dtype=float), np.asarray(d.a_plans, dtype=float)
    if np.any(~np.isfinite(v_plans)) and np.any(np.isfinite(v_plans)):
        out.append(term("kd_no_plan", lang) + ".")
    drawn = [numbers[k] for k in range(len(numbers)) if math.isfinite(a_plans[k])]
    if np.any(np.isfinite(v_plans) & ~np.isfinite(a_plans)):
        out.append(term("kd_no_acceleration_plan", lang).format(a=a, positions=", ".join(dict.fromkeys(drawn)) or "—") + ".")
    out.append(term("chords_order", lang) + ".")
    worst = None
    for key in ("v", "a"):
        errors = np.asarray(e[f"{key}_diagram"], dtype=float)
        if np.any(np.isfinite(errors)):
            k = int(np.nanargmax(np.abs(errors)))
            if abs(errors[k]) > PEAK_NOTE and (worst is None or abs(errors[k]) > abs(worst[2])):
                worst = (key, k, float(errors[k]))
    if worst is not None:
        key, k, error = worst
        ours, exact = (d.v, d.v_analytic) if key == "v" else (d.a, d.a_analytic)
        count = len(set(numbers))
        out.append(term("kd_peak_note", lang).format(
            q=words[key], n=count, position=numbers[k], diagram=_num(float(ours[k]), lang), analytic=_num(float(exact[k]), lang),
            unit=words[f"{key}_unit"], error=localised(f"{error:+.1f}", lang), more=2 * count) + ".")
    if d.reference is not None and analytic_cut(d):
        out.append(term("kd_analytic_cut", lang) + ".")
    if d.start == "output":
        out.append(term("kd_extreme_reading", lang).format(v=v) + ".")
    return out


def page_heading(lang: str = "en") -> str:
    """The heading of the page: what it shows, by which method."""
    return f"{term('kinematic_diagrams', lang)}: {term('graphical_differentiation', lang)}"


def header_lines(d: KinematicDiagrams, lang: str = "en") -> list[str]:
    """The page's data lines (``$…$`` math): the output link, positions and law; the time scale; what s is."""
    sc = d.scales
    words = diagram_words(d, lang)
    count = len(set(d.motion.numbers))  # an open turn ends at position 0 again
    duration = d.motion.duration
    law = ""
    if d.law is not None:
        law = f";  {d.law.describe(lang, d.driver, **({'phase': d.start_phase} if d.start_phase is not None else {}))}"
    steps = even = ""
    if d.law is not None and d.law.kind in ("constant", "harmonic") and d.motion.period is not None:
        steps = f",  Δt = T/{d.motion.intervals} = {_short(duration / d.motion.intervals, lang)} s"
        even = f" ({term('equal_time_steps', lang)} Δt)"
    return [
        f"{words['output']};  {term('positions', lang)}: {count}{even}" + law,
        f"T = {_short(duration, lang)} s ({term('cycle_time' if d.law is None or d.law.crank else 'stroke_time', lang)}){steps},  L = {_short(sc.length, lang)} mm ({term('abscissa_length', lang)}),  "
        f"$\\mu_{{t}}$ = T/L = {_short(sc.mu_t, lang)} s/mm",
        scales_line(d, lang),
        origin_line(d, lang),
    ]


def scales_line(d: KinematicDiagrams, lang: str = "en") -> str:
    """That the diagrams' μ are theirs, not the plans' k (one plate holds both: the v–t diagram's μ_v is not the
    velocity plans' k_v), in the reader's language."""
    words = diagram_words(d, lang)
    mu = ", ".join(["$\\mu_{t}$"] + [f"$\\mu_{{{words[k + '_tex']}}}$" for k in KEYS])
    return term("kd_mu_not_k", lang).format(mu=mu, k="$k_{l}$, $k_{v}$, $k_{a}$")


def origin_line(d: KinematicDiagrams, lang: str = "en") -> str:
    """What s (or ψ) is: its origin, position 0 (which one), and its positive sense."""
    words = diagram_words(d, lang)
    name = d.motion.name
    if d.motion.kind == "slider":
        definition = f"s = $s_{{\\mathrm{{{name}}}}}$ − $s_{{\\mathrm{{{name}}}}}$(0)"
        sense = term("positive_along_guide", lang)
    else:
        sub = subscript(name)
        definition = f"{words['s']} = φ{sub} − φ{sub}(0)"
        sense = term("positive_ccw", lang)
    origin = term("from_position_0_extreme" if d.start == "output" else "from_position_0", lang)
    return f"{definition}: {origin}, {sense}"


def unavailable_reason(error, lang: str = "en") -> str:
    """Why the kinematic diagrams are not drawn (*error* a :class:`plans.differentiation.DiagramsError`), in *lang*."""
    if error.cause == "unsolved":
        return term("kd_unsolved", lang).format(positions=", ".join(map(str, error.positions)))
    if error.cause == "no_output":
        return term("kd_no_output", lang)
    return str(error)
