"""The benchmark's fixed suite: every bundled example, plus three stiff scenes.

Each :class:`Case` is a scene with

* a **sweep**: the interval of driver positions the analytic solver is timed
  over (a crank's full turn from the scene's angle, a linear driver's
  stroke, the assemblable arc of a crank that cannot turn fully);
* its **samples**: the driver positions where every method is compared with
  the 50-digit reference; the scene's own position comes first.

The stiff scenes are generated here with :func:`plans.scene.from_mapping`:

* ``four-bar-toggle``: a four-bar whose crank cannot turn fully; its RRR
  group stretches (coupler and rocker in line: a dead centre) at φ_t =
  arccos(−3/8) ≈ 112°.  The samples approach φ_t from 1e-1 rad down to
  1e-9 rad, where |sin| of the angle between the construction lines is ~4e-5;
* ``slider-crank-micro``: the offset slider-crank of ``slider-crank.toml``
  with lengths × 1e-5 (crank 1 µm) and ω × 1e4 (2.1e6 rad/s);
* ``slider-crank-large``: the same with lengths × 1e3 (crank 100 m) and
  ω × 1e-5 (2.1e-3 rad/s).

Relative errors must not depend on the unit system: the last two should
show the same errors as ``slider-crank``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..scene import Crank, Scene, example_names, example_path, from_mapping, load

__all__ = ["Case", "suite", "slider_crank_scene", "toggle_four_bar_scene", "TOGGLE_ANGLE", "dyad_chain_toml", "CHAIN_DYADS"]


@dataclass(frozen=True)
class Case:
    """One scene of the suite.

    Attributes
    ----------
    name : str
    scene : Scene
    kind : str
        ``"example"`` (bundled) or ``"stiff"`` (generated).
    sweep : tuple[float, float]
        Driver positions ``[start, end)`` the analytic solver is timed over
        (rad or m).
    samples : tuple[float, ...]
        Driver positions where errors are measured, the scene's own first.
    yardstick : dict or None
        ``r, l, e, omega, epsilon`` of an offset slider-crank in the
        yardstick's frame (see :mod:`plans.bench.yardstick`), or None.
    """

    name: str
    scene: Scene
    kind: str
    sweep: tuple[float, float]
    samples: tuple[float, ...]
    yardstick: dict | None = field(default=None)

    def grid(self, n: int):
        """*n* driver positions over the sweep, with the samples at evenly spread indices.

        The error of a timed run is read at the samples it contains: all of
        them when n ≥ len(samples), else the first n.
        """
        import numpy as np

        samples = np.asarray(self.samples, dtype=float)
        if n <= len(samples):
            return samples[:n].copy(), np.arange(n)
        a, b = self.sweep
        positions = a + (b - a) * (np.arange(n) + 0.5) / n
        index = np.round(np.linspace(0, n - 1, len(samples))).astype(int)
        positions[index] = samples
        return positions, index


def _position(scene: Scene) -> float:
    driver = scene.driver
    return driver.phi if isinstance(driver, Crank) else driver.s


def _crank_samples(x0: float, m: int) -> tuple[float, ...]:
    return tuple(x0 + 2 * math.pi * j / m for j in range(m))


def _linear_samples(x0: float, stroke: tuple[float, float], m: int) -> tuple[float, ...]:
    a, b = stroke
    return (x0,) + tuple(a + (b - a) * (j + 0.5) / (m - 1) for j in range(m - 1))


# --- the offset slider-crank (E2), at any scale --------------------------------

#: E2 of domain.md: crank 0.1 m, coupler 0.25 m, guide y = 0.05 m, 2000 rpm, at 45°.
SLIDER_CRANK = {"r": 0.1, "l": 0.25, "e": 0.05, "omega": 2000 * 2 * math.pi / 60, "phi": math.radians(45)}


def slider_crank_scene(length: float = 1.0, rate: float = 1.0, title: str = "Offset slider-crank") -> Scene:
    """The offset slider-crank of ``slider-crank.toml`` with lengths × *length* and ω × *rate*."""
    r, l, e = (SLIDER_CRANK[k] * length for k in ("r", "l", "e"))
    omega = SLIDER_CRANK["omega"] * rate
    phi = SLIDER_CRANK["phi"]
    B = r * math.cos(phi) + math.sqrt(l * l - (e - r * math.sin(phi)) ** 2)
    return from_mapping(
        {
            "title": title,
            "frame": {"points": {"O": [0.0, 0.0]}, "lines": {"cylinder": {"through": [0.0, e], "angle": "0 rad"}}},
            "link": {"2": {"points": {"O": [0.0, 0.0], "A": [r, 0.0]}}, "3": {"points": {"A": [0.0, 0.0], "B": [l, 0.0]}}},
            "slider": [{"pin": "B", "on": "frame.cylinder"}],
            "driver": {"crank": "2", "angle": f"{phi!r} rad", "omega": f"{omega!r} rad/s"},
            "assembly": {"B": [B, e]},
        },
        source=f"<{title}>",
    )


def _yardstick_parameters(length: float, rate: float) -> dict:
    return {
        "r": SLIDER_CRANK["r"] * length,
        "l": SLIDER_CRANK["l"] * length,
        "e": SLIDER_CRANK["e"] * length,
        "omega": SLIDER_CRANK["omega"] * rate,
        "epsilon": 0.0,
    }


# --- a four-bar near its toggle ----------------------------------------------------

#: O = (0, 0), D = (0.3, 0), crank OA = 0.1, coupler AC = 0.25, rocker DC = 0.1 [m]:
#: |AD| reaches AC + DC = 0.35 at cos φ_t = (0.1² + 0.3² − 0.35²)/(2·0.1·0.3) = −3/8.
_TOGGLE = {"d": 0.3, "r": 0.1, "coupler": 0.25, "rocker": 0.1}
TOGGLE_ANGLE = math.acos((0.1**2 + 0.3**2 - 0.35**2) / (2 * 0.1 * 0.3))

#: How far from the toggle the samples go [rad of crank angle]: 1e-1 … 1e-9.
TOGGLE_DISTANCES = (1e-1, 1e-9)


def toggle_four_bar_scene(distance: float = 1e-6) -> Scene:
    """A four-bar *distance* rad of crank angle before its RRR group stretches out (a dead centre)."""
    t = _TOGGLE
    return from_mapping(
        {
            "title": "Four-bar near its toggle",
            "frame": {"points": {"O": [0.0, 0.0], "D": [t["d"], 0.0]}},
            "link": {
                "2": {"points": {"O": [0.0, 0.0], "A": [t["r"], 0.0]}},
                "3": {"points": {"A": [0.0, 0.0], "C": [t["coupler"], 0.0]}},
                "4": {"points": {"D": [0.0, 0.0], "C": [t["rocker"], 0.0]}},
            },
            "driver": {"crank": "2", "angle": f"{TOGGLE_ANGLE - distance!r} rad", "omega": "10 rad/s", "epsilon": "5 rad/s^2"},
            "assembly": {"C": 1},
        },
        source="<four-bar near its toggle>",
    )


def _toggle_samples(x0: float, m: int) -> tuple[float, ...]:
    if m <= 1:
        return (x0,)
    far, near = (math.log10(d) for d in TOGGLE_DISTANCES)
    steps = [far + (near - far) * j / max(1, m - 2) for j in range(m - 1)]
    return (x0,) + tuple(TOGGLE_ANGLE - 10.0**s for s in steps)


# --- the suite ----------------------------------------------------------------------


def suite(samples: int = 8) -> list[Case]:
    """Every bundled example, then the stiff cases, each with *samples* reference positions."""
    cases = []
    for name in example_names():
        scene = load(example_path(name))
        x0 = _position(scene)
        if isinstance(scene.driver, Crank):
            sweep = (x0, x0 + 2 * math.pi)
            points = _crank_samples(x0, samples)
        else:
            stroke = scene.driver.stroke or (x0 - 0.05, x0 + 0.05)
            sweep = (min(stroke), max(stroke))
            points = _linear_samples(x0, sweep, samples)
        yardstick = _yardstick_parameters(1.0, 1.0) if name == "slider-crank" else None
        cases.append(Case(name, scene, "example", sweep, points, yardstick))

    toggle = toggle_four_bar_scene()
    x0 = _position(toggle)
    cases.append(Case("four-bar-toggle", toggle, "stiff", (-TOGGLE_ANGLE, TOGGLE_ANGLE), _toggle_samples(x0, samples)))
    for name, length, rate in (("slider-crank-micro", 1e-5, 1e4), ("slider-crank-large", 1e3, 1e-5)):
        scene = slider_crank_scene(length, rate, title=f"Offset slider-crank, lengths × {length:g}, ω × {rate:g}")
        x0 = _position(scene)
        cases.append(
            Case(name, scene, "stiff", (x0, x0 + 2 * math.pi), _crank_samples(x0, samples), _yardstick_parameters(length, rate))
        )
    return cases


#: Chains of RRR dyads whose ``plans draw`` the benchmark times (the growth with the number of groups).
CHAIN_DYADS = (5, 20, 50)


def dyad_chain_toml(dyads: int, angle_deg: float = 45.0) -> str:
    """TOML text of a crank followed by *dyads* RRR groups in a row (``plans bench`` times drawing it).

    A crank OA (20 mm) drives dyad 1 (coupler A–P1, rocker D1–P1); dyad k hangs
    on the previous rocker's tip P(k−1): coupler P(k−1)–Pk, rocker Dk–Pk
    (80 mm) with Dk = (100·k, 0) mm.  Every rocker tip sits near
    (100·k, 80) mm, so each dyad assembles near the same shape.
    """
    frame = {"O": (0.0, 0.0)}
    lines = [f'title = "Chain of {dyads} RRR dyads"', ""]
    links = []
    a = 20.0 * complex(math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg)))
    links.append(("2", {"O": 0j, "A": complex(20.0, 0)}))
    prev, prev_at = "A", a
    hints = {}
    for k in range(1, dyads + 1):
        d = f"D{k}"
        p = f"P{k}"
        frame[d] = (100.0 * k, 0.0)
        at = complex(100.0 * k, 80.0)
        links.append((str(2 * k + 1), {prev: 0j, p: complex(abs(at - prev_at), 0)}))
        links.append((str(2 * k + 2), {d: 0j, p: complex(80.0, 0)}))
        hints[p] = at
        prev, prev_at = p, at
    pts = ", ".join(f'{n} = ["{x:g} mm", "{y:g} mm"]' for n, (x, y) in frame.items())
    lines += ["[frame]", f"points = {{ {pts} }}", ""]
    for name, points in links:
        pts = ", ".join(f'{n} = ["{z.real:.6g} mm", "{z.imag:.6g} mm"]' for n, z in points.items())
        lines += [f'[link.{name}]', f"points = {{ {pts} }}", ""]
    lines += ["[driver]", 'crank = "2"', f'angle = "{angle_deg:g} deg"', 'omega = "10 rad/s"', ""]
    lines += ["[assembly]"] + [f"{n} = [{z.real / 1000:.6g}, {z.imag / 1000:.6g}]" for n, z in hints.items()]
    return "\n".join(lines) + "\n"
