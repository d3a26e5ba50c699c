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
from review_handouts import built_pdf

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
