"""The handout's page flow and text as a teacher reviewed them (issue 20, the pages' review): an equation never parted
from its solution, a formula never broken inside, a long title legible in the title block, i·number in the loop
equations.

Read off the typeset pages by poppler's ``pdftotext -bbox-layout`` (word boxes) where the question is where the
typesetter put something; the expected text from the course's notation (domain.md §4, §5), not from the code.
"""

from __future__ import annotations

import re
import shutil

import pytest

import plans
from plans.loops import loop_equations, plain
from plans.pages.document import A4_PORTRAIT, Document, formula_parts
from plans.pages.typesetting import compile_document

from pdf_lines import page_lines

pytestmark = [pytest.mark.filterwarnings("ignore"),
              pytest.mark.skipif(shutil.which("pdftotext") is None, reason="poppler's pdftotext reads the pages")]

PT = 25.4 / 72  # mm per PDF point


def _pages(pdf: bytes) -> list[list[tuple[float, float, float, float, str]]]:
    """Every page's text lines (:func:`pdf_lines.page_lines`, as written)."""
    return page_lines(pdf, normalise=False)


def _body(lines):
    """The lines of a page's text area (not the title block under it), top to bottom."""
    bottom = (A4_PORTRAIT.size[1] - A4_PORTRAIT.margins[3]) / PT
    return sorted((line for line in lines if line[3] <= bottom), key=lambda line: line[1])


# --- 1. an equation and its solution on one page --------------------------------------------------------------


def test_a_loop_equation_is_never_parted_from_its_solution_by_a_page_break():
    """The quick-return's loops set under fillers of 14 heights, 3 mm apart, each starting a page: wherever the page
    ends, the first line of the next page is never a solution (a line with ⇒) whose equation is on the page before."""
    scene = plans.load(plans.example_path("quick-return"))
    blocks = loop_equations(plans.solve(scene))
    assert sum(line.startswith("$\\quad") for b in blocks for line in b.lines) >= 6  # (solution lines to part)
    doc = Document(scene, "sr")
    doc.plate = {"k_l": 0.006}
    heights = [A4_PORTRAIT.text_height - 60.0 + 3.0 * k for k in range(14)]
    for n, height in enumerate(heights):
        if n:
            doc.body.append("#pagebreak()")
        doc.body.append(f"#block(height: {height:.1f}mm, width: 100%)")
        for block in blocks:
            doc.loop_block(block)
    pages = _pages(compile_document(doc.source(), doc.images, "pdf"))
    starts = 0
    for n, lines in enumerate(pages[1:], start=2):
        body = _body(lines)
        if body and not body[0][4].startswith(("група", "погонски")):
            starts += 1
            assert "⇒" not in body[0][4], (n, body[0][4])
    assert starts >= 5  # (the breaks fell inside the loops, not only between blocks)


# --- 3. a formula never broken inside ---------------------------------------------------------------------------


def test_a_formula_without_a_unit_is_one_box():
    assert formula_parts("|a_A| = 0, |a_F| = 0 (the same)") == [("|a_A| = 0", True), (", ", False), ("|a_F| = 0", True), (" (the same)", False)]
    assert formula_parts("ω₂ = 6 rad/s") == [("ω₂ = 6 rad/s", True)]


# --- 4. the title block's title legible --------------------------------------------------------------------------


def test_a_long_title_wraps_in_the_title_block_at_eight_points_or_more(tmp_path):
    """A long Bulgarian title (the linear-arm's as it read, about 90 characters) in the title block: its words as
    tall as the 8 pt words of the block's 'drawn by' cell or taller (it was shrunk to about 6 pt to stay on one
    line), on two lines."""
    import re

    from plans.i18n import term

    long_title = "Линеен задвижващ механизъм с рамо, заварена изместена втулка и плъзгач по подвижен прът"
    text = plans.example_path("linear-arm").read_text(encoding="utf-8")
    text = re.sub(r'(?m)^(title = \{.*?bg = )"[^"]*"', lambda m: m.group(1) + f'"{long_title}"', text, count=1)
    (tmp_path / "arm.toml").write_text(text, encoding="utf-8")
    scene = plans.load(tmp_path / "arm.toml")
    title = scene.title_in("bg")
    assert title == long_title
    assert len(title) > 80
    doc = Document(scene, "bg")
    doc.plate = {"k_l": 0.006}
    doc.line("x")
    lines = _pages(compile_document(doc.source(), doc.images, "pdf"))[0]
    bottom = (A4_PORTRAIT.size[1] - A4_PORTRAIT.margins[3]) / PT
    block = [line for line in lines if line[1] > bottom]
    drawn_by = next(line for line in block if line[4].startswith(term("drawn_by", "bg")))
    sheet = next(line for line in block if line[4].startswith(term("sheet", "bg")))
    titled = sorted((line for line in block if line[2] < sheet[0]), key=lambda line: line[1])[:2]  # (the first cell)
    assert " ".join(line[4] for line in titled).endswith(title), [t[4] for t in block]
    assert titled[1][1] > titled[0][3] - 1.0  # two lines, one under the other
    for line in titled:
        assert line[3] - line[1] >= (drawn_by[3] - drawn_by[1]) - 0.05, (line, drawn_by)


# --- 5. i times a number ----------------------------------------------------------------------------------------


@pytest.mark.parametrize("example", ["six-bar", "quick-return", "linear-arm", "four-bar"])
def test_i_times_a_number_has_its_dot(example):
    """i·0.2502·0.45, not i0.2502·0.45: the imaginary unit is never run into a number."""
    lines = [plain(line) for b in loop_equations(plans.solve(plans.load(plans.example_path(example)))) for line in b.lines]
    joined = "\n".join(lines)
    assert not re.search(r"(?<![\w.^])i[(\d]", joined), re.findall(r".{20}(?<![\w.^])i[(\d].{10}", joined)  # (e^{i 55°}: an angle)
    assert re.search(r"i·\(?-?\d", joined)  # (a number after i, with its dot)


@pytest.mark.parametrize("lang, number", [("en", "0.2502"), ("sr", "0,2502"), ("ru", "0,2502"), ("bg", "0,2502"), ("sl", "0,2502")])
def test_the_six_bar_loop_line_on_a_page_in_every_language(lang, number):
    """The six-bar's v_B line as Typst sets it: i ⋅ 0.2502 ⋅ 0.45 (decimal comma in sr, ru, bg, sl)."""
    scene = plans.load(plans.example_path("six-bar"))
    doc = Document(scene, lang)
    doc.plate = {"k_l": 0.006}
    for block in loop_equations(plans.solve(scene)):
        doc.loop_block(block)
    text = " ".join(line[4] for page in _pages(compile_document(doc.source(), doc.images, "pdf")) for line in page)
    assert f"𝑖 ⋅ {number} ⋅ {number[0]}{number[1]}45" in text, text[:400]
    assert not re.search(r"(?<!𝑒 )𝑖 ?\d", text)  # (𝑒 𝑖 55.00°: an angle in an exponent)
