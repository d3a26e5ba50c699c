"""The analytic solver's fast paths give what the plain path gives.

* a long sweep is solved in pieces of ``CHUNK`` positions: the same numbers,
  NaN where the same, the same error for the same first failing position;
* what does not depend on the positions (branch signs, the result's layout)
  is kept per scene: another scene, or another hint, is not served stale;
* near-dead-centre warnings, found without a loop over the positions, are
  one per run of consecutive positions, at the worst.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from plans.analytic import solve, solver
from plans.bench.cases import TOGGLE_ANGLE, toggle_four_bar_scene
from plans.errors import AssemblyError, PlansError
from plans.scene import example_names, example_path, load


def _sweep(scene, n, wide=False):
    driver = scene.driver
    if hasattr(driver, "phi"):
        return driver.phi + np.linspace(0, 2 * np.pi, n, endpoint=False)
    a, b = driver.stroke or (driver.s - 0.05, driver.s + 0.05)
    if wide:  # beyond the stroke: some positions do not assemble
        a, b = 3 * a - 2 * b, 3 * b - 2 * a
    return np.linspace(a, b, n)


def _arrays(solution):
    out = {"driver": solution.driver, "valid": solution.valid}
    for kind in ("links", "points", "sliders", "origins"):
        for name, motion in getattr(solution, kind).items():
            for field in dataclasses.fields(motion):
                out[f"{kind}.{name}.{field.name}"] = getattr(motion, field.name)
    for name, (phi, origin) in solution.poses.items():
        out[f"poses.{name}"] = phi
        out[f"poses.{name}.origin"] = origin
    out.update({f"conditions.{k}": v for k, v in solution.conditions.items()})
    out.update({f"sines.{k}": v for k, v in solution.sines.items()})
    return out


@pytest.mark.parametrize("name", example_names())
def test_pieces_give_the_numbers_of_one_piece(name, monkeypatch):
    scene = load(example_path(name))
    positions = _sweep(scene, 3 * solver.CHUNK + 17, wide=True)
    pieces = solve(scene, positions, allow_partial=True)
    monkeypatch.setattr(solver, "CHUNK", 10**9)
    whole = solve(scene, positions, allow_partial=True)
    a, b = _arrays(pieces), _arrays(whole)
    assert a.keys() == b.keys()
    for key in a:
        assert a[key].shape == (len(positions),), key
        assert a[key].dtype == b[key].dtype, key
        assert not a[key].flags.writeable, key
        np.testing.assert_array_equal(a[key], b[key], err_msg=key)
    assert pieces.warnings == whole.warnings


@pytest.mark.parametrize("name", ["ladder", "linear-arm", "four-bar-toggle"])
def test_pieces_raise_the_error_of_one_piece(name, monkeypatch):
    scene = toggle_four_bar_scene() if name == "four-bar-toggle" else load(example_path(name))
    positions = _sweep(scene, 3 * solver.CHUNK + 17, wide=True)
    with pytest.raises(PlansError) as pieces:
        solve(scene, positions)
    monkeypatch.setattr(solver, "CHUNK", 10**9)
    with pytest.raises(PlansError) as whole:
        solve(scene, positions)
    assert type(pieces.value) is type(whole.value)
    assert str(pieces.value) == str(whole.value)
    assert pieces.value.position == whole.value.position


def test_a_new_hint_is_not_served_the_kept_branch():
    scene = load(example_path("four-bar"))
    point = next(iter(scene.assembly))
    first = solve(scene, [0.3, 0.4])
    up = solve(dataclasses.replace(scene, assembly={point: 1}), [0.3, 0.4])
    down = solve(dataclasses.replace(scene, assembly={point: -1}), [0.3, 0.4])
    # the two signs give the two branches; the scene's own hint chooses one of them
    assert not np.allclose(up.points[point].r, down.points[point].r)
    assert np.allclose(first.points[point].r, up.points[point].r) != np.allclose(first.points[point].r, down.points[point].r)
    # and the plan kept for the first scene still serves it
    np.testing.assert_array_equal(solve(scene, [0.3, 0.4]).points[point].r, first.points[point].r)


def test_kept_structure_and_a_given_one_agree():
    scene = load(example_path("six-bar"))
    from plans.structure import find_structure

    a = solve(scene, [0.1, 0.2])
    b = solve(scene, [0.1, 0.2], find_structure(scene))
    assert a.structure == b.structure
    np.testing.assert_array_equal(a.points["M"].a, b.points["M"].a)


def test_an_unresolvable_hint_raises_in_its_place_every_time():
    scene = toggle_four_bar_scene()
    beyond = dataclasses.replace(
        scene, driver=dataclasses.replace(scene.driver, phi=TOGGLE_ANGLE + 0.3), assembly={"C": 0.1 + 0.2j}
    )
    for _ in range(2):  # the second call uses the kept plan
        with pytest.raises(AssemblyError, match="chooses the branch"):
            solve(beyond, [0.0, 0.1])
        with pytest.raises(AssemblyError) as here:
            solve(beyond)
        assert "chooses the branch" not in str(here.value)


def _warnings_by_loop(solution, warn_condition):
    """The warnings as the solver found them before: a loop over the positions."""
    out = []
    for group, condition in solution.conditions.items():
        near = np.asarray(solution.valid) & (np.asarray(condition) > warn_condition)
        k = 0
        while k < len(near):
            if not near[k]:
                k += 1
                continue
            end = k
            while end < len(near) and near[end]:
                end += 1
            worst = k + int(np.argmax(condition[k:end]))
            out.append((group, float(solution.driver[worst]), float(condition[worst])))
            k = end
    return out


@pytest.mark.parametrize("warn_condition", [1.5, 3.0, 100.0, math.inf])
def test_warnings_are_one_per_run_at_the_worst(warn_condition):
    scene = toggle_four_bar_scene()
    up = np.linspace(0.0, TOGGLE_ANGLE + 0.05, 300)  # to the toggle and past it (not assembled there)
    positions = np.concatenate([up, np.linspace(-1.0, 0.0, 20), up])
    solution = solve(scene, positions, allow_partial=True, warn_condition=warn_condition)
    found = [(w.group, w.position, w.condition) for w in solution.warnings]
    assert found == _warnings_by_loop(solution, warn_condition)
    if warn_condition < 10:
        assert len(found) >= 2  # a run at least per approach to the toggle
