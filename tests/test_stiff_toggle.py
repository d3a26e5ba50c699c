"""Stiff sequences: a four-bar driven towards its limit position, 1e-2 … 1e-9 rad away.

The crank-rocker O(0,0)–A (0.1 m), coupler AB 0.45 m, rocker DB 0.2 m about
D = (0.7, 0) assembles while |AD| < AB + BD = 0.65 m, i.e. up to the crank
angle φ* = acos((0.7² + 0.1² − 0.65²)/(2·0.7·0.1)) ≈ 56.39°, where coupler and
rocker line up: the RRR(3,4) group reaches its dead centre.  Approaching it,
the sine between the construction lines falls like √δ and the condition
number grows like 1/√δ.

The reference is an independent 50-digit mpmath evaluation: the rocker angle
from the law of cosines in triangle ADB, the rates from the loop equation
differentiated once and twice, solved with mpmath's own linear solver.

Asserted at every step: the solution exists (the refuse threshold is below
what 1e-9 rad gives), it carries a warning exactly when the condition exceeds
the warning threshold, the condition grows step by step, and every result
agrees with the reference within ERROR_MARGIN × the expected relative error
the program states (4·ε_mach·cond², plans.limits).  Measured (see the report
of issue 4): the error of v, a, ω, ε is 0.8 … 5 × ε_mach·cond².
"""

import math

import mpmath as mp
import numpy as np
import pytest

from plans.analytic import solve
from plans.cli import main
from plans.errors import SingularPositionError
from plans.graphical import construct
from plans.limits import EPS, ERROR_MARGIN, REFUSE_SINE, WARN_CONDITION, expected_rel_error
from plans.scene import loads

GROUP = "RRR(3,4)"
R2, L3, L4, XD = "0.1", "0.45", "0.2", "0.7"
OMEGA, EPSILON = "10", "5"
DISTANCES = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9]


def scene_text(l3=L3, angle="0.0", extra=""):
    return f"""
title = "crank-rocker near its limit"
[frame]
points = {{ O = [0, 0], D = [{XD}, 0] }}
[link.2]
points = {{ O = [0, 0], A = [{R2}, 0] }}
[link.3]
points = {{ A = [0, 0], B = [{l3}, 0] }}
[link.4]
points = {{ D = [0, 0], B = [{L4}, 0] }}
[driver]
crank = "2"
angle = "{angle} rad"
omega = {OMEGA}
epsilon = {EPSILON}
[assembly]
B = 1
{extra}
"""


def limit_angle():
    mp.mp.dps = 50
    r, d, s = mp.mpf(R2), mp.mpf(XD), mp.mpf(L3) + mp.mpf(L4)
    return mp.acos((d**2 + r**2 - s**2) / (2 * d * r))


def reference(phi: float):
    """B, v_B, a_B, ω3, ω4, ε3, ε4 at the crank angle phi (a double, taken exactly), 50 digits."""
    mp.mp.dps = 50
    r2, l3, l4, xd = mp.mpf(R2), mp.mpf(L3), mp.mpf(L4), mp.mpf(XD)
    w2, e2 = mp.mpf(OMEGA), mp.mpf(EPSILON)
    phi = mp.mpf(phi)
    A = r2 * mp.expj(phi)
    D = mp.mpc(xd, 0)
    d = abs(A - D)
    gamma = mp.acos((l4**2 + d**2 - l3**2) / (2 * l4 * d))  # angle ADB
    base = mp.arg(A - D)
    for theta4 in (base + gamma, base - gamma):
        B = D + l4 * mp.expj(theta4)
        if mp.im(mp.conj(D - A) * (B - A)) > 0:  # branch +1: B left of the line A → D
            break
    theta3 = mp.arg(B - A)
    # loop r2 e^{iφ} + l3 e^{iθ3} = xd + l4 e^{iθ4}, differentiated: unknowns (ω3, ω4), then (ε3, ε4)
    M = mp.matrix([[-l3 * mp.sin(theta3), l4 * mp.sin(theta4)], [l3 * mp.cos(theta3), -l4 * mp.cos(theta4)]])
    rhs = r2 * w2 * mp.matrix([mp.sin(phi), -mp.cos(phi)])
    w3, w4 = mp.lu_solve(M, rhs)
    known = (
        r2 * e2 * mp.expj(phi) * 1j
        - r2 * w2**2 * mp.expj(phi)
        - l3 * w3**2 * mp.expj(theta3)
        + l4 * w4**2 * mp.expj(theta4)
    )  # i·l3·ε3·e^{iθ3} − i·l4·ε4·e^{iθ4} = −known
    e3, e4 = mp.lu_solve(M, mp.matrix([-mp.re(known), -mp.im(known)]))
    vB = 1j * w2 * A + 1j * w3 * (B - A)
    aB = (1j * e2 - w2**2) * A + (1j * e3 - w3**2) * (B - A)
    return {"B.r": B, "B.v": vB, "B.a": aB, "3.omega": w3, "4.omega": w4, "3.epsilon": e3, "4.epsilon": e4}


def rel_error(got, want) -> float:
    return float(abs(mp.mpc(complex(got)) - want) / abs(want))


def measured(values: dict, ref: dict) -> dict:
    return {key: rel_error(values[key], ref[key]) for key in ref}


def analytic_values(solution, k=0):
    return {
        "B.r": solution.points["B"].r[k],
        "B.v": solution.points["B"].v[k],
        "B.a": solution.points["B"].a[k],
        "3.omega": solution.links["3"].omega[k],
        "4.omega": solution.links["4"].omega[k],
        "3.epsilon": solution.links["3"].epsilon[k],
        "4.epsilon": solution.links["4"].epsilon[k],
    }


def graphical_values(g):
    return {
        "B.r": g.positions["B"],
        "B.v": g.points["B"]["v"],
        "B.a": g.points["B"]["a"],
        "3.omega": g.links["3"]["omega"],
        "4.omega": g.links["4"]["omega"],
        "3.epsilon": g.links["3"]["epsilon"],
        "4.epsilon": g.links["4"]["epsilon"],
    }


@pytest.fixture(scope="module")
def sequence():
    """Crank angles 1e-2 … 1e-9 rad before the limit, solved in one vectorised call, with their references."""
    star = limit_angle()
    phis = [float(star - mp.mpf(delta)) for delta in DISTANCES]
    scene = loads(scene_text())
    solution = solve(scene, phis)
    return scene, phis, solution, [reference(phi) for phi in phis]


def test_every_step_is_solved_and_the_condition_grows(sequence):
    _, phis, solution, _ = sequence
    assert solution.valid.all()
    condition = np.asarray(solution.conditions[GROUP])
    sine = np.asarray(solution.sines[GROUP])
    assert np.all(np.diff(condition) > 0) and np.all(np.diff(sine) < 0)
    # the sine falls like √δ: a factor √10 per decade
    assert np.allclose(sine[:-1] / sine[1:], math.sqrt(10), rtol=0.01)
    assert sine[-1] > 100 * REFUSE_SINE  # 1e-9 rad from the limit is still far from the refuse threshold


def test_the_error_stays_within_the_stated_bound_at_every_step(sequence):
    _, phis, solution, refs = sequence
    worst = []
    for k, ref in enumerate(refs):
        condition = float(solution.conditions[GROUP][k])
        bound = ERROR_MARGIN * expected_rel_error(condition)
        errors = measured(analytic_values(solution, k), ref)
        for key, error in errors.items():
            assert error <= bound, (DISTANCES[k], key, error, bound)
        worst.append(max(errors.values()))
    # the error grows as the condition does: by orders of magnitude over the sequence
    assert max(worst[-2:]) > 1e4 * max(worst[:2])
    # and positions stay near ε_mach·cond (they are not divided by the sine)
    for k, ref in enumerate(refs):
        assert rel_error(solution.points["B"].r[k], ref["B.r"]) <= ERROR_MARGIN * EPS * solution.conditions[GROUP][k]


def test_a_warning_names_group_joint_and_position_exactly_when_the_condition_is_high(sequence):
    scene, phis, solution, _ = sequence
    for k, phi in enumerate(phis):
        single = solve(scene, phi)
        condition = float(single.conditions[GROUP][0])
        if condition > WARN_CONDITION:
            (warning,) = single.warnings
            assert (warning.group, warning.joint, warning.position) == (GROUP, "B", phi)
            assert warning.condition == condition and warning.expected_rel_error == pytest.approx(expected_rel_error(condition))
            assert str(warning).startswith(f"{GROUP} near a dead centre at φ = {math.degrees(phi):.9g}°: joint B, condition ")
        else:
            assert single.warnings == ()
    # one warning for the whole run of near-singular positions, at the worst of them
    (warning,) = solution.warnings
    assert warning.position == phis[-1]
    assert solve(scene, phis, warn_condition=math.inf).warnings == ()


@pytest.mark.parametrize("k", [0, 3, 5, 7])
def test_the_graphical_plans_meet_the_same_bound(sequence, k):
    scene, phis, solution, refs = sequence
    g = construct(loads(scene_text(angle=repr(phis[k]))))
    condition = g.conditions[GROUP]
    assert condition == pytest.approx(float(solution.conditions[GROUP][k]), rel=1e-3)
    assert g.sines[GROUP] == pytest.approx(float(solution.sines[GROUP][k]), rel=1e-3)
    bound = ERROR_MARGIN * expected_rel_error(condition)
    for key, error in measured(graphical_values(g), refs[k]).items():
        assert error <= bound, (DISTANCES[k], key, error, bound)
    assert bool(g.warnings) == (condition > WARN_CONDITION)


# --- exactly at a dead centre: both methods refuse, by the same threshold -------------------------

#: a four-bar whose dead centre is crossed, not a limit: |AD| reaches AB + BD = 0.8 m at φ = 180° only
FLAT = "0.6"


@pytest.mark.parametrize("delta, refused", [(0.0, True), (1e-9, True), (3e-8, True), (1e-6, False), (1e-4, False)])
def test_both_methods_refuse_exactly_the_positions_below_the_threshold(delta, refused):
    scene = loads(scene_text(l3=FLAT, angle=repr(math.pi - delta)))
    analytic = solve(scene, allow_partial=True)
    assert (not analytic.valid[0]) == refused
    if refused:
        with pytest.raises(SingularPositionError, match=r"^RRR\(3,4\): dead centre at φ = (180\.0|179\.99999\d*)°: A, B and D are in line"):
            solve(scene)
        with pytest.raises(SingularPositionError, match=r"^RRR\(3,4\): the construction lines .* are parallel"):
            construct(scene)
    else:
        g = construct(scene)
        assert g.sines[GROUP] >= REFUSE_SINE and float(analytic.sines[GROUP][0]) >= REFUSE_SINE
        assert g.warnings and analytic.warnings


# --- the command line -----------------------------------------------------------------------------


def test_the_cli_prints_the_warning_on_stderr_and_in_json(tmp_path, capsys):
    phi = float(limit_angle() - mp.mpf("1e-9"))
    path = tmp_path / "toggle.toml"
    path.write_text(scene_text())
    status = main(["solve", str(path), "--at", f"{phi!r} rad", "--json"])
    out, err = capsys.readouterr()
    assert status == 0
    lines = err.splitlines()
    assert len(lines) == 1  # analytic and graphical agree: one warning per group
    assert lines[0].startswith("plans: warning: RRR(3,4) near a dead centre at φ = 56.3876253°: joint B, condition 5.6e+04, expected relative error ≈ 3e-06")
    assert lines[0] == "plans: warning: RRR(3,4) near a dead centre at φ = 56.3876253°: joint B, condition 5.6e+04, expected relative error ≈ 3e-06"
    import json

    doc = json.loads(out)
    group = doc["groups"][GROUP]
    assert group["condition"] == pytest.approx(5.5567e4, rel=1e-3)
    assert group["expected_rel_error"] == pytest.approx(expected_rel_error(group["condition"]))
    assert group["sine"] == pytest.approx(3.5993e-5, rel=1e-3) and group["joint"] == "B"
    assert {w["method"] for w in doc["warnings"]} == {"analytic", "graphical"}
    assert all(w["group"] == GROUP and w["joint"] == "B" for w in doc["warnings"])
    # a higher threshold silences it
    assert main(["solve", str(path), "--at", f"{phi!r} rad", "--warn-condition", "1e6"]) == 0
    out, err = capsys.readouterr()
    assert err == "" and "expected rel. error" in out


def test_the_cli_refuses_a_dead_centre_with_one_line(tmp_path, capsys):
    path = tmp_path / "flat.toml"
    path.write_text(scene_text(l3=FLAT, angle=repr(math.pi)))
    assert main(["solve", str(path)]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith(f"plans: error: {path}: RRR(3,4): dead centre at φ = 180.0°: A, B and D are in line")
    assert f"below the dead-centre threshold {REFUSE_SINE:g}" in err
