"""Fuzzing the scene loader: mutated valid scenes give a scene or a PlansError, nothing else."""

import copy
import math
import tomllib

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from plans import PlansError
from plans.scene import example_names, example_path, from_mapping
from plans.structure import find_structure

SCENES = {name: tomllib.loads(example_path(name).read_text()) for name in example_names()}

EXTREMES = [0, -1, 1e-300, 1e300, -1e300, math.nan, math.inf, -math.inf, "", "1 kg", "nan m", [], {}, [1, 2, 3], True, "x"]


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
        action = draw(st.sampled_from(["drop", "replace", "replace", "rename"]))
        value = draw(st.sampled_from(EXTREMES))
        data = _mutate(data, path, action, value)
    return name, data


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mutated_scenes())
def test_mutated_scene_gives_a_scene_or_a_plans_error(case):
    name, data = case
    try:
        scene = from_mapping(data, source=f"{name}.toml")
        find_structure(scene)
    except PlansError as exc:
        assert str(exc), "an error must say something"
        assert "Traceback" not in str(exc)
