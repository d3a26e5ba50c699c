"""The single-position sheet (issue 10 §4, issue 20 §2): A3 landscape, a drawing frame, and the plate's title
block with the plate's name, the scene's title and the scale factors; the structural formula and the assembly of
the groups said in the course's words on the sheet, never as program tokens."""

from __future__ import annotations

import io
import re

import pytest
from pypdf import PdfReader

import plans
from sheet_pages import scales, text
from review_handouts import drawn_sheet

#: ISO 216 A3 landscape [mm], typed from the standard
A3_LANDSCAPE = (420.0, 297.0)
#: the kind of each class II group as the course numbers them (Artobolevsky): RRR 1, RRP 2, RPR 3, PRP 4, RPP 5
KINDS = {"RRR": 1, "RRP": 2, "PRR": 2, "RPR": 3, "PRP": 4, "RPP": 5, "PPR": 5}


def _course_formula(formula: str) -> str:
    return re.sub(r"\b([RP]{3})\(", lambda m: f"II{KINDS[m.group(1)]}(", formula)


@pytest.mark.parametrize("example", plans.example_names())
def test_the_sheet_is_a3_landscape_with_the_plate_s_title_block(example):
    pdf = drawn_sheet(example, output="sheet.pdf").read_bytes()
    (page,) = PdfReader(io.BytesIO(pdf)).pages
    size = tuple(round(float(v) * 25.4 / 72, 1) for v in (page.mediabox.width, page.mediabox.height))
    assert size == A3_LANDSCAPE, (example, size)
    flat = " ".join(text(pdf).split())
    scene = plans.load(plans.example_path(example))
    assert "Kinematic analysis of the mechanism" in flat and scene.title in flat
    assert "Drawn by" in flat and "Checked by" in flat and "Sheet 1 of 1" in flat
    formula = _course_formula(plans.find_structure(scene).formula)
    assert "".join(formula.split()) in "".join(flat.split()), (formula, flat[:300])
    k = scales(flat)
    assert {"k_l", "k_v"} <= set(k), k


def test_the_assembly_of_each_group_that_has_two_is_said_in_words():
    flat = " ".join(text(drawn_sheet("six-bar", output="sheet.pdf").read_bytes()).split())
    # the six-bar has two groups with two assemblies each: 3–4 (RRR) and 5–6 (RPR) (README, examples)
    assert "Assembly of the groups: group 3–4:" in flat and "group 5–6:" in flat, flat
    for token in ("RRR(3,4)", "RPR(5,6)", "5.rod", "frame.", "(+1)", "(−1)"):
        assert token not in flat, token
