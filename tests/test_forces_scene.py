"""The kinetostatic part of a scene (issue 22): masses, centres, inertias, gravity, loads.

Values are typed here from domain.md §11 and the SI definitions (1 g = 1e-3 kg,
1 kN = 1000 N, 1 N·mm = 1e-3 N·m, 1 kg·mm² = 1e-6 kg·m²); hard cases must give
one clear message naming the file, the key and the link, and exit status 2.
"""

import cmath
import math

import pytest

from plans.cli import main
from plans.errors import PlansError, SceneError
from plans.scene import example_names, example_path, load, loads

WORKED = example_path("slider-crank-loads").read_text(encoding="utf-8")

BASE = """title = "t"
[frame]
points = { O = [0, 0] }
lines = { cylinder = { through = [0, "20 mm"], angle = 0 } }
[link.2]
points = { O = [0, 0], A = ["100 mm", 0] }
[link.3]
points = { A = [0, 0], B = ["300 mm", 0], S3 = ["100 mm", 0] }
[[slider]]
pin = "B"
on = "frame.cylinder"
[driver]
crank = "2"
angle = "60 deg"
omega = "150 rad/s"
[assembly]
B = [0.38, 0.02]
"""


def edit(text, old, new):
    assert old in text, old
    return text.replace(old, new, 1)


def scene_with(**sections):
    """BASE with lines added after a section header (key: the header without brackets)."""
    text = BASE
    for header, lines in sections.items():
        header = header.replace("_", ".")
        text = edit(text, f"[{header}]\n", f"[{header}]\n{lines}\n")
    return text


def test_the_worked_example_reads_as_domain_md_states_it():
    scene = load(example_path("slider-crank-loads"))
    m2, m3, m4 = scene.masses["2"], scene.masses["3"], scene.masses["4"]
    assert (m2.mass, m2.centre, m2.inertia, m2.point) == (2.0, 0.04 + 0j, 0.004, None)
    assert (m3.mass, m3.centre, m3.inertia, m3.point) == (3.0, 0.1 + 0j, 0.025, "S3")
    assert (m4.mass, m4.centre, m4.inertia, m4.point) == (4.0, 0j, 0.0, "B")  # a block's centre: its pin
    assert scene.gravity.g == 9.81 and scene.gravity.vector == pytest.approx(-9.81j, abs=1e-15)
    (resistance,) = scene.loads
    assert (resistance.name, resistance.body, resistance.kind, resistance.point, resistance.magnitude) == ("F_r", "4", "resistance", "B", 1500.0)
    assert resistance.working is None
    assert scene.has_forces


def test_a_scene_without_masses_or_loads_has_none():
    for name in example_names():
        scene = load(example_path(name))
        assert scene.masses == {} and scene.loads == () and scene.gravity is None and not scene.has_forces


def test_every_kinematic_example_with_loads_has_a_loaded_variant():
    loaded = example_names(loads=True)
    assert "slider-crank-loads" in loaded
    for name in example_names():
        if name == "slider-crank":
            continue  # its variant is the worked example of §11
        assert f"{name}-loads" in loaded, name
        scene = load(example_path(f"{name}-loads"))
        assert scene.has_forces and scene.gravity is not None
        plain = load(example_path(name))
        assert [b for b in scene.bodies] == [b for b in plain.bodies]
        assert all(scene.bodies[b].points == plain.bodies[b].points for b in plain.bodies), name


@pytest.mark.parametrize(
    "written, kind, si",
    [
        ('mass = "2500 g"\ncentre = "S3"', "mass", 2.5),
        ('mass = "0.002 t"\ncentre = "S3"', "mass", 2.0),
        ('mass = 3\ncentre = "S3"\ninertia = "25000 kg*mm^2"', "inertia", 0.025),
        ('mass = 3\ncentre = "S3"\ninertia = "0.025 kg·m²"', "inertia", 0.025),
        ('mass = 3\ncentre = "S3"\ninertia = 0.5', "inertia", 0.5),
    ],
)
def test_masses_and_inertias_in_their_units(written, kind, si):
    scene = loads(scene_with(link_3=written))
    m = scene.masses["3"]
    assert (m.mass if kind == "mass" else m.inertia) == pytest.approx(si, rel=1e-15)


def test_a_centre_by_coordinates_in_the_links_own_frame():
    scene = loads(scene_with(link_3='mass = 1\ncentre = ["50 mm", "-10 mm"]'))
    assert scene.masses["3"].centre == pytest.approx(0.05 - 0.01j, abs=1e-16) and scene.masses["3"].point is None


@pytest.mark.parametrize(
    "force, expected",
    [
        ('force = ["1.5 kN", "-200 N"]', 1500 - 200j),
        ('force = { magnitude = "100 N", angle = "30 deg" }', 100 * cmath.exp(1j * math.pi / 6)),
        ('force = { magnitude = "2 kN", angle = 90 }', 2000j),
    ],
)
def test_forces_in_their_forms_and_units(force, expected):
    scene = loads(BASE + f'[[load]]\nlink = "3"\nat = "B"\n{force}\n')
    (f,) = scene.loads
    assert f.kind == "force" and f.force == pytest.approx(expected, abs=1e-12) and f.name == "F1"
    assert f.at == 0.3 + 0j and f.point == "B"


def test_a_couple_and_a_resistance_over_the_working_stroke():
    scene = loads(
        BASE
        + '[[load]]\nlink = "2"\nmoment = "-2500 N*mm"\n'
        + '[[load]]\nname = "F_c"\nlink = "4"\nat = "B"\nforce = { magnitude = "1 kN", against = "velocity" }\nworking = [-1, 0]\n'
    )
    couple, resistance = scene.loads
    assert (couple.name, couple.kind, couple.moment) == ("M1", "moment", pytest.approx(-2.5, rel=1e-15))
    assert (resistance.kind, resistance.magnitude) == ("resistance", 1000.0)
    assert resistance.working == pytest.approx(-1 + 0j, abs=1e-15)


def test_gravity_in_any_direction():
    scene = loads(BASE + '[gravity]\ng = "1 g"\nangle = "180 deg"\n')
    assert scene.gravity.vector == pytest.approx(-9.80665 + 0j, abs=1e-12)


# --- hard cases: one clear message, naming file, key and link --------------------

HARD = [
    (BASE + '[[load]]\nlink = "2"\nat = "B"\nforce = [1, 0]\n', "load.0.at", ["'B' is not a point of link 2", "link 3", "O, A"]),
    (scene_with(link_3='mass = "-3 kg"\ncentre = "S3"'), "link.3.mass", ["not negative"]),
    (scene_with(link_3='mass = 3\ncentre = "S3"\ninertia = "-1 kg*m^2"'), "link.3.inertia", ["not negative"]),
    (scene_with(link_3='mass = "3 kg"'), "link.3.mass", ["link 3 has a mass but no centre of mass", "centre = "]),
    (scene_with(link_3='mass = "3 kg"\ncentre = "S2"'), "link.3.centre", ["link 3 has no point 'S2'", "its points: A, B, S3"]),
    (scene_with(link_3='centre = "S3"'), "link.3.centre", ["no mass or inertia"]),
    (scene_with(link_3='mass = "3 m"\ncentre = "S3"'), "link.3.mass", ["is not a mass", "a unit of length"]),
    (scene_with(frame='mass = "3 kg"'), "frame.mass", ["the frame does not move"]),
    (BASE + '[[load]]\nlink = "frame"\nat = "O"\nforce = [1, 0]\n', "load.0.link", ["a load on the frame"]),
    (BASE + '[[load]]\nlink = "7"\nat = "O"\nforce = [1, 0]\n', "load.0.link", ["there is no link '7'"]),
    (BASE + '[[load]]\nlink = "3"\nat = "B"\nforce = [1, 0]\nmoment = 2\n', "load.0", ["give one of them"]),
    (BASE + '[[load]]\nlink = "3"\nat = "B"\n', "load.0", ["give one of them"]),
    (BASE + '[[load]]\nlink = "3"\nat = "B"\nmoment = "2 N*m"\n', "load.0.at", ["a couple acts on the whole link"]),
    (BASE + '[[load]]\nlink = "3"\nforce = [1, 0]\n', "load.0", ["a force needs the point it acts at"]),
    (BASE + '[[load]]\nlink = "3"\nat = "B"\nforce = { magnitude = "1 N", against = "acceleration" }\n', "load.0.force.against", ['against = "velocity"']),
    (BASE + '[[load]]\nlink = "3"\nat = "B"\nforce = { magnitude = "-1 N", angle = 0 }\n', "load.0.force.magnitude", ["not negative"]),
    (BASE + '[[load]]\nlink = "3"\nat = "B"\nforce = { magnitude = "1 N" }\n', "load.0.force", ["angle"]),
    (BASE + '[[load]]\nlink = "3"\nat = "B"\nforce = { magnitude = "1 N", angel = 0 }\n', "load.0.force", ["angle"]),
    (BASE + '[[load]]\nlink = "3"\nat = "B"\nforce = ["1 N*m", 0]\n', "load.0.force[0]", ["is not a force", "a unit of moment"]),
    (BASE + '[[load]]\nlink = "3"\nat = "B"\nforce = [1, 0]\nworking = [0, 0]\n', "load.0.working", ["zero length"]),
    (BASE + '[[load]]\nlink = "3"\nat = "B"\nforce = [1, 0]\n[[load]]\nname = "F1"\nlink = "3"\nat = "A"\nforce = [0, 1]\n', "load.1.name", ["both named 'F1'"]),
    (BASE + '[gravity]\ng = "-9.81 m/s^2"\n', "gravity.g", ["not negative"]),
    (BASE + '[gravity]\nangle = "-90 deg"\n', "gravity", ["give g ="]),
    (BASE + '[[load]]\nlink = "3"\nat = "B"\nfroce = [1, 0]\n', "load.0.froce", ["did you mean 'force'"]),
]


@pytest.mark.parametrize("text, key, words", HARD, ids=[h[1] + ":" + h[2][0][:20] for h in HARD])
def test_hard_cases_are_refused_naming_the_key(text, key, words):
    with pytest.raises(SceneError) as info:
        loads(text, source="s.toml")
    message = str(info.value)
    assert message.startswith(f"s.toml: {key}"), message
    for word in words:
        assert word in message, (word, message)
    assert isinstance(info.value, PlansError) and isinstance(info.value, ValueError)


def test_a_merged_blocks_mass_belongs_under_its_link():
    text = edit(BASE, 'on = "frame.cylinder"\n', 'on = "frame.cylinder"\nmass = "1 kg"\nname = "4"\n')
    text = edit(text, "[[slider]]\n", "[link.4]\npoints = { B = [0, 0] }\n[[slider]]\n")
    assert loads(edit(text, 'mass = "1 kg"\n', ""), source="s.toml").masses == {}  # without the mass it is a scene
    with pytest.raises(SceneError, match=r"slider.0.mass.*described under \[link.4\]"):
        loads(text, source="s.toml")


def test_the_cli_refuses_a_hard_case_with_exit_status_2(tmp_path, capsys):
    path = tmp_path / "bad.toml"
    path.write_text(HARD[0][0], encoding="utf-8")
    assert main(["solve", str(path), "--analytic-only"]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"plans: error: {path}: load.0.at (line ") and "not a point of link 2" in err
    assert "Traceback" not in err
