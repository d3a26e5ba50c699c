"""Handouts: the PDF read back — pages, page size, text, embedded fonts with the Cyrillic glyphs — and SVG pages.

The PDF is opened with pypdf (a test dependency); nothing is checked by pixels.
"""

from __future__ import annotations

import re
import warnings
import xml.etree.ElementTree as ET

import pypdf
import pytest

import plans
from plans.errors import AssemblyError
from plans.handout import HandoutError, handout_pages, scene_data_lines, write_handout
from test_positions import STUCK

A4_PT = (595.2756, 841.8898)
CYRILLIC = re.compile(r"[\u0400-\u04FF]")
SVG = "{http://www.w3.org/2000/svg}"


def _write(path, scene, **options):
    """Write a handout, turning matplotlib's missing-glyph warnings into failures."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        paths = write_handout(scene, path, **options)
    missing = [str(w.message) for w in caught if "missing from" in str(w.message).lower()]
    assert not missing, missing
    return paths


@pytest.fixture(scope="module")
def russian(tmp_path_factory):
    """The four-bar in two positions, in Russian: cover, 2 × (graphical, check), two diagram pages, the kinematic
    diagrams of the output link and their table."""
    path = tmp_path_factory.mktemp("ru") / "four-bar.pdf"
    # from the scene's own angle (by default position 0 is the output's extreme position: test_motion_outputs.py)
    assert _write(path, plans.load(plans.example_path("four-bar")), positions=2, lang="ru", start="scene") == [path]
    return pypdf.PdfReader(path)


@pytest.fixture(scope="module")
def single(tmp_path_factory):
    path = tmp_path_factory.mktemp("en") / "slider-crank.pdf"
    _write(path, plans.load(plans.example_path("slider-crank")))
    return path


def test_the_pages_of_a_multi_position_handout(russian):
    total = len(russian.pages)
    assert total in (10, 11)  # the kinematic diagrams' table under them, or on a page of its own
    for page in russian.pages:
        assert (float(page.mediabox.width), float(page.mediabox.height)) == pytest.approx(A4_PT, abs=0.01)
    texts = [page.extract_text() for page in russian.pages]
    assert "План положений механизма" in texts[0]  # the plan of positions
    assert "Положения" in texts[0] and "0:  φ₂ = 60,0°" in texts[0] and "1:  φ₂ = 240,0°" in texts[0]  # decimal comma in Russian
    # each position: the mechanism and the velocity plan, the acceleration plan, the check
    for k, (velocity, acceleration, check) in enumerate(((1, 2, 3), (4, 5, 6))):
        for graphical in (velocity, acceleration):
            assert f"Положение {k}:" in texts[graphical]
            assert "Векторные уравнения планов" in texts[graphical]
        assert "План скоростей" in texts[velocity] and "План ускорений" not in texts[velocity]
        # each drawing states its scale factor once, under it (decimal comma), not again in the header
        assert len(re.findall(r"k\s*l\s*= [0-9]+,[0-9]+ m/mm", texts[velocity])) == 1
        assert len(re.findall(r"k\s*v\s*= [0-9]+,[0-9]+ \(m/s\)/mm", texts[velocity])) == 1
        assert len(re.findall(r"k\s*a\s*= [0-9]+,[0-9]+ \(m/s²\)/mm", texts[acceleration])) == 1
        assert "План ускорений" in texts[acceleration] and "План скоростей" not in texts[acceleration]
        assert "Аналитическая проверка: метод комплексных чисел" in texts[check]
        assert "RRR(3,4)" in texts[check] and "величина" in texts[check]
    assert "Кинематические диаграммы за цикл" in texts[7] and "Звенья" in texts[7]
    for page in (0, 7, 8):  # the driver's law over the cycle, on the cover and the diagrams (issue 19)
        assert "закон движения ведущего звена: постоянная угловая скорость" in texts[page]
    assert "Точки: скорость и ускорение" in texts[8]
    # the output link's kinematic diagrams by graphical differentiation (12 positions: fewer than 8 asked), then their table
    assert "Кинематические диаграммы выходного звена" in texts[9] and "методом хорд" in texts[9]
    assert "Выходное звено во всех положениях" in texts[-1]
    for number, text in enumerate(texts, start=1):
        assert f"стр. {number}/{total}" in text


def test_one_k_l_on_every_position_page_and_the_page_says_k_v_k_a_are_its_own(russian):
    pages = [russian.pages[1].extract_text(), russian.pages[4].extract_text()]
    k_l = {re.search(r"k\s*l\s*= ([0-9,]+) m/mm", text).group(1) for text in pages}
    assert all("," in value for value in k_l)  # decimal comma in Russian
    assert len(k_l) == 1
    for text in pages:
        assert "выбраны для каждого положения" in text


def test_fonts_are_embedded_truetype_dejavu(russian):
    seen = set()
    for page in russian.pages:
        fonts = page["/Resources"]["/Font"]
        for ref in fonts.values():
            font = ref.get_object()
            assert font["/Subtype"] == "/Type0", font["/Subtype"]  # no Type 3 bitmaps, no unembedded Type 1
            descendant = font["/DescendantFonts"][0].get_object()
            assert descendant["/Subtype"] == "/CIDFontType2"
            assert "/FontFile2" in descendant["/FontDescriptor"].get_object()  # the TrueType program is in the file
            seen.add(str(font["/BaseFont"]).split("+")[-1])
    assert {"DejaVuSans", "DejaVuSans-Bold"} <= seen


def test_cyrillic_is_drawn_with_real_glyphs_not_missing_glyph_boxes(russian):
    """Every Cyrillic character maps to a glyph of its own, never to glyph 0 (.notdef, the empty box)."""
    cyrillic_glyphs = 0
    for page in russian.pages:
        for ref in page["/Resources"]["/Font"].values():
            cmap = ref.get_object()["/ToUnicode"].get_object().get_data().decode("latin-1")
            for cid, code in re.findall(r"<([0-9A-Fa-f]{4})>\s*<([0-9A-Fa-f]{4})>", cmap):
                if CYRILLIC.match(chr(int(code, 16))):
                    assert int(cid, 16) != 0
                    cyrillic_glyphs += 1
    assert cyrillic_glyphs > 20
    text = "".join(page.extract_text() for page in russian.pages)
    assert "\ufffd" not in text and "□" not in text
    assert len(CYRILLIC.findall(text)) > 500


def test_a_one_position_handout_is_three_pages_the_plans_and_the_check(single):
    reader = pypdf.PdfReader(single)
    assert len(reader.pages) == 3
    first, accel, second = (page.extract_text() for page in reader.pages)
    assert "Offset slider-crank (E2)" in first and "φ₂ = 45.0°" in first
    assert "Mechanism" in first and "Velocity plan" in first and "Acceleration plan" in accel
    assert "Structural formula:  I(1,2) → RRP(3,4)" in first
    assert "Vector equations of the plans" in first and "Vector equations of the plans" in accel
    assert "Graphical against analytic" in second and "rel. error" in second
    assert "Analytic check: complex-number method" in second
    assert "−16.04" in second  # v_B of E2 on the loop line, with a true minus sign


def test_the_pdf_is_the_same_bytes_every_time(single, tmp_path):
    again = tmp_path / "again.pdf"
    _write(again, plans.load(plans.example_path("slider-crank")))
    assert again.read_bytes() == single.read_bytes()
    assert b"/CreationDate" not in single.read_bytes()


def test_svg_pages(tmp_path):
    paths = write_handout(plans.load(plans.example_path("slider-crank")), tmp_path / "page.svg", lang="sl")
    assert [p.name for p in paths] == ["page-01.svg", "page-02.svg", "page-03.svg"]  # zero-padded: they sort in page order
    root = ET.parse(paths[0]).getroot()
    assert (root.get("width"), root.get("height")) == ("210mm", "297mm")
    text = " ".join("".join(t.itertext()) for t in root.iter(f"{SVG}text"))
    second = " ".join("".join(t.itertext()) for t in ET.parse(paths[1]).getroot().iter(f"{SVG}text"))
    assert "Načrt hitrosti" in text and "Načrt pospeškov" in second and "Kinematska shema" in text


@pytest.mark.parametrize(
    "path, options, message",
    [
        ("out.jpg", {}, "a handout is written as .pdf (or .svg or .png, one file per page), not .jpg"),
        ("out.pdf", {"lang": "de"}, "no language 'de'; plans speaks en, sr, ru, bg, sl"),
    ],
)
def test_what_cannot_be_written_is_refused_before_anything_is(tmp_path, path, options, message):
    with pytest.raises(HandoutError) as info:
        write_handout(plans.load(plans.example_path("four-bar")), tmp_path / path, **options)
    assert message in str(info.value)
    assert isinstance(info.value, ValueError) and isinstance(info.value, plans.PlansError)
    assert list(tmp_path.iterdir()) == []


def test_a_single_position_that_cannot_assemble_is_the_solvers_error(tmp_path):
    from dataclasses import replace
    import math

    scene = plans.loads(STUCK)
    scene = replace(scene, driver=replace(scene.driver, phi=math.pi))
    with pytest.raises(AssemblyError, match=r"RRR\(3,4\)"):
        write_handout(scene, tmp_path / "x.pdf")
    assert list(tmp_path.iterdir()) == []


def test_a_position_that_cannot_assemble_gets_a_page_that_says_so():
    pages = handout_pages(plans.loads(STUCK), positions="10, 180 deg")
    names = [name for name, _ in pages]
    # the kinematic diagrams of the output take their own positions (a swing of this crank: every one assembles)
    assert names[:7] == ["cover", "position-0", "acceleration-0", "check-0", "unsolved-1", "diagram-links", "diagram-points"]
    assert names[7:] in (["kinematic-1"], ["kinematic-1", "kinematic-2"])  # the table under the diagrams, or on a page of its own
    words = [t.get_text() for t in pages[4][1].findobj(lambda a: hasattr(a, "get_text"))]
    assert any("cannot assemble" in w for w in words)


def test_the_scene_data_lines():
    lines = scene_data_lines(plans.load(plans.example_path("six-bar")), "sr")
    assert lines[0] == "погонски члан 2 (O):  ω₂ = −10 rad/s,  ε₂ = 0 rad/s²"
    assert "2: OA = 150" in lines[1] and "3: AB = 450, AC = 600, BC = 150" in lines[1] and lines[1].startswith("дужине [mm]")
    assert lines[2] == "непокретне тачке [mm]:  O (0, 0),  D (−450, 350),  E (−200, −150)"


def test_long_loop_equations_continue_on_another_page():
    from plans.drawing.sheets import draw_check_pages
    from plans.loops import loop_equations
    from plans.positions import run_positions

    run = run_positions(plans.load(plans.example_path("linear-arm"))).runs[0]
    figures = draw_check_pages(run, loops=loop_equations(run.analytic), table=[["quantity", "value"]] + [["x", "1"]] * 30)
    assert len(figures) == 2
    words = [t.get_text() for t in figures[1].findobj(lambda a: hasattr(a, "get_text") and hasattr(a, "get_fontsize"))]
    assert "Analytic check: complex-number method (loop equations) (continued)" in words
    assert "RRP(5,6)" in words  # the last group's equations, moved whole to the next page
