"""The readings tables of an A3 sheet: no cell's words run into the next cell's (the teacher's review of the
six-bar and quick-return sheets: "÷ 0.6765 (l_EB)" overprinted the value, read "(l_EB)815 rad/s").

Read off the typeset sheet by poppler's ``pdftotext -bbox`` (word boxes): on a row of the readings tables, no two
words overlap."""

from __future__ import annotations

import re
import shutil
import subprocess

import pytest

from review_handouts import drawn_sheet

pytestmark = pytest.mark.skipif(shutil.which("pdftotext") is None, reason="poppler's pdftotext reads the sheet")

_WORD = re.compile(r'<word xMin="([\d.]+)" yMin="([\d.]+)" xMax="([\d.]+)" yMax="([\d.]+)">([^<]*)</word>')


@pytest.mark.parametrize("example, lang", [("six-bar", "en"), ("quick-return", "sr")])
def test_no_word_of_a_readings_row_over_another(example, lang):
    pdf = drawn_sheet(example, lang, "sheet.pdf")
    text = subprocess.run(["pdftotext", "-bbox", str(pdf), "-"], capture_output=True, text=True, check=True).stdout
    words = [(float(a), float(b), float(c), float(d), w) for a, b, c, d, w in _WORD.findall(text)]
    # the readings rows: those holding a "÷" (a link's length divides the reading: ω, ε) and their neighbours
    rows = [w for w in words if w[4] == "÷"]
    assert rows, "the readings tables give ω and ε through a link's length"
    crowded = []
    for x0, y0, x1, y1, _ in rows:
        line = [w for w in words if w[1] < y1 + 12 and w[3] > y0 - 12 and abs(w[0] - x0) < 120]
        for i, a in enumerate(line):
            for b in line[i + 1:]:
                # on one line (their boxes, a font's whole height, overlap by half the smaller) and across each other
                tall = 0.5 * min(a[3] - a[1], b[3] - b[1])
                if min(a[2], b[2]) - max(a[0], b[0]) > 0.5 and min(a[3], b[3]) - max(a[1], b[1]) > tall:
                    crowded.append((a[4], b[4]))
    assert not crowded, crowded


@pytest.mark.parametrize("example, lang, words, said", [
    ("quick-return", "sr", "Кратке дужи", False),  # its plans have no note under them at the sheet's factors
    ("six-bar", "en", "Short segments and near-coincident directions", True),  # a′n₁ = 0.25 mm, ∠(πm′) ∠(πa′)
])
def test_the_legend_explains_the_notes_under_a_plan_only_where_there_are_some(example, lang, words, said):
    # the review of the quick-return sheet: "the note 'Кратке дужи … дати су испод плана' refers to nothing"
    pdf = drawn_sheet(example, lang, "sheet.pdf")
    text = " ".join(subprocess.run(["pdftotext", str(pdf), "-"], capture_output=True, text=True, check=True).stdout.split())
    assert (words in text) == said
