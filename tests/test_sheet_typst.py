"""The single sheets of ``plans draw`` set by Typst on the plate's page (issue 20 §1 "One layout engine", §2).

Expected values come from outside the code: the four-bar's crank gives v_A = ω₂·OA = 10 rad/s · 0.08 m =
0.8 m/s and |a_A| = OA·√(ω₂⁴ + ε₂²) = 0.08·√(10⁴ + 5²) m/s² (domain.md §2); A3 is 420 × 297 mm (ISO 216);
a plate's frame keeps a 20 mm binding margin; a Serbian page holds no English word and no program token.
"""

from __future__ import annotations

import math
import re

import pytest

import plans
from plans.cli import main
from sheet_pages import by_kind, drawings, english, overlap, page_count, page_size, scales, text, words
from review_handouts import drawn_sheet

pytestmark = pytest.mark.filterwarnings("ignore")

#: A3 landscape [mm]
A3 = (420.0, 297.0)


@pytest.fixture(scope="module")
def four_bar():
    """The four-bar's sheet in Russian, as SVG and PDF."""
    return drawn_sheet("four-bar", "ru", "sheet.svg").read_bytes(), drawn_sheet("four-bar", "ru", "sheet.pdf").read_bytes()


@pytest.fixture(scope="module")
def quick_return_sr(tmp_path_factory):
    d = tmp_path_factory.mktemp("qr")
    assert main(["draw", "--example", "quick-return", "--lang", "sr", "-o", str(d), "--format", "pdf"]) == 0
    assert main(["draw", "--example", "quick-return", "--lang", "sr", "-o", str(d / "page.svg")]) == 0
    return d


@pytest.fixture(scope="module")
def positions(tmp_path_factory):
    d = tmp_path_factory.mktemp("positions")
    assert main(["draw", "--example", "slider-crank", "--positions", "4", "-o", str(d), "--format", "pdf"]) == 0
    return d


def test_the_sheet_is_one_a3_landscape_page_with_the_drawings_at_100_percent(four_bar):
    svg, pdf = four_bar
    assert page_size(svg) == A3 and page_count(pdf) == 1
    placed = by_kind(svg)
    assert {"mechanism", "velocity", "acceleration", "legend"} <= set(placed)
    for kind, d in placed.items():  # placed at the size the drawing declares: 1 mm of drawing is 1 mm of paper
        if kind == "legend":  # (not a drawing at a scale: narrower where the table beside it leaves less, never wider,
            # its proportions kept)
            assert 0.9 * d.declared[0] <= d.width <= d.declared[0] + 0.02, kind
            assert d.height / d.width == pytest.approx(d.declared[1] / d.declared[0], rel=1e-3), kind
            continue
        assert d.width == pytest.approx(d.declared[0], abs=0.02) and d.height == pytest.approx(d.declared[1], abs=0.02), kind


def _arrow_lengths(drawing, prefix: str) -> list[float]:
    from sheet_measure import vectors

    return [abs(b - a) for a, b in vectors(drawing.root, prefix)]


def test_the_stated_scale_factors_hold_on_the_drawn_plans(four_bar):
    svg, pdf = four_bar
    k = scales(text(pdf))
    assert set(k) == {"k_l", "k_v", "k_a"}
    placed = by_kind(svg)
    v_a = 10.0 * 0.08  # ω₂·OA [m/s]
    a_a = 0.08 * math.hypot(10.0 ** 2, 5.0)  # OA·√(ω₂⁴ + ε₂²) [m/s²]
    # some drawn arrow of each plan is the crank pin's absolute vector, to the drafting precision (0.1 mm)
    assert min(abs(length * k["k_v"] - v_a) for length in _arrow_lengths(placed["velocity"], "vel-")) < 0.2 * k["k_v"]
    assert min(abs(length * k["k_a"] - a_a) for length in _arrow_lengths(placed["acceleration"], "acc-")) < 0.2 * k["k_a"]
    # the mechanism: the crank OA = 80 mm of the scene, drawn 0.08 m / k_l long, fits inside the drawing
    mech = placed["mechanism"]
    assert 0.08 / k["k_l"] < max(mech.width, mech.height)


def test_drawings_stay_inside_the_frame_clear_of_each_other_the_texts_and_the_title_block(four_bar, quick_return_sr, positions):
    pages = [four_bar, ((quick_return_sr / "page.svg").read_bytes(), (quick_return_sr / "sheet.pdf").read_bytes())]
    for svg, pdf in pages:
        placed = [d for d in drawings(svg)]
        frame = (20.0, 5.0, 415.0, 292.0)  # 20 mm binding margin, 5 mm from the other edges
        for d in placed:
            assert frame[0] < d.x and d.x + d.width < frame[2] and frame[1] < d.y and d.y + d.height < frame[3], d.box
        for i, a in enumerate(placed):
            for b in placed[i + 1:]:
                assert not overlap(a.box, b.box), (a.kind, b.kind)
        typeset = words(pdf)
        assert typeset, "the page's words"
        for d in placed:  # a word over a drawing is one of the drawing's own (its labels), wholly inside it
            own = {w for t in d.root.iter("{http://www.w3.org/2000/svg}text") for w in "".join(t.itertext()).split()}
            for word, box in typeset:
                if overlap(d.box, box, 0.3):
                    inside = d.x <= box[0] and box[2] <= d.x + d.width and d.y <= box[1] and box[3] <= d.y + d.height
                    assert inside and any(word in w or w in word for w in own), (d.kind, word, box, d.box)
        # the title block: its words at the foot of the frame, on the right
        foot = [box for _, box in typeset if box[1] > 250.0 and box[0] > 225.0]
        assert foot and all(box[3] < 292.0 for box in foot)


def test_a_serbian_sheet_holds_no_english_word_and_no_program_token(quick_return_sr):
    page = text((quick_return_sr / "sheet.pdf").read_bytes(), plain=False)
    assert not english(page, {"rad"}), english(page, {"rad"})
    flat = " ".join(page.split())
    for token in ("RRR(", "RPR(", "RRP(", "(+1)", "(−1)", "(-1)", "driver", "slot", "ram", "frame."):
        assert token not in flat, token
    # the plate's title and the scene's own Serbian title in the title block; the assembly in words
    assert "Кинематичка анализа механизма" in flat and "Кулисни механизам" in flat
    assert "Склоп група" in flat and "Лист 1 од 1" in flat


@pytest.mark.parametrize("example, lang", [("linear-arm", "bg"), ("four-bar", "sl")])
def test_other_languages_hold_no_english_word(example, lang, tmp_path):
    out = tmp_path / "page.pdf"
    assert main(["draw", "--example", example, "--lang", lang, "-o", str(out)]) == 0
    page = text(out.read_bytes(), plain=False)
    allowed = {"rad"} if lang != "bg" else set()
    if lang == "sl":  # Slovenian is written in Latin letters: no English word of the old sheet
        flat = " ".join(page.split())
        for word in ("Velocity", "Acceleration", "Mechanism", "readings", "Sheet", "Scale", "quantity", "graphical", "driver", "group"):
            assert not re.search(rf"\b{word}\b", flat), word
        assert "Načrt hitrosti" in flat and "List 1 od 1" in flat
    else:
        assert not english(page, allowed), english(page, allowed)


def test_a_russian_sheet_holds_no_english_word(four_bar):
    page = text(four_bar[1], plain=False)
    assert not english(page, {"rad"}), english(page, {"rad"})
    assert "Лист 1 из 1" in " ".join(page.split())


def test_given_factors_are_kept_and_stated(tmp_path):
    out = tmp_path / "page.pdf"
    assert main(["draw", "--example", "four-bar", "--k-v", "0.01", "--k-l", "0.004", "-o", str(out)]) == 0
    k = scales(text(out.read_bytes()))
    assert k["k_v"] == 0.01 and k["k_l"] == 0.004


def test_the_same_bytes_every_time(tmp_path):
    for name in ("a.svg", "b.svg", "a.pdf", "b.pdf"):
        assert main(["draw", "--example", "four-bar", "-o", str(tmp_path / name)]) == 0
    assert (tmp_path / "a.svg").read_bytes() == (tmp_path / "b.svg").read_bytes()
    pdf = (tmp_path / "a.pdf").read_bytes()
    assert pdf == (tmp_path / "b.pdf").read_bytes() and b"CreationDate" not in pdf


def test_position_sheets_share_one_factor_per_kind_and_are_numbered(positions):
    files = sorted(p.name for p in positions.iterdir())
    assert files == ["positions.pdf", "sheet-00.pdf", "sheet-01.pdf", "sheet-02.pdf", "sheet-03.pdf"]
    stated = []
    for n, name in enumerate(files[1:], start=1):
        page = text((positions / name).read_bytes())
        flat = " ".join(page.split())
        assert f"Sheet {n + 1} of 5" in flat, flat[-300:]  # the plan of positions is sheet 1 (the textbook's order)
        # titled with its position in words: "Position 2: φ2 = 180.0°" (the crank turns 360°/4 from the scene's)
        assert re.search(rf"Position {n - 1}: φ2 = [0-9.]+°", flat), flat[:200]
        stated.append(scales(page))
    assert all(s == stated[0] for s in stated) and set(stated[0]) == {"k_l", "k_v", "k_a"}
    plan = " ".join(text((positions / "positions.pdf").read_bytes()).split())
    # sheet 1, at a k_l of its own (a drawing of every position), stated
    assert "Sheet 1 of 5" in plan and set(scales(plan)) == {"k_l"}


def test_position_sheets_drawn_at_one_factor_fill_their_regions_without_overlap(tmp_path):
    assert main(["draw", "--example", "slider-crank", "--positions", "3", "-o", str(tmp_path)]) == 0
    for name in ("sheet-00.svg", "sheet-01.svg", "sheet-02.svg"):
        placed = drawings((tmp_path / name).read_bytes())
        for i, a in enumerate(placed):
            for b in placed[i + 1:]:
                assert not overlap(a.box, b.box), (name, a.kind, b.kind)
    # fewer positions afterwards: the sheets plans wrote before go, all files written at once
    assert main(["draw", "--example", "slider-crank", "--positions", "2", "-o", str(tmp_path)]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["positions.svg", "sheet-00.svg", "sheet-01.svg"]


def test_several_positions_into_one_file_is_refused(tmp_path, capsys):
    assert main(["draw", "--example", "four-bar", "--positions", "3", "-o", str(tmp_path / "page.pdf")]) == 2
    assert "plans draw -o takes a directory" in capsys.readouterr().err
    assert not (tmp_path / "page.pdf").exists()


def test_write_drawings_from_the_library_writes_the_drawings_and_the_sheet(tmp_path):
    solution = plans.construct(plans.load(plans.example_path("slider-crank")))
    paths = plans.write_drawings(solution, tmp_path, lang="sr")
    assert [p.name for p in paths] == ["mechanism.svg", "velocity.svg", "acceleration.svg", "sheet.svg"]
    assert page_size((tmp_path / "sheet.svg").read_bytes()) == A3
    # the drawings stay drawings (matplotlib's, true to scale), not pages
    assert b"data:image/svg+xml" not in (tmp_path / "velocity.svg").read_bytes()
