"""The drawings as artists: user axes, label placement, symbols, import isolation, bundled examples."""

from __future__ import annotations

import itertools
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

import drawing_fixtures as F
from plans import write_drawings
from plans.drawing import draw_acceleration_plan, draw_mechanism, draw_plan, draw_velocity_plan
from plans.drawing._canvas import fmt_number
from plans.drawing.mechanism import mechanism_labels

ROOT = Path(__file__).resolve().parent.parent
SVG = "{http://www.w3.org/2000/svg}"


def _label_boxes(artists, prefixes):
    fig = artists[0].figure
    renderer = FigureCanvasAgg(fig).get_renderer()
    boxes = {}
    for a in artists:
        gid = a.get_gid() or ""
        if hasattr(a, "get_text") and any(gid.startswith(p) for p in prefixes):
            boxes[gid] = a.get_window_extent(renderer)
    return boxes


@pytest.mark.parametrize("name", ["slider_crank", "quick_return", "ladder"])
def test_labels_do_not_overlap_each_other(name):
    solution = getattr(F, name)()
    cases = [(draw_mechanism(solution), ("mech-point-", "mech-number-", "mech-omega-label", "mech-velocity-label"))]
    for plan in (solution.velocity_plan, solution.acceleration_plan):
        if plan is not None:
            prefix = "vel" if plan.kind == "velocity" else "acc"
            cases.append((draw_plan(plan), (f"{prefix}-image-", f"{prefix}-pole-label")))
    for artists, prefixes in cases:
        boxes = _label_boxes(artists, prefixes)
        assert boxes
        for (ga, a), (gb, b) in itertools.combinations(boxes.items(), 2):
            # pieces of one merged label ("p, o") sit side by side on one line
            same_line = abs(a.y0 - b.y0) < 0.01 and abs(a.y1 - b.y1) < 0.01
            if same_line and (a.x1 <= b.x0 + 0.5 or b.x1 <= a.x0 + 0.5):
                continue
            assert not a.overlaps(b), f"{ga} overlaps {gb} in {name}"


def test_point_labels_clear_the_pins():
    solution = F.quick_return()
    artists = draw_mechanism(solution)
    renderer = FigureCanvasAgg(artists[0].figure).get_renderer()
    labels = [a for a in artists if (a.get_gid() or "").startswith("mech-point-")]
    pins = [a for a in artists if (a.get_gid() or "").startswith("mech-pin-")]
    for label, pin in itertools.product(labels, pins):
        assert not label.get_window_extent(renderer).overlaps(pin.get_window_extent(renderer)), (label.get_gid(), pin.get_gid())


def test_draw_into_a_given_axes():
    fig = Figure(figsize=(6, 4))
    ax = fig.add_subplot(1, 2, 1)
    artists = draw_velocity_plan(F.slider_crank().velocity_plan, ax=ax)
    assert artists and all(a.axes is ax for a in artists if hasattr(a, "axes") and a.axes is not None)
    ax2 = fig.add_subplot(1, 2, 2)
    assert draw_acceleration_plan(F.slider_crank().acceleration_plan, ax=ax2)
    fig3 = Figure()
    assert draw_mechanism(F.ladder(), ax=fig3.add_subplot())


def test_both_plan_names_work_and_kind_is_checked():
    import dataclasses

    plan = F.slider_crank().velocity_plan
    assert draw_plan(plan) and draw_velocity_plan(plan)
    with pytest.raises(ValueError, match="velocity"):
        draw_plan(dataclasses.replace(plan, kind="jerk"))


def test_mechanism_symbols():
    gids = [a.get_gid() or "" for a in draw_mechanism(F.quick_return())]
    assert "mech-block-3" in gids and "mech-block-6" in gids  # the blocks
    assert "mech-ground-O" in gids and "mech-ground-C" in gids  # frame pivots
    assert "mech-guide-ram" in gids and "mech-line-4-slot" in gids  # frame guide, slot of the lever
    assert "mech-omega" in gids and "mech-epsilon" not in gids  # ε = 0 is not drawn
    assert {"mech-number-2", "mech-number-4", "mech-number-5"} <= set(gids)
    ladder = [a.get_gid() or "" for a in draw_mechanism(F.ladder())]
    assert "mech-velocity" in ladder and "mech-acceleration" not in ladder and "mech-omega" not in ladder


def test_epsilon_arrow_only_when_epsilon_is_not_zero():
    import dataclasses

    solution = F.slider_crank()
    scene = dataclasses.replace(solution.scene, driver=dataclasses.replace(solution.scene.driver, epsilon=-30.0))
    artists = draw_mechanism(dataclasses.replace(solution, scene=scene))
    gids = [a.get_gid() or "" for a in artists]
    assert "mech-epsilon" in gids and "mech-epsilon-label" in gids
    assert "ε₂" in [a.get_text() for a in artists if hasattr(a, "get_text")]


def test_omega_arrow_turns_with_the_sign_of_omega():
    import dataclasses

    solution = F.slider_crank()
    for omega in (+5.0, -5.0):
        scene = dataclasses.replace(solution.scene, driver=dataclasses.replace(solution.scene.driver, omega=omega))
        artists = draw_mechanism(dataclasses.replace(solution, scene=scene))
        arc = next(a for a in artists if a.get_gid() == "mech-omega")
        head = next(a for a in artists if a.get_gid() == "mech-omega-head")
        xs, ys = arc.get_data()
        centre = solution.positions["O"] / solution.scales["k_l"]
        start = complex(xs[0], ys[0]) - centre
        tip = complex(*head.get_xy()[0]) - centre
        turn = (tip * start.conjugate()).imag  # > 0: counter-clockwise from start to tip
        assert (turn > 0) == (omega > 0)


def test_plate_for_a_ternary_link():
    import cmath
    import dataclasses

    from plans.scene import example_path, load

    solution = F.slider_crank()
    scene = load(example_path("four-bar"))
    # a hand-made pose set is enough for drawing: only positions and poses are read
    poses = {"2": (1.0, 0j), "3": (0.3, 0.08 * cmath.exp(1j)), "4": (2.0, 0.22 + 0j)}
    positions = {}
    for body, (phi, origin) in poses.items():
        for name, z in scene.bodies[body].points.items():
            positions.setdefault(name, origin + cmath.exp(1j * phi) * z)
    positions["D"] = 0.22 + 0j
    solution = dataclasses.replace(solution, scene=scene, poses=poses, positions=positions)
    artists = draw_mechanism(solution)
    plate = next(a for a in artists if a.get_gid() == "mech-link-3")
    assert len(plate.get_xy()) >= 4  # a closed polygon of three corners
    assert "M" in [a.get_text() for a in artists if hasattr(a, "get_text")]


def test_fmt_number():
    assert fmt_number(0.005) == "0.005"
    assert fmt_number(50.0) == "50"
    assert fmt_number(2.5e-6) == "2.5·10⁻⁶"
    assert fmt_number(1e6) == "10⁶"


def test_scene_structure_and_graphical_do_not_import_matplotlib():
    code = (
        "import sys, importlib\n"
        "for m in ('plans.scene', 'plans.structure', 'plans.graphical.plan', 'plans.graphical', 'plans.analytic'):\n"
        "    try:\n"
        "        importlib.import_module(m)\n"
        "    except ModuleNotFoundError as exc:\n"
        "        if exc.name != m: raise\n"
        "bad = [m for m in sys.modules if m == 'matplotlib' or m.startswith('matplotlib.') or m.startswith('plans.drawing')]\n"
        "assert not bad, bad\n"
    )
    subprocess.run([sys.executable, "-c", code], cwd=ROOT, check=True)


def _bundled():
    from plans.scene import example_names

    return example_names()


@pytest.mark.parametrize("name", _bundled())
def test_every_bundled_example_draws(name, tmp_path):
    from plans.graphical import construct
    from plans.scene import example_path, load

    solution = construct(load(example_path(name)))
    paths = write_drawings(solution, tmp_path)
    expected = ["mechanism.svg", "velocity.svg"] + (["acceleration.svg"] if solution.acceleration_plan else []) + ["sheet.svg"]
    assert [p.name for p in paths] == expected
    mech = ["".join(t.itertext()) for t in ET.parse(tmp_path / "mechanism.svg").getroot().iter(f"{SVG}text")]
    for point in mechanism_labels(solution):
        assert point in mech
    for plan, file in ((solution.velocity_plan, "velocity.svg"), (solution.acceleration_plan, "acceleration.svg")):
        if plan is None:
            continue
        root = ET.parse(tmp_path / file).getroot()
        found = ["".join(t.itertext()) for t in root.iter(f"{SVG}text")]
        labelled = {e.get("id") for e in root.iter() if e.get("id")}
        assert plan.pole in found
        for image in plan.images:
            tag = "vel" if plan.kind == "velocity" else "acc"
            assert f"{tag}-image-{image.rstrip('′')}" in labelled or image == plan.pole, (name, image)
