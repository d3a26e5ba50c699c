"""The analytic solver against references that share no code with it.

* E1 and E2 of domain.md: the printed values (to the digits printed) and
  closed forms worked by hand from the same data (to EXACT_REL);
* the six-bar against a 50-digit mpmath evaluation of its loop equations,
  with velocities and accelerations by mpmath's own differentiation in time.
"""

import cmath
import math

import mpmath
import numpy as np
import pytest

from plans.analytic import solve
from plans.scene import example_names, example_path, load
from tolerances import EXACT_REL, MPMATH_REL, WORKED_EXAMPLE_REL


def printed(value: str, scale: float | None = None) -> dict:
    """pytest.approx arguments for a number as domain.md prints it.

    A value printed with decimals is known to half a unit of its last digit
    (where it has enough digits, that is within WORKED_EXAMPLE_REL); one printed
    without decimals is exact, and is compared to WORKED_EXAMPLE_REL of
    ``scale`` (the magnitude of the vector a zero component belongs to) or of
    itself.
    """
    x = float(value)
    half_unit = 0.5 * 10.0 ** -len(value.split(".")[1]) if "." in value else 0.0
    return {"expected": x, "abs": max(half_unit, WORKED_EXAMPLE_REL * (scale or abs(x))), "rel": 0}


def close(got, want, rel=EXACT_REL):
    assert abs(got - want) <= rel * abs(want), (got, want, abs(got - want) / abs(want))


# --- E1: the sliding ladder ------------------------------------------------------

# Hand solution: AB = L = 0.5 m at θ = 30° with the floor; A moves at v_A = 1 m/s
# along x, B stays on the wall x = const.
#   x_B = x_A + L cos θ = const   ⇒ v_A − L ω sin θ = 0       ⇒ ω = v_A / (L sin θ) = 4
#                                 ⇒ −L ε sin θ − L ω² cos θ = 0 ⇒ ε = −ω² cot θ = −16√3
#   y_B = L sin θ                 ⇒ v_B = L ω cos θ = √3,  a_B = L ε cos θ − L ω² sin θ = −16
E1_EXACT = {
    "omega": 4.0,
    "v_B": complex(0, math.sqrt(3)),
    "epsilon": -16 * math.sqrt(3),
    "a_B": complex(0, -16.0),
}


def test_e1_ladder_matches_the_hand_solution():
    solution = solve(load(example_path("ladder")))
    ladder = solution.links["3"]
    B = solution.points["B"]
    close(ladder.omega[0], E1_EXACT["omega"])
    close(ladder.epsilon[0], E1_EXACT["epsilon"])
    assert abs(B.v[0] - E1_EXACT["v_B"]) <= EXACT_REL * abs(E1_EXACT["v_B"])
    assert abs(B.a[0] - E1_EXACT["a_B"]) <= EXACT_REL * abs(E1_EXACT["a_B"])
    assert B.r[0] == pytest.approx(complex(0.5 * math.cos(math.pi / 6), 0.25), rel=EXACT_REL)


def test_e1_ladder_matches_the_printed_values():
    solution = solve(load(example_path("ladder")))
    B = solution.points["B"]
    assert solution.links["3"].omega[0] == pytest.approx(**printed("4"))
    assert solution.links["3"].epsilon[0] == pytest.approx(**printed("-27.7128129"))
    assert B.v[0].real == pytest.approx(**printed("0", scale=1.7320508))
    assert B.v[0].imag == pytest.approx(**printed("1.7320508"))
    assert B.a[0].real == pytest.approx(**printed("0", scale=16.0))
    assert B.a[0].imag == pytest.approx(**printed("-16.0"))


# --- E2: the offset slider-crank -------------------------------------------------


def e2_hand_solution():
    """Textbook closed form of the offset slider-crank, written out term by term.

    r sin φ + l sin θ = e fixes the coupler angle θ (B right of A: cos θ > 0);
    differentiating it once and twice gives ω₃ and ε₃, and x_B = r cos φ + l cos θ
    gives v_B and a_B.
    """
    r, l, e = 0.1, 0.25, 0.05
    phi, w = math.radians(45), 2000 * 2 * math.pi / 60
    theta = math.asin((e - r * math.sin(phi)) / l)
    w3 = -r * w * math.cos(phi) / (l * math.cos(theta))
    e3 = (r * w**2 * math.sin(phi) + l * w3**2 * math.sin(theta)) / (l * math.cos(theta))
    return {
        "omega2": w,
        "A": r * cmath.exp(1j * phi),
        "v_A": 1j * w * r * cmath.exp(1j * phi),
        "a_A": -(w**2) * r * cmath.exp(1j * phi),
        "B": complex(r * math.cos(phi) + l * math.cos(theta), e),
        "theta": theta,
        "omega3": w3,
        "v_B": complex(-r * w * math.sin(phi) - l * w3 * math.sin(theta), 0),
        "epsilon3": e3,
        "a_B": complex(-r * w**2 * math.cos(phi) - l * e3 * math.sin(theta) - l * w3**2 * math.cos(theta), 0),
    }


def test_e2_slider_crank_matches_the_hand_solution():
    want = e2_hand_solution()
    solution = solve(load(example_path("slider-crank")))
    crank, coupler = solution.links["2"], solution.links["3"]
    A, B = solution.points["A"], solution.points["B"]
    close(crank.omega[0], want["omega2"])
    close(A.r[0], want["A"])
    close(A.v[0], want["v_A"])
    close(A.a[0], want["a_A"])
    close(B.r[0], want["B"])
    close(coupler.phi[0], want["theta"])
    close(coupler.omega[0], want["omega3"])
    close(B.v[0], want["v_B"])
    close(coupler.epsilon[0], want["epsilon3"])
    close(B.a[0], want["a_B"])
    slider = solution.sliders["B"]
    close(slider.v_rel[0], want["v_B"].real)
    close(slider.a_rel[0], want["a_B"].real)
    assert slider.coriolis[0] == 0


@pytest.mark.parametrize(
    "quantity, value",
    [
        ("omega2", "209.4395102"),
        ("B.x", "0.3198513"),
        ("B.y", "0.05"),  # the guide's line, exactly
        ("theta_deg", "-4.7519838"),
        ("v_A.x", "-14.8096098"),
        ("v_A.y", "14.8096098"),
        ("omega3", "-59.4427657"),
        ("v_B.x", "-16.0407098"),
        ("v_B.y", "0"),
        ("a_A.x", "-3101.71742"),
        ("a_A.y", "-3101.71742"),
        ("epsilon3", "12155.93412"),
        ("a_B.x", "-3730.28395"),
        ("a_B.y", "0"),
    ],
)
def test_e2_slider_crank_matches_the_printed_values(quantity, value):
    solution = solve(load(example_path("slider-crank")))
    P = solution.points
    got = {
        "omega2": solution.links["2"].omega[0],
        "B.x": P["B"].r[0].real,
        "B.y": P["B"].r[0].imag,
        "theta_deg": math.degrees(solution.links["3"].phi[0]),
        "v_A.x": P["A"].v[0].real,
        "v_A.y": P["A"].v[0].imag,
        "omega3": solution.links["3"].omega[0],
        "v_B.x": P["B"].v[0].real,
        "v_B.y": P["B"].v[0].imag,
        "a_A.x": P["A"].a[0].real,
        "a_A.y": P["A"].a[0].imag,
        "epsilon3": solution.links["3"].epsilon[0],
        "a_B.x": P["B"].a[0].real,
        "a_B.y": P["B"].a[0].imag,
    }[quantity]
    scale = {"v_B.y": 16.0407098, "a_B.y": 3730.28395}.get(quantity)
    assert got == pytest.approx(**printed(value, scale))


# --- the six-bar at 50 digits ------------------------------------------------------


class SixBar50:
    """The six-bar of ``six-bar.toml``, written from its data with mpmath at 50 digits.

    Four-bar OACD (crank OA = 0.15 m, coupler AC = 0.6 m with B at 0.45 m along
    it, rocker DC = 0.4 m), then rod 5 through B sliding in the sleeve 6 that
    swings about E, M on the rod 0.8 m from B.  The coupler angle comes from the
    law of cosines in triangle ADC, the branch (±) chosen once, at the scene's
    crank angle, as the one that puts C nearer the scene's hint; the rod points
    from B towards E (branch +1 of the RPR convention).  Velocities and
    accelerations are mpmath's numerical derivatives in time of these
    positions, with φ(t) = φ + ωt.
    """

    def __init__(self, scene):
        mpmath.mp.dps = 50
        mpf, mpc = mpmath.mpf, mpmath.mpc
        self.omega = mpf(-10)
        self.D, self.E = mpc("-0.45", "0.35"), mpc("-0.2", "-0.15")
        self.OA, self.AC, self.AB, self.DC, self.BM = (mpf(x) for x in ("0.15", "0.6", "0.45", "0.4", "0.8"))
        hint = mpc("-0.3", "0.7")
        phi0 = mpf(scene.driver.phi)
        self.sign = 1
        self.sign = min((1, -1), key=lambda s: abs(self._with_sign(phi0, s)["C"] - hint))

    def _with_sign(self, phi, sign):
        A = self.OA * mpmath.expj(phi)
        AD = self.D - A
        d = abs(AD)
        angle_at_A = mpmath.acos((d**2 + self.AC**2 - self.DC**2) / (2 * d * self.AC))
        u3 = mpmath.expj(mpmath.arg(AD) + sign * angle_at_A)
        B, C = A + self.AB * u3, A + self.AC * u3
        u4 = (C - self.D) / abs(C - self.D)
        u5 = (self.E - B) / abs(self.E - B)
        return {"A": A, "B": B, "C": C, "M": B + self.BM * u5, "u3": u3, "u4": u4, "u5": u5, "s": abs(self.E - B)}

    def at(self, phi, key, t=0):
        return self._with_sign(phi + self.omega * t, self.sign)[key]

    def motion(self, phi, key):
        """(value, d/dt, d²/dt²) of a point or of the travel s."""
        f = lambda t: self.at(phi, key, t)  # noqa: E731
        return f(0), mpmath.diff(f, 0), mpmath.diff(f, 0, 2)

    def angular(self, phi, key):
        """(ω, ε) of the direction u(t): derivatives of arg(u(t)/u(0))."""
        u0 = self.at(phi, key)
        turned = lambda t: mpmath.arg(self.at(phi, key, t) / u0)  # noqa: E731
        return mpmath.diff(turned, 0), mpmath.diff(turned, 0, 2)


def test_six_bar_matches_a_50_digit_evaluation_of_its_loop_equations():
    scene = load(example_path("six-bar"))
    phis = np.linspace(0, 2 * np.pi, 16, endpoint=False) + 0.1
    solution = solve(scene, phis)
    reference = SixBar50(scene)
    worst = 0.0

    def check(got, want):
        nonlocal worst
        error = float(abs(mpmath.mpmathify(complex(got)) - want) / abs(want))
        worst = max(worst, error)
        assert error <= MPMATH_REL, (got, want, error)

    for k, phi in enumerate(phis):
        phi = mpmath.mpf(float(phi))
        for name in "ABCM":
            r, v, a = reference.motion(phi, name)
            point = solution.points[name]
            check(point.r[k], r)
            check(point.v[k], v)
            check(point.a[k], a)
        for link, key in (("3", "u3"), ("4", "u4"), ("5", "u5"), ("6", "u5")):
            omega, epsilon = reference.angular(phi, key)
            check(solution.links[link].omega[k], omega)
            check(solution.links[link].epsilon[k], epsilon)
        s, v_rel, a_rel = reference.motion(phi, "s")
        check(solution.sliders["E"].s[k], s)
        check(solution.sliders["E"].v_rel[k], v_rel)
        check(solution.sliders["E"].a_rel[k], a_rel)
    assert worst < MPMATH_REL


# --- every bundled example -----------------------------------------------------------


@pytest.mark.parametrize("name", example_names())
def test_every_bundled_example_solves_at_its_own_position(name):
    scene = load(example_path(name))
    solution = solve(scene)
    assert solution.valid.all()
    assert set(solution.points) == set(scene.point_names)
    assert set(solution.links) == set(scene.links)
    assert set(solution.sliders) == {pair.name for pair in scene.prismatics}
    for motion in solution.points.values():
        assert np.isfinite(motion.r).all() and np.isfinite(motion.v).all() and np.isfinite(motion.a).all()
