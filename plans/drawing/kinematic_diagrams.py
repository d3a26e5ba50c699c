"""The output link's kinematic diagrams by graphical differentiation, drawn as a plate shows them.

One block (:func:`diagrams_block`), true to scale (one data unit one millimetre
of paper), of three diagrams stacked over one time axis:

* **s–t** (a rocker: ψ–t): the points of the positions, the smooth curve
  through them, and the chords between neighbouring points;
* **v–t** (ω–t): the pole P₁ at H₁ [mm] to the left of the origin, the rays
  from it parallel to the chords, each ray's intercept on the ordinate carried
  across to the middle of its interval (a point of the v–t curve), and the
  smooth curve through those points; the chords between them, for the next;
* **a–t** (ε–t): the same from the v–t curve, pole P₂ at H₂.

The analytic curves are drawn thin and dashed beside the constructed ones, for
comparison.  The ordinates' values are written on the right of each diagram
(the rays of the pole fill the left), the positions' numbers under it; every
scale is stated above its diagram, μ_v = μ_s/(μ_t·H₁) and μ_a = μ_v/(μ_t·H₂)
with their numbers.  Every text is at least 8 pt.

:func:`diagrams_table` is the comparison at every position (diagrams, plans,
analytic, errors), :func:`draw_kinematic_pages` the handout's page (or two,
when the table does not fit under the diagrams).

Only the drawing happens here: every number comes from a
:class:`plans.differentiation.KinematicDiagrams`.
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.ticker import MaxNLocator

from .._text import subscript
from ..differentiation import ORDINATE_MAX, KinematicDiagrams, rescaled, smooth
from ..i18n import term
from .blocks import Block, text_rows
from .layout import A4, GAP, PAGE_MARGIN, footer, header, header_height, new_page
from .numerals import localised
from .typeset import draw_text, measure

__all__ = ["draw_unavailable_page", "diagrams_block", "diagrams_table", "comparison_block", "header_lines", "diagram_words", "draw_kinematic_pages", "TEXT_PT", "DIAGRAM_GAP"]

#: Size [pt] of every text in the diagrams and their table.
TEXT_PT = 8.0
#: Room [mm] above a diagram for its title line, and between diagrams.
TITLE_ROOM = 7.0
DIAGRAM_GAP = 4.5
#: Room [mm] under a diagram for the positions' numbers, and under the block for its legend.
NUMBER_ROOM = 5.0
LEGEND_ROOM = 6.0
#: Room [mm] on the right of a diagram for its ordinate's values.
RIGHT_ROOM = 18.0
CURVE = "#0072B2"
CHORD = "#D55E00"
RAY = "#404040"
ANALYTIC = "#808080"
GRID = "#b0b0b0"
#: How far [share of its constructed range] the analytic curve may widen a diagram; beyond, it is cut off.
REFERENCE_ROOM = 0.25
#: The shortest [mm] the diagrams are drawn to leave the table room under them on the same page.
SHORTEST = 24.0


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


def diagrams_block(d: KinematicDiagrams, lang: str = "en", *, analytic: bool = True) -> Block:
    """The three diagrams with the chord construction, true to scale, as a :class:`Block` [mm].

    *analytic*: draw the analytic curves (thin, dashed) beside the constructed ones.
    """
    sc = d.scales
    words = diagram_words(d, lang)
    motion = d.motion
    period = motion.period
    t0 = float(motion.t[0])
    x_of = lambda t: (np.asarray(t, dtype=float) - t0) / sc.mu_t  # noqa: E731
    tt = _dense(d)
    vel, acc = d.velocity, d.acceleration
    # drawn ordinates [mm]
    s_mm = motion.s / sc.mu_s
    te, se = motion.points()  # with an open turn's points beyond its ends (not drawn: the chords to them are cut at the ends)
    s_curve = smooth(te, se, tt, period=period) / sc.mu_s
    v_mm = vel.intercepts()
    v_curve = smooth(vel.middles, vel.rates, tt, period=period) / sc.mu_v
    a_mm = acc.intercepts()
    a_curve = smooth(acc.middles, acc.rates, tt, period=period) / sc.mu_a
    ref = d.reference if analytic else None
    ref_mm = None
    if ref is not None:
        rt, rs, rv, ra = ref
        inside = (rt >= t0 - 1e-12) & (rt <= t0 + motion.duration * (1 + 1e-9))
        ref_mm = (x_of(rt[inside]), rs[inside] / sc.mu_s, rv[inside] / sc.mu_v, ra[inside] / sc.mu_a)
    panels = [
        ("s", _range(s_mm, s_curve)),
        ("v", _range(v_mm, v_curve)),
        ("a", _range(a_mm, a_curve)),
    ]
    if ref_mm is not None:
        # the analytic curve widens a diagram by at most REFERENCE_ROOM of its constructed range; beyond, it is cut
        widened = []
        for (key, (lo, hi)), ref in zip(panels, ref_mm[1:]):
            room = REFERENCE_ROOM * (hi - lo)
            r_lo, r_hi = _range(ref)
            widened.append((key, (max(min(lo, r_lo), lo - room), min(max(hi, r_hi), hi + room))))
        panels = widened
        ref_mm = (ref_mm[0],) + tuple(np.where((ref >= lo) & (ref <= hi), ref, np.nan) for ref, (_, (lo, hi)) in zip(ref_mm[1:], panels))
    length = sc.length
    left = max(sc.pole_v, sc.pole_a) + 6.0  # the poles and their labels
    width = left + length + 8.0 + RIGHT_ROOM
    heights = [TITLE_ROOM + (hi - lo) + NUMBER_ROOM for _, (lo, hi) in panels]
    items = [(CURVE, 1.0, None, term("chords_curve", lang)), (CHORD, 0.7, None, term("chord", lang)),
             (RAY, 0.35, None, term("ray", lang))]
    if ref_mm is not None:
        items.append((ANALYTIC, 0.6, (3, 2), term("analytic_curve", lang)))
    legend_places, lx, row = [], left, 0
    for *_, label in items:
        need = 7.5 + measure(label, TEXT_PT)[0]
        if lx > left and lx + need > width:
            lx, row = left, row + 1
        legend_places.append(complex(lx, LEGEND_ROOM / 2 + 1.0 + row * 4.5))
        lx += need + 5.0
    legend_h = LEGEND_ROOM + row * 4.5
    height = sum(heights) + DIAGRAM_GAP * (len(panels) - 1) + legend_h
    pos_x = x_of(motion.t)
    closing = [length] if period is not None else []
    numbers = list(motion.numbers) + ([motion.numbers[0]] if period is not None else [])

    def place(sketch, x, y, page) -> None:
        top = y + height
        origins = []
        for (key, (lo, hi)), h in zip(panels, heights):
            y0 = top - TITLE_ROOM - hi  # the abscissa (zero) of this diagram
            origins.append(y0)
            top -= h + DIAGRAM_GAP
        ox = x + left

        def P(px, py, y0):  # noqa: N802 — a point of a diagram [mm]
            return complex(ox + px, y0 + py)

        mu = {"s": sc.mu_s, "v": sc.mu_v, "a": sc.mu_a}
        for (key, (lo, hi)), y0 in zip(panels, origins):
            symbol, unit = words[key], words[f"{key}_unit"]
            # title line: what, the scale
            ms, mv, ma = (f"$\\mu_{{{words[k + '_tex']}}}$" for k in ("s", "v", "a"))
            if key == "s":
                scale = f"{ms} = {_short(sc.mu_s, lang)} {unit}/mm"
            elif key == "v":
                scale = (f"{mv} = {ms}/($\\mu_{{t}}$·$H_{{1}}$) = {_short(sc.mu_v, lang)} ({unit})/mm,  "
                         f"$H_{{1}}$ = {_short(sc.pole_v, lang)} mm")
            else:
                scale = (f"{ma} = {mv}/($\\mu_{{t}}$·$H_{{2}}$) = {_short(sc.mu_a, lang)} ({unit})/mm,  "
                         f"$H_{{2}}$ = {_short(sc.pole_a, lang)} mm")
            title = f"{symbol}–t: {words[f'{key}_title']} [{unit}];  {scale}"
            draw_text(sketch, complex(x, y0 + hi + TITLE_ROOM - 2.2), title, size=TEXT_PT, gid=f"kd-{key}-title")
            # position lines, axes, the ordinate's values on the right
            for px in list(pos_x) + closing:
                sketch.line([P(px, lo, y0), P(px, hi, y0)], color=GRID, lw=0.35, gid=f"kd-{key}-position", obstacle=False)
            sketch.arrow(P(0, 0, y0), P(length + 5.0, 0, y0), lw=0.6, head=2.2, gid=f"kd-{key}-abscissa")
            sketch.arrow(P(0, lo, y0), P(0, hi + 1.5, y0), lw=0.6, head=2.2, gid=f"kd-{key}-ordinate")
            draw_text(sketch, P(length + 4.0, 2.4, y0), "t", size=TEXT_PT, ha="center", gid=f"kd-{key}-t")
            draw_text(sketch, P(1.2, hi + 0.5, y0), symbol, size=TEXT_PT, gid=f"kd-{key}-symbol")
            right = length + 8.0
            sketch.line([P(right, lo, y0), P(right, hi, y0)], lw=0.4, gid=f"kd-{key}-scale", obstacle=False)
            for value in _ticks(lo * mu[key], hi * mu[key], hi - lo):
                py = value / mu[key]
                sketch.line([P(right, py, y0), P(right + 1.5, py, y0)], lw=0.4, gid=f"kd-{key}-tick", obstacle=False)
                draw_text(sketch, P(right + 2.3, py, y0), _tick(float(value), lang), size=TEXT_PT, gid=f"kd-{key}-value")
            for px, number in zip(list(pos_x) + closing, numbers):
                draw_text(sketch, P(px, lo - 3.0, y0), str(number), size=TEXT_PT, ha="center", gid=f"kd-{key}-number")

        ys, yv, ya = origins
        tx = x_of(tt)
        # s–t: curve, points, chords
        if ref_mm is not None:
            for run in _runs(ref_mm[0], ref_mm[1]):
                sketch.line([P(a, b, ys) for a, b in run], color=ANALYTIC, lw=0.6, dashes=(3, 2), gid="kd-s-analytic", obstacle=False)
        sketch.line([P(a, b, ys) for a, b in zip(tx, s_curve)], color=CURVE, lw=1.0, gid="kd-s-curve", obstacle=False)
        chord_x = list(x_of(te)) + closing
        chord_y = list(se / sc.mu_s) + ([s_mm[0]] if period is not None else [])
        for first, second in _clipped(chord_x, chord_y, length):
            sketch.line([P(*first, ys), P(*second, ys)], color=CHORD, lw=0.7, gid="kd-s-chord", obstacle=False)
        for px, py in zip(list(pos_x) + closing, list(s_mm) + ([s_mm[0]] if period is not None else [])):
            sketch.circle(P(px, py, ys), 0.6, fc=CURVE, ec=CURVE, lw=0.3, gid="kd-s-point", obstacle=False)
        # v–t and a–t: pole, rays, intercepts carried to the middles, points, curve
        for key, diff, y0, pole, curve, name in (("v", vel, yv, sc.pole_v, v_curve, "1"), ("a", acc, ya, sc.pole_a, a_curve, "2")):
            pole_at = P(-pole, 0, y0)
            sketch.circle(pole_at, 0.7, fc="black", ec="black", lw=0.3, gid=f"kd-{key}-pole", obstacle=False)
            draw_text(sketch, pole_at + complex(-1.0, 2.6), f"$P_{{{name}}}$", size=TEXT_PT, ha="right", gid=f"kd-{key}-pole-label")
            # H: a dimension under the diagram, from the pole to the origin
            lo = panels[1 if key == "v" else 2][1][0]
            dim = lo - 0.6
            for end in (0.0, -pole):
                sketch.line([P(end, dim - 1.0, y0), P(end, 0, y0)], color=RAY, lw=0.3, dashes=(2, 1.5), gid=f"kd-{key}-H-extension", obstacle=False)
            sketch.arrow(P(-pole / 2, dim, y0), P(-pole, dim, y0), lw=0.4, head=1.8, gid=f"kd-{key}-H-dimension")
            sketch.arrow(P(-pole / 2, dim, y0), P(0, dim, y0), lw=0.4, head=1.8, gid=f"kd-{key}-H-dimension")
            draw_text(sketch, P(-pole / 2, lo - 3.0, y0), f"$H_{{{name}}}$", size=TEXT_PT, ha="center", gid=f"kd-{key}-H")
            for middle, intercept in zip(diff.middles, diff.intercepts()):
                if not -1.0 <= float(x_of(middle)) <= length + 1.0:  # beyond an open turn's ends: not drawn
                    continue
                axis_at = P(0, intercept, y0)
                sketch.line([pole_at, axis_at], color=RAY, lw=0.35, gid=f"kd-{key}-ray", obstacle=False)
                sketch.line([axis_at, P(float(x_of(middle)), intercept, y0)], color=RAY, lw=0.35, dashes=(1, 1.5), gid=f"kd-{key}-carry", obstacle=False)
                sketch.circle(P(float(x_of(middle)), intercept, y0), 0.6, fc=CURVE, ec=CURVE, lw=0.3, gid=f"kd-{key}-point", obstacle=False)
            if ref_mm is not None:
                ry = ref_mm[2] if key == "v" else ref_mm[3]
                for run in _runs(ref_mm[0], ry):
                    sketch.line([P(a, b, y0) for a, b in run], color=ANALYTIC, lw=0.6, dashes=(3, 2), gid=f"kd-{key}-analytic", obstacle=False)
            sketch.line([P(a, b, y0) for a, b in zip(tx, curve)], color=CURVE, lw=1.0, gid=f"kd-{key}-curve", obstacle=False)
        # the chords of the v–t points, from which the a–t rays are drawn
        mx = x_of(vel.middles)
        my = vel.intercepts()
        if period is not None:  # the chord across the end of the cycle, drawn at both ends of the abscissa
            mx, my = np.concatenate([[mx[-1] - length], mx, [mx[0] + length]]), np.concatenate([[my[-1]], my, [my[0]]])
        for first, second in _clipped(mx, my, length):
            sketch.line([P(*first, yv), P(*second, yv)], color=CHORD, lw=0.7, gid="kd-v-chord", obstacle=False)
        # the legend, in rows as wide as the block
        legend_at = [(x + at.real, y + legend_h - at.imag) for at in legend_places]
        for colour, lw, dashes, label, (lx, ly) in zip(*zip(*items), legend_at):
            sketch.line([complex(lx, ly), complex(lx + 6, ly)], color=colour, lw=lw, dashes=dashes, gid="kd-legend-line", obstacle=False)
            draw_text(sketch, complex(lx + 7.5, ly), label, size=TEXT_PT, gid="kd-legend")

    return Block(width, height, place, kind="diagrams")


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
    for k, number in enumerate(d.motion.numbers):
        row = [str(number), _num(float(d.motion.t[k]), lang, 3), _num(float(d.motion.s[k]), lang, 4)]
        for key, ours, theirs, exact in (("v", d.v, d.v_plans, d.v_analytic), ("a", d.a, d.a_plans, d.a_analytic)):
            row += [_num(float(ours[k]), lang), _num(float(theirs[k]), lang), _num(float(exact[k]), lang),
                    _percent(e[f"{key}_diagram"][k], lang), _percent(e[f"{key}_plans"][k], lang)]
        rows.append(row)
    return rows


def comparison_block(d: KinematicDiagrams, lang: str = "en", *, size: float = TEXT_PT, pad: float = 1.2) -> Block:
    """The comparison table (:func:`diagrams_table`) with a two-line header: the quantity over its five columns
    (``v [m/s]``), the method under it, so that it fits an A4 page's width in every language."""
    flat = diagrams_table(d, lang)
    words = diagram_words(d, lang)
    body = flat[1:]
    columns = len(flat[0])
    diagram, plans, analytic = term("from_diagram", lang), term("from_plans", lang), term("from_analytic", lang)
    methods = [diagram, plans, analytic, f"δ {diagram}", f"δ {plans}"]
    second = ["", "[s]", f"[{words['s_unit']}]"] + methods + methods
    first = [term("position_no", lang), "t", words["s"]]
    groups = [(3, f"{words['v']} [{words['v_unit']}]"), (8, f"{words['a']} [{words['a_unit']}]")]
    widths = [max([measure(r[c], size)[0] for r in body] + [measure(second[c], size, "bold")[0]] +
                  ([measure(first[c], size, "bold")[0]] if c < 3 else [])) + 2 * pad for c in range(columns)]
    row_h = measure("lp", size)[1] * 1.1 + 0.6
    heading = f"{term('diagrams_table', lang)} (δ [%])"
    heading_h = measure(heading, size + 1, "bold")[1] + 1.2
    width = max(sum(widths), measure(heading, size + 1, "bold")[0])
    height = heading_h + row_h * (len(body) + 2) + 1.0
    right = set(range(1, columns))

    def place(sketch, x, y, page) -> None:
        top = y + height
        draw_text(sketch, complex(x, top - heading_h / 2), heading, size=size + 1, weight="bold", gid="kd-table-heading")
        top -= heading_h
        sketch.line([complex(x, top), complex(x + sum(widths), top)], lw=0.9, gid="kd-table-rule", obstacle=False)
        edges = np.concatenate([[0.0], np.cumsum(widths)]) + x
        yc = top - row_h / 2
        for c in range(3):
            draw_text(sketch, complex(edges[c + 1] - pad, yc) if c in right else complex(edges[c] + pad, yc), first[c], size=size, weight="bold",
                      ha="right" if c in right else "left", gid="kd-table-cell")
        for start, text in groups:
            draw_text(sketch, complex((edges[start] + edges[start + 5]) / 2, yc), text, size=size, weight="bold", ha="center", gid="kd-table-cell")
            sketch.line([complex(edges[start] + pad, top - row_h), complex(edges[start + 5] - pad, top - row_h)], lw=0.4, gid="kd-table-rule", obstacle=False)
        rows = [second] + body
        for i, row in enumerate(rows):
            yc = top - row_h * (i + 1.5)
            for c, cell in enumerate(row):
                at = complex(edges[c + 1] - pad, yc) if c in right else complex(edges[c] + pad, yc)
                draw_text(sketch, at, cell, size=size, ha="right" if c in right else "left", weight="bold" if i == 0 else "normal", gid="kd-table-cell")
            if i == 0:
                sketch.line([complex(x, top - row_h * 2), complex(edges[-1], top - row_h * 2)], lw=0.5, gid="kd-table-rule", obstacle=False)
        bottom = top - row_h * (len(rows) + 1)
        sketch.line([complex(x, bottom), complex(edges[-1], bottom)], lw=0.9, gid="kd-table-rule", obstacle=False)

    return Block(width, height, place, kind="table")


def _percent(value: float, lang: str) -> str:
    if not math.isfinite(value):
        return "—"
    if abs(value) < 0.005:
        return "0,00" if lang != "en" else "0.00"
    return localised(f"{value:+.2f}", lang)


def _tick(value: float, lang: str) -> str:
    """A round value of an ordinate, as short as it is: ``0.05``, ``−2500``."""
    return localised(f"{value:.6g}" if abs(value) >= 1e-12 else "0", lang)


def _notes(d: KinematicDiagrams, lang: str) -> list[str]:
    """The lines under the table: what δ is, the largest errors, the method of tangents, the order of the chords."""
    e = d.errors()
    words = diagram_words(d, lang)
    largest = lambda x: float(np.nanmax(np.abs(x))) if np.any(np.isfinite(x)) else math.nan  # noqa: E731
    pct = lambda x: localised(f"{x:.2f}", lang) + " %" if math.isfinite(x) else "—"  # noqa: E731
    v, a = words["v"], words["a"]
    return [
        term("diagram_error_note", lang) + ".",
        f"max |δ|:  {v} {term('from_diagram', lang)} {pct(largest(e['v_diagram']))},  {a} {term('from_diagram', lang)} {pct(largest(e['a_diagram']))};  "
        f"{v} {term('from_plans', lang)} {pct(largest(e['v_plans']))},  {a} {term('from_plans', lang)} {pct(largest(e['a_plans']))}.",
        f"{term('method_of_tangents', lang)}:  max |δ| {v} {pct(largest(e['v_tangents']))},  {a} {pct(largest(e['a_tangents']))}.",
        term("chords_order", lang) + ".",
    ] + ([term("kd_extreme_reading", lang).format(v=v) + "."] if d.start == "output" else [])


def header_lines(d: KinematicDiagrams, lang: str = "en") -> list[str]:
    """The page's data lines: the output link and method, the time scale."""
    sc = d.scales
    words = diagram_words(d, lang)
    count = len(set(d.motion.numbers))  # an open turn ends at position 0 again
    duration = d.motion.duration
    width = A4[0] - 2 * PAGE_MARGIN
    law = ""
    if d.law is not None:
        law = f";  {d.law.describe(lang, d.driver, **({'phase': d.start_phase} if d.start_phase is not None else {}))}"
    steps = even = ""
    if d.law is not None and d.law.kind in ("constant", "harmonic") and d.motion.period is not None:
        steps = f",  Δt = T/{d.motion.intervals} = {_num(duration / d.motion.intervals, lang, 4)} s"
        even = f" ({term('equal_time_steps', lang)} Δt)"
    return [
        "§" + f"{term('kinematic_diagrams', lang)}: {term('graphical_differentiation', lang)}",
        *_wrap(f"{words['output']};  {term('positions', lang)}: {count}{even}" + law, width),
        *_wrap(f"T = {_num(duration, lang, 4)} s ({term('cycle_time', lang)}){steps},  L = {_short(sc.length, lang)} mm ({term('abscissa_length', lang)}),  "
               f"$\\mu_{{t}}$ = T/L = {_short(sc.mu_t, lang)} s/mm", width),
        *_wrap(origin_line(d, lang), width),
    ]


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


def _wrap(text: str, width: float, size: float = 8.0) -> list[str]:
    """*text* broken at spaces into lines at most *width* [mm] wide at *size* pt (a word longer than that alone)."""
    lines, line = [], ""
    for word in text.split(" "):
        trial = f"{line} {word}" if line else word
        if line and measure(trial, size)[0] > width:
            lines.append(line.rstrip())
            line = "   " + word
        else:
            line = trial
    return lines + ([line] if line else [])


def draw_kinematic_pages(d: KinematicDiagrams, *, title: str, lang: str = "en", footer_text: str = "", extra_lines=()) -> list:
    """The handout's page of the kinematic diagrams (A4 portrait): the construction, then the table.

    Returns one figure, or two when the table does not fit under the
    diagrams (the table then has a page of its own, its rows continued).
    """
    lines = list(extra_lines) + header_lines(d, lang)
    table = comparison_block(d, lang)
    width, height = A4
    notes = [(text, size) for text, size, _ in text_rows("", _notes(d, lang), width - 2 * PAGE_MARGIN, TEXT_PT)[1:]]
    notes_h = sum(measure(t, s)[1] + 1.2 for t, s in notes) + 2.0
    room = height - header_height(lines) - PAGE_MARGIN - 8.0
    # the diagrams as tall as their scales allow, down to SHORTEST mm, so that the table fits under them
    together = False
    for tallest in (ORDINATE_MAX, 36.0, 34.0, 32.0, 30.0, 28.0, 26.0, SHORTEST):
        block = diagrams_block(rescaled(d, tallest), lang)
        if block.height + GAP + table.height + notes_h <= room:
            together = True
            break
    if not together:
        block = diagrams_block(d, lang)
    pages = []
    fig, sketch = new_page(A4)
    top = header(sketch, A4, title, lines)
    block.place(sketch, PAGE_MARGIN, top - block.height, A4)
    top -= block.height + GAP
    if footer_text:
        footer(sketch, footer_text)
    pages.append(fig)
    if not together:
        fig, sketch = new_page(A4)
        top = header(sketch, A4, title, lines[:1] + [term("continued", lang)])
        if footer_text:
            footer(sketch, footer_text)
        pages.append(fig)
    table.place(sketch, PAGE_MARGIN, top - table.height, A4)
    top -= table.height + 2.0
    for text, size in notes:
        h = measure(text, size)[1]
        draw_text(sketch, complex(PAGE_MARGIN, top - h / 2), text, size=size, gid="kd-note")
        top -= h + 1.2
    return pages


def draw_unavailable_page(error, *, title: str, lang: str = "en", footer_text: str = ""):
    """The page that says, in the reader's language, why the kinematic diagrams are not drawn
    (*error* a :class:`plans.differentiation.DiagramsError`)."""
    if error.cause == "unsolved":
        reason = term("kd_unsolved", lang).format(positions=", ".join(map(str, error.positions)))
    elif error.cause == "no_output":
        reason = term("kd_no_output", lang)
    else:
        reason = str(error)
    fig, sketch = new_page(A4)
    top = header(sketch, A4, title, ["§" + f"{term('kinematic_diagrams', lang)}: {term('graphical_differentiation', lang)}"])
    lines = [term("kd_not_drawn", lang) + ":"] + _wrap(reason, A4[0] - 2 * PAGE_MARGIN, 10.0)
    for k, line in enumerate(lines):
        h = measure(line, 10.0, "bold" if k == 0 else "normal")[1]
        draw_text(sketch, complex(PAGE_MARGIN, top - h / 2), line, size=10.0, weight="bold" if k == 0 else "normal", gid="kd-unavailable")
        top -= h + 1.5
    if footer_text:
        footer(sketch, footer_text)
    return fig
