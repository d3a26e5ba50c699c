"""The handout as the course project's plate (issue 20 §1, §2): one scale per kind, the plate's order, a title
block on every sheet, the known parts of the vector equations underlined, the reader's language only.

Expected values come from the textbook's conventions (domain.md §10), not from the code: a plate states
one μ_v; the velocity of a known point is known in magnitude and direction (underlined twice), a relative
velocity of rotation in direction only (once); a Serbian page holds no English word.
"""

from __future__ import annotations

import io
import re
import unicodedata

import pytest
from pypdf import PdfReader

import plans
from plans.handout import handout
from plans.pages.equations import equation_math, twice
from plans.pages.handout import ORDER
from plans.scene import example_path, loads
from review_handouts import built, built_pdf

pytestmark = pytest.mark.filterwarnings("ignore")


def _pages(pdf: bytes, plain: bool = True) -> list[str]:
    """The text of every page, math letters (𝑘𝑣) as plain letters when *plain*."""
    pages = [page.extract_text() or "" for page in PdfReader(io.BytesIO(pdf)).pages]
    return [unicodedata.normalize("NFKC", page) for page in pages] if plain else pages


@pytest.fixture(scope="module")
def quick_return_sr():
    return built("quick-return", 6, "sr", centres=True), built_pdf("quick-return", 6, "sr", centres=True)


@pytest.fixture(scope="module")
def six_bar_bg():
    return built("six-bar", 4, "bg"), built_pdf("six-bar", 4, "bg")


@pytest.fixture(scope="module")
def four_bar_en():
    return built("four-bar", None, "en"), built_pdf("four-bar", None, "en")


# --- one scale per kind ------------------------------------------------------------------------


def test_one_k_l_k_v_k_a_for_every_position(quick_return_sr):
    doc, pdf = quick_return_sr
    assert len(doc.runs) == 6
    for key in ("k_l", "k_v", "k_a"):
        values = {r.graphical.scales[key] for r in doc.runs}
        assert values == {doc.scales[key]}, key
    # the pages state each factor with one value only (the title block, the captions)
    text = "\n".join(_pages(pdf))
    for symbol in ("v", "a"):
        stated = set(re.findall(rf"k\s*{symbol}\s*=\s*([0-9][0-9,]*)", text))
        assert len(stated) == 1, (symbol, stated)


def test_every_velocity_plan_and_two_acceleration_plans_drawn(quick_return_sr):
    doc, _ = quick_return_sr
    velocity = [k for k in doc.images if k.startswith("v-")]
    acceleration = [k for k in doc.images if k.startswith("a-")]
    assert len(velocity) == 6
    assert len(acceleration) == 2
    # one of the working stroke, one of the idle: the ram moves opposite ways at the two
    senses = [float(r.analytic.sliders["E"].v_rel[0]) for r in doc.runs if r.index in doc.accelerations]
    assert senses[0] * senses[1] < 0


def test_plans_drawn_at_the_stated_size(quick_return_sr):
    """A plan's drawing holds its largest vector at length/k_v mm: the SVG block is at least that large."""
    doc, _ = quick_return_sr
    for r in doc.runs:
        plan = r.graphical.velocity_plan
        longest = max(abs(v.tip - v.tail) for v in plan.vectors)
        assert longest == pytest.approx(max(v.value for v in plan.vectors) / doc.scales["k_v"], rel=0.02, abs=0.2)
        w, h = doc.drawn[f"v-{r.index}"]
        assert max(w, h) >= longest


def test_per_position_scales_only_when_asked():
    doc = handout(plans.load(example_path("quick-return")), positions=4, lang="en", scales="per-position")
    assert len({s["k_v"] for s in doc.per_position.values()}) > 1


# --- the plate's order, the title block -------------------------------------------------------


def test_the_plate_order(quick_return_sr):
    doc, pdf = quick_return_sr
    assert [s for s in ORDER if s in doc.order] == doc.order
    assert doc.order[:6] == ["data", "positions", "velocity-equations", "velocity-plans", "acceleration-equations", "acceleration-plans"]
    text = "\n".join(_pages(pdf))
    headings = ["План положаја механизма", "Планови брзина", "Планови убрзања", "Графичке и аналитичке вредности", "Кинематски дијаграми"]
    at = [text.find(h) for h in headings]
    assert all(a >= 0 for a in at), dict(zip(headings, at))
    assert at == sorted(at)


def test_title_block_on_every_sheet_with_sheet_n_of_m(quick_return_sr, six_bar_bg):
    for (doc, pdf), (sheet, of, fields) in ((quick_return_sr, ("Лист", "од", ("Цртао", "Прегледао", "Датум"))),
                                            (six_bar_bg, ("Лист", "от", ("Изработил", "Проверил", "Дата")))):
        pages = _pages(pdf)
        for n, page in enumerate(pages, start=1):
            flat = " ".join(page.split())
            assert f"{sheet} {n} {of} {len(pages)}" in flat, (n, flat[-200:])
            for field in fields:
                assert field in flat
        assert doc.scene_title if hasattr(doc, "scene_title") else True


# --- equations -----------------------------------------------------------------------------------


def test_known_parts_underlined_as_the_course_marks_them():
    # v_C = v_B + v_CB: v_B known (twice), v_CB direction only (once), v_C sought (not underlined)
    math = equation_math("v_C = v_B + v_CB", known={"v_B"}, found={"v_CB"})
    assert math == "arrow(v)_(C) = " + twice("arrow(v)_(B)") + " + underline(arrow(v)_(C B))"
    # a_C = a_B + a^n_CB + a^t_CB: the normal component known in full, the tangential in direction
    math = equation_math("a_C = a_B + a^n_CB + a^t_CB", known={"a_B", "a^n_CB"}, found={"a^t_CB"})
    assert twice("arrow(a)^n_(C B)") in math
    assert "underline(arrow(a)^t_(C B))" in math and twice("arrow(a)^t_(C B)") not in math


def test_the_handout_source_underlines_the_four_bar_equations(four_bar_en):
    doc, _ = four_bar_en
    # the four-bar's RRR group 3–4 finds B from A (on the crank) and D (on the frame)
    assert "arrow(v)_(B) = " + twice("arrow(v)_(A)") + " + underline(arrow(v)_(B A))" in doc.source
    assert "underline(arrow(a)^t_(B A))" in doc.source and twice("arrow(a)^n_(B A)") in doc.source


# --- words ----------------------------------------------------------------------------------------


def _english(text: str, allowed=()) -> set[str]:
    # the unit mm (as the course writes it) runs into the next label in the PDF's text ("51 mmP₁₃"): split there
    text = re.sub(r"mm(?=[A-Z])", "mm ", text)
    return {w for w in re.findall(r"[A-Za-z]{3,}", text) if w.lower() not in allowed}


def test_no_english_word_on_a_serbian_or_bulgarian_page(quick_return_sr, six_bar_bg):
    operators = {"max", "min", "sin", "cos"}  # the operators of mathematics, written so in every language
    for (doc, pdf), allowed in ((quick_return_sr, {"rad"} | operators), (six_bar_bg, operators)):
        for n, page in enumerate(_pages(pdf, plain=False), start=1):  # (symbols in math are math letters, not words)
            assert not _english(page, allowed), (n, _english(page, allowed))


def test_english_handout_has_no_program_tokens(four_bar_en):
    doc, pdf = four_bar_en
    text = "\n".join(_pages(pdf))
    for token in ("RRR(", "(+1)", "(−1)", "(-1)", "→D", "driver:"):
        assert token not in text, token
    # the structural formula as the course writes it: the class of each group and its kind
    assert "I(1,2) → II1(3,4)" in " ".join(text.split())
    assert "to the left of the line" in text or "to the right of the line" in text


def test_one_frame_number(quick_return_sr):
    _, pdf = quick_return_sr
    text = " ".join(" ".join(_pages(pdf)).split())
    assert "I(1,2)" in text and "I(0,2)" not in text


def test_the_same_pdf_every_time(four_bar_en):
    doc, pdf = four_bar_en
    assert b"CreationDate" not in pdf
    again = handout(plans.load(example_path("four-bar")), lang="en").pdf()
    assert again == pdf


# --- scenes in five languages -------------------------------------------------------------------


def test_every_example_gives_its_title_and_names_in_five_languages():
    from pathlib import Path

    paths = [example_path(name) for name in plans.scene.example_names()]
    paths += sorted((Path(plans.__file__).parent / "examples" / "loaded").glob("*.toml"))  # the loaded ones too
    assert len(paths) >= 18
    for path in paths:
        scene, name = plans.load(path), Path(path).stem
        assert set(scene.titles) == {"en", "sr", "ru", "bg", "sl"}, name
        assert not re.search(r"\((?:E\d|[RP]{3})\)", scene.title), scene.title
        guides = {line for body in scene.bodies.values() if not body.block for line in body.lines}
        for guide in guides:
            assert set(scene.names.get(guide, {})) == {"en", "sr", "ru", "bg", "sl"}, (name, guide)


BASE = """
[frame]
points = { O = [0, 0], D = [0.3, 0] }
[link.2]
points = { O = [0, 0], A = [0.1, 0] }
[link.3]
points = { A = [0, 0], B = [0.3, 0] }
[link.4]
points = { B = [0, 0], D = [0.25, 0] }
[driver]
crank = "2"
angle = "60 deg"
omega = "1 rad/s"
"""


def test_a_plain_title_prints_as_written_and_a_table_per_language():
    plain = loads('title = "Pump $x$ #1"\n' + BASE)
    assert plain.title_in("sr") == "Pump $x$ #1"
    table = loads('title = { en = "Pump", sr = "Пумпа" }\n' + BASE)
    assert (table.title_in("sr"), table.title_in("en"), table.title_in("ru")) == ("Пумпа", "Pump", "Pump")


@pytest.mark.parametrize("text, key", [
    ('title = { xx = "Pump" }', "title.xx"),
    ('title = { sr = 3 }', "title.sr"),
    ('title = "P"\n[names]\nslot = "x"', "names.slot"),
])
def test_a_bad_title_or_name_is_refused_naming_its_key(text, key):
    with pytest.raises(plans.errors.PlansError) as caught:
        loads(text + "\n" + BASE)
    assert key in str(caught.value)


# --- the command line -------------------------------------------------------------------------------


def test_accelerations_on_request_and_a_position_not_there_refused(tmp_path, capsys):
    from plans.cli import main

    doc = handout(plans.load(example_path("six-bar")), positions=4, accelerations="all")
    assert sorted(doc.accelerations) == [0, 1, 2, 3] and len([k for k in doc.images if k.startswith("a-")]) == 4
    assert len({r.graphical.scales["k_a"] for r in doc.runs}) == 1  # all of them at one k_a
    assert main(["handout", "--example", "six-bar", "--positions", "4", "--accelerations", "0,3", "-o", str(tmp_path / "h.pdf"), "-q"]) == 0
    assert main(["handout", "--example", "six-bar", "--positions", "4", "--accelerations", "0,9", "-o", str(tmp_path / "x.pdf"), "-q"]) == 2
    err = capsys.readouterr().err
    assert "position 9 is not one of the handout's solved positions (0, 1, 2, 3)" in err
    assert not (tmp_path / "x.pdf").exists()


def test_per_position_scales_on_the_command_line_say_so(tmp_path):
    from plans.cli import main

    assert main(["handout", "--example", "quick-return", "--positions", "4", "--scales", "per-position", "--lang", "sr",
                 "-o", str(tmp_path / "h.pdf"), "-q"]) == 0
    text = " ".join(" ".join(_pages((tmp_path / "h.pdf").read_bytes())).split())
    assert "размере изабране за сваки положај" in text


def _centre(svg: str, gid: str) -> complex:
    """The centre of a drawn circle (its path's points averaged), SVG y turned up."""
    import re

    m = re.search(rf'id="{gid}"[^>]*>\s*<path d="([^"]+)"', svg)
    assert m, gid
    nums = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?", m.group(1))]
    xs, ys = nums[0::2], nums[1::2]
    return complex((max(xs) + min(xs)) / 2, -(max(ys) + min(ys)) / 2)


def test_the_plan_of_positions_draws_the_other_extreme_position(quick_return_sr):
    """Position 0 is the output's extreme that starts the working stroke; 0′, the other, is drawn dash-dotted and
    numbered (A₀′): the crank pin there lies at the crank angle plans.motion gives for 0′, as seen from O."""
    import cmath
    import math

    from plans.motion import strokes

    doc, _ = quick_return_sr
    svg = doc.images["positions"].decode()
    # (its number: the letter A and its index 0′ set at the small text size, two texts)
    assert 'id="positions-link-extreme-2"' in svg and 'id="positions-position-extreme-A-index"' in svg and "0′" in svg
    other = strokes(doc.runs[0].scene).other_position  # the crank angle of 0′ [rad]
    drawn = _centre(svg, "positions-mark-extreme-A") - _centre(svg, "positions-pin-O")
    assert math.degrees(abs(cmath.phase(drawn / cmath.exp(1j * other)))) < 1.0


def test_the_grashof_line_names_the_four_bar_by_its_links():
    # the course names a four-bar by its links (frame first), not by its Assur group's notation
    pdf = handout(plans.load(example_path("four-bar")), positions=2, lang="en").pdf()
    text = " ".join(" ".join(_pages(pdf)).split())
    assert "Grashof class (four-bar 1–2–3–4): crank-rocker" in text
    assert "Grashof class II" not in text and "Grashof class RRR" not in text
