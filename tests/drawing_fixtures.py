"""Hand-made graphical solutions for the drawing tests.

Each is built from closed-form kinematics worked here (complex numbers, one
2×2 real system per group), independently of plans.graphical, so the drawings
can be tested before and apart from the construction.

* :func:`slider_crank` — E2 of domain.md (offset slider-crank, 45°, 2000 rpm):
  velocity plan p, a, b with v_A, v_B, v_BA; acceleration plan with normal
  and tangential components, no Coriolis.
* :func:`quick_return` — the bundled crank and slotted lever at 30°: a block
  sliding in a turning slot, so its acceleration plan has a Coriolis component.
* :func:`ladder` — E1 (linear driver, block on a vertical wall), velocities only.
"""

from __future__ import annotations

import cmath
import dataclasses
import math

import numpy as np

from plans.graphical.plan import ConstructionLine, GraphicalSolution, Plan, PlanVector, Step
from plans.scene import example_path, load

__all__ = ["slider_crank", "quick_return", "ladder", "E2"]


def _solve2(c1: complex, c2: complex, rhs: complex) -> tuple[float, float]:
    """Real x, y with x·c1 + y·c2 = rhs."""
    m = np.array([[c1.real, c2.real], [c1.imag, c2.imag]])
    x, y = np.linalg.solve(m, [rhs.real, rhs.imag])
    return float(x), float(y)


def _unit(z: complex) -> complex:
    return z / abs(z)


def _vec(tail: complex, tip: complex, kind: str, label: str, k: float) -> PlanVector:
    return PlanVector(complex(tail), complex(tip), kind, label, abs(tip - tail) * k)


#: E2 worked values of domain.md (exact).
E2 = {
    "B": complex(0.3198513, 0.05),
    "v_A": complex(-14.8096098, 14.8096098),
    "v_B": complex(-16.0407098, 0.0),
    "a_A": complex(-3101.71742, -3101.71742),
    "a_B": complex(-3730.28395, 0.0),
    "omega3": -59.4427657,
    "epsilon3": 12155.93412,
}


def slider_crank(accelerations: bool = True) -> GraphicalSolution:
    scene = load(example_path("slider-crank"))
    k_l, k_v, k_a = 0.002, 0.5, 100.0
    phi2 = math.radians(45)
    omega2 = 2000 * 2 * math.pi / 60
    A = 0.1 * cmath.exp(1j * phi2)
    B = complex(A.real + math.sqrt(0.25**2 - (0.05 - A.imag) ** 2), 0.05)
    phi3 = cmath.phase(B - A)
    v_A = 1j * omega2 * A
    v_B, omega3 = _solve2(1, -1j * (B - A), v_A)
    a_A = -(omega2**2) * A
    a_B, epsilon3 = _solve2(1, -1j * (B - A), a_A - omega3**2 * (B - A))

    a, b = v_A / k_v, v_B / k_v
    vA = _vec(0, a, "absolute", "v_A", k_v)
    vB = _vec(0, b, "absolute", "v_B", k_v)
    vBA = _vec(a, b, "relative", "v_BA", k_v)
    velocity = Plan(
        kind="velocity",
        scale=k_v,
        pole="p",
        images={"o": 0j, "a": a, "b": b},
        steps=(
            Step("driver", ("v_A = ω_2 × r_OA",), (vA,), (), (), "a"),
            Step(
                "RRP(3,4)",
                ("v_B = v_A + v_BA", "v_B = v_B0 + v_BB0"),
                (),
                (ConstructionLine(a, 1j * _unit(B - A), "⊥ AB"), ConstructionLine(0j, 1 + 0j, "∥ guide")),
                (vBA,),
                "b",
                sine=abs(math.sin(phi3)),
            ),
        ),
        vectors=(vA, vB, vBA),
    )
    acceleration = None
    if accelerations:
        a1, b1 = a_A / k_a, a_B / k_a
        n = a1 + (-(omega3**2) * (B - A)) / k_a
        aA = _vec(0, a1, "absolute", "a_A", k_a)
        aB = _vec(0, b1, "absolute", "a_B", k_a)
        an = _vec(a1, n, "normal", "a^n_BA", k_a)
        at = _vec(n, b1, "tangential", "a^t_BA", k_a)
        acceleration = Plan(
            kind="acceleration",
            scale=k_a,
            pole="π",
            images={"o′": 0j, "a′": a1, "b′": b1},
            steps=(
                Step("driver", ("a_A = a^n_AO",), (aA,), (), (), "a′"),
                Step(
                    "RRP(3,4)",
                    ("a_B = a_A + a^n_BA + a^t_BA", "a_B = a_B0 + a^r_BB0"),
                    (an,),
                    (ConstructionLine(n, 1j * _unit(B - A), "⊥ AB"), ConstructionLine(0j, 1 + 0j, "∥ guide")),
                    (at,),
                    "b′",
                ),
            ),
            vectors=(aA, an, at, aB),
        )
    scales = {"k_l": k_l, "k_v": k_v} | ({"k_a": k_a} if accelerations else {})
    return GraphicalSolution(
        scene=scene,
        scales=scales,
        precision=None,
        poses={"2": (phi2, 0j), "3": (phi3, A), "4": (0.0, B)},
        positions={"O": 0j, "A": A, "B": B},
        velocity_plan=velocity,
        acceleration_plan=acceleration,
        points={"A": {"v": v_A, "a": a_A}, "B": {"v": complex(v_B), "a": complex(a_B)}},
        links={"2": {"omega": omega2, "epsilon": 0.0}, "3": {"omega": omega3, "epsilon": epsilon3}, "4": {"omega": 0.0, "epsilon": 0.0}},
        sliders={"B": {"v_rel": v_B, "a_rel": a_B, "coriolis": 0j}},
        sines={"RRP(3,4)": abs(math.sin(phi3))},
    )


def quick_return() -> GraphicalSolution:
    scene = load(example_path("quick-return"))
    k_l, k_v, k_a = 0.005, 0.02, 0.1
    O, C = 0.25j, 0j
    omega2 = 6.0
    A = O + 0.12 * cmath.exp(1j * math.radians(30))
    theta4 = cmath.phase(A - C)
    u = cmath.exp(1j * theta4)
    D = C + 0.55 * u
    E = complex(D.real + math.sqrt(0.2**2 - (0.52 - D.imag) ** 2), 0.52)
    phi5 = cmath.phase(E - D)

    v_A = 1j * omega2 * (A - O)
    omega4, v_rel = _solve2(1j * (A - C), u, v_A)
    v_A4 = 1j * omega4 * (A - C)
    v_D = 1j * omega4 * (D - C)
    v_E, omega5 = _solve2(1, -1j * (E - D), v_D)

    a_A = -(omega2**2) * (A - O)
    coriolis = 2j * omega4 * v_rel * u
    epsilon4, a_rel = _solve2(1j * (A - C), u, a_A + omega4**2 * (A - C) - coriolis)
    a_A4 = (1j * epsilon4 - omega4**2) * (A - C)
    a_D = (1j * epsilon4 - omega4**2) * (D - C)
    a_E, epsilon5 = _solve2(1, -1j * (E - D), a_D - omega5**2 * (E - D))

    a, a4, d, e = v_A / k_v, v_A4 / k_v, v_D / k_v, v_E / k_v
    vA = _vec(0, a, "absolute", "v_A", k_v)
    vA4 = _vec(0, a4, "absolute", "v_A4", k_v)
    vrel = _vec(a4, a, "relative", "v_A3A4", k_v)
    vD = _vec(0, d, "absolute", "v_D", k_v)
    vE = _vec(0, e, "absolute", "v_E", k_v)
    vED = _vec(d, e, "relative", "v_ED", k_v)
    velocity = Plan(
        kind="velocity",
        scale=k_v,
        pole="p",
        images={"o": 0j, "c": 0j, "a": a, "a4": a4, "d": d, "e": e},
        steps=(
            Step("driver", ("v_A = ω_2 × r_OA",), (vA,), (), (), "a"),
            Step(
                "RPR(3,4)",
                ("v_A4 = v_A3 + v_A4A3", "v_A4 = v_C + v_A4C"),
                (),
                (ConstructionLine(a, u, "∥ CD"), ConstructionLine(0j, 1j * u, "⊥ CA")),
                (vrel,),
                "a4",
            ),
            Step(
                "RRP(5,6)",
                ("v_E = v_D + v_ED", "v_E = v_E0 + v_EE0"),
                (vD,),
                (ConstructionLine(d, 1j * _unit(E - D), "⊥ DE"), ConstructionLine(0j, 1 + 0j, "∥ ram")),
                (vED,),
                "e",
            ),
        ),
        vectors=(vA, vA4, vrel, vD, vE, vED),
    )

    a1, a41, d1, e1 = a_A / k_a, a_A4 / k_a, a_D / k_a, a_E / k_a
    n4 = (-(omega4**2) * (A - C)) / k_a
    kpt = a41 + coriolis / k_a
    n5 = d1 + (-(omega5**2) * (E - D)) / k_a
    aA = _vec(0, a1, "absolute", "a_A", k_a)
    aA4 = _vec(0, a41, "absolute", "a_A4", k_a)
    an4 = _vec(0, n4, "normal", "a^n_A4C", k_a)
    at4 = _vec(n4, a41, "tangential", "a^t_A4C", k_a)
    ak = _vec(a41, kpt, "coriolis", "a^k_A3A4", k_a)
    ar = _vec(kpt, a1, "relative", "a^r_A3A4", k_a)
    aD = _vec(0, d1, "absolute", "a_D", k_a)
    an5 = _vec(d1, n5, "normal", "a^n_ED", k_a)
    at5 = _vec(n5, e1, "tangential", "a^t_ED", k_a)
    aE = _vec(0, e1, "absolute", "a_E", k_a)
    acceleration = Plan(
        kind="acceleration",
        scale=k_a,
        pole="π",
        images={"o′": 0j, "c′": 0j, "a′": a1, "a4′": a41, "d′": d1, "e′": e1},
        steps=(
            Step("driver", ("a_A = a^n_AO",), (aA,), (), (), "a′"),
            Step(
                "RPR(3,4)",
                ("a_A4 = a_A3 + a^k_A4A3 + a^r_A4A3", "a_A4 = a^n_A4C + a^t_A4C"),
                (ak, an4),
                (ConstructionLine(kpt, u, "∥ CD"), ConstructionLine(n4, 1j * u, "⊥ CA")),
                (ar, at4),
                "a4′",
            ),
            Step(
                "RRP(5,6)",
                ("a_E = a_D + a^n_ED + a^t_ED", "a_E = a_E0 + a^r_EE0"),
                (aD, an5),
                (ConstructionLine(n5, 1j * _unit(E - D), "⊥ DE"), ConstructionLine(0j, 1 + 0j, "∥ ram")),
                (at5,),
                "e′",
            ),
        ),
        vectors=(aA, an4, at4, ak, ar, aA4, aD, an5, at5, aE),
    )
    return GraphicalSolution(
        scene=scene,
        scales={"k_l": k_l, "k_v": k_v, "k_a": k_a},
        precision=None,
        poses={"2": (math.radians(30), O), "4": (theta4, C), "5": (phi5, D), "3": (theta4, A), "6": (0.0, E)},
        positions={"O": O, "C": C, "A": A, "D": D, "E": E},
        velocity_plan=velocity,
        acceleration_plan=acceleration,
        points={"A": {"v": v_A, "a": a_A}, "D": {"v": v_D, "a": a_D}, "E": {"v": complex(v_E), "a": complex(a_E)}},
        links={"4": {"omega": omega4, "epsilon": epsilon4}, "5": {"omega": omega5, "epsilon": epsilon5}},
        sliders={"3": {"v_rel": v_rel, "a_rel": a_rel, "coriolis": coriolis}},
    )


def ladder() -> GraphicalSolution:
    """E1 at the instant of domain.md, velocities only (acceleration_plan is None)."""
    scene = dataclasses.replace(load(example_path("ladder")), accelerations=False)
    k_l, k_v = 0.005, 0.05
    A = 0j
    B = 0.5 * cmath.exp(1j * math.radians(30))
    v_A = 1 + 0j
    v_B, omega = _solve2(1j, -1j * (B - A), v_A)
    v_B = 1j * v_B
    a, b = v_A / k_v, v_B / k_v
    vA = _vec(0, a, "absolute", "v_A", k_v)
    vB = _vec(0, b, "absolute", "v_B", k_v)
    vBA = _vec(a, b, "relative", "v_BA", k_v)
    velocity = Plan(
        kind="velocity",
        scale=k_v,
        pole="p",
        images={"a": a, "b": b},
        steps=(
            Step("driver", ("v_A = v (given)",), (vA,), (), (), "a"),
            Step(
                "RRP(3,4)",
                ("v_B = v_A + v_BA", "v_B = v_B0 + v_BB0"),
                (),
                (ConstructionLine(a, 1j * _unit(B - A), "⊥ AB"), ConstructionLine(0j, 1j, "∥ wall")),
                (vBA,),
                "b",
            ),
        ),
        vectors=(vA, vB, vBA),
    )
    return GraphicalSolution(
        scene=scene,
        scales={"k_l": k_l, "k_v": k_v},
        precision=None,
        poses={"2": (0.0, A), "3": (math.radians(30), A), "4": (math.pi / 2, B)},
        positions={"O": 0j, "W": complex(0.4330127018922193, 0), "A": A, "B": B},
        velocity_plan=velocity,
        acceleration_plan=None,
        points={"A": {"v": v_A}, "B": {"v": v_B}},
        links={"3": {"omega": omega, "epsilon": 0.0}},
        sliders={},
    )
