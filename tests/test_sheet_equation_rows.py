"""The vector equations' rows on the A3 sheet are spaced at least as on the handout (issue 20, reviews 10 and 11).

The double underline of a known vector hangs a fixed 1.7 pt under its row; with the sheets' rows padded 1.2 mm, and
then 1.5 mm scaled down with a column reduced to 0.85 to fit A3, it sat on the arrows of the row under it, read as an
overline there: "would not print" on four sheets, while the handout's rows, padded 1.5 mm at 9.5 pt, were judged
right. The padding is read from the typeset source, at every size the sheet may set its column: never under 1.5 mm.
"""

from __future__ import annotations

import re

import pytest

import plans
from plans.graphical import construct
from plans.pages.sheet import sheet_at

#: what the reviewers judged right on the handout: rows padded 1.5 mm above and below at 9.5 pt text
RIGHT_MM, RIGHT_PT = 1.5, 9.5
#: the least a sheet's column is reduced to before a larger paper (plans.pages.sheet.TEXT_REDUCED's last, typed here)
LEAST = 0.85
_TABLE = re.compile(r"#text\(size: ([0-9.]+)pt\)\[#table\(columns: \(auto, auto, 1fr\), stroke: none, inset: \(x: [0-9.]+mm, y: ([0-9.]+)(mm|em)\)")


def _paddings(source: str) -> list[tuple[float, float]]:
    """(text size [pt], row padding [mm]) of every equations table in a Typst source."""
    out = []
    for size, value, unit in _TABLE.findall(source):
        size, value = float(size), float(value)
        out.append((size, value if unit == "mm" else value * size * 25.4 / 72))
    return out


@pytest.mark.parametrize("example, lang", [("six-bar", "en"), ("quick-return", "sr"), ("four-bar", "ru")])
def test_the_sheets_equation_rows_are_padded_as_the_handouts(example, lang):
    sheet = sheet_at(construct(plans.load(plans.example_path(example))), lang=lang)
    found = _paddings(sheet.source)
    assert len(found) == 2, found  # the velocity plan's equations and the acceleration plan's
    for size, padding in found:
        assert size == pytest.approx(RIGHT_PT)
        assert padding >= RIGHT_MM - 0.01, (size, padding)


def test_a_reduced_column_keeps_its_rows_padding_in_proportion():
    from plans.pages.sheet import enlarged

    sheet = sheet_at(construct(plans.load(plans.example_path("six-bar"))))
    for factor in (LEAST, 0.9, 1.25):  # as the sheet sets a column reduced or enlarged
        found = _paddings(enlarged(sheet.source, factor))
        assert len(found) == 2
        for size, padding in found:
            assert size == pytest.approx(RIGHT_PT * factor, abs=0.01)
            assert padding >= RIGHT_MM - 0.01, (factor, size, padding)
