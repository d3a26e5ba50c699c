"""Handouts: the PDF read back — pages, page size, text, embedded fonts with the Cyrillic glyphs — and SVG pages.

The PDF is opened with pypdf (a test dependency); nothing is checked by pixels.  The plate's own
promises (one scale per kind, the order, the title block, the underlines, the reader's language) are
in test_plate_handout.py.
"""

from __future__ import annotations

import re
import unicodedata
import warnings
import xml.etree.ElementTree as ET

import pypdf
import pytest

import plans
from plans.errors import AssemblyError
from plans.handout import HandoutError, handout, scene_data_lines, write_handout
from test_positions import STUCK

A4_PT = (595.2756, 841.8898)
CYRILLIC = re.compile(r"[\u0400-\u04FF]")


def _write(path, scene, **options):
    """Write a handout, turning matplotlib's missing-glyph warnings into failures."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        paths = write_handout(scene, path, **options)
    missing = [str(w.message) for w in caught if "missing from" in str(w.message).lower()]
    assert not missing, missing
    return paths


def _texts(reader) -> list[str]:
    """Each page's text, math letters (𝑘𝑙) as plain ones and runs of spaces as one."""
    return [" ".join(unicodedata.normalize("NFKC", page.extract_text()).split()) for page in reader.pages]


@pytest.fixture(scope="module")
def russian(tmp_path_factory):
    """The four-bar in two positions, in Russian."""
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
    for page in russian.pages:
        assert (float(page.mediabox.width), float(page.mediabox.height)) == pytest.approx(A4_PT, abs=0.01)
    texts = _texts(russian)
    whole = "\n".join(texts)
    assert "План положений механизма" in texts[0]  # the plan of positions
    assert "Положения" in texts[0] and "0: φ2 = 60,0°" in texts[0] and "1: φ2 = 240,0°" in texts[0]  # decimal comma in Russian
    assert "закон движения ведущего звена: постоянная угловая скорость" in texts[0]  # the driver's law over the cycle (issue 19)
    for words in ("Векторные уравнения планов: план скоростей", "Планы скоростей (каждый из своего полюса)",
                  "Векторные уравнения планов: план ускорений", "Планы ускорений", "Положение 0:", "Положение 1:",
                  "Графические и аналитические значения", "Аналитическая проверка: метод комплексных чисел",
                  "Кинематические диаграммы за цикл", "Точки: скорость и ускорение",
                  "Кинематические диаграммы выходного звена", "методом хорд"):
        assert words in whole, words
    # k_v, k_a each stated once under its heading (decimal comma) and in every title block
    assert len(re.findall(r"kv = [0-9]+,[0-9]+ \(м/с\)/мм", whole)) == 1 + total
    for number, text in enumerate(texts, start=1):
        assert f"Лист {number} из {total}" in text


def test_fonts_are_embedded(russian):
    """Every font is embedded (a CFF or TrueType program in the file), none a Type 3 bitmap; the page's serif,
    the equations' math font and the drawings' DejaVu Sans."""
    seen = set()
    for page in russian.pages:
        for ref in page["/Resources"]["/Font"].values():
            font = ref.get_object()
            assert font["/Subtype"] == "/Type0", font["/Subtype"]
            descriptor = font["/DescendantFonts"][0].get_object()["/FontDescriptor"].get_object()
            assert any(key in descriptor for key in ("/FontFile2", "/FontFile3")), descriptor
            seen.add(str(font["/BaseFont"]).split("+")[-1].split("-Identity")[0])
    assert {"LibertinusSerif-Regular", "NewCMMath-Book", "DejaVuSans"} <= seen, seen


def test_cyrillic_is_real_text_not_missing_glyph_boxes(russian):
    text = "".join(page.extract_text() for page in russian.pages)
    assert "\ufffd" not in text and "□" not in text
    assert len(CYRILLIC.findall(text)) > 500


def test_a_one_position_handout_is_three_pages(single):
    reader = pypdf.PdfReader(single)
    assert len(reader.pages) == 3
    first, accel, check = _texts(reader)
    assert "Offset slider-crank" in first and "φ2 = 45.0°" in first
    assert "Mechanism" in first and "Velocity plans" in first and "Acceleration plans" in accel
    assert "Structural formula: I(1,2) → II2(3,4)" in first  # class II, 2nd kind (RRP)
    # the acceleration equations follow the velocity plans where the page has room, the plans on a page of their own
    assert "Vector equations: velocity plan" in first and "Vector equations: acceleration plan" in first + accel
    # the tables flow on under the acceleration plan where its page has room
    assert "Graphical and analytic values" in accel + check and "rel. error" in accel + check
    assert "Analytic check: complex-number method" in check
    assert "−16.04" in check  # v_B of E2 on the loop line, with a true minus sign


def test_the_pdf_is_the_same_bytes_every_time(single, tmp_path):
    again = tmp_path / "again.pdf"
    _write(again, plans.load(plans.example_path("slider-crank")))
    assert again.read_bytes() == single.read_bytes()
    assert b"/CreationDate" not in single.read_bytes()


def test_svg_pages(tmp_path):
    paths = write_handout(plans.load(plans.example_path("slider-crank")), tmp_path / "page.svg", lang="sl")
    assert [p.name for p in paths] == ["page-01.svg", "page-02.svg", "page-03.svg"]  # zero-padded: they sort in page order
    root = ET.parse(paths[0]).getroot()
    assert (root.get("width"), root.get("height")) == ("210mm", "297mm")  # printed at 100 %, the scales hold


def test_png_pages(tmp_path):
    paths = write_handout(plans.load(plans.example_path("slider-crank")), tmp_path / "page.png", lang="sr")
    assert len(paths) == 3 and all(p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" for p in paths)


@pytest.mark.parametrize(
    "path, options, message",
    [
        ("out.jpg", {}, "a handout is written as .pdf (or .svg or .png, one file per page), not .jpg"),
        ("out.pdf", {"lang": "de"}, "no language 'de'; plans speaks en, sr, ru, bg, sl"),
        ("out.pdf", {"scales": "each"}, "scales: 'each' is not one of plate, per-position"),
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


def test_a_position_that_cannot_assemble_is_said_where_its_plan_would_be():
    doc = handout(plans.loads(STUCK), positions="10, 180 deg", start="scene")
    assert [r.index for r in doc.runs] == [0]  # the solved one
    assert "v-0" in doc.images and "v-1" not in doc.images
    text = " ".join(" ".join(page.extract_text() for page in pypdf.PdfReader(__import__("io").BytesIO(doc.pdf())).pages).split())
    assert "Position 1:" in text and "not solved" in text and "cannot assemble" in text


def test_the_scene_data_lines():
    lines = scene_data_lines(plans.load(plans.example_path("six-bar")), "sr")
    assert lines[0] == "погонски члан 2 (O):  ω₂ = −10 rad/s,  ε₂ = 0 rad/s²"
    assert "2: OA = 150" in lines[1] and "3: AB = 450, AC = 600, BC = 150" in lines[1] and lines[1].startswith("дужине [mm]")
    assert lines[2] == "непокретне тачке [mm]:  O (0, 0),  D (−450, 350),  E (−200, −150)"


def test_the_scene_data_lines_name_the_guides_in_the_readers_language():
    lines = scene_data_lines(plans.load(plans.example_path("quick-return")), "ru")
    assert "направляющая ползуна под углом 0°" in lines[2] and "ram" not in " ".join(lines)


def test_long_loop_equations_flow_on_and_nothing_is_lost():
    """The typesetter breaks the loop equations over pages: every group's block is set, the last one included."""
    doc = handout(plans.load(plans.example_path("linear-arm")), positions=12, lang="en")
    text = " ".join(" ".join(page.extract_text() for page in pypdf.PdfReader(__import__("io").BytesIO(doc.pdf())).pages).split())
    start = text.index("Analytic check: complex-number method")
    for k in doc.accelerations:
        assert f"Position {k}:" in text[start:]
    # the last group of each position, named as every page names a group
    assert unicodedata.normalize("NFKC", text[start:]).count("group 5–6") == len(doc.accelerations)
