"""Pages laid out: on the plate every drawing big enough at the handout's one k_l, k_v, k_a (12 positions of
every example) and inside the text area, the plan of positions at the k_l it states, a crowded plan's detail;
the sheets' long equations broken for any width; page text never parsed as math (issues 11, 15, 20)."""

from __future__ import annotations

import re

import pytest
from matplotlib.figure import Figure

import plans
from plans._text import user_text
from plans.drawing.svg import drawing_rc
from plans.loops import loop_equations
from review_handouts import built

#: what the plate gives its drawings [mm] (issue 11 §1, issue 20 §1): at 12 positions of every bundled example,
#: at the one k_v and k_a of the handout, the largest velocity plan's longest vector at least 30 mm, the
#: largest acceleration plan's at least 50 mm, the plan of positions at least 100 mm across
LARGEST_VELOCITY_MM = 30.0
LARGEST_ACCELERATION_MM = 50.0
POSITIONS_ACROSS_MM = 100.0
POSITIONS = 12


@pytest.fixture(scope="module", params=plans.example_names())
def plate(request):
    """One handout of each example at 12 positions, shared by the tests of this module."""
    return built(request.param, POSITIONS)


def test_every_drawing_is_big_enough_and_inside_the_text_area(plate):
    from plans.pages.handout import TEXT_HEIGHT, TEXT_WIDTH

    velocity = max(max((abs(v.tip - v.tail) for v in r.graphical.velocity_plan.vectors), default=0.0) for r in plate.runs)
    assert velocity >= LARGEST_VELOCITY_MM, velocity
    accelerations = [max((abs(v.tip - v.tail) for v in r.graphical.acceleration_plan.vectors), default=0.0)
                     for r in plate.runs if r.index in plate.accelerations]
    if any(accelerations):  # (the wedge at constant speed has none)
        assert max(accelerations) >= LARGEST_ACCELERATION_MM, accelerations
    assert max(plate.drawn["positions"]) >= POSITIONS_ACROSS_MM, plate.drawn["positions"]
    for key, (w, h) in plate.drawn.items():
        if not key.startswith(("diagram-", "kinematic-")):
            assert w <= TEXT_WIDTH + 0.5 and h <= TEXT_HEIGHT, (key, w, h)


def test_the_plan_of_positions_is_drawn_at_the_k_l_it_states(plate):
    """The crank pin's (or the driver's) path on the plan of positions is 2·OA / k_l wide: read in its SVG."""
    scene = plate.runs[0].scene
    if not hasattr(scene.driver, "omega"):
        return
    svg = plate.images["positions"].decode()
    m = re.search(r'<g id="positions-path-([A-Za-z0-9]+)"[^>]*>\s*<path d="([^"]+)"', svg)
    assert m, "the path of the crank pin"
    xy = [(float(x), float(y)) for x, y in re.findall(r"[ML] ?(-?[0-9.]+) (-?[0-9.]+)", m.group(2))]
    xs, ys = [x for x, _ in xy], [y for _, y in xy]
    crank = scene.bodies[scene.driver.link].points
    radius = max(abs(z - crank[scene.driver.pivot]) for z in crank.values())
    width_mm = (max(xs) - min(xs)) * 25.4 / 72  # SVG user units are points
    full_turn = abs((max(ys) - min(ys)) - (max(xs) - min(xs))) < 0.01 * (max(xs) - min(xs))  # a circle, not a swing's arc
    if full_turn and m.group(1) in crank and abs(abs(crank[m.group(1)] - crank[scene.driver.pivot]) - radius) < 1e-9:
        assert 2 * radius / width_mm == pytest.approx(plate.scales["k_l"], rel=2e-2)


def test_a_crowded_plan_has_its_enlarged_detail_where_it_fits(plate):
    """A plan with a crowd of images (six-bar's a b c within 8 mm) is drawn with its detail "Detail I (n : 1)" unless the
    detail would run out of the plan's cell; a plan without a crowd has none."""
    for r in plate.runs:
        plan = r.graphical.velocity_plan
        svg = plate.images[f"v-{r.index}"].decode()
        if not _crowded_links(plan) and not _short_chains(plan):
            assert 'id="vel-detail' not in svg, r.index




def test_user_text_is_plain_and_visible():
    assert user_text("\ufeffPump\u200b  station\n") == "Pump station"
    assert user_text("$\\alpha$") == "\\$\\alpha\\$"
    with drawing_rc():
        fig = Figure()
        text = fig.text(0, 0, user_text("$\\undefinedmacro$"))
        fig.draw_without_rendering()  # matplotlib lays it out as plain text
    assert text.get_text() == "\\$\\undefinedmacro\\$" and not text._preprocess_math(text.get_text())[1]


def test_a_squared_number_in_powers_of_ten_is_bracketed():
    scene = plans.load(plans.example_path("four-bar"))
    fast = plans.loads(scene.source.read_text().replace('omega = "10 rad/s"', 'omega = "5e4 rad/s"')) if hasattr(scene.source, "read_text") else None
    if fast is None:
        text = open(plans.example_path("four-bar"), encoding="utf-8").read().replace('omega = "10 rad/s"', 'omega = "5e4 rad/s"')
        fast = plans.loads(text)
    lines = [line for block in loop_equations(plans.solve(fast)) for line in block.lines]
    assert any(r"(5\cdot10^{4})^2" in line for line in lines)
    # a power of a power (``10^{4}^2``) is what mathtext refused as a "Double superscript"
    assert not any(re.search(r"\^\{[^{}]*\}\^", line) for line in lines)


def _crowded_links(plan) -> list[str]:
    """Links with 3 or more distinct images within 8 mm of each other on *plan* (the crowd a detail enlarges)."""
    out = []
    for link, labels in plan.links.items():
        pts = []
        for z in (plan.images[n] for n in labels if n in plan.images):
            if all(abs(z - q) > 0.3 for q in pts):
                pts.append(z)
        if len(pts) >= 3 and 0.5 < max(abs(q - r) for q in pts for r in pts) < 8.0:
            out.append(link)
    return out


def _short_chains(plan) -> list[list[complex]]:
    """Groups of 3 or more points within 8 mm joined by vectors 0.7…3 mm long (too short for an arrow, readable at
    10 : 1): the crowd of short components a detail enlarges (quick-return pos 2: a′ →k →a₄′)."""
    groups: list[list[complex]] = []
    for v in plan.vectors:
        if not 0.7 <= abs(v.tip - v.tail) < 3.0:
            continue
        ends = [complex(v.tail), complex(v.tip)]
        touching = [g for g in groups if any(abs(e - q) < 1e-3 for e in ends for q in g)]
        merged = ends + [q for g in touching for q in g]
        groups = [g for g in groups if g not in touching]
        distinct = []
        for q in merged:
            if all(abs(q - w) > 1e-3 for w in distinct):
                distinct.append(q)
        groups.append(distinct)
    return [g for g in groups if len(g) >= 3 and max(abs(q - r) for q in g for r in g) < 8.0]


