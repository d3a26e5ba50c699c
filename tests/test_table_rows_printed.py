"""Teacher's review (issue 20): every comparison table a student can check by hand.

Read back from the typeset handout (``pdftotext``): in each row of the graphical-against-analytic tables and
of the centres page's table, the analytic value is printed to the graphical one's decimals (trailing zeros kept)
and to at least 4 significant digits (round 21: rounded to the reading's decimals it hid the graphical method's
error, "v_K 0,032 | 0,032 | 0" against 0,03238), and the relative error printed is the one of the two printed numbers (recomputed here from the strings alone; a vector
``m ∠ θ°`` from its printed magnitude and direction).  The driver's ω is given, not found: "—" on every page.
The column headers are the course's words (по плану), and the readings table's last column has a word.
"""

from __future__ import annotations

import cmath
import math
import re
import subprocess

import pytest

import plans
from review_handouts import built, built_pdf

SUPERSCRIPT = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")
NUMBER = r"−?\d+(?:[.,]\d+)?"
CELL = rf"{NUMBER}(?: ∠ {NUMBER}°)?"
ERROR = rf"(?:—|0|\d[.,]\d·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)"
# the centres page puts its centre and the lengths ω was read from between the quantity and the values
ROW = re.compile(rf"^\s*(?P<q>\S+) \[[^\]]+\](?:\s+P\S+)?(?:\s+\S.*?)??\s+(?P<g>{CELL})\s+(?P<a>{CELL})\s+(?P<e>{ERROR})\s*$")


def _number(text: str) -> float:
    text = text.replace("−", "-").replace(",", ".")
    if "·10" in text:
        mantissa, exponent = text.split("·10")
        return float(mantissa) * 10 ** int(exponent.translate(SUPERSCRIPT))
    return float(text)


def _value(cell: str) -> complex:
    if "∠" in cell:
        magnitude, angle = cell.split("∠")
        return _number(magnitude) * cmath.exp(1j * math.radians(_number(angle.strip().rstrip("°"))))
    return complex(_number(cell))


def _decimals(cell: str) -> int:
    magnitude = cell.split(" ∠")[0].replace(",", ".")
    return len(magnitude.partition(".")[2])


@pytest.fixture(scope="module")
def rows(tmp_path_factory):
    path = tmp_path_factory.mktemp("rows") / "h.pdf"
    path.write_bytes(built_pdf("six-bar", centres=True))  # as `plans handout --example six-bar --centres`
    text = subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True, text=True, check=True).stdout
    import unicodedata

    plain = "".join(unicodedata.normalize("NFKC", c) if 0x1D400 <= ord(c) <= 0x1D7FF else c for c in text)
    return [m for line in plain.splitlines() if (m := ROW.match(line))]


def _significant(cell: str) -> int:
    return len(cell.split(" ∠")[0].replace("−", "").replace(",", "").replace(".", "").lstrip("0"))


def test_the_analytic_value_to_four_digits_and_the_error_of_the_printed_numbers(rows):
    assert len(rows) >= 25  # the plans' table (22 rows) and the centres page's (9)
    checked = 0
    for m in rows:
        g, a, e = m["g"], m["a"], m["e"]
        assert _decimals(a) >= _decimals(g), m.group(0)
        assert _significant(a) >= 4 or _decimals(a) == _decimals(g) or e == "—", m.group(0)
        if e == "—":
            continue
        recomputed = abs(_value(g) - _value(a)) / abs(_value(a))
        if e == "0":
            assert recomputed == 0, m.group(0)
        else:
            assert _number(e) == pytest.approx(recomputed, rel=0.05), m.group(0)  # the error printed to 2 digits
            checked += 1
    assert checked >= 10


def test_the_teachers_rows(rows):
    """The rows an earlier review quoted: ε₅ −3.35 against −3.344 (it had asked for −3.34, the reading's decimals:
    round 21 showed that this hides the graphical method's error, and the analytic value keeps 4 digits), v_E5 0.775
    against 0.7759."""
    by = {}
    for m in rows:
        by.setdefault(m["q"], []).append(m)
    eps5 = by["ε5"][0]
    assert (eps5["g"], eps5["a"]) == ("−3.35", "−3.344")
    assert _number(eps5["e"]) == pytest.approx(0.006 / 3.344, rel=0.05)
    v = by["vE5"][0]
    assert v["a"].startswith("0.7759 ∠") and _decimals(v["g"]) == 3  # (the reading at the plate's k_v, to its 3 decimals)


def test_the_drivers_omega_has_no_error_on_any_page(rows):
    omega2 = [m for m in rows if m["q"] == "ω2"]
    assert len(omega2) >= 2  # the plans' tables and the centres pages'
    assert {m["e"] for m in omega2} == {"—"}


@pytest.mark.parametrize("lang, word", [("ru", "по плану"), ("sr", "са плана"), ("bg", "от плана"), ("sl", "iz načrta")])
def test_the_plans_column_in_the_courses_words(lang, word):
    from plans.drawing.sheet import translate_table

    assert translate_table([["quantity", "graphical", "analytic", "rel. error"]], lang)[0][1] == word


@pytest.mark.parametrize("lang", ["en", "sr", "ru", "bg", "sl"])
def test_the_readings_value_column_has_a_word(lang):
    from plans.drawing.readings import plan_readings
    from plans.graphical import construct

    scene = plans.load(plans.example_path("slider-crank"))
    head = plan_readings(construct(scene), "velocity", lang)[0][-1]
    assert head.startswith("= ") and re.search(r"\w{4,}", head), head


# --- round 21: the analytic value to 4 digits, read off the handouts with two tables across a page --------------------

#: a comparison row as pdftotext -layout sets it, two tables side by side on a line (several rows to a line)
ROW_ACROSS = re.compile(rf"\] +(?P<g>{CELL}) +(?P<a>{CELL}) +(?P<e>0|\d[.,]\d·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)(?= |$)")


def _rows_across(pdf: bytes) -> list:
    import tempfile
    from pathlib import Path

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "h.pdf"
        path.write_bytes(pdf)
        text = subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True, check=True).stdout.decode()
    return [m for line in text.splitlines() for m in ROW_ACROSS.finditer(line)]


@pytest.mark.parametrize("example, positions, lang", [("linear-arm", 8, "bg"), ("quick-return", 12, "sr")])
def test_the_error_is_the_printed_numbers_and_the_analytic_value_has_four_digits(example, positions, lang):
    """Round 21 (bg linear-arm handout): "v_K 0,032 ∠ 41,9° | 0,032 ∠ 41,9° | 0", where the analytic |v_K| is 0,03238
    and the graphical method is 1,2 % off: a student would believe the plan exact. In every comparison row of the
    handouts the analytic value has at least 4 significant digits, and the printed error is |g − a| / |a| of the two
    printed numbers, to the two digits it is printed with."""
    rows = _rows_across(built_pdf(example, positions, lang))
    assert len(rows) >= 40, len(rows)
    for m in rows:
        g, a, e = m.group("g"), m.group("a"), m.group("e")
        assert _significant(a) >= 4, m.group(0)
        error = abs(_value(g) - _value(a)) / abs(_value(a))
        if e == "0":
            assert error <= 1e-12, m.group(0)
            continue
        exponent = int(e.split("·10")[1].translate(SUPERSCRIPT))
        assert _number(e) == pytest.approx(error, abs=0.051 * 10.0 ** exponent), m.group(0)


def test_the_linear_arms_v_k_is_not_exact_on_the_plan():
    """Position 2: pk reads 3,2 mm at k_v 0,01 (m/s)/mm, 0,032 m/s; |v_K| = ω₄·DK (the analytic solution) 0,03238."""
    import numpy as np

    doc = built("linear-arm", 8, "bg")
    run = next(r for r in doc.runs if r.index == 2)
    v_k = abs(complex(np.ravel(run.analytic.points["K"].v)[0]))
    assert round(v_k, 5) == pytest.approx(0.03238)
    rows = [m.group(0) for m in _rows_across(built_pdf("linear-arm", 8, "bg"))]
    assert any(re.fullmatch(r"\] +0,032 ∠ 41,9° +0,03238 ∠ 41,9° +1,2·10⁻²", row) for row in rows), "v_K at position 2"
