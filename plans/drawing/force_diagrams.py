"""The driving moment M_b(φ) and the polar diagram of the crank bearing's reaction, over one cycle.

One A4 page (:func:`draw_force_diagrams`), from a :class:`plans.forces.cycle.CycleForces`
(nothing is solved here):

* above, M_b over the crank angle turned from position 0 in the sense of ω
  (signed, counter-clockwise on the crank positive), at round scales
  μ_φ [°/mm] and μ_M [(N·m)/mm] stated in its title line, with its mean over
  the turn (the mean driving moment) drawn dashed and written; a linear
  driver: F_b over its position s, at μ_s [mm/mm] and μ_F [N/mm];
* below (a crank only), the polar diagram (hodograph) of the frame's reaction
  on the crank, R_12: each R_12 drawn from one pole at a round μ_F [N/mm],
  axes x, y through the pole, the ends joined in the order of the cycle and
  numbered at the project's positions 0, 1, … (from the output's extreme
  position), the largest |R_12| drawn from the pole and written.

Every drawn length is the value divided by its stated scale, exactly: the axes
are sized in millimetres on the page (a test reads the curves back from the
SVG by their gids ``M_b-curve``, ``M_b-origin``, ``M_b-mean``,
``R-hodograph``, ``R-points``, ``R-pole``, ``R-max``).  Every text is at least
:data:`TEXT` pt; numbers use the language's decimal mark and a true minus.
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.figure import Figure

from .._text import user_text
from ..rounding import round_up
from ..i18n import term
from .style import A4
from ..forces.cycle import is_swing
from .numerals import localised
from .svg import drawing_rc

__all__ = ["draw_force_diagrams", "round_scale", "TEXT"]

#: Size [pt] of every text but the page's title.
TEXT = 8.0
#: The page's margins and the diagrams' boxes [mm].
LEFT, WIDTH = 27.0, 170.0
MOMENT_HEIGHT = 70.0
POLAR_HEIGHT = 125.0
ROUND = (1.0, 2.0, 2.5, 5.0)


def round_scale(need: float) -> float:
    """The smallest round scale (1, 2, 2.5 or 5 × 10ᵏ) not below *need* (units per mm); 1 when there is nothing to draw."""
    if not need > 0 or not math.isfinite(need):
        return 1.0
    return round_up(need, ROUND)


def _number(value: float, lang: str, decimals: int = 1) -> str:
    """A value for a note: grouped thousands by a thin space, *decimals* decimals, the language's decimal mark (no −0)."""
    value = round(float(value), decimals) + 0.0
    text = f"{value:,.{decimals}f}".replace(",", "\u2009")
    if float(text.replace("\u2009", "")) == 0:
        text = text.lstrip("-")
    return localised(text, lang)


def _scale_text(value: float, lang: str) -> str:
    return localised(f"{value:g}", lang)


def _box(fig: Figure, left: float, bottom: float, width: float, height: float, size):
    """Axes whose box is *width* × *height* mm with its lower-left corner at (*left*, *bottom*) mm from the page's lower left."""
    ax = fig.add_axes((left / size[0], bottom / size[1], width / size[0], height / size[1]))
    ax.tick_params(labelsize=TEXT)
    return ax


def _names(cf, lang: str) -> dict:
    scene = cf.forces.scene
    crank = cf.crank
    driver = scene.driver.link if hasattr(scene.driver, "link") else ""
    return {"symbol": "M" if crank else "F", "unit": "N·m" if crank else "N", "driver": driver,
            "frame": str(scene.frame_number)}


def draw_force_diagrams(cf, *, lang: str = "en", title: str = "", size=A4) -> Figure:
    """The page of M_b(φ) (F_b(s)) and the polar diagram of the crank bearing's reaction.

    Parameters
    ----------
    cf : plans.forces.cycle.CycleForces
    lang : str
        Language of the words.
    title : str
        The page's title (plain text); empty: the scene's title in *lang*.
    """
    with drawing_rc():  # (path.simplify off: every position's point drawn)
        return _draw(cf, lang, title, size)


def _draw(cf, lang: str, title: str, size) -> Figure:
    from matplotlib.backends.backend_svg import FigureCanvasSVG

    scene = cf.forces.scene
    fig = Figure(figsize=(size[0] / 25.4, size[1] / 25.4), dpi=72)
    fig.plans_size = tuple(size)
    FigureCanvasSVG(fig)
    title = title or scene.title_in(lang)
    import textwrap

    title_lines = textwrap.wrap(user_text(title), 62) or [""]
    fig.text(11 / size[0], 1 - 11 / size[1], "\n".join(title_lines), fontsize=13.5, weight="bold", ha="left", va="top", linespacing=1.15)
    below = 6.5 * (len(title_lines) - 1)  # [mm] each further line of the title
    law = cf.cycle.law.describe(lang, scene.driver.link, **({"phase": float(cf.cycle.phase[0])} if is_swing(cf.cycle) else {}))
    what = term("forces_cycle_title", lang) if cf.bearing is not None else term("driving_force", lang)
    subtitle = user_text(what) + (f"; {user_text(law)}" if law else "")
    sub_lines = textwrap.wrap(subtitle, 100)
    fig.text(11 / size[0], 1 - (19 + below) / size[1], "\n".join(sub_lines), fontsize=9, ha="left", va="top", linespacing=1.3)
    below += 4.2 * max(0, len(sub_lines) - 3)  # a fourth line of the subtitle and on push the diagrams down
    top = size[1] - 47.0 - below  # the upper edge of the first box [mm from the bottom]
    height = _moment_diagram(cf, fig, top, lang, size)
    if cf.bearing is not None:
        _polar_diagram(cf, fig, top - height - 30.0 - POLAR_HEIGHT, lang, size)
    return fig


def _x_of(cf, positions, phase=None) -> np.ndarray:
    """The horizontal coordinate: the crank angle turned from position 0 in the sense of ω [°], or s [mm];
    a harmonic swing's time from position 0 [s] (from the *phase* of the positions)."""
    p = np.asarray(positions, dtype=float)
    if is_swing(cf.cycle):
        psi = np.asarray(phase, dtype=float)
        return ((psi - float(cf.cycle.phase[0])) % (2 * math.pi)) / cf.cycle.law.frequency
    if cf.crank:
        start = float(cf.cycle.positions[0])
        sense = -1.0 if getattr(cf.forces.scene.driver, "omega", 0.0) < 0 else 1.0
        return np.degrees(sense * (p - start)) % 360.0
    return p * 1e3


def _moment_diagram(cf, fig, top: float, lang: str, size) -> float:
    """Draw M_b (F_b) with its box's upper edge at *top* [mm from the page's bottom]; returns the box's height [mm]."""
    names = _names(cf, lang)
    values = np.asarray(cf.forces.balancing, dtype=float)
    swing = is_swing(cf.cycle)
    x = _x_of(cf, cf.cycle.positions, cf.cycle.phase)
    if swing:
        period = 2 * math.pi / cf.cycle.law.frequency
        x = np.append(x, period)  # there and back: position 0 a period on
        values = np.append(values, values[0])
        x0, span = 0.0, period
    elif cf.crank:
        x = np.append(x, 360.0)  # the turn closed: position 0 a turn on
        values = np.append(values, values[0])
        x0, span = 0.0, 360.0
    else:
        x0, span = float(np.nanmin(x)), float(np.nanmax(x) - np.nanmin(x)) or 1.0
    mu_x = round_scale(span / WIDTH)
    width = span / mu_x
    finite = values[np.isfinite(values)]
    lo = min(0.0, float(finite.min())) if finite.size else -1.0
    hi = max(0.0, float(finite.max())) if finite.size else 1.0
    mu_y = round_scale(max(hi - lo, 1e-9) / (MOMENT_HEIGHT - 20.0))  # room for the margins below (7 mm) and above (5 mm), rounded to 5 mm
    ylo = math.floor((lo - 7.0 * mu_y) / mu_y / 5.0) * 5.0 * mu_y  # the box's lower edge on a 5 mm line
    height = min(MOMENT_HEIGHT, math.ceil((hi - ylo) / mu_y / 5.0 - 1e-9) * 5.0 + 5.0)
    bottom = top - height
    ax = _box(fig, LEFT, bottom, width, height, size)
    ax.set_xlim(x0, x0 + width * mu_x)
    ax.set_ylim(ylo, ylo + height * mu_y)
    for side in ("top", "right"):
        ax.spines[side].set_visible(False)
    ax.grid(True, axis="y", lw=0.3, color="#c8c8c8")
    ax.plot([x0, x0 + span], [0.0, 0.0], color="#000000", lw=0.7, gid="M_b-origin", clip_on=False)
    ax.plot(x, values, color="#0072B2", lw=1.2, gid="M_b-curve")
    unit = names["unit"]
    label = f"${names['symbol']}_{{\\mathrm{{b}}}}$"
    if math.isfinite(cf.mean):
        ax.plot([x0, x0 + span], [cf.mean, cf.mean], color="#D55E00", lw=0.9, ls="--", gid="M_b-mean")
        bar = rf"$\overline{{{names['symbol']}}}_{{\mathrm{{b}}}}$"
        ax.text(x0 + span, cf.mean, f"{term('mean_value', lang)} {bar} = {_number(cf.mean, lang, 2)} {unit}", fontsize=TEXT, color="#D55E00",
                ha="right", va="bottom", gid="M_b-mean-text", bbox={"facecolor": "white", "edgecolor": "none", "pad": 0.5, "alpha": 0.85})
    else:
        fig.text(LEFT / size[0], (bottom - 10.5) / size[1], term("no_mean_swing" if swing else "no_mean_moment", lang), fontsize=TEXT,
                 ha="left", va="top", gid="M_b-no-mean")
    if swing:
        ax.set_xlabel("t [s]", fontsize=TEXT)
    elif cf.crank:
        ax.set_xticks(np.arange(0.0, 360.0 + 1e-9, 30.0))
        ax.set_xlabel("Δφ [°]", fontsize=TEXT)
    else:
        ax.set_xlabel("s [mm]", fontsize=TEXT)
    ax.set_ylabel(f"{label} [{unit}]", fontsize=TEXT)
    ax.xaxis.set_major_formatter(_Formatter(lang))
    ax.yaxis.set_major_formatter(_Formatter(lang))
    if cf.marked is not None:  # the numbered positions on the curve
        xm = _x_of(cf, cf.marked_cycle.positions, cf.marked_cycle.phase)
        ym = np.asarray(cf.marked.balancing, dtype=float)
        ax.plot(xm, ym, ls="none", marker="o", ms=3.0, color="#0072B2", gid="M_b-points")
        for k, (a, b) in enumerate(zip(xm, ym)):
            if math.isfinite(b):
                up = not math.isfinite(cf.mean) or b >= cf.mean - 1e-9 * max(1.0, abs(cf.mean))
                ax.annotate(str(k), (a, b), xytext=(0, 4 if up else -4), textcoords="offset points", fontsize=TEXT, ha="center",
                            va="bottom" if up else "top")
    words = term("driving_moment" if cf.crank else "driving_force", lang)
    x_scale = rf"$\mu_{{t}}$ = {_scale_text(mu_x, lang)} s/mm" if swing else rf"$\mu_{{\varphi}}$ = {_scale_text(mu_x, lang)} °/mm" if cf.crank else rf"$\mu_{{s}}$ = {_scale_text(mu_x, lang)} mm/mm"
    y_scale = rf"$\mu_{{{names['symbol']}}}$ = {_scale_text(mu_y, lang)} {f'({unit})' if '·' in unit else unit}/mm"
    fig.text(LEFT / size[0], (bottom + height + 9.5) / size[1], f"{words} {label} ({term('ccw_positive', lang)})" if cf.crank else f"{words} {label}",
             fontsize=9, ha="left", va="bottom", gid="M_b-title")
    fig.text(LEFT / size[0], (bottom + height + 4.5) / size[1], f"{x_scale},  {y_scale}", fontsize=9, ha="left", va="bottom", gid="M_b-scales")
    ax.plans_scales = (mu_x, mu_y)
    return height


def _polar_diagram(cf, fig, bottom: float, lang: str, size) -> None:
    names = _names(cf, lang)
    sub = (names["frame"] + names["driver"]) if (names["frame"] + names["driver"]).isdigit() else f"{names['frame']},{names['driver']}"
    symbol = f"$R_{{{sub}}}$"
    force = np.asarray(cf.reaction().force)
    ok = np.isfinite(force)
    xs = np.concatenate([[0.0], force.real[ok]])
    ys = np.concatenate([[0.0], force.imag[ok]])
    xlo, xhi, ylo, yhi = xs.min(), xs.max(), ys.min(), ys.max()
    width, height = WIDTH, POLAR_HEIGHT
    mu = round_scale(max((xhi - xlo) / (width - 16.0), (yhi - ylo) / (height - 16.0)))
    cx, cy = (xlo + xhi) / 2, (ylo + yhi) / 2
    ax = _box(fig, LEFT, bottom, width, height, size)
    ax.set_xlim(cx - width * mu / 2, cx + width * mu / 2)
    ax.set_ylim(cy - height * mu / 2, cy + height * mu / 2)
    ax.set_xticks([])
    ax.set_yticks([])
    for spine in ax.spines.values():
        spine.set_color("#9a9a9a")
        spine.set_linewidth(0.4)
    ax.axhline(0.0, color="#000000", lw=0.5)
    ax.axvline(0.0, color="#000000", lw=0.5)
    ax.text(cx + width * mu / 2, 0.0, "x ", fontsize=TEXT, ha="right", va="bottom")
    ax.text(0.0, cy + height * mu / 2, " y", fontsize=TEXT, ha="left", va="top")
    ax.plot([0.0], [0.0], ls="none", marker="o", ms=3.5, mfc="white", mec="#000000", gid="R-pole")
    ax.annotate(term("pole", lang), (0.0, 0.0), xytext=(-3, -3), textcoords="offset points", fontsize=TEXT, ha="right", va="top")
    closed = np.append(force, force[:1]) if cf.crank else force  # (a swing, too, comes back to position 0)
    # a load that switches (a resistance against the velocity, reversed at a dead centre; a force over the working
    # stroke only) makes R jump between two positions: the jump is drawn dotted, not as a stretch of the curve
    steps = np.abs(np.diff(closed))
    finite_steps = steps[np.isfinite(steps)]
    jumps = np.zeros(len(steps), dtype=bool)
    if finite_steps.size > 2:  # a step far longer than both its neighbours' (a fast but smooth stretch has long neighbours too)
        around = np.maximum(np.roll(steps, 1), np.roll(steps, -1))
        jumps = np.isfinite(steps) & (steps > 5.0 * np.nan_to_num(around, nan=np.inf)) & (steps > 0.02 * float(np.nanmax(np.abs(closed))))
    curve = closed.astype(complex)
    pieces = []
    for k in np.flatnonzero(jumps)[::-1]:  # a gap (NaN) between the two ends of each jump
        curve = np.insert(curve, k + 1, complex(np.nan, np.nan))
        pieces.append(closed[k:k + 2])
    ax.plot(curve.real, curve.imag, color="#0072B2", lw=1.0, gid="R-hodograph")
    for piece in pieces:
        ax.plot(piece.real, piece.imag, color="#0072B2", lw=0.6, ls=":", gid=None)
    k_max = int(np.nanargmax(np.abs(np.where(ok, force, np.nan))))
    f_max = complex(force[k_max])
    ax.annotate("", (f_max.real, f_max.imag), (0.0, 0.0), arrowprops={"arrowstyle": "-|>", "color": "#D55E00", "lw": 0.9, "shrinkA": 0, "shrinkB": 0})
    ax.plot([0.0, f_max.real], [0.0, f_max.imag], color="#D55E00", lw=0.0, gid="R-max")
    at = _x_of(cf, [cf.cycle.positions[k_max]], [cf.cycle.phase[k_max]])[0]
    angle = math.degrees(math.atan2(f_max.imag, f_max.real))
    where = f"t = {_number(at, lang, 4)} s" if is_swing(cf.cycle) else f"Δφ = {_number(at, lang, 0)}°"
    ax.text(0.01, 0.01, f"|{symbol}|" + r"$_{\mathrm{max}}$" + f" = {_number(abs(f_max), lang, 0)} N  "
            f"({term('at_crank_angle', lang)} {where}, {term('direction', lang)} {_number(angle, lang, 1)}°)",
            transform=ax.transAxes, fontsize=TEXT, color="#D55E00", ha="left", va="bottom", gid="R-max-text")
    if cf.marked is not None:
        points = np.asarray(cf.reaction(marked=True).force)
        ax.plot(points.real, points.imag, ls="none", marker="o", ms=3.0, color="#0072B2", gid="R-points")
        centre = complex(np.nanmean(force))
        for k, p in enumerate(points):
            if np.isfinite(p):
                out = p - centre
                out = out / abs(out) if abs(out) > 0 else 1.0
                ax.annotate(str(k), (p.real, p.imag), xytext=(7 * out.real, 7 * out.imag), textcoords="offset points",
                            fontsize=TEXT, ha="center", va="center")
    fig.text(LEFT / size[0], (bottom + height + 9.5) / size[1], f"{term('polar_diagram', lang)} {symbol} ({term('frame_on_crank', lang)})",
             fontsize=9, ha="left", va="bottom", gid="R-title")
    fig.text(LEFT / size[0], (bottom + height + 4.5) / size[1], f"$\\mu_{{F}}$ = {_scale_text(mu, lang)} N/mm", fontsize=9, ha="left", va="bottom",
             gid="R-scale")
    import textwrap

    fig.text(LEFT / size[0], (bottom - 4.0) / size[1], "\n".join(textwrap.wrap(term("polar_note", lang), 95)), fontsize=TEXT, ha="left", va="top")
    ax.plans_scale = mu


def _Formatter(lang: str):
    """Tick labels with the language's decimal mark and a true minus."""
    from matplotlib.ticker import FuncFormatter

    return FuncFormatter(lambda x, pos=None: localised(f"{x:g}", lang))
