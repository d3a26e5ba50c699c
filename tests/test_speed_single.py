"""The prepared solver and its path for a few positions (plain complex arithmetic) give the vectorised numbers.

``plans.analytic.single`` solves each dyad with Python complex numbers; the
vectorised path (numpy over the positions) is forced with ``FEW = 0``.  The
two compute the same loop equations in the same steps, so they agree to
round-off of each quantity's scale; a test of every bundled example and of
seeded random mechanisms of every dyad kind (turning and offset guides, ε ≠ 0).
"""

from __future__ import annotations

import cmath
import dataclasses
import math

import numpy as np
import pytest

import plans
from plans.analytic import single, solve, solver
from plans.errors import AssemblyError, SingularPositionError
from plans.scene import Crank, example_names, example_path, load, loads

#: agreement of the two paths, relative to the largest magnitude of each quantity
REL = 1e-13
#: quantities of one kind share a scale
KIND = {"r": "length", "origin": "length", "s": "length", "v": "velocity", "v_rel": "velocity", "a": "acceleration",
        "a_rel": "acceleration", "coriolis": "acceleration", "phi": "phi", "omega": "omega", "epsilon": "epsilon"}


def _quantities(solution):
    out = {"driver": solution.driver, "valid": solution.valid}
    for kind in ("links", "points", "sliders", "origins"):
        for name, motion in getattr(solution, kind).items():
            for field in dataclasses.fields(motion):
                out[f"{kind}.{name}.{field.name}"] = getattr(motion, field.name)
    for name, (phi, origin) in solution.poses.items():
        out[f"poses.{name}.phi"] = phi
        out[f"poses.{name}.origin"] = origin
    out.update({f"conditions.{k}": v for k, v in solution.conditions.items()})
    out.update({f"sines.{k}": v for k, v in solution.sines.items()})
    return out


def _count_single_calls(monkeypatch) -> list[str]:
    calls: list[str] = []
    for kind, function in list(single.SOLVERS.items()):
        def counted(*args, _function=function, _kind=kind, **kwargs):
            calls.append(_kind)
            return _function(*args, **kwargs)

        monkeypatch.setitem(single.SOLVERS, kind, counted)
    return calls


def _agree(scene, positions, monkeypatch) -> None:
    calls = _count_single_calls(monkeypatch)
    few = solve(scene, positions)
    assert len(calls) == len(few.structure.groups) * len(np.atleast_1d(positions)), "the few-positions path was not taken"
    monkeypatch.setattr(solver, "FEW", 0)
    vectorised = solve(scene, positions)
    monkeypatch.undo()
    a, b = _quantities(few), _quantities(vectorised)
    assert a.keys() == b.keys()
    # the scale of each kind of quantity over the whole mechanism (round-off is relative to it); angles in rad
    scales: dict[str, float] = {"phi": 1.0}
    for key, value in b.items():
        if value.dtype != bool:
            kind = KIND.get(key.rsplit(".", 1)[-1], key)
            scales[kind] = max(scales.get(kind, 0.0), float(np.abs(value).max()))
    for key in a:
        assert a[key].dtype == b[key].dtype, key
        assert a[key].shape == b[key].shape == (len(np.atleast_1d(positions)),), key
        assert not a[key].flags.writeable, key
        if a[key].dtype == bool:
            assert (a[key] == b[key]).all(), key
            continue
        scale = scales[KIND.get(key.rsplit(".", 1)[-1], key)]
        assert np.abs(a[key] - b[key]).max() <= REL * scale, (key, a[key], b[key])
    assert [str(w) for w in few.warnings] == [str(w) for w in vectorised.warnings]


def _positions(scene, rng, count):
    driver = scene.driver
    if isinstance(driver, Crank):
        return driver.phi + rng.uniform(-0.3, 0.3, count)
    return driver.s + rng.uniform(-1e-3, 1e-3, count)


@pytest.mark.parametrize("name", example_names())
def test_every_example_at_one_and_at_a_few_positions(name, monkeypatch):
    scene = load(example_path(name))
    rng = np.random.default_rng(14)
    _agree(scene, None, monkeypatch)
    _agree(scene, _positions(scene, rng, 1), monkeypatch)
    _agree(scene, _positions(scene, rng, solver.FEW), monkeypatch)
    turned = dataclasses.replace(scene, driver=dataclasses.replace(scene.driver, **(
        {"omega": -37.5, "epsilon": 1234.5} if isinstance(scene.driver, Crank) else {"velocity": -0.7, "acceleration": 3.25})))
    _agree(turned, None, monkeypatch)


# --- seeded random mechanisms of every kind ---------------------------------------------------


def _xy(z: complex) -> str:
    return f"[{z.real!r}, {z.imag!r}]"


def _crank(rng) -> tuple[str, complex]:
    r, phi = rng.uniform(0.05, 0.3), rng.uniform(-math.pi, math.pi)
    text = f"""
[link.2]
points = {{ O = [0, 0], A = [{r!r}, 0] }}
lines = {{ rod = {{ through = "O", angle = "{rng.uniform(-90, 90)!r} deg" }} }}
[driver]
crank = "2"
angle = "{math.degrees(phi)!r} deg"
omega = {rng.uniform(-50, 50)!r}
epsilon = {rng.uniform(-500, 500)!r}
"""
    return text, r * cmath.exp(1j * phi)


def _rrr(rng):
    crank, A = _crank(rng)
    C = A + 0.6 * cmath.exp(1j * rng.uniform(0, 2 * math.pi))
    D = C + 0.5 * cmath.exp(1j * rng.uniform(0, 2 * math.pi))
    return crank + f"""
[frame]
points = {{ O = [0, 0], D = {_xy(D)} }}
[link.3]
points = {{ A = [0, 0], C = [{abs(C - A)!r}, 0], M = [0.1, 0.05] }}
[link.4]
points = {{ D = [0, 0], C = [{abs(C - D)!r}, 0] }}
[assembly]
C = {_xy(C)}
"""


def _rrp_on_the_turning_crank(rng):
    # link 3 pinned at a frame point B, its end C pinned to a block sliding on the crank's rod (Coriolis)
    crank, A = _crank(rng)
    B = complex(rng.uniform(0.3, 0.5), rng.uniform(-0.2, 0.2))
    length = abs(B) + rng.uniform(-0.1, 0.2)
    return crank + f"""
[frame]
points = {{ O = [0, 0], B = {_xy(B)} }}
[link.3]
points = {{ B = [0, 0], C = [{length!r}, 0] }}
[[slider]]
pin = "C"
on = "2.rod"
name = "4"
[assembly]
C = {rng.choice([-1, 1])}
"""


def _prp(rng):
    # a block on the crank's rod pinned at C to a block on a fixed guide
    crank, A = _crank(rng)
    angle = rng.uniform(30, 150)
    return crank + f"""
[frame]
points = {{ O = [0, 0], G = [0.2, -0.1] }}
lines = {{ guide = {{ through = "G", angle = "{angle!r} deg" }} }}
[[slider]]
pin = "C"
on = "2.rod"
name = "3"
[[slider]]
pin = "C"
on = "frame.guide"
name = "4"
"""


RANDOM = {"RRR": _rrr, "RRP": _rrp_on_the_turning_crank, "PRP": _prp}


@pytest.mark.parametrize("kind", sorted(RANDOM))
def test_seeded_random_mechanisms(kind, monkeypatch):
    rng = np.random.default_rng(1400 + len(kind) + ord(kind[1]))
    solved = 0
    for _ in range(60):
        try:
            scene = loads(RANDOM[kind](rng))
            here = solve(scene)
        except (AssemblyError, SingularPositionError):
            continue  # this draw does not assemble at its own position: another one
        if max(float(c.max()) for c in here.conditions.values()) > 10:
            continue  # near a dead centre round-off grows like cond²: compared in tests/test_stiff_*.py
        assert plans.find_structure(scene).groups[0].kind == kind
        _agree(scene, None, monkeypatch)
        nearby = scene.driver.phi + rng.uniform(-0.01, 0.01, 3)
        around = solve(scene, nearby, allow_partial=True)
        if around.valid.all() and max(float(c.max()) for c in around.conditions.values()) <= 10:
            _agree(scene, nearby, monkeypatch)
        solved += 1
        if solved == 12:
            break
    assert solved >= 8


# --- the prepared solver -------------------------------------------------------------------------


def test_prepare_is_solve_made_once():
    scene = load(example_path("six-bar"))
    prepared = plans.prepare(scene)
    assert prepared.scene is scene
    x = np.array([0.3, 1.1, 2.0])
    a, b = prepared(x), solve(scene, x)
    for key, value in _quantities(a).items():
        assert np.array_equal(value, _quantities(b)[key]), key
    assert len(prepared(np.linspace(0, 1, 1000))) == 1000


def test_a_position_that_is_not_ordinary_is_reported_as_by_the_vectorised_path(monkeypatch):
    # the four-bar's crank cannot reach every angle: the single path gives up, the vectorised one names the group
    scene = load(example_path("rocker-limit"))
    turn = solve(scene, np.linspace(0, 2 * np.pi, 72, endpoint=False), allow_partial=True)
    bad = float(turn.driver[np.argmin(turn.valid)])
    assert not turn.valid.all()
    with pytest.raises(AssemblyError, match="cannot assemble"):
        solve(scene, bad)
    partial = solve(scene, [bad, float(scene.driver.phi)], allow_partial=True)
    assert partial.valid.tolist() == [False, True]
    assert math.isnan(partial.points["B"].r[0].real) if "B" in partial.points else True


def test_near_a_dead_centre_the_two_paths_agree_within_the_expected_error(monkeypatch):
    # rocker-limit at 56.3876°: condition 2.6e3, both paths round differently; they agree within what each may be off
    from plans.limits import ERROR_MARGIN

    scene = load(example_path("rocker-limit"))
    x = [math.radians(56.3876), math.radians(56.38)]
    few = solve(scene, x)
    monkeypatch.setattr(solver, "FEW", 0)
    vectorised = solve(scene, x)
    assert [str(w) for w in few.warnings] == [str(w) for w in vectorised.warnings] != []
    (group,) = few.conditions
    bound = ERROR_MARGIN * few.expected_rel_errors(group)
    for name in ("3", "4"):
        for field in ("omega", "epsilon"):
            a, b = getattr(few.links[name], field), getattr(vectorised.links[name], field)
            assert (np.abs(a - b) <= bound * np.abs(b).max()).all(), (name, field)
