"""Structure detection: Assur groups found in solving order, and clear refusals."""

import pytest

from plans import StructureError, load, loads
from plans.scene import example_path
from plans.structure import find_structure, mobility

# worked out by hand from each example's kinematic scheme
EXPECTED = {
    "ladder": "I(1,2) → RRP(3,4)",
    "slider-crank": "I(1,2) → RRP(3,4)",
    "four-bar": "I(1,2) → RRR(3,4)",
    "quick-return": "I(1,2) → RPR(3,4) → RRP(5,6)",
    "six-bar": "I(1,2) → RRR(3,4) → RPR(5,6)",
    "linear-arm": "I(1,2) → RPR(3,4) → RRP(5,6)",
    "wedge": "I(1,2) → PRP(3,4)",
    "scotch-yoke": "I(1,2) → RPP(3,4)",
    "rocker-limit": "I(1,2) → RRR(3,4)",
}


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_structural_formula_of_every_example(name):
    structure = find_structure(load(example_path(name)))
    assert structure.formula == EXPECTED[name]
    assert structure.mobility == 1


def test_group_links_and_joints_follow_the_documented_order():
    groups = find_structure(load(example_path("six-bar"))).groups
    rrr, rpr = groups
    assert (rrr.links, rrr.outer_i.point, rrr.inner.point, rrr.outer_j.point) == (("3", "4"), "A", "C", "D")
    assert rrr.outer_i.bodies == ("3", "2") and rrr.outer_j.bodies == ("4", "frame")
    # RPR: i carries the guide line of the inner prismatic, j slides on it
    assert rpr.links == ("5", "6") and rpr.inner.prismatic.guide == "5"
    assert (rpr.outer_i.point, rpr.outer_j.point) == ("B", "E")


def test_rpp_orders_the_revolute_link_first():
    (group,) = find_structure(load(example_path("scotch-yoke"))).groups
    assert group.links == ("3", "4")
    assert (group.outer_i.kind, group.inner.kind, group.outer_j.kind) == ("R", "P", "P")


def test_grubler_count():
    assert mobility(load(example_path("six-bar"))) == (1, 5, 7)


CLASS_III = """
[frame]
points = { O = [0, 0], E = [0.5, -0.2], F = [0.6, 0.4] }
[link.2]
points = { O = [0, 0], A = [0.1, 0] }
[link.3]        # ternary link of the class III group
points = { B = [0, 0], C = [0.2, 0], D = [0.1, 0.15] }
[link.4]
points = { A = [0, 0], B = [0.3, 0] }
[link.5]
points = { C = [0, 0], E = [0.25, 0] }
[link.6]
points = { D = [0, 0], F = [0.3, 0] }
[driver]
crank = "2"
angle = 30
omega = 1
"""


def test_class_three_group_is_refused_naming_its_links():
    with pytest.raises(StructureError) as info:
        find_structure(loads(CLASS_III, source="iii.toml"))
    message = str(info.value)
    assert "links 3, 4, 5, 6 do not form class-II Assur groups" in message
    assert "class III" in message


def test_wrong_mobility_is_refused_with_the_count():
    text = example_path("four-bar").read_text().replace('D = ["220 mm", 0] }', 'Z = ["220 mm", 0] }')
    with pytest.raises(StructureError) as info:
        find_structure(loads(text, source="loose.toml"))
    message = str(info.value)
    assert "mobility W = 3n − 2p = 3·3 − 2·3 = 3" in message and "loose.toml" in message


def test_over_constrained_link_is_named():
    text = example_path("four-bar").read_text().replace(
        'points = { D = [0, 0], B = ["200 mm", 0] }', 'points = { D = [0, 0], B = ["200 mm", 0] }\n[link.5]\npoints = { O = [0, 0], D = ["220 mm", 0] }'
    )
    with pytest.raises(StructureError) as info:
        find_structure(loads(text))
    assert "mobility" in str(info.value) and "= 0" in str(info.value)


def _renumbered(name: str, shift: int) -> str:
    """The example's text with every link number lowered by *shift* (crank 2 -> crank 1)."""
    import re

    text = example_path(name).read_text()
    return re.sub(r'(\[link\.|crank = "|link = "|")(\d)(?=[\]".])', lambda m: m.group(1) + str(int(m.group(2)) - shift), text)


@pytest.mark.parametrize("shift, frame", [(0, "1"), (1, "0")])
def test_one_frame_number_in_the_formula_and_the_centres(shift, frame):
    # the scene's numbering decides: crank 2 -> frame 1 (Serbian workbook), crank 1 -> frame 0 (Russian, Bulgarian)
    from plans.centres import instant_centres

    scene = loads(_renumbered("four-bar", shift), source="four-bar.toml")
    crank = scene.driver.link
    assert crank == str(2 - shift)
    assert find_structure(scene).formula.startswith(f"I({frame},{crank}) → RRR(")
    numbers = instant_centres(scene).numbers
    assert numbers["frame"] == frame
