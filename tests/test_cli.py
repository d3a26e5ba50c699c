"""The command line: output, exit status, messages, and files left alone on failure."""

import csv
import math
import io
import json
import subprocess
import sys

import pytest

from plans.cli import main
from plans.scene import example_names, example_path

# domain.md §6, E2 (exact values)
E2_V_B = complex(-16.0407098, 0.0)
E2_A_B = complex(-3730.28395, 0.0)
E2_OMEGA_3 = -59.4427657


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_examples_lists_every_bundled_scene(capsys):
    status, out, _ = run(capsys, "examples")
    assert status == 0
    assert [line.split()[0] for line in out.splitlines()] == example_names()


def test_solve_json_follows_the_schema_and_matches_e2(capsys):
    status, out, _ = run(capsys, "solve", "--example", "slider-crank", "--json")
    assert status == 0
    doc = json.loads(out)
    assert doc["title"] == "Offset slider-crank"  # the English title (the example gives it in five languages)
    assert doc["structure"] == "I(1,2) → RRP(3,4)"
    assert doc["driver"]["type"] == "crank" and doc["driver"]["phi_deg"] == pytest.approx(45.0)
    b = doc["points"]["B"]
    assert complex(*b["analytic"]["v"]) == pytest.approx(E2_V_B, rel=1e-7)
    assert complex(*b["analytic"]["a"]) == pytest.approx(E2_A_B, rel=1e-7)
    assert doc["links"]["3"]["analytic"]["omega"] == pytest.approx(E2_OMEGA_3, rel=1e-7)
    assert complex(*b["graphical"]["v"]) == pytest.approx(E2_V_B, rel=1e-7)
    assert b["graphical"]["v_rel_error"] < 1e-9
    assert set(doc["scales"]) >= {"k_l", "k_v", "k_a"}
    assert set(doc["sliders"]["B"]["analytic"]) == {"s", "v_rel", "a_rel", "coriolis"}
    assert doc["groups"]["RRP(3,4)"]["condition"] >= 1


def test_solve_json_is_deterministic(capsys):
    first = run(capsys, "solve", "--example", "six-bar", "--json")[1]
    second = run(capsys, "solve", "--example", "six-bar", "--json")[1]
    assert first == second


def test_velocities_only_scene_has_no_acceleration_keys(capsys, tmp_path):
    text = example_path("four-bar").read_text() + "\n[compute]\naccelerations = false\npoints = [\"B\", \"M\"]\n"
    scene = tmp_path / "v.toml"
    scene.write_text(text)
    status, out, _ = run(capsys, "solve", str(scene), "--json")
    doc = json.loads(out)
    assert status == 0
    assert list(doc["points"]) == ["B", "M"]
    assert "a" not in doc["points"]["M"]["analytic"] and "a" not in doc["points"]["M"]["graphical"]
    assert "epsilon" not in doc["links"]["3"]["analytic"]
    assert "k_a" not in doc["scales"]


def test_solve_table_names_units_and_methods(capsys):
    status, out, _ = run(capsys, "solve", "--example", "quick-return")
    assert status == 0
    assert "I(1,2) → RPR(3,4) → RRP(5,6)" in out
    assert "v [m/s]" in out and "graphical" in out and "Coriolis" in out


def test_solve_at_another_position(capsys):
    _, out, _ = run(capsys, "solve", "--example", "slider-crank", "--at", "90", "--json", "--analytic-only")
    doc = json.loads(out)
    assert doc["driver"]["phi_deg"] == pytest.approx(90.0)
    # at 90°, A = (0, 0.1): hand value of the crank pin
    assert doc["points"]["A"]["analytic"]["r"] == pytest.approx([0.0, 0.1], abs=1e-15)


def test_bad_scene_exits_2_with_one_line(capsys, tmp_path):
    scene = tmp_path / "bad.toml"
    scene.write_text(example_path("four-bar").read_text().replace('crank = "2"', 'crank = "9"'))
    status, out, err = run(capsys, "solve", str(scene))
    assert status == 2 and out == ""
    assert err.count("\n") == 1 and "bad.toml" in err and "driver.crank" in err
    assert "Traceback" not in err


def test_missing_scene_argument(capsys):
    status, _, err = run(capsys, "solve")
    assert status == 2 and "--example" in err


def test_sweep_writes_one_row_per_position(capsys, tmp_path):
    target = tmp_path / "sweep.csv"
    status, out, _ = run(capsys, "sweep", "--example", "six-bar", "--steps", "36", "-o", str(target), "--start", "scene")
    assert status == 0
    assert "driver law: constant angular velocity: ω₂ = −10 rad/s, ε₂ = 0" in out  # the law stated beside the file written
    rows = list(csv.DictReader(io.StringIO(target.read_text())))
    assert len(rows) == 36
    assert float(rows[0]["driver_phi_deg"]) == pytest.approx(55.0)
    assert float(rows[0]["t"]) == 0 and float(rows[1]["t"]) == pytest.approx(math.radians(10) / 10)
    assert float(rows[1]["driver_phi_deg"]) == pytest.approx(45.0)  # ω = −10 rad/s: the sweep runs clockwise
    assert all(row["assembled"] == "1" for row in rows)
    assert "RPR(5,6).condition" in rows[0] and "E.coriolis_x" in rows[0]


def test_failed_sweep_leaves_an_existing_file_alone(capsys, tmp_path):
    target = tmp_path / "sweep.csv"
    target.write_text("precious\n")
    scene = tmp_path / "nostroke.toml"
    scene.write_text(example_path("ladder").read_text().replace('stroke = ["-60 mm", "60 mm"]', ""))
    status, _, err = run(capsys, "sweep", str(scene), "-o", str(target))
    assert status == 2 and "stroke" in err
    assert target.read_text() == "precious\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["nostroke.toml", "sweep.csv"]  # no temporary left


def test_solve_never_imports_matplotlib_and_analytic_only_not_shapely():
    code = (
        "import sys, io, contextlib\n"
        "from plans.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        "    main(['solve', '--example', 'six-bar', '--analytic-only'])\n"
        "heavy = [m for m in ('matplotlib', 'shapely') if m in sys.modules]\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        "    main(['solve', '--example', 'six-bar'])\n"
        "print(heavy, 'matplotlib' in sys.modules)\n"
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert result.stdout.strip() == "[] False"


def test_draw_several_positions_writes_a_sheet_each(capsys, tmp_path):
    status, out, _ = run(capsys, "draw", "--example", "four-bar", "--at", "0,90 deg", "-o", str(tmp_path))
    assert status == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["positions.svg", "sheet-00.svg", "sheet-01.svg"]
    assert out.split() == [str(tmp_path / n) for n in ("sheet-00.svg", "sheet-01.svg", "positions.svg")]


def test_positions_and_a_list_are_exclusive(capsys, tmp_path):
    status, _, err = run(capsys, "draw", "--example", "four-bar", "--at", "0,90", "--positions", "4", "-o", str(tmp_path))
    assert status == 2 and "not both" in err
    assert list(tmp_path.iterdir()) == []


def test_sweep_plot_draws_the_cycle_diagrams(capsys, tmp_path):
    status, out, err = run(capsys, "sweep", "--example", "quick-return", "--steps", "36", "--plot", str(tmp_path), "--positions", "4")
    assert status == 0
    # the cycle diagrams, and the output link's kinematic diagrams by graphical differentiation (issue 19 §4)
    names = sorted(p.name for p in tmp_path.iterdir())
    assert [n for n in names if not n.startswith("kinematic")] == ["links.svg", "points.svg", "sliders.svg"]
    assert names[0] in ("kinematic.svg", "kinematic-1.svg")
    # without -o the CSV goes to standard output as the help says (issue 9), the diagrams' names to stderr
    assert out.startswith("driver_phi_deg,") and len(out.splitlines()) == 37
    assert str(tmp_path / "links.svg") in err


def test_handout_in_russian_is_a_pdf(capsys, tmp_path):
    target = tmp_path / "sc.pdf"
    status, _, _ = run(capsys, "handout", "--example", "slider-crank", "-o", str(target), "--lang", "ru")
    assert status == 0
    assert target.read_bytes().startswith(b"%PDF")


def test_unknown_language_is_refused_by_the_parser(capsys, tmp_path):
    with pytest.raises(SystemExit) as info:
        main(["handout", "--example", "slider-crank", "-o", str(tmp_path / "x.pdf"), "--lang", "de"])
    assert info.value.code == 2
    assert "invalid choice: 'de'" in capsys.readouterr().err
