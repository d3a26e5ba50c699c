"""The expected error of a chain of groups (issue 12), against a 50-digit reference.

A non-Grashof four-bar (crank 100 mm, coupler 450 mm, rocker 200 mm, frame
700 mm: the crank cannot turn fully, its RRR stretches at a limit position)
drives an RRP: a rod from a point E of the rocker to a ram on a horizontal
guide.  Approaching the limit position the RRR's condition grows without
bound while the RRP's stays about 6.  The RRP's own figure, 4·ε·cond²,
stays ~3e-14; its points inherit the four-bar's error.  The chain's figure
must cover that.  The reference is :func:`plans.bench.reference.reference`
(Cartesian constraints solved at 50 digits with mpmath, nothing of the
analytic solver's loop formulas).
"""

from __future__ import annotations

import math

import mpmath
import pytest

from plans.analytic import solve
from plans.bench.reference import reference
from plans.limits import ERROR_MARGIN, chain_rel_error, expected_rel_error
from plans.scene import loads

SCENE = """
[frame]
points = { O = [0, 0], D = ["700 mm", 0] }
lines = { ram = { through = [0, "300 mm"], angle = 0 } }
[link.2]
points = { O = [0, 0], A = ["100 mm", 0] }
[link.3]
points = { A = [0, 0], B = ["450 mm", 0] }
[link.4]
points = { D = [0, 0], B = ["200 mm", 0], E = ["150 mm", "60 mm"] }
[link.5]
points = { E = [0, 0], F = ["400 mm", 0] }
[[slider]]
pin = "F"
on = "frame.ram"
name = "6"
[driver]
crank = "2"
angle = "30 deg"
omega = "10 rad/s"
epsilon = "5 rad/s^2"
[assembly]
B = [0.55, 0.15]
F = [0.8, 0.3]
"""


def _limit(scene) -> tuple[float, float]:
    """(a crank angle just inside the assembled range, the direction towards the limit position) by bisection."""
    def solved(x):
        return bool(solve(scene, [x], allow_partial=True).valid[0])

    good, bad = math.radians(303.6), math.radians(303.8)
    if not solved(good):
        good, bad = bad, good
    assert solved(good) and not solved(bad)
    for _ in range(60):
        middle = (good + bad) / 2
        good, bad = (middle, bad) if solved(middle) else (good, middle)
    return good, math.copysign(1.0, good - bad)


def _errors(scene, solution, points) -> tuple[float, float]:
    """Largest error of v and of a over *points*, relative to the largest reference |v|, |a| over them."""
    seed = {name: (float(phi[0]), complex(origin[0])) for name, (phi, origin) in solution.poses.items()}
    ref = reference(scene, float(solution.driver[0]), seed)
    out = []
    with mpmath.workdps(50):
        for kind, field in ((1, "v"), (2, "a")):
            scale = max(abs(ref.points[name][kind]) for name in points)
            worst = max(abs(mpmath.mpc(complex(getattr(solution.points[name], field)[0])) - ref.points[name][kind]) for name in points)
            out.append(float(worst / scale))
    return tuple(out)


def test_a_well_conditioned_group_after_a_stiff_one_is_covered_by_the_chain_figure():
    scene = loads(SCENE)
    limit, inside = _limit(scene)
    rrr, rrp = (group.name for group in solve(scene).structure.groups)
    beyond_own = 0
    for distance in (1e-2, 1e-4, 1e-6, 1e-8):
        solution = solve(scene, limit + inside * distance, warn_condition=math.inf)
        c_rrr, c_rrp = float(solution.conditions[rrr][0]), float(solution.conditions[rrp][0])
        assert 4 < c_rrp < 8  # the RRP stays well conditioned
        err_v, err_a = _errors(scene, solution, ["F"])  # F: the RRP's own joint on the ram
        own = float(solution.expected_rel_errors(rrp)[0])
        chain = float(solution.expected_chain_rel_errors(rrp)[0])
        # the chain figure, typed from its formula: the RRR takes nothing from other groups
        assert chain == pytest.approx(chain_rel_error(c_rrp, expected_rel_error(c_rrr)), rel=1e-12)
        assert float(solution.expected_chain_rel_errors(rrr)[0]) == pytest.approx(expected_rel_error(c_rrr), rel=1e-12)
        assert max(err_v, err_a) <= ERROR_MARGIN * chain, (distance, err_v, err_a, chain)
        beyond_own += max(err_v, err_a) > ERROR_MARGIN * own
    # the group's own figure alone does not cover its points near the four-bar's limit position
    assert beyond_own >= 2
