"""The JSON schema as a golden key list (every key the README documents), and compare's
errors against errors computed here from perturbed inputs (issue 9 §4)."""

import dataclasses
import json
import re
from pathlib import Path

import pytest

import plans
from plans.cli import main
from plans.report import solution_json

README = (Path(__file__).resolve().parent.parent / "README.md").read_text()

TOP = ["schema", "title", "driver", "structure", "units", "points", "links", "sliders", "groups", "warnings", "scales"]
CRANK = ["type", "link", "pivot", "phi_deg", "omega", "epsilon"]
LINEAR = ["type", "link", "point", "guide", "s", "velocity", "acceleration"]
UNITS = ["length", "angle", "velocity", "acceleration", "omega", "epsilon"]
POINT_ANALYTIC = ["r", "v", "a"]
POINT_GRAPHICAL = ["r", "r_abs_error", "r_rel_error", "v", "v_abs_error", "v_rel_error", "a", "a_abs_error", "a_rel_error"]
LINK_ANALYTIC = ["phi_deg", "omega", "epsilon"]
LINK_GRAPHICAL = ["omega", "omega_abs_error", "omega_rel_error", "epsilon", "epsilon_abs_error", "epsilon_rel_error"]
SLIDER_ANALYTIC = ["s", "v_rel", "a_rel", "coriolis"]
SLIDER_GRAPHICAL = ["s", "s_abs_error", "s_rel_error", "v_rel", "v_rel_abs_error", "v_rel_rel_error",
                    "a_rel", "a_rel_abs_error", "a_rel_rel_error", "coriolis", "coriolis_abs_error", "coriolis_rel_error"]
SLIDER_MOTION = ["body", "relative_to", "guide_deg"]
SLIDER_DRAWN = ["body", "relative_to", "sign", "v_rel", "a_rel", "coriolis"]
GROUP = ["kind", "links", "joint", "condition", "expected_rel_error", "analytic_sine", "sine", "graphical_condition", "branch"]
BRANCH = ["sign", "words", "other_assembly", "chosen_by"]
WARNING = ["group", "joint", "where", "condition", "sine", "expected_rel_error", "method", "message"]
SCALES = ["k_l", "k_v", "k_a"]
POINT_CENTRES = ["v", "v_abs_error", "v_rel_error"]
LINK_CENTRES = ["omega", "omega_abs_error", "omega_rel_error"]
CENTRES = ["body_numbers", "list"]
CENTRE = ["label", "bodies", "point", "direction_deg", "found_by", "lines"]


def solve_json(capsys, *argv):
    assert main(["solve", *argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_the_whole_schema_has_exactly_the_golden_keys(capsys):
    doc = solve_json(capsys, "--example", "quick-return")
    assert list(doc) == TOP + ["cycle", "centres"] and doc["schema"] == 1
    assert list(doc["driver"]) == CRANK
    assert list(doc["units"]) == UNITS
    for entry in doc["points"].values():
        assert list(entry) == ["analytic", "graphical", "centres"]
        assert list(entry["analytic"]) == POINT_ANALYTIC and list(entry["graphical"]) == POINT_GRAPHICAL
        assert list(entry["centres"]) == POINT_CENTRES
    for name, entry in doc["links"].items():
        assert list(entry["analytic"]) == LINK_ANALYTIC
        assert list(entry["graphical"]) == LINK_GRAPHICAL, name
        assert list(entry["centres"]) == LINK_CENTRES, name
    assert list(doc["centres"]) == CENTRES
    assert all(list(c) == CENTRE for c in doc["centres"]["list"])
    for entry in doc["sliders"].values():
        assert list(entry) == ["analytic", "graphical", "motion", "drawn"]
        assert list(entry["analytic"]) == SLIDER_ANALYTIC and list(entry["graphical"]) == SLIDER_GRAPHICAL
        assert list(entry["motion"]) == SLIDER_MOTION and list(entry["drawn"]) == SLIDER_DRAWN
    for entry in doc["groups"].values():
        assert list(entry) == GROUP and list(entry["branch"]) == BRANCH
    assert list(doc["scales"]) == SCALES


def test_a_linear_driver_warnings_and_precision(capsys):
    doc = solve_json(capsys, "--example", "ladder", "--precision", "0.5")
    assert list(doc["driver"]) == LINEAR
    assert list(doc["scales"]) == SCALES + ["precision_mm"]
    doc = solve_json(capsys, "--example", "rocker-limit", "--at", "56.3876 deg")
    assert doc["warnings"] and all(list(w) == WARNING for w in doc["warnings"])
    capsys.readouterr()


def test_analytic_only_and_velocities_only_leave_out_what_the_readme_says(capsys, tmp_path):
    doc = solve_json(capsys, "--example", "six-bar", "--analytic-only")
    assert list(doc) == [k for k in TOP if k != "scales"] + ["cycle"]
    assert all(list(e) == ["analytic"] for e in doc["points"].values())
    path = tmp_path / "v.toml"
    path.write_text(plans.example_path("quick-return").read_text() + "\n[compute]\naccelerations = false\n")
    doc = solve_json(capsys, str(path))
    assert all(list(e["analytic"]) == ["r", "v"] for e in doc["points"].values())
    assert all(list(e["analytic"]) == ["phi_deg", "omega"] for e in doc["links"].values())
    assert all(list(e["analytic"]) == ["s", "v_rel"] for e in doc["sliders"].values())


def test_every_golden_key_is_documented_in_the_readme():
    schema = README[README.index("## JSON schema"):]
    schema = schema[: schema.index("The sweep CSV")]
    documented = set(re.findall(r'"([a-z_]+)"', schema))
    golden = set(TOP + CRANK + LINEAR + GROUP + BRANCH + WARNING + SCALES + ["analytic", "graphical", "precision_mm"]
                 + POINT_ANALYTIC + LINK_ANALYTIC + SLIDER_ANALYTIC + ["motion", "drawn"] + SLIDER_MOTION + SLIDER_DRAWN)
    assert golden - documented == set()
    for suffix in ("_abs_error", "_rel_error"):
        assert suffix in schema


# --- compare against perturbed inputs -------------------------------------------------


@pytest.fixture(scope="module")
def solved():
    scene = plans.load(plans.example_path("quick-return"))
    return plans.solve(scene), plans.construct(scene)


def _perturbed(graphical, section, name, quantity, delta):
    readings = {n: dict(q) for n, q in getattr(graphical, section).items()}
    readings[name][quantity] = readings[name][quantity] + delta
    return dataclasses.replace(graphical, **{section: readings})


@pytest.mark.parametrize("section, name, quantity, delta", [
    ("points", "E", "v", 0.003 - 0.004j),
    ("points", "D", "a", 0.5j),
    ("links", "4", "omega", -0.02),
    ("links", "5", "epsilon", 1.5),
    ("sliders", "A", "v_rel", 0.01),
    ("sliders", "A", "coriolis", 0.25 + 0.25j),
])
def test_compare_reports_the_errors_of_perturbed_readings(solved, section, name, quantity, delta):
    analytic, graphical = solved
    record = getattr(analytic, section)[name]
    exact = getattr(record, quantity)[0]
    exact = complex(exact) if quantity in ("v", "a", "coriolis") else float(exact)
    assert abs(exact) > 1e-3  # so the relative error is against the value itself
    rows = plans.compare(analytic, _perturbed(graphical, section, name, quantity, delta))
    (row,) = [r for r in rows if (r.section, r.name, r.quantity) == (section, name, quantity)]
    # the errors computed here: |g − a| with g = a + δ up to the graphical round-off (1e-12 of the value)
    assert row.abs_error == pytest.approx(abs(delta), rel=1e-9, abs=1e-12 * abs(exact))
    assert row.rel_error == pytest.approx(abs(delta) / abs(exact), rel=1e-9, abs=1e-12)
    others = [r for r in rows if (r.section, r.name, r.quantity) != (section, name, quantity)]
    assert max(r.rel_error for r in others) < 1e-12  # the others are untouched
    doc = solution_json(analytic, graphical, rows)
    key = {"points": "points", "links": "links", "sliders": "sliders"}[section]
    assert doc[key][name]["graphical"][f"{quantity}_rel_error"] == pytest.approx(abs(delta) / abs(exact), rel=1e-9)


def test_compare_of_a_reading_where_the_value_is_zero_measures_against_the_largest_of_its_kind(solved):
    analytic, graphical = solved
    # the ram E slides on a fixed horizontal guide: its Coriolis term is exactly 0
    exact = complex(analytic.sliders["E"].coriolis[0])
    assert exact == 0
    rows = plans.compare(analytic, _perturbed(graphical, "sliders", "E", "coriolis", 0.5))
    (row,) = [r for r in rows if (r.section, r.name, r.quantity) == ("sliders", "E", "coriolis")]
    largest = max(abs(r.analytic) for r in rows if r.quantity in ("a", "a_rel", "coriolis"))
    assert row.abs_error == pytest.approx(0.5, rel=1e-12)
    assert row.rel_error == pytest.approx(0.5 / largest, rel=1e-9)
