"""Fuzzing the scene loader: mutated valid scenes give a solution or a PlansError, nothing else.

Every mutated scene that loads is taken through the whole pipeline: structure,
the analytic solution at the scene's position and over a few more, the
graphical construction, the comparison, the reports (JSON and table, which
refuse non-finite numbers) and a sweep's CSV, which must never hold NaN or inf.
"""

import copy
import csv
import io
import math
import tomllib

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import numpy as np

from plans import PlansError
from plans.analytic import solve
from plans.compare import compare
from plans.graphical import construct
from plans.report import format_json, solution_json, solution_table, sweep_csv
from plans.scene import example_names, example_path, from_mapping
from plans.structure import find_structure

SCENES = {name: tomllib.loads(example_path(name).read_text()) for name in example_names()}

EXTREMES = [
    0, -1, 1e-300, 1e300, -1e300, 1e-9, 1e9, 1e29, -1e-12, math.nan, math.inf, -math.inf,
    "", "1 kg", "nan m", "1e300 mm", "1e-300 km", "3 kg", [], {}, [1, 2, 3], [0, 0], ["1e-9 m", 0], True, "x", "O", "2.rod",
]


def _paths(node, prefix=()):
    """Every key path in a nested table (lists indexed)."""
    if isinstance(node, dict):
        for key, value in node.items():
            yield prefix + (key,)
            yield from _paths(value, prefix + (key,))
    elif isinstance(node, list):
        for index, value in enumerate(node):
            yield prefix + (index,)
            yield from _paths(value, prefix + (index,))


def _mutate(data, path, action, value):
    data = copy.deepcopy(data)
    parent = data
    for key in path[:-1]:
        parent = parent[key]
    last = path[-1]
    if action == "drop":
        del parent[last]
    elif action == "replace":
        parent[last] = value
    elif action == "rename" and isinstance(parent, dict):
        parent[str(value) + "_"] = parent.pop(last)
    return data


@st.composite
def mutated_scenes(draw):
    name = draw(st.sampled_from(sorted(SCENES)))
    data = SCENES[name]
    for _ in range(draw(st.integers(1, 3))):
        paths = list(_paths(data))
        if not paths:
            break
        path = draw(st.sampled_from(paths))
        action = draw(st.sampled_from(["drop", "replace", "replace", "rename", "number"]))
        value = draw(st.sampled_from(EXTREMES))
        if action == "number":  # any double at all, NaN, infinities and subnormals included
            action, value = "replace", draw(st.floats(allow_nan=True, allow_infinity=True))
        data = _mutate(data, path, action, value)
    return name, data


def _whole_pipeline(scene):
    structure = find_structure(scene)
    analytic = solve(scene, structure=structure)
    graphical = construct(scene, structure)
    comparisons = compare(analytic, graphical)
    format_json(solution_json(analytic, graphical, comparisons))  # allow_nan=False: raises on NaN
    solution_table(analytic, graphical, comparisons)
    turn = solve(scene, np.linspace(-3.0, 3.0, 7), structure, allow_partial=True)
    rows = list(csv.reader(io.StringIO(sweep_csv(turn))))[1:]
    for row in rows:
        for cell in row:
            assert cell == "" or math.isfinite(float(cell)), row


@settings(max_examples=250, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mutated_scenes())
def test_mutated_scene_gives_a_solution_or_a_plans_error(case):
    name, data = case
    try:
        scene = from_mapping(data, source=f"{name}.toml")
        _whole_pipeline(scene)
    except PlansError as exc:
        assert str(exc), "an error must say something"
        assert "Traceback" not in str(exc)


# --- valid scenes must still solve ------------------------------------------------------
# Any PlansError passes the test above, so a valid scene wrongly refused would pass too.
# Here the unmutated scenes and harmless rewritings of them must solve, and give the same
# mechanism.

_LENGTH_KEYS = ("points",)


def _in_mm(value):
    """A coordinate written as millimetres: 0.15 -> "150.0 mm"; strings with units kept."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return f"{value * 1000!r} mm"
    return value


def _harmless(data, rewrite):
    data = copy.deepcopy(data)
    if rewrite == "reorder-links":  # the [link.N] tables in the opposite order
        data["link"] = dict(reversed(list(data["link"].items())))
    elif rewrite == "points-in-mm":  # every bare coordinate of every link rewritten in mm
        for link in data["link"].values():
            link["points"] = {k: [_in_mm(c) for c in v] for k, v in link["points"].items()}
    elif rewrite == "title":
        data["title"] = "Заглавље — a title in two scripts, with \"quotes\" & <angle brackets>"
    elif rewrite == "full-turn" and "crank" in data["driver"]:  # the same crank angle, one turn on
        angle = data["driver"]["angle"]
        degrees = float(angle.split()[0]) if isinstance(angle, str) and angle.endswith("deg") else None
        if degrees is not None:
            data["driver"]["angle"] = f"{degrees + 360} deg"
    elif rewrite == "report-listed":  # [compute] points listing every moving point explicitly
        scene = from_mapping(copy.deepcopy(data))
        data.setdefault("compute", {})["points"] = list(scene.report)
    return data


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(sorted(SCENES)), st.lists(st.sampled_from(["reorder-links", "points-in-mm", "title", "full-turn", "report-listed"]), max_size=3))
def test_valid_and_harmlessly_rewritten_scenes_still_solve(name, rewrites):
    data = SCENES[name]
    original = from_mapping(copy.deepcopy(data), source=f"{name}.toml")
    for rewrite in rewrites:
        data = _harmless(data, rewrite)
    scene = from_mapping(data, source=f"{name}.toml")  # no PlansError may escape here ...
    _whole_pipeline(scene)  # ... nor here
    one, two = solve(original), solve(scene)
    for point in original.report:
        assert abs(complex(one.points[point].r[0]) - complex(two.points[point].r[0])) < 1e-12
        assert abs(complex(one.points[point].v[0]) - complex(two.points[point].v[0])) <= 1e-12 * (1 + abs(complex(one.points[point].v[0])))
