"""A solution's dicts of motions are made when first read: reading gives what an eagerly made solution holds.

The solver computes every number before it returns; ``links``, ``points``,
``sliders``, ``poses``, ``origins``, ``conditions``, ``sines`` and ``valid``
are made on first access (see ``plans.analytic.solution``).  These tests hold
that this is invisible: the same values in any order of reading, the same
objects on a second read, the sharing of arrays the eager result had, copies
with every attribute, and a solution that does not change when the solver is
called again.  One check of the values themselves uses only the mechanism's
geometry (|AB| is the coupler's length, B stays on its guide).
"""

from __future__ import annotations

import copy
import dataclasses
import numpy as np
import pytest

from plans.analytic import prepare, solve
from plans.analytic.solution import _ALL, AnalyticSolution
from plans.scene import example_path, load

SLIDER_CRANK = load(example_path("slider-crank"))


def test_the_attributes_a_deferred_solution_makes_are_the_dataclass_fields():
    assert _ALL == tuple(field.name for field in dataclasses.fields(AnalyticSolution))


@pytest.mark.parametrize("n", [1, 3, 360])
def test_any_order_of_reading_gives_the_same_values_and_objects(n):
    positions = np.radians(45) + np.linspace(0, 0.5, n)
    first = solve(SLIDER_CRANK, positions)
    second = solve(SLIDER_CRANK, positions)
    # read in opposite orders
    names = ["links", "points", "sliders", "poses", "origins", "conditions", "sines", "valid"]
    a = {name: getattr(first, name) for name in names}
    b = {name: getattr(second, name) for name in reversed(names)}
    for name in names:
        assert getattr(first, name) is a[name], name  # made once
        if name == "valid":
            assert (a[name] == b[name]).all()
            continue
        assert a[name].keys() == b[name].keys(), name
    for point, motion in first.points.items():
        for field in ("r", "v", "a"):
            x, y = getattr(motion, field), getattr(second.points[point], field)
            assert x.shape == (n,) and not x.flags.writeable
            assert np.array_equal(x, y)
    # the arrays the eager result shared are shared
    for body, (phi, origin) in first.poses.items():
        assert origin is first.origins[body].r
        if body in first.links:
            assert phi is first.links[body].phi


def test_a_solution_does_not_change_when_the_solver_is_called_again():
    solver = prepare(SLIDER_CRANK)
    early = solver(0.3)
    r_alone = solve(SLIDER_CRANK, 0.3).points["B"].r[0]
    for phi in (1.0, 2.0, np.linspace(0, 1, 50)):
        solver(phi).points["B"].r  # noqa: B018 - read another solution first
    assert early.points["B"].r[0] == r_alone
    assert early.driver[0] == 0.3


def test_B_is_on_its_guide_at_the_coupler_length_from_A():
    # independent check of what a first read gives: |AB| = coupler length, B on the guide y = const
    solution = solve(SLIDER_CRANK, [0.2, 1.1, 2.5])
    A, B = solution.points["A"].r, solution.points["B"].r
    lengths = np.abs(B - A)
    assert np.allclose(lengths, lengths[0], rtol=1e-14, atol=0)
    assert np.allclose(B.imag, B.imag[0], rtol=0, atol=1e-15)


@pytest.mark.parametrize("n", [1, 360])
def test_copies_hold_every_attribute(n):
    solution = solve(SLIDER_CRANK, np.linspace(0.1, 0.2, n))
    for copied in (copy.copy(solution), copy.deepcopy(solution)):
        assert set(vars(copied)) == set(_ALL)
        assert np.array_equal(copied.points["B"].v, solution.points["B"].v)
        assert len(copied) == n


def test_an_attribute_that_does_not_exist_is_an_attribute_error():
    solution = solve(SLIDER_CRANK)
    with pytest.raises(AttributeError, match="no attribute 'point'"):
        solution.point  # noqa: B018
    assert not hasattr(solution, "__setstate__")
    assert "points=" in repr(solution)
