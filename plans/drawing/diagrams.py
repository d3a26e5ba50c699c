"""Kinematic diagrams over the driver's cycle, from an analytic sweep.

Three figures (A4 portrait, the size of a handout page):

* links — φ (unwrapped, in degrees), ω and ε of every link (slider blocks
  turn with their guides and are left out);
* points — |v| and |a| of every reported point, and with ``components=True``
  their x and y components;
* sliders — travel s, relative velocity v_rel, relative acceleration a_rel
  and the magnitude of the Coriolis acceleration of every prismatic pair
  (only when the mechanism has one).

The horizontal axis is the angle the crank has turned from position 0 (in
the sense of ω), or the linear driver's position.  Intervals where the
mechanism cannot assemble are shaded grey and hatched; those near a dead
centre (|sin| of the angle between a group's construction lines below
:data:`NEAR_DEAD_CENTRE`, and the positions beside an interval without
assembly, which is entered through a dead centre) light orange; the positions that have sheets are
marked with dotted vertical lines and their numbers.

Only the drawing happens here: every value comes from the
:class:`~plans.analytic.AnalyticSolution`.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from .._files import replace_all
from .._text import subscript, user_text
from ..i18n import term
from .layout import A4
from .svg import drawing_rc

__all__ = ["NEAR_DEAD_CENTRE", "QUANTITIES", "draw_cycle_diagrams", "write_cycle_diagrams", "plot_cycle", "cycle_axis"]

#: |sin| of the angle between construction lines below which a position counts as near a dead centre.
NEAR_DEAD_CENTRE = 0.1

COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442")
STYLES = ("-", "--", "-.", ":")


def cycle_axis(analytic, marked=None) -> tuple[np.ndarray, str, list[tuple[int, float]]]:
    """The x values of a sweep, the axis label, and the marked positions as (number, x).

    For a crank, x is the angle turned from the sweep's first position in the
    sense the sweep runs (that of ω for the sweeps of :mod:`plans.positions`) [°]; for a linear driver, the position [mm].  *marked* are
    driver positions (rad or m), numbered 0, 1, 2 … in the order given.
    """
    scene = analytic.scene
    driver = np.asarray(analytic.driver, dtype=float)
    marks = []
    if hasattr(scene.driver, "omega"):
        # the sense the sweep runs in (that of ω for plans.positions' sweeps)
        if len(driver) > 1 and driver[-1] != driver[0]:
            sense = 1.0 if driver[-1] > driver[0] else -1.0
        else:
            sense = -1.0 if scene.driver.omega < 0 else 1.0
        start = driver[0]
        x = np.degrees(sense * (driver - start))
        label = "Δφ [°]"
        for k, p in enumerate(marked or ()):
            marks.append((k, float(np.degrees(sense * (p - start)) % 360.0)))
    else:
        x = driver * 1e3
        label = "s [mm]"
        for k, p in enumerate(marked or ()):
            marks.append((k, float(p) * 1e3))
    return x, label, marks


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


def _near_dead(analytic) -> np.ndarray:
    """Positions near a dead centre: a group's |sin| below the threshold, or beside a position that
    cannot assemble (the assembly is lost through a dead centre, between the two)."""
    near = np.zeros(len(analytic.driver), dtype=bool)
    for sines in analytic.sines.values():
        s = np.asarray(sines, dtype=float)
        near |= np.isfinite(s) & (s < NEAR_DEAD_CENTRE)
    invalid = ~np.asarray(analytic.valid, dtype=bool)
    beside = np.zeros_like(invalid)
    beside[1:] |= invalid[:-1]
    beside[:-1] |= invalid[1:]
    return near | (beside & ~invalid)


def _decorate(ax, x, invalid, near, marks, *, numbers: bool) -> None:
    for a, b in _spans(x, invalid):
        ax.axvspan(a, b, facecolor="#d0d0d0", edgecolor="#8c8c8c", hatch="///", linewidth=0.0, zorder=0.5)
    for a, b in _spans(x, near & ~invalid):
        ax.axvspan(a, b, facecolor="#fbe3c8", edgecolor="none", linewidth=0.0, zorder=0.4)
    for k, xm in marks:
        ax.axvline(xm, color="#606060", lw=0.6, ls=":", zorder=0.6)
        if numbers:
            ax.text(xm, 1.01, str(k), transform=ax.get_xaxis_transform(), ha="center", va="bottom", fontsize=6.5, color="#404040")
    ax.grid(True, lw=0.3, color="#e0e0e0")
    ax.axhline(0.0, color="#000000", lw=0.5, zorder=0.7)
    ax.tick_params(labelsize=7)
    ax.set_xlim(float(np.nanmin(x)), float(np.nanmax(x)))


def _finite(values, valid) -> np.ndarray:
    v = np.array(values, dtype=float)
    v[~valid] = np.nan
    return v


def _page(title: str, subtitle: str, rows: int) -> tuple[Figure, list]:
    fig = Figure(figsize=(A4[0] / 25.4, A4[1] / 25.4), dpi=72)
    from matplotlib.backends.backend_svg import FigureCanvasSVG

    FigureCanvasSVG(fig)
    import textwrap

    fig.text(11 / A4[0], 1 - 11 / A4[1], title, fontsize=13.5, weight="bold", ha="left", va="top")
    fig.text(11 / A4[0], 1 - 19 / A4[1], "\n".join(w for line in subtitle.split("\n") for w in textwrap.wrap(line, 95)), fontsize=9, ha="left", va="top", linespacing=1.3)
    top = 1 - 36 / A4[1]
    bottom = 22 / A4[1]
    axes = fig.subplots(rows, 1, sharex=True, gridspec_kw={"left": 24 / A4[0], "right": 1 - 40 / A4[0], "top": top, "bottom": bottom, "hspace": 0.16})
    return fig, list(np.atleast_1d(axes))


def _legend_note(fig, lang: str, has_invalid: bool, has_near: bool, has_marks: bool) -> None:
    from matplotlib.patches import Patch
    from matplotlib.lines import Line2D

    handles = []
    if has_invalid:
        handles.append(Patch(facecolor="#d0d0d0", edgecolor="#8c8c8c", hatch="///", label=term("no_assembly", lang)))
    if has_near:
        handles.append(Patch(facecolor="#fbe3c8", label=f"{term('near_dead_centre', lang)} (|sin| < {NEAR_DEAD_CENTRE:g})"))
    if has_marks:
        handles.append(Line2D([], [], color="#606060", lw=0.6, ls=":", label=term("sheet_positions", lang)))
    if handles:
        fig.legend(handles=handles, loc="lower left", bbox_to_anchor=(24 / A4[0], 6 / A4[1]), ncol=len(handles), fontsize=7, frameon=False)


def _plot_series(ax, x, series, ylabel):
    for n, (label, y) in enumerate(series):
        ax.plot(x, y, color=COLOURS[n % len(COLOURS)], ls=STYLES[(n // len(COLOURS)) % len(STYLES)], lw=1.1, label=label)
    ax.set_ylabel(ylabel, fontsize=8)
    if series:
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7, frameon=False, borderaxespad=0.0)


def draw_cycle_diagrams(analytic, *, marked=None, lang: str = "en", components: bool = False) -> list[tuple[str, Figure]]:
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
    """
    scene = analytic.scene
    valid = np.asarray(analytic.valid, dtype=bool)
    invalid = ~valid
    near = _near_dead(analytic)
    x, xlabel, marks = cycle_axis(analytic, marked)
    crank = hasattr(scene.driver, "omega")
    xwords = term("turned_from_0", lang) if crank else term("driver_position", lang)
    title = term("cycle_diagrams", lang)
    out = []
    with drawing_rc():
        # links
        fig, axes = _page(title, user_text(scene.title) + "\n" + term('links_motion', lang), 3 if scene.accelerations else 2)
        _plot_series(axes[0], x, _series(analytic, "phi", valid), f"φ [°]\n({term('angle', lang)})")
        _plot_series(axes[1], x, _series(analytic, "omega", valid), f"ω [rad/s]\n({term('angular_velocity', lang)})")
        if scene.accelerations:
            _plot_series(axes[2], x, _series(analytic, "epsilon", valid), f"ε [rad/s²]\n({term('angular_acceleration', lang)})")
        _finish(fig, axes, x, invalid, near, marks, lang, xlabel, xwords)
        out.append(("links", fig))

        # points
        points = [p for p in scene.report if p in analytic.points]
        rows = (2 if scene.accelerations else 1) * (3 if components else 1)
        fig, axes = _page(title, user_text(scene.title) + "\n" + term('points_motion', lang), rows)
        k = 0
        _plot_series(axes[k], x, _series(analytic, "v", valid), f"|v| [m/s]\n({term('velocity', lang)})")
        k += 1
        if components:
            _plot_series(axes[k], x, [(f"v_{p},x", _finite(analytic.points[p].v.real, valid)) for p in points], "v_x [m/s]")
            _plot_series(axes[k + 1], x, [(f"v_{p},y", _finite(analytic.points[p].v.imag, valid)) for p in points], "v_y [m/s]")
            k += 2
        if scene.accelerations:
            _plot_series(axes[k], x, _series(analytic, "a", valid), f"|a| [m/s²]\n({term('acceleration', lang)})")
            k += 1
            if components:
                _plot_series(axes[k], x, [(f"a_{p},x", _finite(analytic.points[p].a.real, valid)) for p in points], "a_x [m/s²]")
                _plot_series(axes[k + 1], x, [(f"a_{p},y", _finite(analytic.points[p].a.imag, valid)) for p in points], "a_y [m/s²]")
        _finish(fig, axes, x, invalid, near, marks, lang, xlabel, xwords)
        out.append(("points", fig))

        # sliders
        pairs = [p.name for p in scene.prismatics if p.name in analytic.sliders]
        if pairs:
            rows = 4 if scene.accelerations else 2
            fig, axes = _page(title, user_text(scene.title) + "\n" + term('sliders_motion', lang), rows)
            _plot_series(axes[0], x, _series(analytic, "s", valid), f"s [mm]\n({term('travel', lang)})")
            _plot_series(axes[1], x, _series(analytic, "v_rel", valid), f"v_rel [m/s]\n({term('relative_velocity_short', lang)})")
            if scene.accelerations:
                _plot_series(axes[2], x, _series(analytic, "a_rel", valid), f"a_rel [m/s²]\n({term('relative_acceleration_short', lang)})")
                _plot_series(axes[3], x, _series(analytic, "coriolis", valid), f"|aᵏ| [m/s²]\n({term('coriolis_acceleration', lang)})")
            _finish(fig, axes, x, invalid, near, marks, lang, xlabel, xwords)
            out.append(("sliders", fig))
    return out


def _unwrap_nan(phi, valid) -> np.ndarray:
    """φ in degrees, unwrapped along each run of valid positions."""
    phi = np.array(phi, dtype=float)
    out = np.full_like(phi, np.nan)
    ok = valid & np.isfinite(phi)
    k = 0
    n = len(phi)
    while k < n:
        if ok[k]:
            j = k
            while j + 1 < n and ok[j + 1]:
                j += 1
            out[k : j + 1] = np.degrees(np.unwrap(phi[k : j + 1]))
            k = j + 1
        else:
            k += 1
    return out


def _finish(fig, axes, x, invalid, near, marks, lang, xlabel, xwords) -> None:
    for n, ax in enumerate(axes):
        _decorate(ax, x, invalid, near, marks, numbers=n == 0)
    axes[-1].set_xlabel(f"{xlabel}  —  {xwords}", fontsize=8)
    if xlabel.startswith("Δφ"):
        span = float(np.nanmax(x) - np.nanmin(x))
        if span >= 90:
            axes[-1].set_xticks(np.arange(0, np.nanmax(x) + 1e-9, 30.0))
    _legend_note(fig, lang, bool(invalid.any()), bool((near & ~invalid).any()), bool(marks))


def write_cycle_diagrams(analytic, directory, *, marked=None, lang: str = "en", components: bool = False) -> list[Path]:
    """Write ``links.svg``, ``points.svg`` and (with prismatic pairs) ``sliders.svg`` into *directory*, atomically.

    Parameters are those of :func:`draw_cycle_diagrams`.

    Returns
    -------
    list of pathlib.Path
    """
    from .svg import render_svg

    directory = Path(directory)
    contents = {directory / f"{name}.svg": render_svg(fig) for name, fig in draw_cycle_diagrams(analytic, marked=marked, lang=lang, components=components)}
    return replace_all(contents)  # creates the directory


#: quantity -> label of its axis; see :func:`plot_cycle`.
QUANTITIES = {
    "phi": "φ [°]",
    "omega": "ω [rad/s]",
    "epsilon": "ε [rad/s²]",
    "v": "|v| [m/s]",
    "a": "|a| [m/s²]",
    "s": "s [mm]",
    "v_rel": "v_rel [m/s]",
    "a_rel": "a_rel [m/s²]",
    "coriolis": "|aᵏ| [m/s²]",
}


def _series(analytic, quantity: str, valid) -> list[tuple[str, np.ndarray]]:
    scene = analytic.scene
    if quantity in ("phi", "omega", "epsilon"):
        links = [n for n in scene.links if not scene.bodies[n].block]
        symbol = {"phi": "φ", "omega": "ω", "epsilon": "ε"}[quantity]
        if quantity == "phi":
            return [(f"{symbol}{subscript(n)}", _unwrap_nan(analytic.links[n].phi, valid)) for n in links]
        return [(f"{symbol}{subscript(n)}", _finite(getattr(analytic.links[n], quantity), valid)) for n in links]
    if quantity in ("v", "a"):
        points = [p for p in scene.report if p in analytic.points]
        return [(f"|{quantity}_{p}|", _finite(np.abs(getattr(analytic.points[p], quantity)), valid)) for p in points]
    pairs = [p.name for p in scene.prismatics if p.name in analytic.sliders]
    if quantity == "s":
        return [(f"s_{n}", _finite(np.asarray(analytic.sliders[n].s) * 1e3, valid)) for n in pairs]
    if quantity == "coriolis":
        return [(f"|aᵏ| {n}", _finite(np.abs(analytic.sliders[n].coriolis), valid)) for n in pairs]
    return [(f"{quantity} {n}", _finite(getattr(analytic.sliders[n], quantity), valid)) for n in pairs]


def plot_cycle(analytic, quantity: str = "omega", ax=None, *, marked=None, lang: str = "en") -> list:
    """One diagram over the cycle into *ax* (a new figure when None): ``"phi"``, ``"omega"``, ``"epsilon"``
    of the links, ``"v"``, ``"a"`` of the points, ``"s"``, ``"v_rel"``, ``"a_rel"``, ``"coriolis"`` of the
    prismatic pairs.  Returns the curves (Line2D).
    """
    if quantity not in QUANTITIES:
        raise ValueError(f"no diagram of {quantity!r}; choose one of {', '.join(QUANTITIES)}")
    valid = np.asarray(analytic.valid, dtype=bool)
    x, xlabel, marks = cycle_axis(analytic, marked)
    with drawing_rc():
        if ax is None:
            fig = Figure(figsize=(160 / 25.4, 90 / 25.4), dpi=72)
            from matplotlib.backends.backend_svg import FigureCanvasSVG

            FigureCanvasSVG(fig)
            ax = fig.add_axes([0.12, 0.16, 0.72, 0.76])
        series = _series(analytic, quantity, valid)
        _plot_series(ax, x, series, QUANTITIES[quantity])
        _decorate(ax, x, ~valid, _near_dead(analytic), marks, numbers=True)
        ax.set_xlabel(xlabel, fontsize=8)
    return [line for line in ax.get_lines() if not line.get_label().startswith("_")]
