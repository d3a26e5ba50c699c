"""Sheet vector equations as an SVG viewer draws them (review finding 20).

A typeset line is written as runs, each a ``<text>`` placed at its own x:
``" = ω"``, then the subscript ``"2"``, then ``" × OA"``.  An SVG viewer
applies the document's whitespace rule to each run: by default it strips the
spaces at a run's ends and collapses the others (SVG 1.1 §10.15), so a run
with a leading space is drawn a space-width left of where plans measured it:
"ω ₂× OA", "v_A[m/s]".  These tests apply that rule as the SVG states it
(``xml:space``) and measure, with the font's own advances (FreeType, read
here), where each base glyph ends and where its subscript starts.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import pytest
from matplotlib.font_manager import FontProperties, findfont, get_font

from plans.cli import main

SVG = "{http://www.w3.org/2000/svg}"
XML_SPACE = "{http://www.w3.org/XML/1998/namespace}space"
_TRANSLATE = re.compile(r"translate\(([-0-9.e]+) ([-0-9.e]+)\)")
_SIZE = re.compile(r"font-size: ([0-9.]+)px")


def _advance(text: str, size: float, italic: bool) -> float:
    """Advance width [SVG units = pt] of *text* in DejaVu Sans, glyph by glyph."""
    font = get_font(findfont(FontProperties(family="DejaVu Sans", style="italic" if italic else "normal")))
    font.set_size(size, 72)
    return sum(font.load_char(ord(c)).linearHoriAdvance / 65536.0 for c in text)


def _as_drawn(text: str, preserve: bool) -> str:
    """The characters an SVG viewer draws for a text node (SVG 1.1, 10.15 'White space handling')."""
    if preserve:
        return re.sub(r"[\n\t]", " ", text)
    text = re.sub(r"\n", "", text).replace("\t", " ")
    return re.sub(r" +", " ", text.strip(" "))


def _runs(path, prefix: str):
    """Per group whose id starts with *prefix*: its runs (x, y, size, italic, drawn text, written text)."""
    root = ET.parse(path).getroot()
    preserve = root.get(XML_SPACE) == "preserve"
    out = []
    for g in root.iter(f"{SVG}g"):
        if not (g.get("id") or "").startswith(prefix):
            continue
        runs = []
        for t in g.findall(f"{SVG}text"):
            x, y = (float(v) for v in _TRANSLATE.search(t.get("transform")).groups())
            style = t.get("style", "")
            keep = preserve or t.get(XML_SPACE) == "preserve"
            runs.append((x, y, float(_SIZE.search(style).group(1)), "italic" in style, _as_drawn(t.text or "", keep), t.text or ""))
        if runs:
            out.append(runs)
    return out


def _subscript_gaps(path, prefix: str) -> list[tuple[str, float]]:
    """(base + subscript, gap [pt]) for every run followed by a smaller run set lower: the subscript."""
    gaps = []
    for runs in _runs(path, prefix):
        for (x0, y0, s0, i0, drawn, written), (x1, y1, s1, _, sub, _) in zip(runs, runs[1:]):
            if not (s1 < s0 and y1 > y0 and drawn):
                continue
            # the viewer starts the drawn characters at x0 (a stripped leading space is not drawn)
            end = x0 + _advance(drawn, s0, i0)
            gaps.append((f"{written.strip()[-3:]}_{sub}", x1 - end))
    return gaps


@pytest.fixture(scope="module")
def sheet(tmp_path_factory):
    d = tmp_path_factory.mktemp("six-bar")
    assert main(["draw", "--example", "six-bar", "-o", str(d)]) == 0
    return d / "sheet.svg"


def test_every_subscript_of_the_sheet_equations_touches_its_symbol(sheet):
    gaps = _subscript_gaps(sheet, "sheet-equation")
    # ω₂ after " = " and after "|", ω₆ after "2 ", v_A, a^n_CA …: dozens of them
    assert len(gaps) >= 25
    assert any(name.endswith("ω_2") for name, _ in gaps)
    bad = [(name, round(gap, 2)) for name, gap in gaps if abs(gap) > 0.8]  # a space is 2.7 pt at 8.5 pt
    assert not bad, bad


def test_a_table_symbol_keeps_the_space_before_its_unit(sheet):
    # "v_A [m/s]": the run " [m/s]" after the subscript A starts with a space that must be drawn
    for runs in _runs(sheet, "sheet-table-cell"):
        for (x0, _, s0, i0, drawn0, _), (x1, _, s1, _, drawn1, written1) in zip(runs, runs[1:]):
            if written1.startswith(" [") and drawn1.startswith(" ["):
                break
        else:
            continue
        return
    pytest.fail("no table cell draws the space between a symbol and its unit")


def test_the_components_named_in_the_brackets_carry_their_subscripts():
    import plans
    from plans.drawing.sheet import sheet_equations
    from plans.graphical import construct

    lines = sheet_equations(construct(plans.load(plans.example_path("six-bar"))))
    text = " ".join(lines)
    assert "a^n_E5B ∥ EB" in text and "a^t_E5B ⊥ BE" in text
    assert not re.search(r"a\^[nt] [∥⊥]", text), text
