"""Issue 20 §3 (items 5, 6): the frame's number and the driver's link number in every equation and table.

The Serbian quick-return numbers its frame 1 (crank 2, I(1,2), P₁₂), yet its equations and tables wrote
v_E0, v_EE0, a^r_EE0 (frame 0), and the driver's acceleration "ω²·OA; ε = 0" without the crank's number.
A point of the frame carries the scene's frame number (:attr:`plans.scene.Scene.frame_number`): 1 where the
crank is link 2, 0 where it is link 1 (the slider-crank renumbered here, crank 1, as the Russian and Bulgarian
courses number it).  The expected subscripts are the textbook's, written out here by hand from the scene's numbering.

The loop equations named the guide's point "z_{Q_клизач}", a program symbol: the point of the guide from which the
travel s_E is measured is Q_E, defined on the page before the loop uses it.
"""

from __future__ import annotations

import re

import pytest

import plans
from plans.compare import compare
from plans.graphical import construct
from plans.loops import loop_equations, plain
from plans.report import sheet_table
from plans.scene import example_path, load, loads


def _crank_one_slider_crank():
    text = example_path("slider-crank").read_text()
    text = text.replace("[link.2]", "[link.1]").replace("[link.3]", "[link.2]").replace('crank = "2"', 'crank = "1"')
    return loads(text)


@pytest.fixture(scope="module")
def scenes():
    return {"quick-return": (load(example_path("quick-return")), "1", "E", "2"),
            "slider-crank": (load(example_path("slider-crank")), "1", "B", "2"),
            "crank-1": (_crank_one_slider_crank(), "0", "B", "1")}


@pytest.mark.parametrize("name", ["quick-return", "slider-crank", "crank-1"])
def test_a_point_of_the_frame_carries_the_frame_number(scenes, name):
    scene, frame, pin, crank = scenes[name]
    assert scene.frame_number == frame and scene.driver.link == crank
    other = "0" if frame == "1" else "1"
    g = construct(scene)
    labels = [v.label for p in (g.velocity_plan, g.acceleration_plan) for v in p.vectors]
    assert f"v_{pin}{pin}{frame}" in labels and f"a^r_{pin}{pin}{frame}" in labels
    assert not [x for x in labels if x.endswith(f"{pin}{pin}{other}")]
    equations = " ".join(e for p in (g.velocity_plan, g.acceleration_plan) for s in p.steps for e in s.equations)
    assert f"v_{pin}{frame} = 0" in equations and f"v_{pin}{other} " not in equations
    # the tables name it so too
    analytic = plans.solve(scene)
    rows = sheet_table(compare(analytic, g), g, analytic)
    names = " ".join(r[0] for r in rows)
    assert f"{pin}{pin}{frame}" in names and f"{pin}{pin}{other}" not in names, names


@pytest.mark.parametrize("name", ["quick-return", "crank-1"])
def test_the_driver_equations_carry_the_crank_number(scenes, name):
    scene, _, _, crank = scenes[name]
    g = construct(scene)
    driver = g.acceleration_plan.steps[0].equations[0]
    assert f"ω{crank}²·O" in driver and f"ε{crank} = 0" in driver, driver
    assert "ω²" not in driver and "; ε =" not in driver
    assert f"ω{crank} × O" in g.velocity_plan.steps[0].equations[0]


def test_the_handout_equations_and_tables_use_frame_1_on_the_serbian_quick_return():
    from plans.handout import handout

    doc = handout(plans.load(example_path("quick-return")), positions=4, lang="sr")
    src = doc.source
    assert "(E E 1)" in src and "(E 1)" in src  # v_EE1, v_E1 typeset
    assert "(E E 0)" not in src and "(E 0)" not in src
    assert "ω_2^2 dot.op O A" in src and "ε_2 = 0" in src  # ω₂²·OA; ε₂ = 0
    guide_points = re.findall(r"Q_\((.*?)\)", src)
    assert guide_points and {p.strip() for p in guide_points} == {"E"}, guide_points  # z_{Q_E}, not z_{Q_клизач}


@pytest.mark.parametrize("name", ["quick-return", "slider-crank"])
def test_the_loop_names_the_guide_point_it_defines(name):
    scene = load(example_path(name))
    pin = {"quick-return": "E", "slider-crank": "B"}[name]
    lines = [plain(line) for b in loop_equations(plans.solve(scene)) for line in b.lines]
    uses = [k for k, line in enumerate(lines) if f"Q_{pin}" in line]
    assert uses, lines
    first = lines[uses[0]]
    # defined before it is used: z_{Q_E} (s_E = 0) = the guide's point [m], as the scene places the guide
    m = re.fullmatch(rf"z_Q_{pin} \(s_{pin} = 0\) = (.*) m", first)
    assert m, first
    guide = next(iter(scene.frame.lines.values()))
    value = complex(m.group(1).replace(" ", "").replace("i", "j"))
    assert value == pytest.approx(complex(guide.origin), abs=1e-9)
    for line in lines:
        assert not re.search(r"Q_[a-zа-я]", line), line  # no guide's program name
        for guide_name in scene.frame.lines:
            assert f"Q_{guide_name}" not in line
