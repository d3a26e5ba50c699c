"""``error_vs_time.svg``: relative error (log) against time per position (log).

Three panels, for positions, velocities and accelerations; one marker style
per method, one colour per case, and the settings of one method on one case
joined by a thin line (the trade-off that method offers).  The only module of
the benchmark that imports matplotlib; the SVG is deterministic (no date, a
fixed hash salt) apart from the measured numbers.
"""

from __future__ import annotations

import io
import math

from .run import METHODS, BenchResult

__all__ = ["MARKERS", "EPSILON", "ERROR_FLOOR", "render_svg"]

#: Marker per method.
MARKERS = dict(zip(METHODS, ("o", "*", "s", "^", "D")))

#: Double precision's unit round-off, drawn as a dotted line.
EPSILON = 2.0**-52

#: Errors below this (exactly zero) are drawn at it.
ERROR_FLOOR = 1e-18

_RC = {"svg.hashsalt": "plans-bench", "svg.fonttype": "none", "font.size": 8, "axes.titlesize": 9}


def render_svg(result: BenchResult) -> bytes:
    """The figure as SVG bytes."""
    import matplotlib
    from matplotlib.backends.backend_svg import FigureCanvasSVG
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    with matplotlib.rc_context(_RC):
        fig = Figure(figsize=(11.0, 4.4))
        FigureCanvasSVG(fig)
        axes = fig.subplots(1, 3, sharex=True, sharey=True)
        cases = list(dict.fromkeys(row.case for row in result.rows))
        colours = matplotlib.colormaps["tab20"].colors
        colour = {case: colours[(2 * k) % 20 if k < 10 else (2 * k + 1) % 20] for k, case in enumerate(cases)}
        for ax, (kind, title) in zip(axes, (("err_r", "positions r"), ("err_v", "velocities v"), ("err_a", "accelerations a"))):
            for case in cases:
                for method, marker in MARKERS.items():
                    points = sorted(
                        (row.seconds, max(getattr(row, kind), ERROR_FLOOR))
                        for row in result.rows
                        if row.case == case and row.method == method
                        and math.isfinite(row.seconds) and math.isfinite(getattr(row, kind))
                    )
                    if not points:
                        continue
                    xs, ys = zip(*points)
                    ax.plot(xs, ys, linestyle="-", linewidth=0.5, color=colour[case], alpha=0.6)
                    ax.plot(xs, ys, linestyle="none", marker=marker, markersize=5 if marker != "*" else 8,
                            markerfacecolor="none" if method.startswith("graphical") else colour[case],
                            markeredgecolor=colour[case], markeredgewidth=1.0)
            ax.axhline(EPSILON, linestyle=":", linewidth=0.8, color="0.4")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_title(f"relative error of {title}")
            ax.set_xlabel("time per position [s]")
            ax.grid(True, which="major", linewidth=0.3, alpha=0.5)
        axes[0].set_ylabel("max relative error (vs 50-digit reference); dotted: ε_mach")
        method_handles = [
            Line2D([], [], linestyle="none", marker=m, color="0.2", markerfacecolor="none" if name.startswith("graphical") else "0.2",
                   label=name)
            for name, m in MARKERS.items()
        ]
        case_handles = [Line2D([], [], color=colour[c], linewidth=2, label=c) for c in cases]
        axes[0].legend(handles=method_handles, loc="upper left", fontsize=6, title="method", title_fontsize=7, frameon=True)
        fig.legend(handles=case_handles, loc="center right", fontsize=7, title="case", title_fontsize=7, frameon=False)
        fig.suptitle("plans bench: error against run time (lower left is better)")
        fig.subplots_adjust(left=0.06, right=0.84, bottom=0.12, top=0.86, wspace=0.08)
        buffer = io.BytesIO()
        fig.savefig(buffer, format="svg", metadata={"Date": None})
    return buffer.getvalue()
