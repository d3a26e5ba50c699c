"""The A3 sheets of ``plans draw --positions`` as a plate (issue 20's sheet review): drawings that fill their
regions, the plan of positions as sheet 1 with its own k_l, 0′ drawn, one label per point, the paths named, the
readings' and the comparison's values the same digits, the given data stated."""

from __future__ import annotations

import re
import unicodedata

import pytest

import plans
from plans.i18n import term
from plans.positions import at_page_precision, run_positions

from sheet_pages import by_kind, embedded_text, scales, text
from review_handouts import drawn_sheet


@pytest.fixture(scope="module")
def slider_crank_set():
    from plans.pages.sheet import position_sheets, positions_page

    run = run_positions(at_page_precision(plans.load(plans.example_path("slider-crank"))), 4)  # (as plans draw: 0.1 mm)
    sheets, _ = position_sheets(run, lang="sr")
    page = positions_page(run, lang="sr", number=(1, len(sheets) + 1))
    return run, sheets, page


def test_the_mechanism_of_every_position_sheet_is_100_mm_across(slider_crank_set):
    run, sheets, _ = slider_crank_set
    for _, sheet in sheets:
        mechanism = by_kind(sheet.pages("svg")[0])["mechanism"]
        assert mechanism.width >= 100.0
    # the mechanism drawn large at the set's one k_l: the rod AB (250 mm) ≥ 80 mm on paper (at the old 0.004: 62 mm)
    g = run.runs[0].graphical
    rod = abs(g.positions["B"] - g.positions["A"])
    assert rod == pytest.approx(0.25, abs=1e-6)
    assert rod / sheets[0][1].scales["k_l"] >= 80.0


def test_the_plan_of_positions_fills_its_page(slider_crank_set, tmp_path):
    from plans.pages.sheet import sheet_page

    _, _, page = slider_crank_set
    drawing = by_kind(page.pages("svg")[0])["positions"]
    a3 = sheet_page("A3")
    assert drawing.width * drawing.height >= 0.4 * a3.text_width * a3.text_height


def test_the_plan_of_positions_is_sheet_1_at_its_own_stated_k_l(slider_crank_set):
    run, sheets, page = slider_crank_set
    words = unicodedata.normalize("NFKC", text(page.pdf()))
    flat = " ".join(words.split())
    assert f"{term('sheet', 'sr')} 1 {term('of_sheets', 'sr')} 5" in flat
    for n, (_, sheet) in enumerate(sheets):
        assert f"{term('sheet', 'sr')} {n + 2} {term('of_sheets', 'sr')} 5" in " ".join(text(sheet.pdf()).split())
    stated = scales(words)
    assert stated == {"k_l": page.scales["k_l"]}
    # the crank's path drawn at that k_l: a circle of OA / k_l [mm] about O (the drawing is at 100 %)
    crank = abs(run.runs[0].graphical.positions["A"] - run.runs[0].graphical.positions["O"])
    assert crank / stated["k_l"] >= 60.0  # (at the sheets' old k_l 0.004: 25 mm)


def test_the_plan_of_positions_draws_0_prime_labels_each_point_once_and_names_the_paths(slider_crank_set):
    _, _, page = slider_crank_set
    inside = unicodedata.normalize("NFC", " ".join(t for t in _drawing_texts(page)))
    # the other extreme position its list names: A₀′, B₀′ (a number's letter and its index, set as two texts)
    assert re.search(r"\bA 0′", inside) and re.search(r"\bB 0′", inside)
    # position 0 lettered as the others, once: A₀ (issue 20's second review), not a plain A beside it
    assert re.search(r"\bA 0(?!′)", inside) and re.search(r"\bB 0(?!′)", inside)
    texts = [unicodedata.normalize("NFC", t) for t in _drawing_texts(page)]
    assert all(k + 1 < len(texts) and re.fullmatch(r"[0-9]+′?", texts[k + 1]) for k, t in enumerate(texts) if t in ("A", "B"))
    assert "путања тачке A" in inside and "путања тачке B" in inside


def test_the_cycle_data_one_rounding_of_angles_capitalised(slider_crank_set):
    _, _, page = slider_crank_set
    flat = " ".join(unicodedata.normalize("NFKC", text(page.pdf())).split())
    found = re.findall(r"(\d+,\d+)°", flat)
    assert found and all(len(f.split(",")[1]) == 1 for f in found), found  # every angle to 0.1°
    assert "Закон кретања" in flat  # a sentence starts with a capital
    assert "θ = 11,3°" in flat  # a symbol stays as written (not Θ)


def _drawing_texts(sheet):
    from sheet_pages import drawings, SVG

    out = []
    for d in drawings(sheet.pages("svg")[0]):
        out += ["".join(t.itertext()) for t in d.root.iter(f"{SVG}text")]
    return out


def _number(cell: str) -> str:
    """The digits of a table cell's value: ``20.95 ∠ 188.2°`` -> ``20.95``; ``17680 rad/s² ↺`` -> ``17680``;
    ``−21456`` -> ``21456`` (the readings give a sense by its arrow, the comparison by its sign)."""
    return cell.split()[0].lstrip("−")


def test_the_readings_and_the_comparison_print_one_number_per_quantity(slider_crank_set):
    """Issue 20 (sheets §3): ε₃ was 17690 in the readings and 17688 in the comparison on one sheet."""
    from plans.compare import compare
    from plans.drawing.readings import plan_readings
    from plans.report import sheet_table

    run, sheets, _ = slider_crank_set
    checked = 0
    for r, sheet in sheets:
        g = sheet.graphical
        table = {row[0].split(" [")[0]: _number(row[1]) for row in sheet_table(compare(r.analytic, g), g, r.analytic)[1:]}
        for kind in ("velocity", "acceleration"):
            for row in plan_readings(g, kind, "en")[1:]:
                for name in row[0].split(" = "):
                    name = name if name.startswith("$") else "$" + name
                    name = name if name.endswith("$") else name + "$"
                    if name in table:
                        assert _number(row[4]) == table[name], (r.index, name, row, table[name])
                        checked += 1
    assert checked >= 4 * 5


@pytest.fixture(scope="module")
def six_bar_sheets():
    pages = {}
    for lang in ("en", "sr"):
        pages[lang] = " ".join(unicodedata.normalize("NFKC", text(drawn_sheet("six-bar", lang, "sheet.pdf").read_bytes())).split())
    return pages


def test_the_single_sheet_states_the_given_data(six_bar_sheets):
    """The six-bar's sheet never stated ω₂ nor the link lengths (examples/six-bar.toml: ω₂ = −10 rad/s, OA 150 mm,
    AB 450 mm, CD 400 mm)."""
    flat = six_bar_sheets["en"]
    assert "Driver 2 (O): ω2 = −10 rad/s" in flat
    for length in ("OA = 150", "AB = 450", "DC = 400"):
        assert length in flat
    assert "Погонски члан 2 (O): ω2 = −10 rad/s" in six_bar_sheets["sr"]


def test_the_notes_under_a_plan_are_explained_under_the_legend(six_bar_sheets):
    assert "angles from the x axis, counter-clockwise" in six_bar_sheets["en"]
    assert "углови од осе x, супротно од казаљке на сату" in six_bar_sheets["sr"]


def test_a_short_segment_is_read_as_its_note_gives_it():
    """Issue 20 (sheets §4): the slider-crank at position 2 of 4, k_a 60: the note under the plan says
    n₁ b′ = 2,65 mm, the readings table used 2,6 and got ε₃ = 624 against the analytic 634,8 (1,7 %).  A segment
    under 3 mm is read to 0.01 mm, as its note gives it: n₁ b′ = |ε₃| · l_AB / k_a from the analytic solution."""
    from plans.drawing.readings import plan_readings

    scene = at_page_precision(plans.load(plans.example_path("slider-crank")))
    run = run_positions(scene, 4, k_l=0.004, k_v=0.15, k_a=60.0)
    r = run.runs[2]
    eps3 = abs(r.analytic.links["3"].epsilon[0])
    (row,) = [row for row in plan_readings(r.graphical, "acceleration") if row[0] == r"$\varepsilon_{3}$"]
    assert row[2] == f"{eps3 * 0.25 / 60.0:.2f}" == "2.65"  # (the note's length)
    value = float(row[4].split()[0])
    assert value == pytest.approx(eps3, rel=0.005)
