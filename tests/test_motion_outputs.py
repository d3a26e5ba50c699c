"""The driver's law, the Grashof classes and the strokes on every output that shows a cycle (issue 19 §1–§3):
plans solve (text and JSON), plans sweep (CSV, words, --law), draw --positions and handout (positions from the
output's extreme, rates under the law), cycle diagrams (the law in the reader's language), scene keys."""

from __future__ import annotations

import csv
import io
import json
import math

import numpy as np
import pytest

import plans
from plans.cli import main
from plans.drawing.diagrams import draw_cycle_diagrams
from plans.motion import driver_cycle, strokes
from plans.positions import run_positions


def _run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_solve_json_states_the_cycle(capsys):
    status, out, _ = _run(capsys, "solve", "--example", "slider-crank", "--json", "--analytic-only")
    assert status == 0
    cycle = json.loads(out)["cycle"]
    r, l, e = 0.1, 0.25, 0.05  # slider-crank.toml (domain.md E2)
    H = math.sqrt((l + r) ** 2 - e**2) - math.sqrt((l - r) ** 2 - e**2)
    theta = math.degrees(math.asin(e / (l - r)) - math.asin(e / (l + r)))
    assert cycle["law"]["kind"] == "constant" and cycle["law"]["source"] == "default"
    assert cycle["strokes"]["stroke_H_m"] == pytest.approx(H, rel=1e-9)
    assert cycle["strokes"]["theta_deg"] == pytest.approx(theta, abs=1e-7)
    assert cycle["strokes"]["K"] == pytest.approx((180 + theta) / (180 - theta), rel=1e-8)
    # ω > 0: the longer crank arc (the slower stroke, 180° + θ) runs from the outer extreme (crank along the rod) on
    assert cycle["strokes"]["start_deg"] == pytest.approx(math.degrees(math.asin(e / (l + r))), abs=1e-7)
    assert cycle["strokes"]["other_deg"] == pytest.approx(180 + math.degrees(math.asin(e / (l - r))), abs=1e-7)
    assert cycle["strokes"]["working_arc_deg"] == pytest.approx(180 + theta, abs=1e-7)
    assert cycle["limits_deg"] is None and cycle["four_bar_loops"] == []


def test_solve_states_grashof_classes_and_limits(capsys):
    status, out, _ = _run(capsys, "solve", "--example", "rocker-limit", "--analytic-only")
    assert status == 0
    assert "four-bar loop RRR(3,4) (frame 0.7 m, input 2 0.1 m, coupler 3 0.45 m, output 4 0.2 m): triple-rocker (non-Grashof); no link turns fully" in out
    assert "swings between its limit positions −56.39° and 56.39°" in out
    status, out, _ = _run(capsys, "solve", "--example", "four-bar", "--json", "--analytic-only")
    (loop,) = json.loads(out)["cycle"]["four_bar_loops"]
    assert (loop["grashof_class"], loop["grashof"], loop["turning_links"]) == ("crank-rocker", True, ["2"])
    assert loop["lengths_m"] == pytest.approx({"frame": 0.22, "input": 0.08, "coupler": 0.25, "output": 0.2})


def test_sweep_law_option_and_words(capsys, tmp_path):
    target = tmp_path / "fb.csv"
    status, out, _ = _run(capsys, "sweep", "--example", "four-bar", "--steps", "24", "--law", "uniform", "--start", "scene",
                          "--lang", "sl", "-o", str(target))
    assert status == 0
    assert out.startswith("zakon gibanja pogonskega člena: enakomerno pospešeno: ω₂² = ω₀² + 2ε₂(φ₂ − φ₀)")
    assert "izhodni člen 4: kot nihanja ψ₄ = 56,01°" in out
    rows = list(csv.DictReader(io.StringIO(target.read_text())))
    phi = np.unwrap(np.radians([float(r["driver_phi_deg"]) for r in rows]))
    omega = np.array([float(r["2.omega"]) for r in rows])
    # four-bar.toml: ω₀ = 10 rad/s, ε = 5 rad/s² at φ₀ = 60°
    assert omega == pytest.approx(np.sqrt(100 + 10 * (phi - math.radians(60))), rel=1e-12)
    assert {r["2.epsilon"] for r in rows} == {"5"}
    assert [float(r["t"]) for r in rows] == pytest.approx((omega - 10) / 5, abs=1e-12)


def test_sweep_refuses_a_law_the_driver_cannot_follow(capsys, tmp_path):
    scene = tmp_path / "slow.toml"
    scene.write_text(plans.example_path("four-bar").read_text().replace('epsilon = "5 rad/s^2"', 'epsilon = "-10 rad/s^2"\nlaw = "uniform"'))
    status, _, err = _run(capsys, "sweep", str(scene), "--steps", "36")
    assert status == 2
    assert "driver.law" in err and "cannot cover the cycle" in err and "reaches 0" in err
    status, _, err = _run(capsys, "sweep", "--example", "rocker-limit", "--law", "constant")
    assert status == 2 and "--law" in err and "cannot turn fully" in err
    bad = tmp_path / "bad.toml"
    bad.write_text(plans.example_path("four-bar").read_text().replace('omega = "10 rad/s"', 'omega = "10 rad/s"\nlaw = "steady"'))
    status, _, err = _run(capsys, "solve", str(bad))
    assert status == 2 and "driver.law" in err and "'constant', 'uniform', 'harmonic'" in err


def test_positions_start_at_the_output_extreme_with_the_laws_rates():
    scene = plans.load(plans.example_path("four-bar"))
    run = run_positions(scene, 4)
    st = strokes(scene)
    assert run.positions[0] == pytest.approx(st.start_position)
    assert run.law.kind == "constant"
    for r in run.runs:  # the course's law: ε = 0 at every position (the scene's ε = 5 rad/s² is its own instant's)
        assert float(r.analytic.links["2"].omega[0]) == 10.0 and float(r.analytic.links["2"].epsilon[0]) == 0.0
        assert r.graphical is not None and r.scene.driver.epsilon == 0.0
    # the output (rocker 4) is at rest at position 0, its extreme position
    assert abs(float(run.runs[0].analytic.links["4"].omega[0])) < 1e-9
    uniform = run_positions(scene, 4, law="uniform")
    omega = [float(r.analytic.links["2"].omega[0]) for r in uniform.runs]
    assert omega == pytest.approx(list(np.sqrt(100 + 10 * (np.asarray(uniform.positions) - math.radians(60)))))


@pytest.mark.parametrize("lang, words", [("en", "driver law: constant angular velocity: ω₂ = 10 rad/s, ε₂ = 0"),
                                         ("bg", "закон на движение на водещото звено: постоянна ъглова скорост: ω₂ = 10 rad/s, ε₂ = 0")])
def test_diagrams_state_the_law_in_the_readers_language(lang, words):
    scene = plans.load(plans.example_path("four-bar"))
    cycle = driver_cycle(scene, 72)
    for _, fig in draw_cycle_diagrams(cycle.solve(), lang=lang, cycle=cycle):
        assert words in " ".join(t.get_text() for t in fig.texts)


def test_a_swing_is_drawn_against_time():
    scene = plans.load(plans.example_path("rocker-limit"))
    cycle = driver_cycle(scene, 120)
    marked = driver_cycle(scene, 12)
    figures = dict(draw_cycle_diagrams(cycle.solve(), marked=marked, cycle=cycle))
    ax = figures["links"].axes[-1]
    assert ax.get_xlabel().startswith("t [s]")
    assert ax.get_xlim()[1] == pytest.approx(cycle.period * 119 / 120, rel=1e-9)
    lines = [line for line in ax.get_lines() if line.get_linestyle() == "--" and len(set(line.get_xdata())) == 1]
    assert sorted(float(line.get_xdata()[0]) for line in lines) == pytest.approx(list(marked.t))


def test_the_handout_cover_states_law_class_and_strokes():
    from plans.handout import cycle_lines

    run = run_positions(plans.load(plans.example_path("rocker-limit")), 4)
    text = "\n".join(cycle_lines(run, "ru"))
    assert "закон движения ведущего звена: гармоническое качание между −56,39° … 56,39°" in text
    assert "класс по Грасгофу (шарнирный четырёхзвенник 1–2–3–4): трёхкоромысловый (не Грасгофов) (ни одно звено не проворачивается)" in text
    assert "выходное звено 4: угол качания ψ₄ = 71,32°" in text
    assert all(len(line) <= 110 for line in cycle_lines(run, "en"))  # a cover's width


def test_output_key_in_a_scene(tmp_path):
    text = plans.example_path("six-bar").read_text() + '\n[output]\nlink = "4"\n'
    scene = plans.loads(text)
    assert strokes(scene).output.link == "4"
    with pytest.raises(plans.SceneError, match="output.point.*unknown key 'point'; allowed keys: link"):
        plans.loads(plans.example_path("six-bar").read_text() + '\n[output]\npoint = "C"\n')


def test_the_other_extreme_position_is_marked_0_prime():
    """four-bar: position 0 at the rocker's extreme (36.11°), 0′ at the other (240.1°): 204.0° turned from 0 (θ = 23.97°)."""
    scene = plans.load(plans.example_path("four-bar"))
    run = run_positions(scene, 12)
    figures = dict(run.diagrams().figures())
    top = figures["links"].axes[0]
    assert "0′" in [t.get_text() for t in top.texts]
    dotted = [line for line in top.get_lines() if line.get_linestyle() == ":" and len(set(line.get_xdata())) == 1]
    assert [float(line.get_xdata()[0]) for line in dotted] == pytest.approx([math.degrees(run.strokes.working_arc)])
    assert math.degrees(run.strokes.working_arc) == pytest.approx(180 + 23.9749, abs=1e-3)
    # the output is at rest there: ω₄ = 0 at 0′
    other = plans.solve(scene, [run.strokes.other_position], rates=(10.0, 0.0))
    assert abs(float(other.links["4"].omega[0])) < 1e-9


def test_a_driver_at_rest_draws_its_instant_but_has_no_cycle(capsys, tmp_path):
    scene = tmp_path / "rest.toml"
    scene.write_text(plans.example_path("four-bar").read_text().replace('omega = "10 rad/s"', "omega = 0").replace('epsilon = "5 rad/s^2"', "epsilon = 0"))
    status, out, _ = _run(capsys, "draw", str(scene), "-o", str(tmp_path / "one"))
    assert status == 0 and (tmp_path / "one" / "sheet.svg").exists()  # the instant: all its plans at the pole
    status, out, err = _run(capsys, "draw", str(scene), "--positions", "4", "-o", str(tmp_path / "four"))
    assert status == 2 and "driver.law" in err and "does not move" in err and not (tmp_path / "four").exists()
    status, out, _ = _run(capsys, "solve", str(scene), "--json", "--analytic-only")
    cycle = json.loads(out)["cycle"]
    assert cycle["law"] is None and "does not move" in cycle["law_error"] and cycle["four_bar_loops"][0]["grashof_class"] == "crank-rocker"
