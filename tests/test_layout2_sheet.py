"""The single-position sheet (issue 10 §4): A4 or A3 landscape (never the smallest ISO page of any
orientation), a drawing frame, and a title block with the title, the structural formula, the scale
factors and the assembly branches."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import pytest

import plans
from plans.cli import main

SVG = "{http://www.w3.org/2000/svg}"
#: ISO 216 landscape sheets [mm], typed from the standard
A4_LANDSCAPE = ("297mm", "210mm")
A3_LANDSCAPE = ("420mm", "297mm")


def _gid_texts(root, gid_prefix):
    """The text of each row drawn under ids ``sheet-<gid_prefix>[N][-k]`` (a row is set as several runs), in order."""
    rows: dict[str, str] = {}
    for g in root.iter(f"{SVG}g"):
        m = re.fullmatch(rf"sheet-{gid_prefix}(\d*)(?:-\d+)?", g.get("id") or "")
        if m:
            rows[m.group(1)] = rows.get(m.group(1), "") + "".join("".join(t.itertext()) for t in g.iter(f"{SVG}text"))
    return list(rows.values())


@pytest.mark.parametrize("example", plans.example_names())
def test_the_sheet_is_a4_or_a3_landscape_with_a_frame_and_a_title_block(example, tmp_path):
    assert main(["draw", "--example", example, "-o", str(tmp_path)]) == 0
    root = ET.parse(tmp_path / "sheet.svg").getroot()
    # A4 or A3 landscape, every example (the sheet's layout chooses the factors that fill A3)
    formats = (A4_LANDSCAPE, A3_LANDSCAPE)
    assert (root.get("width"), root.get("height")) in formats, (example, root.get("width"), root.get("height"))
    ids = {g.get("id") for g in root.iter(f"{SVG}g")}
    assert "sheet-sheet-frame" in ids and "sheet-title-block" in ids
    scene = plans.load(plans.example_path(example))
    title = " ".join(_gid_texts(root, "title-block-title"))
    assert scene.title in title
    rows = ["".join(r.split()) for r in _gid_texts(root, "title-block-row")]
    formula = plans.find_structure(scene).formula
    assert any("".join(formula.split()) in r for r in rows), rows
    assert any("kl=" in r and "kv=" in r for r in rows), rows  # the scale factors, typeset


def test_the_title_block_names_the_assembly_branch_of_each_group_that_has_two(tmp_path):
    assert main(["draw", "--example", "six-bar", "-o", str(tmp_path)]) == 0
    root = ET.parse(tmp_path / "sheet.svg").getroot()
    rows = _gid_texts(root, "title-block-row")
    # the six-bar has two groups with two assemblies each: RRR(3,4) and RPR(5,6) (README, examples)
    assert any(r.startswith("RRR(3,4):") for r in rows) and any(r.startswith("RPR(5,6):") for r in rows), rows
    assert not any("5.rod" in r or "frame." in r for r in rows)
