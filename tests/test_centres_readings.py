"""The centres' values are what a student reads off the drawing (teacher's second review: every row said "rel.
error 0"): each length measured in mm at the drawing's k_l, rounded to the drafting precision 0.1 mm, ω_k = ω_j ·
P_1jP_jk / P_1kP_jk and v_M = |ω|·P_1kM from those lengths.  The expected values are built here from the analytic
joints (plans.analytic, not the centres method): the primary centres at the pins, the others by Kennedy's theorem
as intersections of two lines through them."""

import re
import subprocess

import pytest

from plans.analytic import solve
from plans.centres import instant_centres
from plans.compare import compare_centres
from plans.scene import example_path, load
from review_handouts import built_pdf

K_L, PRECISION = 0.008, 0.1  # the six-bar plate's k_l (page 1) and the handout's drafting precision


def _meet(a, b, c, d):
    """The intersection of line ab with line cd (complex points)."""
    u, w = b - a, d - c
    t = ((c - a).real * w.imag - (c - a).imag * w.real) / (u.real * w.imag - u.imag * w.real)
    return a + t * u


def _read(length: float) -> float:
    """A length [m] as measured on the drawing: its mm at K_L rounded to 0.1 mm, back in metres."""
    return round(length / K_L / PRECISION) * PRECISION * K_L


def _expected():
    scene = load(example_path("six-bar"))
    points = solve(scene).points
    O, A, B, C, D = (complex(points[n].r[0]) for n in "OABCD")
    omega2 = -10.0
    p12, p23, p14, p34 = O, A, D, C
    p13 = _meet(p12, p23, p14, p34)  # Kennedy: P13 on P12P23 and on P14P34
    p24 = _meet(p12, p14, p23, p34)  # P24 on P12P14 and on P23P34
    sign3 = 1.0 if ((p23 - p12) / (p23 - p13)).real > 0 else -1.0
    sign4 = 1.0 if ((p24 - p12) / (p24 - p14)).real > 0 else -1.0
    omega4 = omega2 * sign4 * _read(abs(p24 - p12)) / _read(abs(p24 - p14))
    # a student takes, of the paths to link 3, the one whose shortest length is longest: from the crank through P23
    # (P12P23, P13P23), or from the rocker 4 (found through P24: P12P24, P14P24) through P34 (P14P34, P13P34)
    direct = min(abs(p23 - p12), abs(p23 - p13))
    via_4 = min(abs(p24 - p12), abs(p24 - p14), abs(p34 - p14), abs(p34 - p13))
    path3 = "direct" if direct >= via_4 else "via 4"
    if direct >= via_4:
        omega3 = omega2 * sign3 * _read(abs(p23 - p12)) / _read(abs(p23 - p13))
    else:
        sign = 1.0 if ((p34 - p14) / (p34 - p13)).real > 0 else -1.0
        omega3 = omega4 * sign * _read(abs(p34 - p14)) / _read(abs(p34 - p13))
    return {"path3": path3, "omega3": omega3, "omega4": omega4, "vB": abs(omega3) * _read(abs(B - p13)), "vA": abs(omega2) * _read(abs(A - O))}


def test_six_bar_readings_at_the_drawings_precision():
    scene = load(example_path("six-bar"))
    want = _expected()
    read = instant_centres(scene, k_l=K_L, precision=PRECISION)
    assert read.links["3"] == pytest.approx(want["omega3"], rel=1e-9)
    assert read.links["4"] == pytest.approx(want["omega4"], rel=1e-9)
    assert abs(read.points["B"]) == pytest.approx(want["vB"], rel=1e-9)
    assert abs(read.points["A"]) == pytest.approx(want["vA"], rel=1e-9)  # 18.75 mm read 18.8: 1.504 m/s
    errors = {(c.section, c.name): c.rel_error for c in compare_centres(solve(scene), read)}
    assert 1e-4 < errors[("links", "3")] < 1e-2 and 1e-4 < errors[("points", "B")] < 1e-2
    # exact without a precision (plans solve, plans centres)
    exact = instant_centres(scene)
    assert {(c.section, c.name): c.rel_error for c in compare_centres(solve(scene), exact)}[("links", "3")] < 1e-9


def test_six_bar_handout_table_prints_the_readings(tmp_path):
    pdf = tmp_path / "h.pdf"
    pdf.write_bytes(built_pdf("six-bar", None, "en", centres=True))
    page = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True, check=True).stdout.decode().split("\f")[-2]
    want = _expected()
    # (the labels' subscripts are set as small digits, which the PDF's text gives as digits: P₁₂ reads "P12")
    plain = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")
    rows = {m.group(1): m.group(2).translate(plain).split() for m in re.finditer(r"𝜔(\d) \[rad/s\]\s+P\S+\s+(.*)", page)}
    # the cells: P_1j, the lengths read for ω (the path: "P₁₂P₂₄ / P₁₄P₂₄ = 40.0 / 25.3"), the value, analytic, error
    assert rows["3"][-3] == f"{want['omega3']:.4g}", rows
    assert rows["4"][-3] == f"{want['omega4']:.4g}".replace("-", "−"), rows
    # the reading names what ω is found from and the sense the ratio theorem gives: "−𝜔4 · P14P34 / P13P34 = −𝜔4 · …"
    direct = want["path3"] == "direct"
    source3, omega_source3 = ("𝜔2", -10.0) if direct else ("𝜔4", want["omega4"])
    sign3 = "−" if want["omega3"] * omega_source3 < 0 else ""
    assert rows["3"][:5] == [sign3 + source3, "·"] + (["P12P23", "/", "P13P23"] if direct else ["P14P34", "/", "P13P34"]), rows
    sign4 = "−" if want["omega4"] * -10.0 < 0 else ""
    assert rows["4"][:5] == [sign4 + "𝜔2", "·", "P12P24", "/", "P14P24"], rows
    assert rows["3"][-1] != "0" and rows["4"][-1] != "0", rows  # a real error, as the velocity plans' tables show
