"""plans centres (table and centres.svg) and the instant-centre entry of plans solve.

Expected numbers are typed from domain.md §6 and §8 (E2 slider-crank) or
computed here by hand; the analytic solution is the reference for errors.
"""

import json
import math
import re

import pytest
from matplotlib.lines import Line2D
from matplotlib.patches import Circle, Polygon

from plans.centres import instant_centres
from plans.cli import main
from plans.drawing.centres import centres_svg, draw_centres
from plans.scene import example_path, load, loads
from test_centres_kennedy import FLAT_FOUR_BAR

SIX_BAR_LABELS = ["P12", "P13", "P14", "P15", "P16", "P23", "P24", "P25", "P26", "P34", "P35", "P36", "P45", "P46", "P56"]


def _table_rows(text):
    return [line.split()[0] for line in text.splitlines() if re.match(r"^P\d\d\s", line)]


def test_centres_command_prints_fifteen_centres_and_draws_them(tmp_path, capsys):
    assert main(["centres", "--example", "six-bar", "-o", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert _table_rows(out) == SIX_BAR_LABELS
    assert "n(n−1)/2 = 15 centres" in out
    assert re.search(r"^P13\s+1,3\s+\S+\s+\S+\s+Kennedy: P12P23 ∩ P14P34$", out, re.MULTILINE)
    assert re.search(r"^P56\s+5,6\s+at infinity\s+[\d.]+°\s+prismatic E$", out, re.MULTILINE)
    svg = (tmp_path / "centres.svg").read_text(encoding="utf-8")
    for label in SIX_BAR_LABELS:
        assert f'id="centres-label-{label}"' in svg, label
        assert f'id="centres-mark-{label}"' in svg or f'id="centres-edge-{label}"' in svg, label
        assert "P" + label[1:].translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")) in svg
    assert 'id="centres-diagram-diagonal-P13"' in svg and 'id="centres-diagram-side-P12"' in svg


def test_slider_crank_table_has_the_domain_numbers(capsys):
    assert main(["centres", "--example", "slider-crank", "--no-drawing"]) == 0
    out = capsys.readouterr().out
    rows = {line.split()[0]: line for line in out.splitlines() if re.match(r"^P\d\d\s", line)}
    assert rows["P13"].split()[2:4] == ["0.319851", "0.319851"]
    assert rows["P24"].split()[2:4] == ["0", "0.0765887"]
    assert "at infinity" in rows["P14"] and "90.000°" in rows["P14"]
    assert re.search(r"^3\s+-59\.4428\s+P13$", out, re.MULTILINE)
    assert re.search(r"^B\s+-16\.0407\s+0\s+16\.0407\s+180\.000$", out, re.MULTILINE)


def test_drawing_marks_centres_where_they_are_at_k_l():
    result = instant_centres(load(example_path("slider-crank")))
    fig = draw_centres(result, k_l=0.001)
    by_gid = {a.get_gid(): a for a in fig.axes[0].get_children() if a.get_gid()}
    mark = by_gid["centres-mark-P24"]
    assert isinstance(mark, Circle)
    assert mark.center == pytest.approx((0.0, 0.0765887 / 0.001), abs=1e-3)  # domain.md §8, in mm at k_l
    # P13 at (319.85, 319.85) mm is far beyond the mechanism (issue 20 §4): an arrow at the edge points at it
    p13 = complex(319.8513, 319.8513)
    tip13 = complex(*by_gid["centres-edge-P13-head"].get_xy()[0])
    shaft13 = by_gid["centres-edge-P13"]
    tail13 = complex(shaft13.get_xdata()[0], shaft13.get_ydata()[0])
    assert abs((tip13 - tail13) / abs(tip13 - tail13) - (p13 - tip13) / abs(p13 - tip13)) < 1e-6
    assert "centres-mark-P13" not in by_gid
    # P14 at infinity along ±y: an arrow at the edge in that direction
    head = by_gid["centres-edge-P14-head"]
    shaft = by_gid["centres-edge-P14"]
    assert isinstance(head, Polygon) and isinstance(shaft, Line2D)
    tip = complex(*head.get_xy()[0])
    tail = complex(shaft.get_xdata()[0], shaft.get_ydata()[0])
    direction = (tip - tail) / abs(tip - tail)
    assert abs(direction.real) < 1e-9 and abs(direction.imag) == pytest.approx(1.0)
    assert by_gid["centres-label-P14"].get_text() == "P₁₄ ∞"


def test_far_centre_at_the_edge_with_its_distance():
    result = instant_centres(load(example_path("six-bar")))
    k_l = 0.01
    fig = draw_centres(result, k_l=k_l)
    by_gid = {a.get_gid(): a for a in fig.axes[0].get_children() if a.get_gid()}
    p13 = result.centre("frame", "3").point
    tip = complex(*by_gid["centres-edge-P13-head"].get_xy()[0])
    text = by_gid["centres-label-P13"].get_text()
    # its distance beyond the arrow's tip in mm of the drawing (× k_l: metres), to the mm
    distance = float(re.fullmatch(r"P₁₃ (\d+) mm", text).group(1))
    assert distance == pytest.approx(abs(p13 / k_l - tip), abs=0.5)
    # the arrow points at the centre
    shaft = by_gid["centres-edge-P13"]
    tail = complex(shaft.get_xdata()[0], shaft.get_ydata()[0])
    towards = (p13 / k_l - tip) / abs(p13 / k_l - tip)
    assert abs((tip - tail) / abs(tip - tail) - towards) < 1e-9


def test_centres_svg_is_deterministic():
    result = instant_centres(load(example_path("quick-return")))
    assert centres_svg(result) == centres_svg(instant_centres(load(example_path("quick-return"))))


def test_solve_json_has_the_centres_entry_with_errors(capsys):
    assert main(["solve", "--example", "six-bar", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert [c["label"] for c in doc["centres"]["list"]] == SIX_BAR_LABELS
    assert doc["centres"]["body_numbers"] == {"frame": "1", "2": "2", "3": "3", "4": "4", "5": "5", "6": "6"}
    p56 = doc["centres"]["list"][-1]
    assert p56["point"] is None and 0 <= p56["direction_deg"] < 180 and p56["found_by"] == "prismatic E"
    for name, entry in doc["points"].items():
        v = complex(*entry["centres"]["v"])
        a = complex(*entry["analytic"]["v"])
        assert entry["centres"]["v_abs_error"] == pytest.approx(abs(v - a), abs=1e-300)
        assert entry["centres"]["v_rel_error"] < 1e-12
    for name, entry in doc["links"].items():
        assert entry["centres"]["omega"] == pytest.approx(entry["analytic"]["omega"], rel=1e-12)
        assert entry["centres"]["omega_rel_error"] < 1e-12


def test_solve_table_has_the_centres_section_and_no_centres_skips_it(capsys):
    assert main(["solve", "--example", "slider-crank"]) == 0
    out = capsys.readouterr().out
    assert "Instant centres (Kennedy), a third method" in out
    assert re.search(r"^link 3\s+ω\s+-59\.4428\s+-59\.4428", out, re.MULTILINE)
    for flag in ("--no-centres", "--analytic-only"):
        assert main(["solve", "--example", "slider-crank", flag]) == 0
        assert "Instant centres" not in capsys.readouterr().out
        assert main(["solve", "--example", "slider-crank", flag, "--json"]) == 0
        doc = json.loads(capsys.readouterr().out)
        assert "centres" not in doc and all("centres" not in e for e in doc["points"].values())




def test_centres_command_refuses_an_undetermined_centre_and_writes_nothing(tmp_path, capsys):
    scene = tmp_path / "flat.toml"
    scene.write_text(FLAT_FOUR_BAR, encoding="utf-8")
    out = tmp_path / "out"
    assert main(["centres", str(scene), "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("plans: error: ") and "the velocity of link 3 is not determined" in err and "P13 is undetermined" in err
    assert not out.exists()


def test_frame_is_zero_when_a_link_is_called_one():
    text = """
[frame]
points = { O = [0, 0] }
lines = { rail = { through = [0, 0.05], angle = 0 } }
[link.1]
points = { O = [0, 0], A = [0.1, 0] }
[link.2]
points = { A = [0, 0], B = [0.25, 0] }
[[slider]]
pin = "B"
on = "frame.rail"
name = "3"
[driver]
crank = "1"
angle = "45 deg"
omega = "2000 rpm"
"""
    result = instant_centres(loads(text))
    assert [c.label for c in result.centres] == ["P01", "P02", "P03", "P12", "P13", "P23"]
    # the same mechanism as E2, numbered one lower: P02 is E2's P13
    assert result.centre("frame", "2").point == pytest.approx(complex(0.3198513, 0.3198513), abs=1e-7)
    assert math.isclose(result.links["2"], -59.4427657, rel_tol=1e-8)


def test_undetermined_centres_are_in_the_table_the_json_and_a_warning(tmp_path, capsys):
    assert main(["centres", "--example", "quick-return", "--at", "90", "-o", str(tmp_path)]) == 0
    captured = capsys.readouterr()
    assert re.search(r"^P25\s+2,5\s+—\s+—\s+undetermined: the Kennedy lines P12P15, P23P35, P24P45 are one line", captured.out, re.MULTILINE)
    assert "plans: warning: instant centre P26 is undetermined" in captured.err
    svg = (tmp_path / "centres.svg").read_text(encoding="utf-8")
    assert 'id="centres-undetermined-P25"' in svg and 'id="centres-mark-P25"' not in svg
    assert 'id="centres-diagram-diagonal-P25"' not in svg and 'id="centres-diagram-side-P25"' not in svg
    assert main(["solve", "--example", "quick-return", "--at", "90", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    p25 = next(c for c in doc["centres"]["list"] if c["label"] == "P25")
    assert p25["found_by"] == "undetermined" and p25["point"] is None and p25["direction_deg"] is None
    assert p25["why"].startswith("the Kennedy lines P12P15")
    assert doc["links"]["5"]["centres"]["omega"] == 0.0
