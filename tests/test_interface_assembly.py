"""[assembly] keys that cannot choose a branch are refused; the branch each group took is
reported; one default whatever the spelling of a sliding pair (issue 9 §1)."""

import cmath
import json
import math

import pytest

import plans
from plans.cli import main
from plans.errors import SceneError

FOUR_BAR = plans.example_path("four-bar").read_text()

# An oscillating cylinder: crank OA = 100 mm, frame pivot Q 300 mm from O; rod 3 from A with
# its axis towards Q (a point P 250 mm along it). Written twice: the cylinder as a [[slider]]
# block, and as a link with its own bore, the rod sliding in it ([[prismatic]]).
HEAD = '''title = "Oscillating cylinder"
[frame]
points = { O = [0, 0], Q = ["300 mm", 0] }
[link.2]
points = { O = [0, 0], A = ["100 mm", 0] }
[link.3]                      # piston rod, its axis from A into the cylinder
points = { A = [0, 0], P = ["250 mm", 0] }
lines = { rod = { through = "A", angle = 0 } }
'''
DRIVER = '''[driver]
crank = "2"
angle = "60 deg"
omega = "10 rad/s"
'''
AS_SLIDER = HEAD + '''[[slider]]
pin = "Q"
on = "3.rod"
name = "4"
''' + DRIVER
AS_PRISMATIC = HEAD + '''[link.4]                      # the cylinder, pivoted at Q
points = { Q = [0, 0] }
lines = { bore = { through = "Q", angle = "180 deg" } }
[[prismatic]]
line = "3.rod"
on = "4.bore"
''' + DRIVER
AS_PRISMATIC_OTHER_WAY = HEAD + '''[link.4]
points = { Q = [0, 0] }
lines = { bore = { through = "Q", angle = "180 deg" } }
[[prismatic]]
line = "4.bore"
on = "3.rod"
''' + DRIVER

# Hand geometry: A = 0.1·e^{i60°}; the rod's axis is the line A→Q (the natural assembly).
A = 0.1 * cmath.exp(1j * math.radians(60))
Q = 0.3
P_NATURAL = A + 0.25 * (Q - A) / abs(Q - A)


def without_assembly(text):
    return text[: text.index("[assembly]")]


@pytest.mark.parametrize("text", [AS_SLIDER, AS_PRISMATIC, AS_PRISMATIC_OTHER_WAY], ids=["slider", "prismatic", "prismatic-swapped"])
def test_one_default_branch_whatever_the_spelling(text):
    scene = plans.loads(text)
    solution = plans.solve(scene)
    assert complex(solution.points["P"].r[0]) == pytest.approx(P_NATURAL, abs=1e-12)
    (branch,) = solution.branches
    assert branch.sign == 1 and branch.chosen_by == "default (+1)" and branch.other_assembly
    graphical = plans.construct(scene)
    assert graphical.positions["P"] == pytest.approx(P_NATURAL, abs=1e-9)


@pytest.mark.parametrize("text", [AS_SLIDER, AS_PRISMATIC, AS_PRISMATIC_OTHER_WAY], ids=["slider", "prismatic", "prismatic-swapped"])
def test_sign_minus_one_is_the_other_assembly_whatever_the_spelling(text):
    scene = plans.loads(text + "[assembly]\nP = -1\n")
    solution = plans.solve(scene)
    assert plans.construct(scene).positions["P"] == pytest.approx(A - 0.25 * (Q - A) / abs(Q - A), abs=1e-9)
    # the other assembly: the rod's axis turned half a turn about A
    assert complex(solution.points["P"].r[0]) == pytest.approx(A - 0.25 * (Q - A) / abs(Q - A), abs=1e-12)
    assert solution.branches[0].sign == -1


@pytest.mark.parametrize(
    "key, why",
    [
        ("O = -1", "O is a point of the frame (and of the driver, link 2)"),
        ("D = 1", "D joins RRR(3,4) to the frame (an outer joint)"),
        ("A = [0.05, 0.05]", "A joins RRR(3,4) to link 2 (an outer joint)"),
    ],
)
def test_keys_that_cannot_choose_a_branch_are_refused_naming_those_that_can(key, why):
    text = without_assembly(FOUR_BAR) + "[assembly]   # which branch\n" + key + "\n"
    line = text.splitlines().index(key) + 1
    with pytest.raises(SceneError) as caught:
        plans.solve(plans.loads(text, source="press.toml"))
    message = str(caught.value)
    assert message.startswith(f"press.toml: assembly.{key[0]} (line {line}): ")
    assert why in message
    assert "the branch of RRR(3,4) by B or M" in message


def test_a_key_on_a_group_with_one_assembly_is_refused():
    # scotch-yoke: RPP(3,4), the yoke 4 carries a point Y of its own; an RPP has one assembly
    text = plans.example_path("scotch-yoke").read_text() + "\n[assembly]\nY = 1\n"
    with pytest.raises(SceneError, match=r"assembly.Y \(line \d+\): RPP\(3,4\) has one assembly only"):
        plans.solve(plans.loads(text))


def test_two_keys_for_one_group_are_refused():
    text = without_assembly(FOUR_BAR) + "[assembly]\nB = 1\nM = [0.1, 0.1]\n"
    with pytest.raises(SceneError, match="B and M both choose the branch of RRR"):
        plans.solve(plans.loads(text))


def test_the_outer_joint_of_an_oscillating_cylinder_is_refused_through_the_cli(tmp_path, capsys):
    path = tmp_path / "cylinder.toml"
    text = AS_SLIDER + "[assembly]\nQ = -1\n"
    path.write_text(text)
    line = text.splitlines().index("Q = -1") + 1
    assert main(["solve", str(path)]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert f"{path}: assembly.Q (line {line})" in err and "the branch of RPR(3,4) by P" in err


@pytest.mark.parametrize("sign", [1, -1])
def test_reported_branch_is_the_written_sign_and_its_geometry(sign):
    text = without_assembly(FOUR_BAR) + f"[assembly]\nB = {sign}\n"
    solution = plans.solve(plans.loads(text))
    (branch,) = solution.branches
    assert branch.sign == sign and branch.chosen_by == f"B = {sign:+d}"
    a, b, d = (complex(solution.points[n].r[0]) for n in "ABD")
    left = ((d - a).conjugate() * (b - a)).imag > 0  # RRR(3,4): B left of A→D is +1
    assert left == (sign > 0)
    assert branch.words == f"B to the {'left' if sign > 0 else 'right'} of A→D"


def test_branch_in_table_and_json(capsys):
    assert main(["solve", "--example", "six-bar", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["groups"]["RRR(3,4)"]["branch"] == {
        "sign": -1, "words": "C to the right of A→D", "other_assembly": True, "chosen_by": "C near (-0.3, 0.7) m"}
    assert doc["groups"]["RPR(5,6)"]["branch"]["chosen_by"] == "default (+1)"
    assert main(["solve", "--example", "six-bar"]) == 0
    table = capsys.readouterr().out
    assert "branch -1: C to the right of A→D (chosen by C near (-0.3, 0.7) m; another assembly exists there)" in table
    assert main(["solve", "--example", "wedge", "--json"]) == 0
    (group,) = json.loads(capsys.readouterr().out)["groups"].values()
    assert group["branch"]["sign"] == 0 and group["branch"]["other_assembly"] is False


def test_the_order_of_links_in_the_file_does_not_change_the_default():
    # the four-bar with links 3 and 4 listed the other way round
    head, rest = without_assembly(FOUR_BAR).split("[link.3]", 1)
    link3, rest = rest.split("[link.4]", 1)
    link4, tail = rest.split("[driver]", 1)
    swapped = head + "[link.4]" + link4 + "[link.3]" + link3 + "[driver]" + tail
    one = plans.solve(plans.loads(without_assembly(FOUR_BAR)))
    two = plans.solve(plans.loads(swapped))
    assert complex(one.points["B"].r[0]) == pytest.approx(complex(two.points["B"].r[0]), abs=1e-15)
    assert one.branches[0].sign == two.branches[0].sign == 1
