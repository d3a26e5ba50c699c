"""One quantity, one number on a page (issue 20, rounds 12–15): the comparison table's graphical value of a point and
the plan's readings table printed the same reading differently in its last digit (bg linear-arm position 2: a_K
"0,097" against "π k′ 6,5 × 0,015 = 0,098"; a^k_F4F3 0,298 against 0,299), the first having come through the
vector's direction as 0.09749999999999999.  Expected: 6.5 mm × 0.015 = 0.0975 → 0.098 (half up), typed here."""

import re

import pytest

from plans.drawing.readings import plan_readings
from plans.report import reading_number, sheet_table
from review_handouts import built


def test_half_a_step_rounds_up_wherever_the_value_came_from():
    assert reading_number(0.0975, 0.0015) == "0.098"
    assert reading_number(0.09749999999999999, 0.0015) == "0.098"  # |0.0975·e^{iθ}| in floating point
    assert reading_number(0.2985, 0.0015) == "0.299" and reading_number(-0.2985, 0.0015) == "−0.299"
    assert reading_number(0.0974, 0.0015) == "0.097"


def _number(text: str) -> str:
    return re.match(r"[−-]?[0-9]+(?:[.,][0-9]+)?", text.strip()).group(0).replace(",", ".").replace("−", "-").lstrip("-")


@pytest.mark.parametrize("example, positions", [("linear-arm", 8), ("quick-return", 12), ("six-bar", 12)])
def test_a_points_reading_and_its_table_value_are_one_number(example, positions):
    doc = built(example, positions, "en")
    checked = 0
    for r in doc.runs:
        if r.index not in doc.accelerations:
            continue
        table = {row[0].split(" [")[0]: row[1] for row in sheet_table(r.comparisons, r.graphical, r.analytic, points_of_links=True)[1:]}
        for kind in ("velocity", "acceleration"):
            for symbol, _, _, _, value in plan_readings(r.graphical, kind, "en"):
                if symbol in table and re.fullmatch(r"\$[va]_\{[A-Z][0-9]?\}\$", symbol):
                    assert _number(table[symbol]) == _number(value), (example, r.index, symbol, table[symbol], value)
                    checked += 1
    assert checked >= 6
