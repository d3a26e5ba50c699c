"""``plans forces``, ``plans sweep`` with forces and ``plans examples --loads`` (issue 22).

Expected numbers are domain.md §11's; words are typed here from the textbooks'
terms (domain.md §11's table), so a changed translation or JSON key fails.
"""

import csv
import io
import json
import math

import pytest

from plans.cli import main
from plans.scene import example_names, example_path

M_B = 620.218316

TOP = ["schema", "title", "driver", "structure", "units", "loads", "reactions", "balancing", "power", "lever", "scales", "warnings"]
UNITS = {"force": "N", "moment": "N*m", "length": "m", "angle": "deg", "power": "W", "lever_length": "mm", "lever_moment": "N*mm"}
LOAD = ["name", "link", "kind", "point", "r", "force", "moment"]
REACTION = ["joint", "kind", "by", "on", "group", "analytic", "force_plans"]  # force_plans: the force plans (branch forces-plans) are present
REACTION_R = ["force", "magnitude", "angle_deg", "point"]
REACTION_P = REACTION_R + ["normal", "normal_force"]
LEVER = ["k_v", "precision", "turn_deg", "images", "forces", "couples", "balancing_force", "crank_length"]
LEVER_FORCE = ["name", "link", "kind", "image", "point", "force", "arm_mm", "foot", "moment_Nmm"]


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_json_has_exactly_the_documented_keys_and_the_worked_example(capsys):
    status, out, _ = run(capsys, "forces", "--example", "slider-crank-loads", "--json")
    assert status == 0
    doc = json.loads(out)
    assert list(doc) == TOP and doc["schema"] == 1
    assert doc["units"] == UNITS
    assert doc["structure"] == "I(1,2) → RRP(3,4)"  # one frame number: crank 2, frame 1 (issue 20 §2)
    assert [entry["name"] for entry in doc["loads"]] == ["G_2", "F_Φ2", "M_Φ2", "G_3", "F_Φ3", "M_Φ3", "G_4", "F_Φ4", "F_r"]
    assert all(list(entry) == LOAD for entry in doc["loads"])
    assert list(doc["reactions"]) == ["R_12", "R_23", "R_34", "R_14"]
    for label, entry in doc["reactions"].items():
        assert list(entry) == REACTION
        assert list(entry["analytic"]) == (REACTION_P if entry["kind"] == "P" else REACTION_R)
    assert (doc["reactions"]["R_12"]["by"], doc["reactions"]["R_12"]["on"], doc["reactions"]["R_12"]["joint"]) == ("1", "2", "O")
    assert doc["reactions"]["R_23"]["analytic"]["magnitude"] == pytest.approx(8353.55006, abs=1e-5)
    assert doc["reactions"]["R_23"]["analytic"]["angle_deg"] == pytest.approx(192.098702, abs=5e-7)
    assert doc["reactions"]["R_14"]["analytic"]["normal_force"] == pytest.approx(-2077.57014, abs=1e-5)
    balancing = doc["balancing"]
    assert (balancing["kind"], balancing["symbol"]) == ("moment", "M_b")
    assert balancing["analytic"] == pytest.approx(M_B, abs=5e-7)
    assert balancing["lever"]["value"] == pytest.approx(M_B, abs=5e-7)  # plans forces reads exactly unless told a precision
    assert list(doc["lever"]) == LEVER and doc["lever"]["turn_deg"] == 90
    assert all(list(f) == LEVER_FORCE for f in doc["lever"]["forces"])
    assert doc["lever"]["balancing_force"]["image"] == "a"
    assert doc["power"]["driving"] == pytest.approx(M_B * 150, rel=1e-9)
    assert abs(doc["power"]["residual"]) < 1e-9 * doc["power"]["driving"]


def test_json_is_deterministic_and_a_list_for_several_positions(capsys):
    first = run(capsys, "forces", "--example", "six-bar-loads", "--json")[1]
    assert first == run(capsys, "forces", "--example", "six-bar-loads", "--json")[1]
    status, out, _ = run(capsys, "forces", "--example", "slider-crank-loads", "--at", "60,150 deg", "--json", "--analytic-only")
    docs = json.loads(out)
    assert status == 0 and len(docs) == 2
    assert docs[0]["balancing"]["analytic"] == pytest.approx(M_B, abs=5e-7)
    assert docs[1]["driver"]["phi_deg"] == pytest.approx(150)
    assert docs[0]["lever"] is None and docs[0]["scales"] is None and "lever" not in docs[0]["balancing"]


def test_precision_makes_the_lever_a_drawing(capsys):
    doc = json.loads(run(capsys, "forces", "--example", "slider-crank-loads", "--json", "--precision", "0.1")[1])
    lever = doc["balancing"]["lever"]
    assert lever["rel_error"] == pytest.approx(abs(lever["value"] - M_B) / M_B, rel=1e-3)
    assert 0 < lever["rel_error"] < 1e-2
    assert doc["lever"]["precision"] == 0.1


WORDS = {
    "en": ["Balancing moment", "Joukowski's lever", "Reactions in the kinematic pairs", "inertia force", "Power balance"],
    "sr": ["Уравнотежни момент", "Жуковљева полуга", "Реакције у кинематским паровима", "сила инерције", "Биланс снага"],
    "ru": ["Уравновешивающий момент", "Рычаг Жуковского", "Реакции в кинематических парах", "сила инерции", "Баланс мощностей"],
    "bg": ["Уравновесяващ момент", "Лост на Жуковски", "Реакции в кинематичните двойки", "инерционна сила", "Баланс на мощностите"],
    "sl": ["Uravnotežilni moment", "Žukovskijev vzvod", "Reakcije v kinematičnih parih", "vztrajnostna sila", "Bilanca moči"],
}


@pytest.mark.parametrize("lang", list(WORDS))
def test_the_table_speaks_the_readers_language(capsys, lang):
    status, out, _ = run(capsys, "forces", "--example", "slider-crank-loads", "--lang", lang)
    assert status == 0
    for word in WORDS[lang]:
        assert word in out, (lang, word)
    assert "620.218316" in out and "R_34" in out and "5461.33" in out


def test_a_linear_driver_gets_a_balancing_force(capsys):
    status, out, _ = run(capsys, "forces", "--example", "ladder-loads", "--json")
    doc = json.loads(out)
    assert status == 0 and doc["balancing"]["kind"] == "force" and doc["balancing"]["symbol"] == "F_b"
    assert doc["reactions"]["R_12"]["kind"] == "P"
    assert doc["power"]["driving"] == pytest.approx(doc["balancing"]["analytic"] * 1.0, rel=1e-12)  # F_b·v, v = 1 m/s


BAD = example_path("slider-crank-loads").read_text().replace('at = "B"', 'at = "A"')


def test_hard_cases_exit_2_with_one_line(tmp_path, capsys):
    path = tmp_path / "bad.toml"
    path.write_text(BAD)
    status, out, err = run(capsys, "forces", str(path))
    assert status == 2 and out == ""
    assert err.startswith(f"plans: error: {path}: load.0.at") and "'A' is not a point of link 4" in err and err.count("\n") == 1
    velocities = tmp_path / "v.toml"
    velocities.write_text(example_path("slider-crank-loads").read_text() + "\n[compute]\naccelerations = false\n")
    status, _, err = run(capsys, "forces", str(velocities))
    assert status == 2 and "compute.accelerations" in err
    status, _, err = run(capsys, "forces", "--example", "rocker-limit-loads", "--at", "180 deg")
    assert status == 2 and "cannot assemble" in err


def test_a_scene_without_loads_is_solved_with_a_warning(capsys):
    status, out, err = run(capsys, "forces", "--example", "four-bar", "--analytic-only")
    assert status == 0 and "no masses and no loads" in err


def test_examples_loads_lists_the_loaded_scenes(capsys):
    status, out, _ = run(capsys, "examples", "--loads")
    assert status == 0
    assert [line.split()[0] for line in out.splitlines()] == example_names(loads=True)
    status, out, _ = run(capsys, "examples", "slider-crank-loads")
    assert status == 0 and "620.218316" in out


def test_sweep_adds_the_balancing_moment_and_every_reaction(capsys):
    # from the scene's angle, the worked example (a sweep starts by default at the output's extreme position: issue 19)
    status, out, _ = run(capsys, "sweep", "--example", "slider-crank-loads", "--steps", "12", "--start", "scene")
    assert status == 0
    rows = list(csv.DictReader(io.StringIO(out)))
    header = list(rows[0])
    assert header[-5:] == ["M_b", "R_12.magnitude", "R_23.magnitude", "R_34.magnitude", "R_14.magnitude"]
    first = rows[0]
    assert float(first["driver_phi_deg"]) == 60
    assert float(first["M_b"]) == pytest.approx(M_B, abs=5e-7)
    assert float(first["R_12.magnitude"]) == pytest.approx(9646.41888, abs=1e-5)
    assert float(first["R_14.magnitude"]) == pytest.approx(2077.57014, abs=1e-5)
    plain = run(capsys, "sweep", "--example", "slider-crank", "--steps", "12")[1]
    assert "M_b" not in plain.splitlines()[0]


def test_sweep_of_a_linear_driver_has_the_balancing_force(capsys):
    status, out, _ = run(capsys, "sweep", "--example", "wedge-loads", "--steps", "5")
    header = out.splitlines()[0].split(",")
    assert status == 0 and "F_b" in header and "M_b" not in header


def test_solve_still_solves_the_kinematics_of_a_loaded_scene(capsys):
    status, out, _ = run(capsys, "solve", "--example", "slider-crank-loads", "--json", "--analytic-only")
    doc = json.loads(out)
    assert status == 0 and doc["links"]["3"]["analytic"]["epsilon"] == pytest.approx(6511.74403, abs=5e-6)
    assert math.isclose(doc["points"]["B"]["analytic"]["v"][0], -14.69806, abs_tol=5e-6)


def test_near_a_dead_centre_a_warning_and_at_it_a_refusal(capsys):
    """rocker-limit-loads: A, B, D in line when |AD| = AB + BD = 0.65 m, cos φ_t = (0.1² + 0.7² − 0.65²)/(2·0.1·0.7)."""
    limit = math.degrees(math.acos((0.01 + 0.49 - 0.4225) / 0.14))
    status, out, err = run(capsys, "forces", "--example", "rocker-limit-loads", "--at", f"{limit - 1e-4!r} deg", "--analytic-only")
    assert status == 0 and "near a dead centre" in err and "RRR(3,4)" in err
    doc = json.loads(run(capsys, "forces", "--example", "rocker-limit-loads", "--at", f"{limit - 1e-4!r} deg", "--analytic-only", "--json")[1])
    assert any("near a dead centre" in warning for warning in doc["warnings"])
    status, out, err = run(capsys, "forces", "--example", "rocker-limit-loads", "--at", f"{limit!r} deg", "--analytic-only")
    assert status == 2 and out == "" and "dead centre" in err


def test_the_force_plans_hook_puts_their_numbers_beside_the_analytic(capsys):
    """The contract for the graphical force plans: an object with ``balancing`` and ``reactions`` (label ->
    an object with ``force``); here a stand-in that is off by known amounts, so the differences are known."""
    from dataclasses import replace
    from types import SimpleNamespace

    import plans
    from plans.forces.compare import compare_forces, kinetostatics
    from plans.forces.report import forces_json, forces_table

    run_ = kinetostatics(plans.load(example_path("slider-crank-loads")))
    exact = {label: complex(r.force[0]) for label, r in run_.analytic.reactions.items()}
    stand_in = SimpleNamespace(
        balancing=M_B + 0.5,
        reactions={label: SimpleNamespace(force=force + 2.0) for label, force in exact.items() if label != "R_14"},
    )
    rows = compare_forces(run_.analytic, run_.lever, stand_in)
    assert [(row.quantity, row.method) for row in rows] == [("M_b", "force_plans"), ("M_b", "lever"), ("R_12", "force_plans"),
                                                           ("R_23", "force_plans"), ("R_34", "force_plans")]
    assert rows[0].abs_error == pytest.approx(0.5, abs=1e-6) and rows[2].abs_error == pytest.approx(2.0, rel=1e-12)
    assert rows[3].rel_error == pytest.approx(2.0 / 8353.55006, rel=1e-6)
    run_ = replace(run_, force_plans=stand_in, comparisons=rows)
    doc = forces_json(run_)
    assert doc["balancing"]["force_plans"]["value"] == pytest.approx(M_B + 0.5, abs=1e-6)
    assert doc["reactions"]["R_23"]["force_plans"]["abs_error"] == pytest.approx(2.0, rel=1e-12)
    assert "force_plans" not in doc["reactions"]["R_14"]
    table = forces_table(run_, "ru")
    assert "планы сил" in table and f"{M_B + 0.5:16.9g}".strip() in table


def test_the_kinetostatics_never_imports_matplotlib():
    import subprocess
    import sys

    code = (
        "import sys\n"
        "from plans.cli import main\n"
        "assert main(['forces', '--example', 'slider-crank-loads', '--json']) == 0\n"
        "import plans\n"
        "plans.forces(plans.load(plans.example_path('six-bar-loads')))\n"
        "print('matplotlib' in sys.modules, file=sys.stderr)\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stderr.strip() == "False"


@pytest.mark.parametrize("lang, words", [("en", "(1: the frame)"), ("ru", "(1: стойка)"), ("sr", "(1: постоље)")])
def test_the_table_states_the_frames_number_as_the_labels_use_it(capsys, lang, words):
    # crank 2: the frame is 1, so R_12 is the frame on the crank (issue 20 §2: one frame number)
    status, out, _ = run(capsys, "forces", "--example", "slider-crank-loads", "--lang", lang, "--analytic-only")
    assert status == 0 and words in out and "R_12" in out and "(0:" not in out
