"""The third review of the centres pages (issue 20 §4, a teacher's reading of the rendered pages): the words of the
method page name each guide and say what the circle diagram's lines are, the tables' subscripts are legible, the
labels keep off the links and the names, and a sideways edge arrow's label sits at its own arrow's tip.

Expected words come from the scenes' own ``[names]`` (read here with tomllib) and from the teacher's wording."""

import io
import re
import tomllib

import pytest
from pypdf import PdfReader

from plans.centres import instant_centres
from plans.drawing.centres_page import centres_order_table
from plans.i18n import LANGUAGES, term
from plans.scene import example_path, load
from review_handouts import built_pdf

SUBSCRIPT = re.compile("[₀-₉]")


def _how(name: str, lang: str) -> dict[str, str]:
    result = instant_centres(load(example_path(name)))
    return {row[0]: row[1] for row in centres_order_table(result, lang)[1:]}


def _word(names: dict, guide: str, lang: str) -> str:
    """A guide's name as the scene's ``[names]`` write it in *lang*: the string, or its ``name`` (nominative) form
    where the scene gives grammatical forms (``{ name = "втулка", of = "втулката" }``)."""
    word = names[guide][lang]
    return word["name"] if isinstance(word, dict) else word


def test_each_guide_named_in_the_order_table():
    # bg linear-arm: P₁₂, P₃₄, P₃₅ sat on three guides and read "перпендикулярно на водача" alike
    names = tomllib.loads(example_path("linear-arm").read_text())["names"]
    how = _how("linear-arm", "bg")
    assert len({how["P₁₂"], how["P₃₄"], how["P₃₅"]}) == 3
    assert _word(names, "sleeve", "bg") in how["P₃₄"] and "4" in how["P₃₄"]  # the sleeve welded to rocker 4
    assert _word(names, "rod", "bg") in how["P₃₅"] and "3" in how["P₃₅"]  # block 5 rides on rod 3
    assert "стойка" in how["P₁₂"]  # the driver slides on the frame's floor
    # sr quick-return: the block's centre P₃₄ is perpendicular to the slot (кулиса) of link 4, the ram's P₁₆ to the frame's guide
    names = tomllib.loads(example_path("quick-return").read_text())["names"]
    how = _how("quick-return", "sr")
    assert _word(names, "slot", "sr") in how["P₃₄"] and "4" in how["P₃₄"]
    assert _word(names, "ram", "sr") in how["P₁₆"] and "постољ" in how["P₁₆"]
    assert how["P₁₆"] != how["P₃₄"]


def test_the_circle_diagram_says_solid_lines_not_sides():
    # 1–4 and 3–5 of the six-bar are diagonals: the legend says "solid lines", in every language
    assert term("circle_diagram_legend", "en").startswith("solid lines: centres at the kinematic pairs")
    old = {"en": "sides", "sr": "странице", "ru": "стороны", "bg": "страни", "sl": "stranice"}
    for lang in LANGUAGES:
        assert old[lang] not in term("circle_diagram_legend", lang).lower()
    assert term("centres_omega_rule", "en").startswith("Angular velocities from the instant centres")
    assert "driver's," not in term("centres_omega_rule_linear", "en")


@pytest.fixture(scope="module")
def six_bar_pdf():
    return PdfReader(io.BytesIO(built_pdf("six-bar", None, "en", centres=True)))


def test_centre_subscripts_in_the_tables_at_least_7_5_pt(six_bar_pdf):
    # the order table and the P₁ⱼ column were set with the font's subscript glyphs, about 5 pt at 8 pt
    checked = 0
    for page in six_bar_pdf.pages:
        text = page.extract_text()
        if "The order of finding the centres" not in text and "instant centres" not in text:
            continue
        chunks = []
        page.extract_text(visitor_text=lambda t, cm, tm, fd, fs: chunks.append((t, fs)) if t.strip() else None)
        in_table = False
        for k, (t, fs) in enumerate(chunks):
            in_table |= t.strip() in ("centre", "quantity")
            if not in_table:
                continue  # the drawings' SVG text and the rules above the tables
            assert not SUBSCRIPT.search(t), (t, fs)  # a subscript glyph: ~0.6 of the text's size
            if t.strip() == "P" and k + 1 < len(chunks) and chunks[k + 1][0].isdigit():
                assert chunks[k + 1][1] >= 7.5, chunks[k: k + 2]
                checked += 1
    assert checked >= 30  # 15 centres in the order table, the P₁ⱼ column and the readings' paths


def test_the_method_page_is_filled(six_bar_pdf):
    # third review: the six-bar's method page was ~40 % empty (its order table ended at 54 % of the page's text area):
    # the circle diagram large, the legend and rules at the text's size, the order table across: past 60 %
    page = next(p for p in six_bar_pdf.pages if "The order of finding the centres" in p.extract_text())
    ys = []
    page.extract_text(visitor_text=lambda t, cm, tm, fd, fs: ys.append((cm[5] + tm[5], t)) if t.strip() else None)
    top = max(y for y, _ in ys)  # the page's heading
    block = max(y for y, t in ys if t.startswith("Kinematic analysis of the mechanism"))  # the title block's first line
    lowest = min(y for y, _ in ys if y > block + 5)
    assert (top - lowest) / (top - block) > 0.6
