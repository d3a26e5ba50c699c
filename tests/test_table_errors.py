"""Round 21 (bg linear-arm handout): the comparison tables printed the analytic value rounded to the reading's
decimals, and the relative error of those two numbers: "v_K 0,032 ∠ 41,9° | 0,032 ∠ 41,9° | 0", where the analytic
|v_K| is 0,03238 and the graphical method is 1,2 % off. A student would believe the plan exact.

Read from the typeset PDF (pdftotext): in every comparison row the analytic value has at least 4 significant digits,
and the printed error is |g − a| / |a| of the two printed numbers (vectors for magnitude ∠ direction), to the two
digits it is printed with; v_K at position 2 against the analytic solution itself."""

from __future__ import annotations

import cmath
import math
import re
import subprocess
import tempfile
from pathlib import Path

import numpy as np
import pytest

from review_handouts import built, built_pdf

_NUMBER = r"−?\d+(?:,\d+)?"
_CELL = rf"{_NUMBER}(?: ∠ \d+,\d°)?"
_ROW = re.compile(rf"\] +(?P<g>{_CELL}) +(?P<a>{_CELL}) +(?P<e>0|\d,\d·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)(?= |$)")
_SUPER = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def _value(cell: str) -> complex:
    magnitude, _, angle = cell.partition(" ∠ ")
    m = float(magnitude.replace("−", "-").replace(",", "."))
    return cmath.rect(m, math.radians(float(angle.rstrip("°").replace(",", ".")))) if angle else complex(m)


def _significant(cell: str) -> int:
    digits = cell.partition(" ∠ ")[0].replace("−", "").replace(",", "")
    return len(digits.lstrip("0"))


def _text(pdf: bytes) -> str:
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "h.pdf"
        path.write_bytes(pdf)
        return subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True, check=True).stdout.decode()


@pytest.mark.parametrize("example, positions, lang", [("linear-arm", 8, "bg"), ("quick-return", 12, "sr")])
def test_the_error_is_the_printed_numbers_and_the_analytic_value_has_four_digits(example, positions, lang):
    rows = [m for line in _text(built_pdf(example, positions, lang)).splitlines() for m in _ROW.finditer(line)]
    assert len(rows) >= 40, len(rows)
    for m in rows:
        g, a, e = m.group("g"), m.group("a"), m.group("e")
        assert _significant(a) >= 4, m.group(0)
        error = abs(_value(g) - _value(a)) / abs(_value(a))
        if e == "0":
            assert error <= 1e-12, m.group(0)
            continue
        mantissa, exponent = e.split("·10")
        printed = float(mantissa.replace(",", ".")) * 10.0 ** int(exponent.translate(_SUPER))
        assert printed == pytest.approx(error, abs=0.051 * 10.0 ** int(exponent.translate(_SUPER))), m.group(0)


def test_the_linear_arms_v_k_is_not_exact_on_the_plan():
    """Position 2: pk reads 3,2 mm at k_v 0,01 (m/s)/mm, 0,032 m/s; |v_K| = ω₄·DK (the analytic solution) 0,03238."""
    doc = built("linear-arm", 8, "bg")
    run = next(r for r in doc.runs if r.index == 2)
    v_k = abs(complex(np.ravel(run.analytic.points["K"].v)[0]))
    assert round(v_k, 5) == pytest.approx(0.03238)
    text = _text(built_pdf("linear-arm", 8, "bg"))
    assert re.search(r"0,032 ∠ 41,9° +0,03238 ∠ 41,9° +1,2·10⁻²", text), "v_K at position 2"
