"""The driving moment M_b(φ) and the polar diagram of the crank bearing's reaction (issue 22, "Over the cycle").

The drawn curves are read back from the SVG (by gid) and converted by the scales the
page states (parsed from its text); the expected values come from the sweep's CSV,
from closed forms (the slider's stroke H of an offset slider-crank: the mean driving
moment against a constant resistance F_r is F_r·2H/2π) and from domain.md §11's
worked example (R_12 = 9646.41888 N at 199.942051° at φ = 60°).
"""

import csv
import io
import math
import re
import xml.etree.ElementTree as ET

import pytest

from plans.cli import main

SVG = "{http://www.w3.org/2000/svg}"
PT = 25.4 / 72  # mm per SVG user unit (the viewBox is in points)
STEPS = 360
POSITIONS = 12


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    assert status == 0, err
    return out, err


@pytest.fixture(scope="module")
def swept(tmp_path_factory):
    """``plans sweep --example slider-crank-loads --plot DIR -o CSV`` from the output's extreme position, and with --start scene."""
    out = {}
    for start in ("output", "scene"):
        d = tmp_path_factory.mktemp(start)
        status = main(["sweep", "--example", "slider-crank-loads", "--steps", str(STEPS), "--positions", str(POSITIONS),
                       "--start", start, "--plot", str(d / "plot"), "-o", str(d / "sweep.csv")])
        assert status == 0
        rows = list(csv.DictReader(io.StringIO((d / "sweep.csv").read_text())))
        out[start] = (rows, (d / "plot" / "forces.svg").read_bytes())
    return out


def group(svg: bytes, gid: str):
    root = ET.fromstring(svg)
    found = [g for g in root.iter(f"{SVG}g") if g.get("id") == gid]
    if len(found) != 1:
        raise ValueError(f"{len(found)} groups {gid!r}")
    return found[0]


def path_points(svg: bytes, gid: str) -> list[tuple[float, float]]:
    d = group(svg, gid).find(f"{SVG}path").get("d")
    numbers = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", d)]
    return list(zip(numbers[0::2], numbers[1::2]))


def marker_points(svg: bytes, gid: str) -> list[tuple[float, float]]:
    return [(float(u.get("x")), float(u.get("y"))) for u in group(svg, gid).iter(f"{SVG}use")]


def text(svg: bytes, gid: str) -> str:
    return "".join(t.text or "" for t in group(svg, gid).iter(f"{SVG}tspan")).replace("\xa0", " ")


def all_text(svg: bytes) -> str:
    """Every text element's characters (a line typeset with math is one tspan a glyph: joined without separators)."""
    root = ET.fromstring(svg)
    return "\n".join(((t.text or "") + "".join(s.text or "" for s in t.iter(f"{SVG}tspan"))).replace("\xa0", " ") for t in root.iter(f"{SVG}text"))


def stated(svg: bytes, gid: str, unit: str) -> list[float]:
    """The numbers stated before *unit* (``= 2.5 °/mm``) in the text of *gid*, decimal comma or point."""
    return [float(v.replace(",", ".")) for v in re.findall(r"=\s*([\d.,\u2009]+?)\s*" + re.escape(unit), text(svg, gid).replace("\u2009", ""))]


def scales(svg: bytes) -> tuple[float, float, float]:
    (mu_phi,) = stated(svg, "M_b-scales", "°/mm")
    (mu_m,) = stated(svg, "M_b-scales", "(N·m)/mm")
    (mu_f,) = stated(svg, "R-scale", "N/mm")
    return mu_phi, mu_m, mu_f


def stroke(r=0.1, l=0.3, e=0.02) -> float:
    """H of an offset slider-crank [m], closed form: the pin's distance at the two dead centres."""
    return math.sqrt((l + r) ** 2 - e**2) - math.sqrt((l - r) ** 2 - e**2)


def test_the_moment_curve_is_the_csv_column_at_the_stated_scales(swept):
    rows, svg = swept["output"]
    mu_phi, mu_m, _ = scales(svg)
    assert mu_phi == 2.5 and mu_m == 50  # round scales, fitting the box
    (x0, y0), (x1, _) = path_points(svg, "M_b-origin")
    assert (x1 - x0) * PT * mu_phi == pytest.approx(360.0, abs=1e-4)
    first = float(rows[0]["driver_phi_deg"])
    by_angle = {round((float(r["driver_phi_deg"]) - first) % 360.0, 6): float(r["M_b"]) for r in rows}
    drawn = path_points(svg, "M_b-curve")
    assert len(drawn) == STEPS + 1  # the turn closed: position 0 again at 360°
    for x, y in drawn:
        angle = (x - x0) * PT * mu_phi
        moment = (y0 - y) * PT * mu_m
        def apart(a, b):
            return abs(math.remainder(a - b, 360.0))

        nearest = min(by_angle, key=lambda a: apart(a, angle))
        assert apart(nearest, angle) < 1e-3
        assert moment == pytest.approx(by_angle[nearest], abs=1e-4 * mu_m)


def test_the_stated_mean_is_the_mean_over_a_turn_and_the_power_balance(swept):
    rows, svg = swept["output"]
    _, mu_m, _ = scales(svg)
    moments = [float(r["M_b"]) for r in rows]
    mean = sum(moments) / len(moments)  # constant speed: equal steps of time are equal steps of angle
    (_, y0), _ = path_points(svg, "M_b-origin")
    (_, ym), _ = path_points(svg, "M_b-mean")
    assert (y0 - ym) * PT * mu_m == pytest.approx(mean, abs=1e-4 * mu_m)
    (written,) = stated(svg, "M_b-mean-text", "N·m")
    assert written == pytest.approx(mean, abs=0.005)
    # the mean driving power equals the mean resistance power: M_mean·ω = −mean(F_r·v_B), F_r = 1500 N against v_B
    omega = 150.0
    resistance = [-1500.0 * abs(float(r["B.vx"])) for r in rows]  # the guide is horizontal: v_B = B.vx
    assert mean * omega == pytest.approx(-sum(resistance) / len(resistance), rel=1e-9)
    # and by the closed form: the piston covers 2H a turn against 1500 N (to the sampling's error: |v_B| has kinks
    # at the dead centres, so the mean of 360 samples is within 1e-4, not exact)
    assert mean == pytest.approx(1500.0 * 2 * stroke() / (2 * math.pi), rel=1e-4)


def test_the_polar_points_are_r12_from_the_pole_at_the_stated_scale(swept):
    rows, svg = swept["output"]
    _, _, mu_f = scales(svg)
    assert mu_f == 250
    (px, py), = marker_points(svg, "R-pole")
    points = marker_points(svg, "R-points")
    assert len(points) == POSITIONS
    step = STEPS // POSITIONS
    for k, (x, y) in enumerate(points):  # position k is the sweep's row k·30 (both from the output's extreme position)
        length = math.hypot(x - px, y - py) * PT
        assert length == pytest.approx(float(rows[k * step]["R_12.magnitude"]) / mu_f, abs=0.01)
    # the largest |R_12| drawn from the pole, its value written
    largest = max(float(r["R_12.magnitude"]) for r in rows)
    (ax, ay), (bx, by) = path_points(svg, "R-max")
    assert (ax, ay) == pytest.approx((px, py), abs=1e-4)
    assert math.hypot(bx - px, by - py) * PT == pytest.approx(largest / mu_f, abs=0.01)
    (written,) = stated(svg, "R-max-text", "N")
    assert written == pytest.approx(largest, abs=0.5)


def test_r12_at_the_scene_angle_is_the_worked_example(swept):
    rows, svg = swept["scene"]
    assert float(rows[0]["driver_phi_deg"]) == pytest.approx(60.0)
    assert float(rows[0]["R_12.magnitude"]) == pytest.approx(9646.41888, abs=1e-5)
    _, _, mu_f = scales(svg)
    (px, py), = marker_points(svg, "R-pole")
    x, y = marker_points(svg, "R-points")[0]
    dx, dy = (x - px) * PT, (py - y) * PT  # SVG y runs down
    expected = 9646.41888 / mu_f
    angle = math.radians(199.942051)
    assert dx == pytest.approx(expected * math.cos(angle), abs=0.01)
    assert dy == pytest.approx(expected * math.sin(angle), abs=0.01)
    # the hodograph passes through every R_12 of the sweep (its first point: the scene's position)
    hx, hy = path_points(svg, "R-hodograph")[0]
    assert (hx, hy) == pytest.approx((x, y), abs=0.01 / PT)


WORDS = {  # typed from the textbooks' terms, not from plans.i18n
    "sr": ["Погонски (уравнотежавајући) момент", "Поларни дијаграм реакције", "средња вредност", "пол"],
    "ru": ["Движущий (уравновешивающий) момент", "Полярная диаграмма реакции", "среднее значение", "полюс"],
    "bg": ["Движещ (уравновесяващ) момент", "Полярна диаграма на реакцията", "средна стойност", "полюс"],
    "sl": ["Pogonski (uravnotežni) moment", "Polarni diagram reakcije", "srednja vrednost", "pol"],
    "en": ["Driving (balancing) moment", "Polar diagram of the reaction", "mean", "pole"],
}


@pytest.fixture(scope="module")
def pages():
    import plans
    from plans.drawing.svg import render_svg
    from plans.forces.cycle import forces_over_cycle

    cycle = forces_over_cycle(plans.load(plans.example_path("slider-crank-loads")), 72, 12)
    return {lang: render_svg(cycle.page(lang=lang)) for lang in WORDS}


@pytest.mark.parametrize("lang", sorted(WORDS))
def test_the_words_of_every_language(pages, lang):
    words = all_text(pages[lang])
    for word in WORDS[lang]:
        assert word in words


def test_no_english_on_an_sr_page(pages):
    words = set(re.findall(r"[A-Za-z]+", all_text(pages["sr"])))
    # units and symbols only (math glyphs run together: M, b; "max", the index of |R₁₂|max, as every language writes it)
    assert not {w for w in words if len(w) > 3}, words
    english = {"at", "the", "of", "on", "mean", "pole", "direction", "frame", "crank", "moment", "reaction", "positions"}
    assert not words & english, words


def test_text_is_at_least_8_pt_and_the_page_is_deterministic(pages):
    sizes = [float(s) for s in re.findall(rb"font-size: ([\d.]+)px", pages["sr"])]
    base = {s for s in sizes if s >= 8.0 - 1e-9}
    # every text at least 8 pt; a symbol's subscript (the b of M_b) 0.7 of its text's size
    assert sizes and all(s in base or any(abs(s - 0.7 * b) < 1e-6 for b in base) for s in sizes), sorted(set(sizes))
    import plans
    from plans.drawing.svg import render_svg
    from plans.forces.cycle import forces_over_cycle

    again = forces_over_cycle(plans.load(plans.example_path("slider-crank-loads")), 72, 12)
    assert render_svg(again.page(lang="sr")) == pages["sr"]


def test_a_scene_without_loads_gets_no_force_page(capsys, tmp_path):
    run(capsys, "sweep", "--example", "slider-crank", "--steps", "36", "--plot", str(tmp_path / "p"), "-o", str(tmp_path / "s.csv"))
    assert not (tmp_path / "p" / "forces.svg").exists()
    assert (tmp_path / "p" / "links.svg").exists()


def test_a_linear_driver_draws_its_force_and_no_polar_diagram(capsys, tmp_path):
    out, _ = run(capsys, "sweep", "--example", "wedge-loads", "--steps", "21", "--plot", str(tmp_path / "p"), "-o", str(tmp_path / "s.csv"))
    svg = (tmp_path / "p" / "forces.svg").read_bytes()
    rows = list(csv.DictReader(io.StringIO((tmp_path / "s.csv").read_text())))
    (mu_s,) = stated(svg, "M_b-scales", "mm/mm")
    (mu_f,) = stated(svg, "M_b-scales", "N/mm")
    (x0, y0), _ = path_points(svg, "M_b-origin")
    drawn = path_points(svg, "M_b-curve")
    assert len(drawn) == len(rows)
    for (x, y), row in zip(drawn, rows):
        assert (y0 - y) * PT * mu_f == pytest.approx(float(row["F_b"]), abs=1e-4 * mu_f)
    assert b'id="R-points"' not in svg


def test_the_python_api_states_its_mean_in_newton_metres():
    import plans

    cycle = plans.forces.forces_over_cycle(plans.load(plans.example_path("slider-crank-loads")), steps=36, positions=0)
    assert cycle.bearing == "R_12" and cycle.marked is None
    assert cycle.mean == pytest.approx(1500.0 * 2 * stroke() / (2 * math.pi), rel=3e-3)  # 36 samples of a |v| with kinks


def test_the_hodograph_is_every_r12_and_breaks_only_where_the_resistance_reverses(swept):
    rows, svg = swept["output"]
    _, _, mu_f = scales(svg)
    (px, py), = marker_points(svg, "R-pole")
    d = group(svg, "R-hodograph").find(f"{SVG}path").get("d")
    pieces = [p for p in re.split(r"(?=M )", d.strip()) if p]
    vertices = []
    breaks = []
    for piece in pieces:
        numbers = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", piece)]
        if vertices:
            breaks.append(len(vertices))
        vertices += list(zip(numbers[0::2], numbers[1::2]))
    assert len(vertices) == STEPS + 1  # the turn closed
    for k, (x, y) in enumerate(vertices):
        assert math.hypot(x - px, y - py) * PT == pytest.approx(float(rows[k % STEPS]["R_12.magnitude"]) / mu_f, abs=0.01)
    # F_r = 1500 N against v_B jumps by 3000 N where v_B changes sign (at the dead centres): there, and only there
    signs = [float(r["B.vx"]) > 0 for r in rows] + [float(rows[0]["B.vx"]) > 0]
    assert breaks == [k + 1 for k in range(STEPS) if signs[k] != signs[k + 1]]


def test_a_swing_is_drawn_against_time_and_has_no_mean():
    import plans
    from plans.drawing.svg import render_svg

    cycle = plans.forces.forces_over_cycle(plans.load(plans.example_path("rocker-limit-loads")), steps=40, positions=4)
    assert math.isnan(cycle.mean)
    svg = render_svg(cycle.page(lang="sl"))
    words = all_text(svg)
    assert "ni srednje vrednosti: pogonski člen niha tja in nazaj, ne vrti se" in words
    assert "t [s]" in words and "Δφ [°]" not in words
    with pytest.raises(ValueError):
        group(svg, "M_b-mean")  # no mean line drawn
