"""plans animate without a browser: the page's data, its scales, its words, GIF and MP4, the CLI, notebooks.

Expected values come from outside the page: the analytic solver at each
position's angle (for the values and for the drawn length of each velocity
vector at the stated k_v), the positions a crank's turn gives by hand
(φ₀ + k·360°/N in the sense of ω), the frame count decoded back from the GIF and the MP4.
"""

from __future__ import annotations

import html
import json
import math
import re

import numpy as np
import pytest

import plans
from plans.cli import main
from plans.lecture import Animation, animate
from plans.motion import driver_cycle

N = 6


@pytest.fixture(scope="module")
def four_bar():
    return plans.load(plans.example_path("four-bar"))


@pytest.fixture(scope="module")
def animation(four_bar):
    return animate(four_bar, N)


@pytest.fixture(scope="module")
def data(animation):
    text = animation.html
    found = re.search(r'<script type="application/json" id="plans-data">(.*?)</script>', text, flags=re.S)
    return json.loads(found.group(1))


def _number(text: str) -> float:
    return float(text.replace("−", "-").replace(",", "."))


def _angles(scene, n):
    """A crank's n positions of a turn in the sense of ω, 360°/n apart, from the cycle's first (plans.motion's
    extreme position of the output link, tested there)."""
    first = float(driver_cycle(scene, n).positions[0])
    sense = -1.0 if scene.driver.omega < 0 else 1.0
    return [first + sense * 2 * math.pi * k / n for k in range(n)]


def _solved(scene, n):
    """The analytic solution at the cycle's positions with the driver's rates under its law (plans.motion)."""
    return driver_cycle(scene, n).solve()


def test_the_page_has_a_frame_a_label_and_values_for_every_position(animation, data, four_bar):
    assert len(data["frames"]) == len(data["labels"]) == len(data["values"]) == N
    for k, (label, phi) in enumerate(zip(data["labels"], _angles(four_bar, N))):
        assert label == f"Position {k}: φ₂ = {math.degrees(phi) % 360:.1f}°"  # counted from 0 only, no "(k+1/N)"
    assert all(f.startswith("<svg") and "<metadata" not in f for f in data["frames"])


def test_the_values_are_the_analytic_ones_at_each_position(animation, data, four_bar):
    rows = re.findall(r"<tr><td>(.*?)</td><td class=\"graphical\">", animation.html)
    assert rows[0] == "φ<sub>2</sub>" and "ω<sub>3</sub>" in rows and "|v<sub>M</sub>|" in rows
    solved = _solved(four_bar, N)
    for k, phi in enumerate(_angles(four_bar, N)):
        expected = {
            "ω<sub>3</sub>": solved.links["3"].omega[k],
            "ε<sub>4</sub>": solved.links["4"].epsilon[k],
            "|v<sub>M</sub>|": abs(solved.points["M"].v[k]),
            "|a<sub>B</sub>|": abs(solved.points["B"].a[k]),
            "ω<sub>2</sub>": four_bar.driver.omega,
        }
        cells = dict(zip(rows, data["values"][k]))
        for row, value in expected.items():
            graphical, analytic = (_number(t) for t in cells[row])
            last = [10.0 ** -len(t.replace(",", ".").partition(".")[2]) for t in cells[row]]  # a unit of the last digit shown
            assert analytic == pytest.approx(value, abs=0.5 * last[1] + 1e-9), (k, row)
            # read off the plans at 0.1 mm, rounded to the row's decimals
            assert graphical == pytest.approx(value, rel=0.02, abs=0.02 * abs(value) + 0.5 * last[0] + 1e-6), (k, row)
        assert _number(cells["φ<sub>2</sub>"][0]) == pytest.approx(math.degrees(phi) % 360, abs=0.05)
        assert _number(cells["t"][1]) == pytest.approx(k * 2 * math.pi / N / abs(four_bar.driver.omega), abs=1e-4)  # t = Δφ/ω


def _shaft(svg: str, gid: str) -> complex:
    """Tip − tail [mm] of the vector drawn with *gid*: the head's first vertex is the tip (SVG y down)."""
    shaft = re.search(rf'<g id="{re.escape(gid)}">\s*<path d="M ([-0-9.]+) ([-0-9.]+)', svg)
    head = re.search(rf'<g id="{re.escape(gid)}-head">\s*<path d="M ([-0-9.]+) ([-0-9.]+)', svg)
    tail = complex(float(shaft.group(1)), -float(shaft.group(2)))
    tip = complex(float(head.group(1)), -float(head.group(2)))
    return (tip - tail) * 25.4 / 72  # pt -> mm


def test_one_k_v_for_every_frame_and_the_pole_stays_put(animation, data, four_bar):
    k_v = animation.run.scales["k_v"]
    solved = _solved(four_bar, N)
    poles = set()
    for k, phi in enumerate(_angles(four_bar, N)):
        svg = data["frames"][k]
        assert "(m/s)/mm" in svg
        v_m = solved.points["M"].v[k]
        drawn = _shaft(svg, "vel-absolute-v_M")
        assert abs(drawn) * k_v == pytest.approx(abs(v_m), rel=0.01, abs=0.15 * k_v), k  # |pm| · k_v = |v_M|, 0.1 mm drafting
        assert math.degrees(abs(np.angle(drawn / complex(v_m)))) < 1.0, k  # along v_M
        pole = re.search(r'<g id="vel-pole">\s*<path d="M ([-0-9.]+) ([-0-9.]+)', svg)
        poles.add(pole.groups())
    assert len(poles) == 1  # the pole at one place on one canvas: the plan grows and shrinks about it
    sizes = {re.search(r'viewBox="([^"]+)"', f).group(1) for f in data["frames"]}
    assert len(sizes) == 1


def test_the_page_is_the_same_bytes_every_time(animation, four_bar):
    assert animate(four_bar, N).html == animation.html


def test_the_page_speaks_the_readers_language(four_bar):
    text = animate(four_bar, 3, lang="sr").html
    assert '<html lang="sr">' in text
    for words in ("Покрени", "Вредности у овом положају", "План брзина", "План убрзања", "Кинематска шема", "графички", "аналитички"):
        assert words in text
    assert "Play" not in text and "Velocity plan" not in text
    data = json.loads(re.search(r'id="plans-data">(.*?)</script>', text, flags=re.S).group(1))
    assert data["labels"][1].startswith("Положај 1: φ₂ = ")
    assert any("," in cell[1] for cell in data["values"][1][1:])  # decimal comma
    assert not any(re.search(r"\d\.\d", cell[1]) for cell in data["values"][1])


def test_a_position_that_is_not_solved_says_why(tmp_path):
    scene = plans.load(plans.example_path("rocker-limit"))  # its input swings between about ±56°
    anim = animate(scene, "0,30,60,120,180 deg")
    data = json.loads(re.search(r'id="plans-data">(.*?)</script>', anim.html, flags=re.S).group(1))
    unsolved = [r.index for r in anim.run.runs if not r.ok]
    assert unsolved == [2, 3, 4]
    k = unsolved[0]
    assert "mech-not-solved" in data["frames"][k] and "not solved at this position" in data["frames"][k]
    rows = re.findall(r"<tr><td>(.*?)</td><td class=\"graphical\">", anim.html)
    cells = dict(zip(rows, data["values"][k]))
    assert rows[:2] == ["φ<sub>2</sub>", "t"] and len(rows) > 4
    assert all(cells[row] == ["—", "—"] for row in rows[2:])  # the driver's angle and time are given; nothing else
    assert data["cursors"]["cursor-omega"][k] is None  # the diagrams do not show it
    solved = next(r.index for r in anim.run.runs if r.ok)
    assert data["cursors"]["cursor-omega"][solved] is not None


def test_the_gif_has_a_frame_per_position(animation):
    from io import BytesIO

    from PIL import Image

    data = animation.gif(width_px=480)
    image = Image.open(BytesIO(data))
    assert image.format == "GIF" and image.n_frames == N
    assert image.size[0] == 480
    assert image.info["duration"] == pytest.approx(6000 / N, abs=10)  # a cycle in 6 s


def test_the_mp4_has_a_frame_per_position_and_the_same_bytes_every_time(animation, tmp_path):
    import imageio_ffmpeg

    data = animation.mp4(width_px=320)
    assert data[4:8] == b"ftyp"
    path = tmp_path / "a.mp4"
    path.write_bytes(data)
    frames, seconds = imageio_ffmpeg.count_frames_and_secs(str(path))
    assert frames == N and seconds == pytest.approx(6.0, abs=0.2)
    assert animation.mp4(width_px=320) == data


def test_the_command_writes_the_page_and_refuses_an_unknown_suffix(tmp_path, capsys):
    out = tmp_path / "page.html"
    assert main(["animate", "--example", "slider-crank", "--positions", "4", "-o", str(out)]) == 0
    assert capsys.readouterr().out.strip() == str(out)
    text = out.read_text(encoding="utf-8")
    assert text.startswith("<!DOCTYPE html>") and 'max="3"' in text
    bad = tmp_path / "page.avi"
    assert main(["animate", "--example", "slider-crank", "-o", str(bad)]) == 2
    err = capsys.readouterr().err
    assert str(bad) in err and ".html" in err and ".gif" in err and ".mp4" in err
    assert not bad.exists()


def test_the_command_keeps_given_scales(tmp_path):
    out = tmp_path / "page.html"
    assert main(["animate", "--example", "four-bar", "--positions", "3", "--k-v", "0.05", "-o", str(out)]) == 0
    assert "k<sub>v</sub> = 0.05 (m/s)/mm" in out.read_text(encoding="utf-8")


def test_in_a_notebook_a_solution_animates_as_the_same_page(four_bar):
    shown = plans.construct(four_bar).animate(3)
    assert isinstance(shown, Animation)
    frame = shown._repr_html_()
    srcdoc = re.fullmatch(r'<iframe [^>]*srcdoc="(.*)"></iframe>', frame, flags=re.S).group(1)
    assert html.unescape(srcdoc) == shown.html
    assert plans.solve(four_bar).animate(3).html == shown.html  # an analytic solution the same


def test_a_run_animates_at_its_own_scales(four_bar):
    from plans.positions import run_positions

    run = run_positions(four_bar, 4, k_v=0.1)
    shown = run.animate()
    assert shown.run is run
    assert "k<sub>v</sub> = 0.1 (m/s)/mm" in shown.html


def test_no_two_elements_of_the_page_share_an_id(animation, data):
    from collections import Counter

    static = animation.html.split('id="plans-data"')[0]
    for frame in data["frames"]:  # one frame at a time is in the page beside the diagrams and the legend
        ids = re.findall(r' id="([^"]+)"', static + frame)
        assert [i for i, n in Counter(ids).items() if n > 1] == []
    referred = set(re.findall(r'url\(#([^)]+)\)|href="#([^"]+)"', animation.html))
    assert all(f' id="{a or b}"' in animation.html for a, b in referred)  # what is referred to is there


def test_a_cycle_with_no_position_solved_is_refused_naming_the_scene():
    scene = plans.load(plans.example_path("rocker-limit"))  # its input swings between about ±56°
    with pytest.raises(plans.PlansError, match=r"rocker-limit\.toml: the mechanism is not solved at any of the 2 positions"):
        animate(scene, "100,120 deg")


# --- what a teacher would project: the header, the table, the drawings' size, the diagrams' curves ---------------


@pytest.fixture(scope="module")
def slider_crank_animation():
    return animate(plans.load(plans.example_path("slider-crank")), 4)


def _header(text: str) -> str:
    return re.search(r"<header>(.*?)</header>", text, flags=re.S).group(1)


def test_the_header_typesets_the_scale_factors_with_their_units(animation):
    header = _header(animation.html)
    assert "_" not in re.sub(r"<[^>]+>", "", header)  # no k_l typed as in a program
    k = animation.run.scales
    for letter, unit in (("l", "m/mm"), ("v", "(m/s)/mm"), ("a", "(m/s²)/mm")):
        assert f"<span>k<sub>{letter}</sub> = {k['k_' + letter]:g} {unit}</span>" in header
    assert "flex-wrap:wrap" in re.search(r"#subtitle\{[^}]*\}", animation.html).group(0)  # the line wraps, not runs off


def test_a_row_zero_at_every_position_is_left_out(slider_crank_animation):
    rows = re.findall(r"<tr><td>(.*?)</td><td class=\"graphical\">", slider_crank_animation.html)
    # the slider runs on the frame's guide, which does not turn: no Coriolis acceleration at any position;
    # the crank turns at constant speed: ε₂ = 0 (the header says the law)
    assert not any("a<sup>k</sup>" in row for row in rows) and "ε<sub>2</sub>" not in rows
    assert any("v<sup>r</sup>" in row for row in rows) and "ω<sub>2</sub>" in rows  # constant, not zero: kept


def test_each_row_keeps_its_decimals_and_the_plans_reading_precision(animation, data):
    rows = re.findall(r"<tr><td>(.*?)</td><td class=\"graphical\">", animation.html)

    def decimals(text):
        return len(text.partition(".")[2])

    for n, row in enumerate(rows):
        shown = {decimals(data["values"][k][n][0]) for k in range(N)}
        assert len(shown) == 1, (row, shown)  # the digits do not jump from one position to the next
        if row.startswith("|v<sub>"):  # 0.1 mm of the velocity plan is 0.1·k_v m/s: the last digit shown is no finer
            step = 0.1 * animation.run.scales["k_v"]
            (places,) = shown
            assert 10.0 ** -places <= step + 1e-12 < 10.0 ** -(places - 1), row
        if row.startswith("|a<sub>"):
            step = 0.1 * animation.run.scales["k_a"]
            (places,) = shown
            assert 10.0 ** -places <= step + 1e-12 < 10.0 ** -(places - 1), row


def test_the_sign_of_the_relative_motion_is_defined_under_the_table(slider_crank_animation):
    text = slider_crank_animation.html
    scene = slider_crank_animation.run.scene
    (pair,) = scene.prismatics
    notes = html.unescape(re.search(r'<section id="values-box">.*?</section>', text, flags=re.S).group(0))
    assert scene.bodies[pair.guide].is_frame  # the slider-crank's slider runs on the frame
    assert f"vʳ, aʳ of {pair.name}" in notes and f"the frame's guide line “{pair.guide_line}”" in notes
    assert "(0.1 mm of a plan)" in notes


def test_each_plan_fills_its_panel_at_its_largest_frame(animation):
    frames = animation.frames
    for kind in ("velocity", "acceleration"):
        box = frames.boxes[kind]
        largest = max(max((e[kind][2] - e[kind][0]) / box.width, (e[kind][3] - e[kind][1]) / box.height) for e in frames.extents if e[kind])
        # a plan turns about its pole, which stays put: the panel holds every frame, the largest spans most of it
        assert largest >= 0.6, (kind, largest)
    assert frames.text_scale >= 1.5  # labels legible when a frame ~450 mm wide fills a 1280 px screen


def test_the_diagrams_curves_stand_below_the_notes_written_across_their_top(animation):
    from plans.drawing.frames import NOTE_ROOM, draw_cursor_diagrams
    from plans.lecture import diagram_quantities

    fig, _ = draw_cursor_diagrams(animation.run, diagram_quantities(animation.run))
    noted = 0
    for ax in fig.axes:
        bottom, top = ax.get_ylim()
        ys = np.concatenate([np.asarray(line.get_ydata(), dtype=float) for line in ax.get_lines() if not line.get_label().startswith("_")] or [np.zeros(0)])
        ys = ys[np.isfinite(ys)]
        assert ys.size == 0 or (ys.min() >= bottom and ys.max() <= top), ax.get_ylabel()  # the whole curve inside
        if any(t.get_transform() == ax.transAxes and t.get_position()[1] >= 0.8 for t in ax.texts):
            noted += 1
            assert ys.size == 0 or ys.max() <= bottom + (1 - NOTE_ROOM) * (top - bottom) + 1e-9, ax.get_ylabel()
    assert noted >= 1  # ω₂ = const is written in the ω diagram


def test_the_two_plans_poles_stand_on_one_level_in_every_frame(data):
    for svg in data["frames"]:
        ys = {gid: float(re.search(rf'<g id="{gid}">\s*<path d="M [-0-9.]+ ([-0-9.]+)', svg).group(1)) for gid in ("vel-pole", "acc-pole")}
        assert ys["vel-pole"] == pytest.approx(ys["acc-pole"], abs=0.01)
