"""Inputs a new user gets wrong, and hostile ones (issue 21): each read visibly, refused or warned about."""

import time

import pytest

from plans.cli import main
from plans.errors import SceneError, StructureError
from plans.scene import example_path, loads
from plans.structure import find_structure

SLIDER_CRANK = example_path("slider-crank").read_text()
FOUR_BAR = example_path("four-bar").read_text()
LADDER = example_path("ladder").read_text()


def _line(text: str, start: str) -> int:
    """The number of the first line of *text* that starts with *start* (counted here, from the file)."""
    return next(n for n, line in enumerate(text.splitlines(), start=1) if line.startswith(start))


def _scene(tmp_path, text, name="scene.toml"):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


# --- bare driver numbers ------------------------------------------------------------------------


def test_bare_driver_numbers_meant_in_other_units_are_warned_about(tmp_path, capsys):
    text = SLIDER_CRANK.replace('omega = "2000 rpm"', "omega = 1850").replace('angle = "45 deg"', "angle = 2.396")
    assert main(["solve", _scene(tmp_path, text), "--analytic-only"]) == 0
    out, err = capsys.readouterr()
    warnings = [line for line in err.splitlines() if line.startswith("plans: warning:")]
    assert len(warnings) == 2
    angle = next(w for w in warnings if "driver.angle" in w)
    omega = next(w for w in warnings if "driver.omega" in w)
    assert f"line {_line(text, 'angle =')}" in angle and "2.396°" in angle and '"2.396 rad"' in angle
    assert f"line {_line(text, 'omega =')}" in omega and "17,666 rpm" in omega and '"1850 rpm"' in omega  # 1850·60/(2π) = 17 666
    # the table says how the bare numbers were read, under the driver's line
    assert "bare numbers read as SI and degrees: angle = 2.396 → 2.396°; omega = 1850 → 1850 rad/s" in out


def test_plausible_bare_driver_numbers_are_read_without_a_warning(tmp_path, capsys):
    text = SLIDER_CRANK.replace('omega = "2000 rpm"', "omega = 10").replace('angle = "45 deg"', "angle = 30")
    assert main(["solve", _scene(tmp_path, text), "--analytic-only"]) == 0
    out, err = capsys.readouterr()
    assert err == ""
    assert "angle = 30 → 30°; omega = 10 → 10 rad/s" in out
    assert "φ = 30.000°" in out and "ω = 10 rad/s" in out


def test_driver_numbers_with_units_need_no_reading_line(capsys):
    assert main(["solve", "--example", "slider-crank", "--analytic-only"]) == 0
    assert "bare numbers" not in capsys.readouterr().out


def test_a_bare_linear_velocity_meant_as_mm_per_second_is_warned_about():
    scene = loads(LADDER.replace('velocity = "1 m/s"', "velocity = 250"), "ladder.toml")
    assert len(scene.doubts) == 1 and "driver.velocity" in scene.doubts[0] and '"250 mm/s"' in scene.doubts[0]


# --- TOML and structure errors in the scene's words -------------------------------------------


def test_a_point_given_twice_in_an_inline_table_is_named():
    text = SLIDER_CRANK.replace('points = { A = [0, 0], B = ["250 mm", 0] }', 'points = { A = [0, 0], B = ["250 mm", 0], B = [1, 0] }')
    with pytest.raises(SceneError) as info:
        loads(text, "my.toml")
    message = str(info.value)
    assert message.startswith(f"my.toml: link.3.points (line {_line(text, '[link.3]') + 1}): the point B is given twice")
    assert "immutable namespace" in message  # the parser's words last, in brackets, never alone


def test_a_key_given_twice_and_a_table_declared_twice_are_named():
    with pytest.raises(SceneError, match=rf"driver \(line {_line(SLIDER_CRANK, 'omega =') + 1}\): omega is given twice"):
        loads(SLIDER_CRANK.replace('omega = "2000 rpm"', 'omega = "2000 rpm"\nomega = 5'), "my.toml")
    with pytest.raises(SceneError, match=r"the table \[link.3\] is declared twice"):
        loads(SLIDER_CRANK + '\n[link.3]\nlines = {}\n', "my.toml")


def test_a_point_shared_by_three_links_is_named_with_its_links():
    text = """
[frame]
points = { O = [0, 0], D = ["220 mm", 0], E = ["300 mm", "100 mm"] }
[link.2]
points = { O = [0, 0], A = ["80 mm", 0] }
[link.3]
points = { A = [0, 0], B = ["250 mm", 0] }
[link.4]
points = { D = [0, 0], B = ["200 mm", 0] }
[link.5]
points = { E = [0, 0], B = ["150 mm", 0] }
[driver]
crank = "2"
angle = "60 deg"
omega = "10 rad/s"
"""
    with pytest.raises(StructureError) as info:
        find_structure(loads(text, "three.toml"))
    message = str(info.value)
    assert "W = 3n − 2p = 3·4 − 2·6 = 0" in message  # B joins three links: two joints
    assert "point B joins 3 bodies (link 3, link 4 and link 5)" in message


# --- assembly hints --------------------------------------------------------------------------------


def test_an_assembly_hint_far_from_both_assemblies_is_warned_about(tmp_path, capsys):
    far = FOUR_BAR.replace("B = [0.2, 0.2]", "B = [5, 5]")
    assert main(["solve", _scene(tmp_path, far), "--analytic-only"]) == 0
    err = capsys.readouterr().err
    assert err.count("plans: warning:") == 1
    assert f"assembly.B (line {_line(far, 'B = [5, 5]')}): B near (5, 5) m is far from both assemblies of RRR(3,4)" in err
    # the two assemblies of the four-bar at φ = 60°, by hand: A = 0.08·(cos 60°, sin 60°), circles |AB| = 0.25, |DB| = 0.2
    assert "(0.255, 0.1969) m on the branch chosen" in err and "(0.1139, -0.1695) m on the other" in err


def test_an_assembly_hint_near_one_assembly_is_not_warned_about(tmp_path, capsys):
    near = FOUR_BAR.replace("B = [0.2, 0.2]", "B = [0.12, -0.15]")
    assert main(["solve", _scene(tmp_path, near), "--analytic-only"]) == 0
    assert capsys.readouterr().err == ""


# --- a stroke too long to draw ---------------------------------------------------------------------


@pytest.mark.parametrize("stroke", ['["-1e30 m", "1e30 m"]', '["-1e5 m", "1e5 m"]'])
@pytest.mark.parametrize("command", [["draw", "-o", "OUT"], ["handout", "-o", "OUT.pdf"]])
def test_a_stroke_too_long_to_draw_is_refused_at_once(tmp_path, capsys, stroke, command):
    text = LADDER.replace('stroke = ["-60 mm", "60 mm"]', f"stroke = {stroke}")
    out = tmp_path / "out"
    start = time.perf_counter()
    status = main([command[0], _scene(tmp_path, text)] + [a.replace("OUT", str(out)) for a in command[1:]])
    assert time.perf_counter() - start < 20.0  # drawing a 1e30 m stroke ran out of memory (24 GB) before
    assert status == 2
    err = capsys.readouterr().err
    assert "driver.stroke" in err and "longer than the largest sheet (A0)" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]  # nothing written


def test_the_obstacle_grid_takes_a_shape_of_any_length():
    from shapely.geometry import LineString, Point

    from plans.drawing._canvas import Obstacles

    start = time.perf_counter()
    obstacles = Obstacles([LineString([(-1e12, 0), (1e12, 0)]), Point(5, 5).buffer(1)])
    assert len(obstacles.near(4, 4, 6, 6)) == 1 and len(obstacles.near(-1, -1, 1, 1)) == 1
    assert time.perf_counter() - start < 1.0


def test_plans_centres_says_how_bare_driver_numbers_were_read(tmp_path, capsys):
    text = SLIDER_CRANK.replace('omega = "2000 rpm"', "omega = 1850")
    assert main(["centres", _scene(tmp_path, text), "--no-drawing"]) == 0
    out, err = capsys.readouterr()
    assert "bare numbers read as SI and degrees: omega = 1850 → 1850 rad/s" in out
    assert f"driver.omega (line {_line(text, 'omega =')}) = 1850" in err
