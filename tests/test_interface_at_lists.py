"""``--at`` with a list of positions: every listed position is solved (issue 9 §1), and
positions outside a sane range are refused (issue 9 §2)."""

import cmath
import json
import math

import pytest

from plans.cli import main

# four-bar.toml: crank OA = 80 mm about O = (0, 0) (its A = [0.08, 0] in the crank's own frame)
OA = 0.08


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_solve_at_a_list_gives_one_json_document_per_position(capsys):
    status, out, _ = run(capsys, "solve", "--example", "four-bar", "--at", "10,25 deg", "--json", "--analytic-only")
    assert status == 0
    docs = json.loads(out)
    assert isinstance(docs, list) and len(docs) == 2
    for doc, deg in zip(docs, (10, 25)):
        assert doc["driver"]["phi_deg"] == pytest.approx(deg, abs=1e-12)
        a = complex(*doc["points"]["A"]["analytic"]["r"])
        assert a == pytest.approx(OA * cmath.exp(1j * math.radians(deg)), abs=1e-15)


def test_solve_at_a_bare_list_is_degrees_and_matches_single_positions(capsys):
    status, out, _ = run(capsys, "solve", "--example", "four-bar", "--at", "1,5", "--json")
    assert status == 0
    docs = json.loads(out)
    singles = [json.loads(run(capsys, "solve", "--example", "four-bar", "--at", f"{d} deg", "--json")[1]) for d in (1, 5)]
    assert docs == singles
    assert [d["driver"]["phi_deg"] for d in docs] == pytest.approx([1, 5], abs=1e-12)


def test_solve_at_a_list_prints_a_table_per_position(capsys):
    status, out, _ = run(capsys, "solve", "--example", "four-bar", "--at", "0, 90, 180 deg")
    assert status == 0
    assert out.count("Crank-rocker four-bar with coupler point") == 3
    assert "position 0 of 3: φ = 0.0°" in out and "position 2 of 3: φ = 180.0°" in out
    assert "φ = 90.000°" in out


@pytest.mark.parametrize("command", [("solve",), ("solve", "--json"), ("draw", "-o", "DIR")])
@pytest.mark.parametrize("at", ["1e300", "-1e20 deg", "10, 1e300"])
def test_positions_outside_a_sane_range_are_refused(capsys, tmp_path, command, at):
    argv = [str(tmp_path / "out") if a == "DIR" else a for a in command]
    status, out, err = run(capsys, *argv, "--example", "four-bar", "--at", at)
    assert status == 2
    assert out == ""
    assert "within ±36000°" in err and "--at" in err and len(err) < 400
    assert not (tmp_path / "out").exists()


def test_a_linear_driver_position_far_beyond_the_scene_is_refused(capsys):
    status, out, err = run(capsys, "solve", "--example", "ladder", "--at", "1e300")
    assert status == 2 and out == ""
    assert "linear driver" in err and "±500 m" in err  # the ladder is 0.5 m long
