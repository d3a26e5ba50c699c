"""Every rate column of a cycle's sweep CSV is the time derivative of the column it rates (issue 19 §1–§2).

For every bundled example and each law it can follow over its cycle, a fine
cycle is written as CSV (plans.sweep.sweep_csv with the cycle's time column
``t``) and read back by column name: ε = dω/dt, v = dr/dt, a = dv/dt,
vʳ = ds/dt, aʳ = dvʳ/dt are checked by central differences in t (np.gradient,
second order on the uneven steps of a uniformly accelerated driver), away
from dead centres.  A wrong column, unit or law fails here: the scene's ω and
ε held at every position (the old sweep) gives dω/dt = 0 ≠ ε.
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import replace

import numpy as np
import pytest

import plans
from plans.motion import driver_cycle
from plans.scene import Crank, example_names
from plans.sweep import sweep_csv

#: Positions of the fine cycle.
STEPS = 4000
#: A row is checked when every group's |sin| there is at least this (away from dead centres) and its neighbours are solved.
AWAY = 0.05
#: Central differences are O(h²): relative to the column's scale at most 1.2e-4 at this step (the wedge, uniform law), most below 1e-5.
TOLERANCE = 5e-4


def _scene(name: str, law: str):
    scene = plans.load(plans.example_path(name))
    d = scene.driver
    if law == "uniform":  # an acceleration that the cycle can cover (ω² stays positive over the range asked for)
        if isinstance(d, Crank):
            scene = replace(scene, driver=replace(d, epsilon=d.omega * abs(d.omega) / (10 * math.pi), law="uniform"))
        else:
            span = abs(d.stroke[1] - d.stroke[0]) + abs(d.s)
            scene = replace(scene, driver=replace(d, acceleration=d.velocity * abs(d.velocity) / (4 * span), law="uniform"))
    return scene


def _cases():
    out = []
    for name in example_names():
        if name == "rocker-limit":
            out.append((name, "harmonic"))
            continue
        out += [(name, "constant"), (name, "uniform")]
    return out


def _read(text: str) -> dict[str, np.ndarray]:
    rows = list(csv.DictReader(io.StringIO(text)))
    return {key: np.array([float(r[key]) if r[key] != "" else np.nan for r in rows]) for key in rows[0]}


def _check(name: str, t, y, dy, rows, what: str) -> None:
    slope = np.gradient(y, t)
    # the column's scale; a rate that is 0 everywhere (a constant ω) against the rated column's size per cycle time
    scale = max(np.nanmax(np.abs(dy[rows])), np.nanmax(np.abs(slope[rows])), np.nanmax(np.abs(y[rows])) / t[-1], 1e-9)
    error = np.nanmax(np.abs(slope[rows] - dy[rows])) / scale
    assert error < TOLERANCE, f"{name}: {what}: max |d/dt − column| / scale = {error:.2e}"


@pytest.mark.parametrize("name,law", _cases())
def test_rates_are_time_derivatives(name, law):
    scene = _scene(name, law)
    cycle = driver_cycle(scene, STEPS)
    assert cycle.law.kind == law
    analytic = cycle.solve()
    data = _read(sweep_csv(analytic, cycle.t))
    t = data["t"]
    assert t[0] == 0 and np.all(np.diff(t) > 0), "t [s] runs from 0 at the first row, increasing"
    ok = data["assembled"] == 1
    for group in analytic.structure.groups:
        ok &= np.nan_to_num(data[f"{group.name}.sine"]) >= AWAY
    rows = ok.copy()
    rows[1:-1] &= ok[:-2] & ok[2:]
    rows[0] = rows[-1] = False
    assert rows.sum() > STEPS // 3, f"{name}: too few rows away from dead centres"
    for link in scene.links:
        if f"{link}.phi_deg" not in data:
            continue
        phi = np.unwrap(np.radians(data[f"{link}.phi_deg"]))
        _check(name, t, phi, data[f"{link}.omega"], rows, f"ω{link} = dφ/dt")
        if f"{link}.epsilon" in data:
            _check(name, t, data[f"{link}.omega"], data[f"{link}.epsilon"], rows, f"ε{link} = dω/dt")
    for point in scene.report:
        for axis in "xy":
            _check(name, t, data[f"{point}.{axis}"], data[f"{point}.v{axis}"], rows, f"v{point}{axis} = d{axis}/dt")
            if f"{point}.a{axis}" in data:
                _check(name, t, data[f"{point}.v{axis}"], data[f"{point}.a{axis}"], rows, f"a{point}{axis} = dv/dt")
    for pair in scene.prismatics:
        _check(name, t, data[f"{pair.name}.s"], data[f"{pair.name}.v_rel"], rows, f"vʳ {pair.name} = ds/dt")
        if f"{pair.name}.a_rel" in data:
            _check(name, t, data[f"{pair.name}.v_rel"], data[f"{pair.name}.a_rel"], rows, f"aʳ {pair.name} = dvʳ/dt")


def test_old_behaviour_fails_the_check():
    """The scene's ω and ε held at every position (no rates given): ε₂ = 5 rad/s² while dω₂/dt = 0."""
    scene = plans.load(plans.example_path("four-bar"))
    cycle = driver_cycle(scene, 360)
    held = plans.solve(scene, cycle.positions, allow_partial=True)
    assert np.allclose(held.links["2"].epsilon, 5.0)
    assert np.allclose(cycle.solve().links["2"].epsilon, 0.0)  # constant law: ε = 0, the derivative of a constant ω
