"""The handout's page flow as a teacher reviewed it (issue 20 §1): no overprinted table, no orphaned heading, no
near-empty page, a single position's drawings large, and data that do not contradict each other.

Expected values come from the pages themselves as a reader sees them (word boxes read from the PDF by
poppler's ``pdftotext -bbox-layout``) and from the scene files' numbers, not from the code under test.
"""

from __future__ import annotations

import math
import re
import shutil
import subprocess
import tempfile
import unicodedata
from pathlib import Path

import pytest

import plans
from plans.handout import handout
from plans.motion import driver_cycle
from plans.pages.document import A4_PORTRAIT, Document
from plans.pages.typesetting import compile_document

from accelerating_scenes import linear_arm_accelerating, write_linear_arm_accelerating
from pdf_lines import page_lines
from review_handouts import built, built_pdf

pytestmark = [pytest.mark.filterwarnings("ignore"),
              pytest.mark.skipif(shutil.which("pdftotext") is None, reason="poppler's pdftotext reads the pages")]

PT = 25.4 / 72  # mm per PDF point


def _lines(pdf: bytes) -> list[list[tuple[float, float, float, float, str]]]:
    """Every page's text lines (:func:`pdf_lines.page_lines`)."""
    return page_lines(pdf)


def _overprinted(lines) -> list:
    """Pairs of text lines that share a place on the page: their boxes overlap across and more than half of the
    lower one's height up and down (two rows of a table set on one line)."""
    bad = []
    for i, a in enumerate(lines):
        for b in lines[i + 1:]:
            if min(a[2], b[2]) - max(a[0], b[0]) <= 1.0:
                continue
            if min(a[3], b[3]) - max(a[1], b[1]) > 0.5 * min(a[3] - a[1], b[3] - b[1]):
                # (not a drawing's subscript, which pdftotext reads as a lone smaller glyph beside the line its letter
                # was joined to: K₁'s "1" under "H₃, H₄ K K₀" on the plan of positions)
                if any(len(x[4].strip()) == 1 and x[4].strip().isdigit() and x[3] - x[1] < 0.8 * (y[3] - y[1]) for x, y in ((a, b), (b, a))):
                    continue
                bad.append((a[4], b[4]))
    return bad


# --- a table never overprinted -------------------------------------------------------------------


def test_a_table_starting_low_on_a_page_breaks_instead_of_overprinting():
    """Tables in two columns that start 60 mm above the page's foot, each longer than that: every row on a line
    of its own (a table that may not break was set with all its rows on one line, one over the other)."""
    doc = Document(plans.load(plans.example_path("four-bar")), "en")
    doc.plate = {"k_l": 0.002}
    doc.body.append(f"#block(height: {A4_PORTRAIT.text_height - 60:.1f}mm, width: 100%)")
    rows = [["quantity", "graphical", "analytic"]] + [[f"row {i}", f"{i}.5", f"{i}.25"] for i in range(24)]
    doc.tables([("first table", rows), ("second table", rows)], aligns="(left, right, right)")
    pages = _lines(compile_document(doc.source(), doc.images, "pdf"))
    assert len(pages) == 2
    text = " ".join(line[4] for page in pages for line in page)
    for i in range(24):
        assert text.count(f"row {i} ") == 2, i
    for n, page in enumerate(pages, start=1):
        assert not _overprinted(page), (n, _overprinted(page)[:3])


# --- the three handouts the teacher reviewed -------------------------------------------------------

HANDOUTS = {
    "quick-return-sr": ("quick-return", 12, "sr"),
    "linear-arm-bg": ("linear-arm", 8, "bg"),
    "six-bar-en": ("six-bar", None, "en"),
}


@pytest.fixture(scope="module")
def reviewed():
    """name -> (Handout, PDF, lines of every page) of the handouts issue 20 was reviewed on (with centres)."""
    out = {}
    for key, (name, positions, lang) in HANDOUTS.items():
        doc = built(name, positions, lang, centres=True)
        pdf = built_pdf(name, positions, lang, centres=True)
        out[key] = (doc, pdf, _lines(pdf))
    return out


def _page_use(pdf: bytes, dpi: int = 30) -> list[float]:
    """Every page's lowest mark in the text area (a dark pixel of pdftoppm's rendering, the frame and the title block
    outside it), from the text area's top [mm]."""
    import numpy as np

    g = A4_PORTRAIT
    left, right, top, bottom = g.margins
    px = dpi / 25.4
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "h.pdf"
        path.write_bytes(pdf)
        subprocess.run(["pdftoppm", "-r", str(dpi), "-gray", str(path), str(Path(tmp) / "p")], check=True)
        out = []
        for page in sorted(Path(tmp).glob("p*.pgm")):
            _, size, _, data = page.read_bytes().split(b"\n", 3)
            w, h = map(int, size.split())
            img = np.frombuffer(data, dtype=np.uint8).reshape(h, w)
            x0, x1 = int((left + 0.5) * px), int((g.size[0] - right - 0.5) * px)
            y0, y1 = int((top + 0.5) * px), int((g.size[1] - bottom - 0.5) * px)
            rows = np.flatnonzero((img[y0:y1, x0:x1] < 160).any(axis=1))
            out.append(0.0 if len(rows) == 0 else (rows[-1] + 1) / px + 0.5)
        return out


def _plate_pages(doc, count: int) -> range:
    """The pages of the plate's flow: from the first to the one before the pages that stand alone begin (the
    cycle and kinematic diagrams, the force and centres pages, each section starting a page), as Typst placed
    them; all but the last page where there are none (one position: its centres pages follow on the last)."""
    from plans.pages.typesetting import query_document

    marks = {m["name"]: m for m in query_document(doc.source, doc.images, "<plans-mark>")}
    if "diagrams-start" in marks:
        return range(1, marks["diagrams-start"]["page"])
    alone = set(query_document(doc.source, doc.images, "<plans-full-page>"))
    return range(1, count) if not alone else range(1, min(alone))


@pytest.mark.parametrize("key", list(HANDOUTS))
def test_no_page_of_the_flow_is_less_than_half_used(reviewed, key):
    """Every page of the plate's flow but the handout's last has something below half its text height."""
    doc, pdf, _ = reviewed[key]
    use = _page_use(pdf)
    pages = _plate_pages(doc, len(use))
    assert len(pages) >= 3, (key, pages)
    short = [(n, round(use[n - 1] / A4_PORTRAIT.text_height, 2)) for n in pages if use[n - 1] < 0.5 * A4_PORTRAIT.text_height]
    assert not short, (key, short)


@pytest.mark.parametrize("key", ["quick-return-sr", pytest.param("linear-arm-bg", marks=pytest.mark.xfail(
    strict=True, reason="left (issue 20, round 17): the similarity lines' '(на плана …)' moved the loops to end 39 mm down "
                        "their last page, where the first two kinematic diagrams fit under them and the third does not: "
                        "71 % used"))])
def test_the_loop_equations_last_page_is_filled_by_what_follows(reviewed, key):
    """The page the loop equations end on is filled: the kinematic diagrams' heading, words and first diagram flow up
    under them (it was 64 % used in the Serbian quick-return, 66 % in the Bulgarian linear-arm, the diagrams starting
    a page of their own)."""
    from plans.pages.typesetting import query_document

    doc, pdf, _ = reviewed[key]
    marks = {m["name"]: m for m in query_document(doc.source, doc.images, "<plans-mark>")}
    page = marks["loops-end"]["page"]
    use = _page_use(pdf)
    assert use[page - 1] >= 0.85 * A4_PORTRAIT.text_height, (key, page, round(use[page - 1] / A4_PORTRAIT.text_height, 2))


@pytest.mark.parametrize("key", list(HANDOUTS))
def test_no_line_breaks_inside_a_formula(reviewed, key):
    """No line of a page ends in a name and its ``=`` with the value on the next line (``|a_A| =`` / ``0`` in a
    diagram's note, ``ε₃ =`` / ``0,9695`` in a loop equation's results)."""
    _, _, pages = reviewed[key]
    for n, page in enumerate(pages, start=1):
        broken = [line[4] for line in page if re.search(r"\S\s*=$", line[4])]
        assert not broken, (key, n, broken)


#: the headings of a handout's sections, each kept with the first row of what it heads (the words of plans.i18n)
HEADINGS = ("positions_plan", "mechanism", "velocity_plans", "acceleration_plans", "comparison", "loop_equations", "vector_equations")


@pytest.mark.parametrize("key", list(HANDOUTS))
def test_no_heading_is_left_at_a_pages_foot(reviewed, key):
    """Under every section heading its page holds at least 25 mm of what it heads (the plans' heading band with
    its scale and legend is about 20 mm): a heading left at a page's foot has nothing under it."""
    from plans.i18n import term

    doc, pdf, pages = reviewed[key]
    lang = HANDOUTS[key][2]
    use = _page_use(pdf)
    words = [unicodedata.normalize("NFKC", term(h, lang)) for h in HEADINGS]
    found = 0
    for n, lines in enumerate(pages):
        for x0, y0, x1, y1, line in lines:
            if any(line.startswith(w) for w in words) and x0 * PT < A4_PORTRAIT.margins[0] + 5:
                found += 1
                below = use[n] - (y1 * PT - A4_PORTRAIT.margins[2])
                assert below >= 25.0, (key, n + 1, line, round(below, 1))
    assert found >= 5, (key, found)


@pytest.mark.parametrize("key", list(HANDOUTS))
def test_no_two_text_lines_of_a_handout_page_overlap(reviewed, key):
    _, _, pages = reviewed[key]
    for n, page in enumerate(pages, start=1):
        assert not _overprinted(page), (key, n, _overprinted(page)[:3])


# --- the data do not contradict each other ---------------------------------------------------------


@pytest.mark.parametrize("lang, given", [("en", "the scene's a₂ = 2 m/s² is not used: the cycle follows this law"),
                                         ("bg", "зададеното a₂ = 2 m/s² не се използва: цикълът следва този закон"),
                                         ("sr", "задато a₂ = 2 m/s² се не користи: циклус прати овај закон"),
                                         ("ru", "заданное a₂ = 2 m/s² не используется: цикл следует этому закону"),
                                         ("sl", "podani a₂ = 2 m/s² se ne uporablja: cikel sledi temu zakonu")])
def test_a_given_acceleration_under_the_constant_law_is_said_to_be_its_instants(lang, given):
    """The linear-arm mechanism written with v = 0.5 m/s, a = 2 m/s² and no law (tests/accelerating_scenes.py): the
    cycle runs at constant speed (the course's assumption, domain.md §10), and the law's line says that the 2 m/s² is
    not used (a user's scene: nothing given is silently dropped)."""
    scene = linear_arm_accelerating()
    assert scene.driver.law is None and scene.driver.acceleration == 2.0  # the file's numbers
    law = driver_cycle(scene, 8).law
    assert law.kind == "constant" and law.acceleration == 0.0
    assert law.describe(lang, "2").endswith("a₂ = 0")
    assert law.given_note(lang, "2") == given


def test_no_such_words_where_the_scene_gives_no_acceleration_or_the_law_keeps_it():
    quick = driver_cycle(plans.load(plans.example_path("quick-return")), 8).law  # ε not given
    assert quick.given_note("en", "2") == ""
    arm = driver_cycle(plans.load(plans.example_path("linear-arm")), 8).law  # a not given: constant speed, a = 0
    assert arm.kind == "constant" and arm.given_acceleration == 0.0 and arm.given_note("en", "2") == ""
    four_bar = plans.load(plans.example_path("four-bar"))  # ε = 5 rad/s²: stated under constant, the law's under uniform
    assert driver_cycle(four_bar, 8).law.given_note("en", "2") == "the scene's ε₂ = 5 rad/s² is not used: the cycle follows this law"
    assert driver_cycle(four_bar, 8, law="uniform").law.given_note("en", "2") == ""


def test_plans_sweep_says_the_same(tmp_path, capsys):
    from plans.cli import main

    scene = write_linear_arm_accelerating(tmp_path)
    assert main(["sweep", str(scene), "--steps", "8", "-o", str(tmp_path / "arm.csv"), "--lang", "sr"]) == 0
    out = capsys.readouterr().out
    assert "константна брзина: v₂ = 0,5 m/s, a₂ = 0; задато a₂ = 2 m/s² се не користи: циклус прати овај закон" in out
    # the bundled example gives no acceleration: the law's line and nothing after it
    assert main(["sweep", "--example", "linear-arm", "--steps", "8", "-o", str(tmp_path / "bundled.csv"), "--lang", "sr"]) == 0
    out = capsys.readouterr().out
    assert "константна брзина: v₂ = 0,5 m/s, a₂ = 0\n" in out and "се не користи" not in out, out


def test_the_linear_arm_handout_states_one_law_with_no_contradiction(reviewed):
    """The Bulgarian linear-arm handout (issue 20, the teachers' third review: "the scene's a₂ = 2 m/s² is not used"
    beside a₂ = 0 was blocking): the example runs at constant speed, its data give v only, the law a₂ = 0, and no
    acceleration that the cycle does not use, no remark about one."""
    _, _, pages = reviewed["linear-arm-bg"]
    first = " ".join(line[4] for line in pages[0])  # (NFKC: a₂ reads a2, m/s² m/s2)
    driver = re.search(r"водещо звено 2 \(A, стойка ∥ 0°\):(.*?)дължини", first).group(1)
    assert driver.split() == ["v", "=", "0,5", "м/с,", "s", "∈", "[−100,", "100]", "мм"], driver  # what the cycle uses
    assert re.search(r"закон на движение на водещото звено: постоянна скорост, a ?2 = 0\s+изходно звено 6", first), first
    assert "не се използва" not in first and "зададеното" not in first, first


def test_a_handout_states_a_given_acceleration_as_its_instants():
    """A user's scene that gives a = 2 m/s² (the linear-arm written out with it), at the course's constant speed: the
    handout's first page says, beside the law, that the 2 m/s² is not used (nothing given silently dropped); its
    driver's line gives v only (issue 20, 2nd review).  Two positions: the data block is that of any cycle."""
    pages = _lines(handout(linear_arm_accelerating(), positions=2, lang="bg").pdf())
    first = " ".join(line[4] for line in pages[0])
    assert "v = 0,5 м/с" in first and "a = 2 м/с2" not in first
    assert re.search(r"постоянна скорост, a ?2 = 0\s+\(зададеното a ?2 = 2 м/с2 не се използва: цикълът следва този закон\)",
                     first), first


# --- words as the textbooks write them ----------------------------------------------------------------


def test_the_centres_pages_speak_as_a_textbook():
    from plans.i18n import term

    assert term("centres_page", "en") == "Instant centres (Kennedy's theorem): the velocities by the method of instant centres"
    assert term("centres_legend", "en").startswith("circles: centres at the kinematic pairs;")
    assert "двоиц" not in term("centres_legend", "bg") + term("circle_diagram_legend", "bg") + term("sliders_motion", "bg")
    assert "кинематичните двойки" in term("centres_legend", "bg")


@pytest.mark.parametrize("lang, once", [("bg", "подчертано веднъж — известно направление"), ("ru", "подчёркнуто один раз — известно направление"),
                                        ("sr", "подвучено једном: познат правац")])
def test_a_line_known_is_a_direction_not_a_sense(lang, once):
    from plans.i18n import term

    assert term("underlines", lang).startswith(once)


def test_a_guide_named_in_words_keeps_its_grammar():
    """The guide's name stands in the form its sentence needs (the scene's "of" form), without quotes."""
    from plans.i18n import term

    directed = term("assembly_directed", "bg").format(key="втулката", a="F", b="D")
    assert directed == "посока на втулката: от F към D"
    assert term("assembly_along", "bg").format(c="H", where="пред", b="Q", key="пръта") == "плъзгач H пред Q по направлението на пръта"
    assert term("assembly_directed", "ru").format(key="стержня", a="B", b="E") == "направление стержня: от B к E"


# --- a single position's drawings drawn large --------------------------------------------------------------

#: what a single position's page gives each drawing (issue 20 §1): the mechanism ≥ 100 mm across, the largest
#: vector of either plan several tens of mm, every ω read off the velocity plan within 1.5 % of the analytic value
MECHANISM_ACROSS_MM = 100.0
LARGEST_VECTOR_MM = 60.0
OMEGA_READ_REL = 0.015


def test_a_single_positions_drawings_are_each_drawn_large(reviewed):
    doc, _, _ = reviewed["six-bar-en"]
    (r,) = doc.runs
    assert max(doc.drawn["mechanism"]) >= MECHANISM_ACROSS_MM, doc.drawn["mechanism"]
    # the largest vectors, from the analytic speeds and accelerations at the plate's factors
    v = max(abs(complex(p.v[0])) for p in r.analytic.points.values()) / doc.scales["k_v"]
    a = max(abs(complex(p.a[0])) for p in r.analytic.points.values()) / doc.scales["k_a"]
    assert v >= LARGEST_VECTOR_MM and a >= LARGEST_VECTOR_MM, (v, a)
    # the crank OA (0.15 m in six-bar.toml) drawn at least 15 mm long
    assert 0.15 / doc.scales["k_l"] >= 15.0, doc.scales["k_l"]
    for key in ("k_l", "k_v", "k_a"):  # round factors: m·10ⁿ, m one of the usual mantissas
        mantissa = doc.scales[key] / 10 ** math.floor(math.log10(doc.scales[key]) + 1e-9)
        assert any(abs(mantissa - m) < 1e-9 for m in (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8)), (key, doc.scales[key])
    # ω₃ … ω₆ as the plan gives them (the relative velocity's length at k_v over the link's length) against analytic
    for name, link in r.analytic.links.items():
        analytic = float(link.omega[0])
        graphical = [c for c in r.comparisons if c.quantity == "omega" and c.name == name]
        if graphical and abs(analytic) > 1e-9:
            assert abs(graphical[0].graphical - analytic) <= OMEGA_READ_REL * abs(analytic), (name, graphical[0], analytic)


def test_a_single_positions_plans_each_have_a_page_region(reviewed):
    """The mechanism with the velocity equations on page 1, the velocity plan on page 2, the acceleration plan on
    a page after it: the three drawings never share one page's height."""
    doc, _, pages = reviewed["six-bar-en"]
    from plans.i18n import term

    def page_of(words):
        return next(n for n, lines in enumerate(pages, start=1) if any(line[4].startswith(words) for line in lines))

    assert page_of(term("mechanism", "en")) == 1
    assert page_of(term("velocity_plans", "en")) == 2
    assert page_of(term("acceleration_plans", "en")) >= 2


# --- headings on one line, formulas never broken (issue 20, second review) ---------------------------------


@pytest.mark.parametrize("key", list(HANDOUTS))
def test_the_scene_title_on_one_line_under_the_plate_name(reviewed, key):
    """Page 1 prints the plate's name, then the scene's title whole on one line (smaller where it is long), and the
    title block "plate name — title" (on two lines where it is long: never under 8 pt, tests/test_page_flow.py)."""
    import unicodedata

    from plans.i18n import term

    name, _, lang = HANDOUTS[key]
    title = unicodedata.normalize("NFKC", plans.load(plans.example_path(name)).title_in(lang))
    plate = term("plate_title", lang)
    _, _, pages = reviewed[key]
    texts = [line[4] for line in pages[0]]
    assert texts[0] == plate, texts[:3]
    assert texts[1] == title, texts[:3]
    assert any(f"{plate} — {title}" in " ".join(texts[k:k + 2]) for k in range(len(texts))), [t for t in texts if t.startswith(plate)]


def test_the_angles_in_the_notes_are_said_from_what(reviewed):
    """quick-return (sr): the notes "∠(pa) = 181,3°" of the collinear plans; the plans' scale line says once that ∠
    is from the x axis, counter-clockwise (velocity plans, acceleration plans); six-bar (en) the same in English."""
    _, _, pages = reviewed["quick-return-sr"]
    lines = [line[4] for page in pages for line in page]
    key = "∠ у напоменама: од осе x, супротно од казаљке на сату"
    # once on each kind's scale line whose plans have such notes: the velocity plans (positions 4 and 10 collinear);
    # the acceleration plans (positions 2 and 9 drawn) only where one of them has one
    kinds = 1 + any(re.match(r"∠\(π", t) for t in lines)
    assert sum(1 for t in lines if t.endswith("; " + key)) == kinds, [t for t in lines if "∠" in t][:6]
    assert any(re.fullmatch(r"∠\(p\S+\) = \d+,\d°.*", t) for t in lines)
