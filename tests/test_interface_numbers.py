"""Numbers as people write them (issue 9 §2): inputs back as given, round-off as 0, angles in
0°–360°, polar points, points on a slider block, the bare-metres hint, line numbers."""

import cmath
import json
import math
import re

import pytest

import plans
from plans.cli import main
from plans.errors import SceneError

FOUR_BAR = plans.example_path("four-bar").read_text()


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_an_angle_given_in_degrees_comes_back_as_given(capsys):
    status, out, _ = run(capsys, "solve", "--example", "slider-crank", "--at", "30 deg", "--json")
    assert status == 0
    doc = json.loads(out)
    assert doc["driver"]["phi_deg"] == 30  # not 29.999999999999996
    assert doc["links"]["2"]["analytic"]["phi_deg"] == 30
    assert json.loads(run(capsys, "solve", "--example", "six-bar", "--json")[1])["driver"]["phi_deg"] == 55


def test_every_angle_in_table_and_json_is_in_0_to_360(capsys):
    for name in plans.example_names():
        out = run(capsys, "solve", "--example", name, "--json")[1]
        doc = json.loads(out)
        angles = [entry["analytic"]["phi_deg"] for entry in doc["links"].values()]
        if doc["driver"]["type"] == "crank":
            angles.append(doc["driver"]["phi_deg"])
        assert all(0 <= a < 360 for a in angles), (name, angles)
        table = run(capsys, "solve", "--example", name)[1]
        directions = re.findall(r"^\S*\s+[rva]\s+(?:analytic|graphical)\s+\S+\s+\S+\s+\S+\s+(-?[\d.]+)$", table, re.M)
        assert directions and all(0 <= float(d) < 360 for d in directions), name


def test_a_crank_angle_beyond_a_turn_is_reported_within_one(capsys):
    doc = json.loads(run(capsys, "solve", "--example", "four-bar", "--at", "-30 deg", "--json")[1])
    assert doc["driver"]["phi_deg"] == pytest.approx(330, abs=1e-12)
    doc = json.loads(run(capsys, "solve", "--example", "four-bar", "--at", "750 deg", "--json")[1])
    assert doc["driver"]["phi_deg"] == pytest.approx(30, abs=1e-12)


@pytest.mark.parametrize("name", ["ladder", "wedge"])
def test_round_off_far_below_the_scale_prints_as_zero(capsys, name):
    # ladder (E1): B slides on the vertical wall, so v_Bx = a_Bx = 0 exactly; wedge: the block
    # on a vertical guide. Their round-off (1e-16 … 1e-18 next to values of order 1) prints as 0.
    out = run(capsys, "solve", "--example", name)[1]
    for line in out.split("Links")[0].splitlines():
        cells = line.split()
        if "analytic" in cells or "graphical" in cells:
            start = cells.index("analytic" if "analytic" in cells else "graphical") + 1
            for cell in cells[start : start + 3]:  # x, y, magnitude
                assert float(cell) == 0 or abs(float(cell)) > 1e-9, line
    doc = json.loads(run(capsys, "solve", "--example", name, "--json")[1])
    for point, entry in doc["points"].items():
        for q in ("r", "v", "a"):
            for value in entry["analytic"][q] + entry["graphical"][q]:
                assert value == 0 or abs(value) > 1e-9, (point, q, value)
    if name == "ladder":
        b = doc["points"]["B"]
        assert b["analytic"]["v"][0] == 0 and b["analytic"]["a"][0] == 0
        assert b["graphical"]["r_abs_error"] > 0  # errors are not rounded away: they are what they are


def test_polar_points_are_in_the_links_own_frame():
    text = FOUR_BAR.replace('M = ["100 mm", "60 mm"]', 'M = { r = "260 mm", angle = "50 deg" }')
    assert text != FOUR_BAR
    scene = plans.loads(text)
    m = scene.bodies["3"].points["M"]
    assert m == pytest.approx(0.26 * complex(math.cos(math.radians(50)), math.sin(math.radians(50))), abs=1e-15)
    solution = plans.solve(scene)
    a, b = (complex(solution.points[n].r[0]) for n in "AB")
    phi3 = float(solution.links["3"].phi[0])
    assert complex(solution.points["M"].r[0]) == pytest.approx(a + 0.26 * cmath.exp(1j * (phi3 + math.radians(50))), abs=1e-14)
    with pytest.raises(SceneError, match=r"link.3.points.M \(line 12\): expected coordinates .* r = \"260 mm\", angle = \"50 deg\""):
        plans.loads(FOUR_BAR.replace('M = ["100 mm", "60 mm"]', 'M = { r = "260 mm" }'))


CYLINDER = '''title = "Oscillating cylinder"
[frame]
points = { O = [0, 0], Q = ["300 mm", 0] }
[link.2]
points = { O = [0, 0], A = ["100 mm", 0] }
[link.3]
points = { A = [0, 0] }
lines = { rod = { through = "A", angle = 0 } }
BLOCK
[driver]
crank = "2"
angle = "60 deg"
omega = "10 rad/s"
'''


@pytest.mark.parametrize("block", [
    '[[slider]]\npin = "Q"\non = "3.rod"\nname = "4"\npoints = { T = ["120 mm", 0] }',
    '[link.4]\npoints = { Q = [0, 0], T = ["120 mm", 0] }\n[[slider]]\npin = "Q"\non = "3.rod"\nname = "4"',
])
def test_a_slider_block_carries_points_of_its_own(block):
    solution = plans.solve(plans.loads(CYLINDER.replace("BLOCK", block)))
    a = 0.1 * cmath.exp(1j * math.radians(60))
    u = (0.3 - a) / abs(0.3 - a)  # the rod's axis A→Q, the block's x axis along it
    assert complex(solution.points["T"].r[0]) == pytest.approx(0.3 + 0.12 * u, abs=1e-14)


def test_bare_lengths_get_the_metres_hint_when_they_cannot_assemble(tmp_path, capsys):
    path = tmp_path / "bare.toml"
    path.write_text(FOUR_BAR.replace('A = ["80 mm", 0]', "A = [80, 0]"))
    status, out, err = run(capsys, "solve", str(path))
    assert status == 2 and out == ""
    assert err.startswith(f"plans: error: {path}: RRR(3,4): joint B cannot assemble")
    assert "bare lengths are metres: link.2.points.A[0] (line 9) = 80 is 80 m" in err and 'write "80 mm"' in err
    # a scene in metres throughout gets no such note
    status, _, err = run(capsys, "solve", "--example", "rocker-limit", "--at", "90")
    assert status == 2 and "bare lengths" not in err and "rocker-limit.toml: RRR(3,4)" in err


def test_dead_centre_errors_name_the_scene_file(capsys):
    status, _, err = run(capsys, "solve", "--example", "rocker-limit", "--at", "56.38762540153387 deg")
    assert status == 2 and re.match(r"plans: error: \S*rocker-limit\.toml: RRR\(3,4\): dead centre", err)


def test_errors_point_at_the_line_of_their_section_despite_header_comments():
    text = plans.example_path("six-bar").read_text().replace('M = ["800 mm", 0]', 'M = ["800 mx", 0]')
    line = next(k for k, t in enumerate(text.splitlines(), 1) if "800 mx" in t)
    assert "[link.5]" in text and "#" in text.splitlines()[line - 2]  # the header has a trailing comment
    with pytest.raises(SceneError, match=rf"link\.5\.points\.M\[0\] \(line {line}\)"):
        plans.loads(text)
    # a key of a table whose header has a comment, and whose name appears earlier in the file
    text = FOUR_BAR.replace("[assembly]", "[assembly]   # which branch").replace("B = [0.2, 0.2]", "B = [0.2, 0.2]\nD = 1")
    line = text.splitlines().index("D = 1") + 1
    with pytest.raises(SceneError, match=rf"assembly\.D \(line {line}\)"):
        plans.solve(plans.loads(text))


def test_a_ternary_link_by_its_side_lengths():
    # link 3 of the four-bar as a triangle A B M: |AM| = 0.1 m... given by two distances
    m = complex(0.1, 0.06)
    am, bm = abs(m), abs(m - 0.25)
    text = FOUR_BAR.replace('M = ["100 mm", "60 mm"]', f'M = {{ distances = {{ A = "{am * 1000!r} mm", B = {bm!r} }} }}')
    assert text != FOUR_BAR
    assert plans.loads(text).bodies["3"].points["M"] == pytest.approx(m, abs=1e-15)
    below = plans.loads(text.replace("} }", '}, side = "right" }')).bodies["3"].points["M"]
    assert below == pytest.approx(m.conjugate(), abs=1e-15)
    with pytest.raises(SceneError, match=r"link.3.points.M.distances \(line 12\): no triangle has sides AB = 0.25 m"):
        plans.loads(FOUR_BAR.replace('M = ["100 mm", "60 mm"]', 'M = { distances = { A = "10 mm", B = "20 mm" } }'))
