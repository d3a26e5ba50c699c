"""Bad input: one clear message, exit status 2, no traceback, and no file written or overwritten.

Every item of the list in issue 4 (malformed TOML, unknown keys, references to
things that do not exist, a group attached to nothing solved, duplicate names,
zero or negative lengths, coincident points, a zero guide direction, NaN or
infinite numbers, impossible units, a driver missing or doubled, mobility ≠ 1,
numbers beyond range) plus positions that cannot be solved, each run through
``plans solve``, ``plans sweep -o FILE.csv`` and ``plans draw -o DIR`` with
existing output files that must stay untouched, with no temporary file left.
"""

import re

import pytest

from plans.cli import main
from plans.scene import example_path

FOUR_BAR = """title = "test four-bar"
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

SLIDER_CRANK = example_path("slider-crank").read_text(encoding="utf-8")

TRIAD = """[frame]
points = { O = [0, 0], Y = [0.3, -0.2], Z = [0.6, -0.1] }
[link.2]
points = { O = [0, 0], A = [0.1, 0] }
[link.5]
points = { P = [0, 0], Q = [0.2, 0], R = [0.1, 0.15] }
[link.6]
points = { A = [0, 0], P = [0.2, 0] }
[link.7]
points = { Q = [0, 0], Y = [0.25, 0] }
[link.8]
points = { R = [0, 0], Z = [0.3, 0] }
[driver]
crank = "2"
angle = "30 deg"
omega = "10 rad/s"
"""


def edit(text, old, new):
    assert old in text, old
    return text.replace(old, new, 1)


def line_of(text, needle):
    return next(i for i, line in enumerate(text.splitlines(), 1) if needle in line)


# (id, scene text, extra arguments, words the one-line message must contain)
CASES = [
    (
        "malformed-toml",
        edit(FOUR_BAR, 'crank = "2"', 'crank = "2'),
        [],
        ["bad.toml", "not valid TOML", f"line {line_of(FOUR_BAR, 'crank =')}"],
    ),
    (
        "unknown-key",
        edit(FOUR_BAR, 'omega = "10', 'omegaa = "10'),
        [],
        ["bad.toml", f"driver.omegaa (line {line_of(FOUR_BAR, 'omega =')})", "unknown key 'omegaa'", "did you mean 'omega'?"],
    ),
    ("unknown-section", edit(FOUR_BAR, "[assembly]", "[asembly]"), [], ["bad.toml", "unknown key 'asembly'", "did you mean 'assembly'?"]),
    (
        "missing-point-in-compute",
        FOUR_BAR + '[compute]\npoints = ["B", "X"]\n',
        [],
        ["bad.toml", "compute.points[1]", "no link has a point 'X'"],
    ),
    (
        "missing-point-of-a-line",
        edit(FOUR_BAR, 'M = ["100 mm", "60 mm"] }', 'M = ["100 mm", "60 mm"] }\nlines = { rod = { through = "N", angle = 0 } }'),
        [],
        ["bad.toml", "link.3.lines.rod.through", "link 3 has no point 'N'"],
    ),
    ("missing-link-of-a-guide", edit(SLIDER_CRANK, 'on = "frame.cylinder"', 'on = "9.cylinder"'), [], ["bad.toml", "slider.0.on", "there is no link '9'"]),
    ("missing-line", edit(SLIDER_CRANK, 'on = "frame.cylinder"', 'on = "frame.cylindre"'), [], ["bad.toml", "slider.0.on", "did you mean 'cylinder'?"]),
    ("missing-driver-link", edit(FOUR_BAR, 'crank = "2"', 'crank = "9"'), [], ["bad.toml", "driver.crank", "there is no link '9'"]),
    ("missing-hint-point", edit(FOUR_BAR, "B = [0.2, 0.2]", "X = [0.2, 0.2]"), [], ["bad.toml", "assembly.X", "no link has a point 'X'"]),
    (
        "group-attached-to-nothing-solved",
        TRIAD,
        [],
        ["bad.toml", "links 5, 6, 7, 8 do not form class-II Assur groups", "solved before them (the frame, 2)",
         "link 5 joins P with 6 (not solved)", "each dyad needs one joint from each of its two links to a solved link"],
    ),
    (
        "misspelt-joint",
        edit(FOUR_BAR, 'D = [0, 0], B = ["200 mm", 0]', 'D = [0, 0], b = ["200 mm", 0]'),
        [],
        ["bad.toml", "mobility W = 3n − 2p = 3·3 − 2·3 = 3", "needs W = 1", "did you mean 'b', of link 4?"],
    ),
    ("duplicate-link-name", edit(SLIDER_CRANK, 'on = "frame.cylinder"', 'on = "frame.cylinder"\nname = "3"'), [], ["bad.toml", "slider.0.name", "there is already a link named '3'"]),
    ("duplicate-point-in-compute", FOUR_BAR + '[compute]\npoints = ["B", "M", "B"]\n', [], ["bad.toml", "compute.points[2]", "'B' is listed twice (also as compute.points[0])"]),
    ("frame-as-a-link", FOUR_BAR + "[link.frame]\npoints = { O = [0, 0] }\n", [], ["bad.toml", "link.frame", "described under [frame]"]),
    ("zero-length-crank", edit(FOUR_BAR, 'A = ["80 mm", 0]', "A = [0, 0]"), [], ["bad.toml", "link.2.points.A", "points O and A of link 2 coincide"]),
    ("negative-scale", FOUR_BAR + "[scales]\nk_v = -0.1\n", [], ["bad.toml", "scales.k_v", "must be a positive number"]),
    ("zero-precision", FOUR_BAR + "[scales]\nprecision = 0\n", [], ["bad.toml", "scales.precision", "must be a positive number"]),
    (
        "nearly-coincident-points",
        edit(FOUR_BAR, 'A = ["80 mm", 0]', 'A = ["1e-12 mm", 0]'),
        [],
        ["bad.toml", "link.2.points.A", "points O and A of link 2 are 1e-15 m apart", "coincide to double precision"],
    ),
    (
        "zero-guide-direction",
        edit(SLIDER_CRANK, 'angle = 0 } }', "direction = [0, 0] } }"),
        [],
        ["bad.toml", "frame.lines.cylinder.direction", "has zero length and points nowhere", "give a non-zero [dx, dy]"],
    ),
    ("nan", edit(FOUR_BAR, 'omega = "10 rad/s"', "omega = nan"), [], ["bad.toml", "driver.omega", "not a finite number"]),
    ("infinite", edit(FOUR_BAR, 'D = ["220 mm", 0]', "D = [inf, 0]"), [], ["bad.toml", "frame.points.D[0]", "not a finite number"]),
    ("nan-text", edit(FOUR_BAR, 'angle = "60 deg"', 'angle = "nan deg"'), [], ["bad.toml", "driver.angle", "expected an angle such as"]),
    ("kilograms-as-a-length", edit(FOUR_BAR, 'A = ["80 mm", 0]', 'A = ["3 kg", 0]'), [], ["bad.toml", "link.2.points.A[0]", "'3 kg' is not a length", "use one of: m, mm"]),
    ("metres-as-an-angle", edit(FOUR_BAR, 'angle = "60 deg"', 'angle = "60 m"'), [], ["bad.toml", "driver.angle", "('m' is a unit of length)", "use one of: deg"]),
    ("beyond-range", edit(FOUR_BAR, 'D = ["220 mm", 0]', 'D = ["1e300 mm", 0]'), [], ["bad.toml", "frame.points.D[0]", "beyond the range plans computes in", "at most 1e+30 m"]),
    ("missing-driver", FOUR_BAR.split("[driver]")[0] + "[assembly]\nB = [0.2, 0.2]\n", [], ["bad.toml", "missing [driver]", 'crank = "2"']),
    ("doubled-driver", edit(FOUR_BAR, 'crank = "2"', 'crank = "2"\nslider = "2"'), [], ["bad.toml", "driver", "either crank", "not both"]),
    ("driver-table-twice", FOUR_BAR + '[driver]\ncrank = "2"\n', [], ["bad.toml", "not valid TOML"]),
    (
        "mobility-two",
        FOUR_BAR.split("[link.4]")[0] + FOUR_BAR.split('B = ["200 mm", 0] }')[1].replace("B = [0.2, 0.2]", ""),
        [],
        ["bad.toml", "mobility W = 3n − 2p = 3·2 − 2·2 = 2", "needs W = 1", "a link or joint is missing"],
    ),
    (
        "mobility-zero",
        edit(FOUR_BAR, 'points = { A = [0, 0], B = ["250 mm", 0], M = ["100 mm", "60 mm"] }', 'points = { A = [0, 0], B = ["250 mm", 0], D = ["220 mm", "-100 mm"] }'),
        [],
        ["bad.toml", "mobility W = 3n − 2p = 3·3 − 2·5 = -1", "needs W = 1", "too many joints"],
    ),
    ("position-in-kilograms", FOUR_BAR, ["--at", "3 kg"], ["bad.toml", "--at", "'3 kg' is not a"]),
]

#: positions that cannot be solved (no scene error): solve and draw only
POSITION_CASES = [
    (
        "cannot-assemble",
        edit(edit(FOUR_BAR, 'D = ["220 mm", 0]', 'D = ["700 mm", 0]'), 'B = ["250 mm", 0]', 'B = ["450 mm", 0]').replace("B = [0.2, 0.2]", "B = 1"),
        ["--at", "180"],
        ["RRR(3,4): joint B cannot assemble at φ = 180.0°: |AD| = 0.780 m > AB + BD = 0.650 m (gap 0.130 m)"],
    ),
    (
        "dead-centre",
        edit(edit(FOUR_BAR, 'D = ["220 mm", 0]', 'D = ["700 mm", 0]'), 'B = ["250 mm", 0]', 'B = ["580 mm", 0]').replace("B = [0.2, 0.2]", "B = 1"),
        ["--at", "180"],
        ["RRR(3,4): dead centre at φ = 180.0°: A, B and D are in line", "below the dead-centre threshold 1e-07"],
    ),
]


@pytest.fixture
def outputs(tmp_path):
    """An existing CSV and an existing drawing directory, with contents that must survive."""
    csv_file = tmp_path / "out" / "sweep.csv"
    csv_file.parent.mkdir()
    csv_file.write_text("precious csv\n")
    drawings = tmp_path / "drawings"
    drawings.mkdir()
    for name in ("mechanism.svg", "velocity.svg", "acceleration.svg", "sheet.svg"):
        (drawings / name).write_text(f"precious {name}\n")
    return csv_file, drawings


def snapshot(*directories):
    return {p: (p.read_bytes() if p.is_file() else None) for d in directories for p in sorted(d.rglob("*"))}


def run(capsys, argv):
    status = main(argv)
    out, err = capsys.readouterr()
    return status, out, err


def assert_one_clear_line(status, out, err, words):
    assert status == 2, err
    assert out == ""
    assert err.count("\n") == 1 and err.startswith("plans: error: "), err
    assert "Traceback" not in err
    for word in words:
        assert word in err, (word, err)


@pytest.mark.parametrize("name, text, extra, words", CASES, ids=[c[0] for c in CASES])
def test_bad_scene_gives_one_clear_message_and_writes_nothing(tmp_path, capsys, outputs, name, text, extra, words):
    scene = tmp_path / "bad.toml"
    scene.write_text(text, encoding="utf-8")
    csv_file, drawings = outputs
    before = snapshot(csv_file.parent, drawings)
    commands = [["solve", str(scene)], ["sweep", str(scene), "--steps", "12", "-o", str(csv_file)], ["draw", str(scene), "-o", str(drawings)]]
    for argv in commands:
        if extra and argv[0] == "sweep":
            continue  # a sweep takes no --at
        status, out, err = run(capsys, argv + extra)
        assert_one_clear_line(status, out, err, words)
    assert snapshot(csv_file.parent, drawings) == before  # untouched, and no temporary file left


@pytest.mark.parametrize("name, text, extra, words", POSITION_CASES, ids=[c[0] for c in POSITION_CASES])
def test_a_position_that_cannot_be_solved_gives_one_clear_message_and_writes_nothing(tmp_path, capsys, outputs, name, text, extra, words):
    scene = tmp_path / "bad.toml"
    scene.write_text(text, encoding="utf-8")
    csv_file, drawings = outputs
    before = snapshot(csv_file.parent, drawings)
    for argv in (["solve", str(scene)], ["solve", str(scene), "--analytic-only", "--json"], ["draw", str(scene), "-o", str(drawings)]):
        status, out, err = run(capsys, argv + extra)
        assert_one_clear_line(status, out, err, words)
    assert snapshot(csv_file.parent, drawings) == before


def test_a_sweep_that_solves_no_position_is_an_error_and_writes_nothing(tmp_path, capsys, outputs):
    text = edit(FOUR_BAR, 'D = ["220 mm", 0]', 'D = ["900 mm", 0]').replace("B = [0.2, 0.2]", "B = 1")
    scene = tmp_path / "bad.toml"
    scene.write_text(text)
    csv_file, drawings = outputs
    before = snapshot(csv_file.parent)
    status, out, err = run(capsys, ["sweep", str(scene), "--steps", "12", "-o", str(csv_file)])
    assert_one_clear_line(status, out, err, ["RRR(3,4): joint B cannot assemble at φ = 60.0°", "not solved at any of the 12 positions"])
    assert snapshot(csv_file.parent) == before


@pytest.mark.parametrize("argv, words", [
    (["solve", "--example", "four-bar", "--k-l", "-1"], ["--k-l", "expected a positive number, got '-1'"]),
    (["solve", "--example", "four-bar", "--precision", "nan"], ["--precision", "expected a positive number"]),
    (["solve", "--example", "four-bar", "--warn-condition", "0.5"], ["--warn-condition", "at least 1"]),
])
def test_bad_options_exit_2_without_a_traceback(capsys, argv, words):
    with pytest.raises(SystemExit) as exit_info:
        main(argv)
    _, err = capsys.readouterr()
    assert exit_info.value.code == 2 and "Traceback" not in err
    for word in words:
        assert word in err


def test_messages_quote_the_file_even_for_structure_errors(tmp_path, capsys):
    scene = tmp_path / "triad.toml"
    scene.write_text(TRIAD)
    status, _, err = run(capsys, ["solve", str(scene)])
    assert status == 2 and re.match(rf"^plans: error: {re.escape(str(scene))}: links ", err)


def test_an_output_that_cannot_be_written_is_one_line_and_leaves_no_temporary(tmp_path, capsys):
    target = tmp_path / "a-directory"
    target.mkdir()
    (target / "keep.txt").write_text("keep\n")
    before = snapshot(tmp_path)
    status, out, err = run(capsys, ["sweep", "--example", "four-bar", "--steps", "12", "-o", str(target)])
    assert_one_clear_line(status, out, err, [f"cannot write {target}", "Is a directory"])
    assert snapshot(tmp_path) == before
