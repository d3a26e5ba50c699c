"""Scene files: what they mean, and the messages bad ones get."""

import cmath
import math

import pytest

from plans import PlansError, SceneError, load, loads
from plans.scene import FRAME, Crank, LinearDriver, example_names, example_path

from accelerating_scenes import linear_arm_accelerating

FOUR_BAR = """
title = "test"
[frame]
points = { O = [0, 0], D = ["220 mm", 0] }
[link.2]
points = { O = [0, 0], A = ["80 mm", 0] }
[link.3]
points = { A = [0, 0], B = ["250 mm", 0], M = ["100 mm", "60 mm"] }
[link.4]
points = { D = [0, 0], B = ["200 mm", 0] }
[driver]
crank = "2"
angle = "60 deg"
omega = "10 rad/s"
[assembly]
B = [0.2, 0.2]
"""


def test_four_bar_is_read_in_si():
    scene = loads(FOUR_BAR)
    assert scene.title == "test"
    assert list(scene.bodies) == [FRAME, "2", "3", "4"]
    assert scene.bodies["3"].points["M"] == pytest.approx(0.1 + 0.06j)
    assert scene.driver == Crank(link="2", pivot="O", phi=math.radians(60), omega=10.0, epsilon=0.0)
    assert scene.assembly == {"B": 0.2 + 0.2j}
    assert scene.accelerations is True
    assert scene.report == ("A", "B", "M")  # frame points are at rest: not reported unless asked
    assert scene.bodies_with("B") == ["3", "4"]


def test_slider_block_becomes_a_link_with_a_prismatic_joint():
    scene = load(example_path("slider-crank"))
    (prismatic,) = scene.prismatics
    assert (prismatic.name, prismatic.slider, prismatic.guide, prismatic.guide_line) == ("B", "4", FRAME, "cylinder")
    block = scene.bodies["4"]
    assert block.block and block.points == {"B": 0j}
    guide = scene.line("frame.cylinder")
    assert guide.origin == pytest.approx(0.05j) and guide.angle == 0


def test_line_through_a_named_point_at_an_angle():
    scene = load(example_path("linear-arm"))
    sleeve = scene.line("4.sleeve")
    assert sleeve.through == "K" and sleeve.origin == pytest.approx(0.1)
    assert sleeve.direction == pytest.approx(cmath.exp(1j * math.pi / 3))
    driver = scene.driver
    assert isinstance(driver, LinearDriver)
    # the file gives v = 0.5 m/s and no acceleration (constant speed: a = 0), a stroke of ±100 mm
    assert (driver.velocity, driver.acceleration, driver.stroke) == (0.5, 0.0, pytest.approx((-0.1, 0.1)))
    # a given acceleration = "2 m/s^2" is read in m/s² (the same mechanism written out with it)
    assert linear_arm_accelerating().driver.acceleration == 2.0


def test_two_blocks_on_one_pin_get_distinct_joint_names():
    scene = load(example_path("wedge"))
    assert [p.name for p in scene.prismatics] == ["C3", "C4"]


def test_every_example_loads():
    assert len(example_names()) >= 8
    for name in example_names():
        assert load(example_path(name)).title


def _error(text: str) -> str:
    with pytest.raises(SceneError) as info:
        loads(text, source="bad.toml")
    assert isinstance(info.value, PlansError) and isinstance(info.value, ValueError)
    return str(info.value)


@pytest.mark.parametrize(
    "old, new, words",
    [
        ('crank = "2"', 'crank = "7"', ["bad.toml", "driver.crank", "there is no link '7'"]),
        ('omega = "10 rad/s"', 'omegaa = "10 rad/s"', ["unknown key 'omegaa'", "did you mean 'omega'?"]),
        ('angle = "60 deg"', 'angle = "60 kg"', ["driver.angle", "'60 kg' is not an angle"]),
        ('B = ["250 mm", 0], M', 'B = ["250 mm", 0, 1], M', ["link.3.points.B", "expected coordinates [x, y]"]),
        ('M = ["100 mm", "60 mm"]', 'M = ["250 mm", 0]', ["coincide", "link 3"]),
        ('[assembly]\nB = [0.2, 0.2]', '[assembly]\nX = [0.2, 0.2]', ["assembly.X", "no link has a point 'X'"]),
        ('D = ["220 mm", 0] }', 'D = ["220 mm", nan] }', ["frame.points.D[1]", "not a finite number"]),
    ],
)
def test_bad_scenes_name_file_field_and_fix(old, new, words):
    assert old in FOUR_BAR
    message = _error(FOUR_BAR.replace(old, new))
    for word in words:
        assert word in message, message


def test_malformed_toml_gives_the_line():
    message = _error(FOUR_BAR.replace('crank = "2"', 'crank = "2'))
    assert "not valid TOML" in message and "line 12" in message


def test_unknown_key_message_gives_its_line():
    message = _error(FOUR_BAR.replace('omega = "10 rad/s"', 'omegaa = "10 rad/s"'))
    assert "driver.omegaa (line 14)" in message


def test_missing_driver():
    assert "missing [driver]" in _error(FOUR_BAR.split("[driver]")[0])


def test_doubled_driver():
    assert "not both" in _error(FOUR_BAR.replace('crank = "2"', 'crank = "2"\nslider = "2"'))


def test_slider_on_a_missing_line_lists_the_lines():
    text = load_text("slider-crank").replace('on = "frame.cylinder"', 'on = "frame.cylindre"')
    message = _error(text)
    assert "slider.0.on" in message and "did you mean 'cylinder'?" in message


def test_slider_pinned_to_nothing():
    text = load_text("slider-crank").replace('pin = "B"', 'pin = "Q"')
    assert "no link or frame has a point 'Q'" in _error(text)


def test_unreadable_file(tmp_path):
    with pytest.raises(SceneError) as info:
        load(tmp_path / "missing.toml")
    assert "missing.toml" in str(info.value) and "cannot read" in str(info.value)


def test_unknown_example_suggests_a_name():
    with pytest.raises(SceneError) as info:
        example_path("six-bars")
    assert "did you mean 'six-bar'?" in str(info.value)


def load_text(name: str) -> str:
    return example_path(name).read_text()
