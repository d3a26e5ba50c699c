"""The kinematic diagrams' table against the plate's own plans (issue 20, second teacher's review, items 1, 2, 6, 7):
its "plan" values are what the handout's velocity and acceleration plans give (the drawn vector's length read at the
plate's k_v, k_a to the drafting precision, to the digits that precision gives), the acceleration only where its plan
is drawn ("—" elsewhere, with a note), no method of tangents on the page, the dead-centre note naming its cause."""

from __future__ import annotations

import math
import re

import pytest

import plans
from plans.handout import handout
from review_handouts import built


@pytest.fixture(scope="module")
def quick_return():
    return built("quick-return", 12, "sr")


def _table(source: str, heading: str, columns: int = 13) -> list[list[str]]:
    """The body rows of the kinematic table (after *heading*) as the page prints them."""
    start = source.index(heading)
    body = source[source.index("table.hline(stroke: 0.5pt)),", start):]
    body = body[: body.index("table.hline(stroke: 0.8pt))")]
    cells = [c.replace("\u2212", "-").replace(",", ".") for c in re.findall(r'\[#"([^"]*)"\]', body)]
    assert len(cells) % columns == 0
    return [cells[k:k + columns] for k in range(0, len(cells), columns)]


def _read(value: float, k: float, precision: float = 0.1) -> str:
    """A plan's reading |value| to the digits one drafting step (precision × k) gives: 0.1 mm × 0.02 → 3 decimals."""
    decimals = max(0, -math.floor(math.log10(precision * k)))
    return f"{abs(value):.{decimals}f}"


def test_plan_values_are_the_plates_own_readings(quick_return):
    doc = quick_return
    rows = _table(doc.source, "Излазни члан у сваком положају")
    assert len(rows) == 12
    k_v, k_a = doc.scales["k_v"], doc.scales["k_a"]
    assert doc.accelerations  # (two: one of each stroke)
    for h in doc.runs:
        row = rows[h.index]
        assert row[0] == str(h.index)
        # the velocity plan's drawn vector p→e: its length as measured (to 0.1 mm) × k_v
        v_e = {v.label: v.value for v in h.graphical.velocity_plan.vectors}.get("v_E", 0.0)  # (none drawn at a dead centre)
        assert abs(v_e / k_v - round(v_e / k_v, 1)) < 1e-9  # read to the drafting precision
        printed = row[4].lstrip("-")
        assert printed == ("0" if v_e == 0 else _read(v_e, k_v)), (h.index, row[4], v_e)
        if h.index in doc.accelerations:
            a_e = {v.label: v for v in h.graphical.acceleration_plan.vectors}["a_E"]
            assert row[9].lstrip("-") == _read(a_e.value, k_a), (h.index, row[9], a_e.value)
            assert row[12] != "—"
        else:  # no acceleration plan of this position on the plate: nothing "read" from one
            assert row[9] == "—" and row[12] == "—", (h.index, row)
    # the reviewer's positions: 0.542 at position 1, 1.068 at position 4, as on the plans' readings
    assert rows[1][4] == "-0.542" and rows[4][4] == "-1.068"


def test_signs_follow_the_guide_and_the_notes_say_so(quick_return):
    """The ram E moves against its guide's direction on the working stroke (s falls from position 0): v < 0 there,
    v > 0 on the return (positions 9–11), in both the plans' and the analytic columns; the notes state the rule."""
    rows = _table(quick_return.source, "Излазни члан у сваком положају")
    for row in rows[1:8]:
        assert float(row[4]) < 0 and float(row[5]) < 0, row
    for row in rows[9:12]:
        assert float(row[4]) > 0 and float(row[5]) > 0, row
    page = quick_return.source[quick_return.source.index("Излазни члан у сваком положају"):]
    assert "позитивно у смеру вођице" in page
    assert "план убрзања тог положаја није нацртан у овом раду (нацртан за положаје 2, 9)" in page


def test_no_method_of_tangents_on_the_page_and_the_extreme_note_names_its_cause(quick_return):
    page = quick_return.source[quick_return.source.index("Кинематски дијаграми излазног члана"):]
    assert "тангент" not in page
    assert "средини њеног интервала" in page and "а не нулу између њих" in page


def test_the_peak_note_where_the_chords_cut_the_fast_stroke(quick_return):
    """Quick-return at 12 positions: the v–t diagram gives about 2.61 m/s at position 10 where the analytic value
    is 3.05 m/s (the return stroke's peak), 14.4 % of the largest |v|: the notes say so and ask for more positions."""
    page = quick_return.source[quick_return.source.index("Кинематски дијаграми излазног члана"):]
    m = re.search(r"у положају (\d+) дијаграм v–t даје ([0-9,]+) m/s према ([0-9,]+) m/s аналитички \(δ ([−+][0-9,]+) %\)", page)
    assert m, "peak note"
    assert m.group(1) == "10"
    diagram, analytic = (float(m.group(k).replace(",", ".")) for k in (2, 3))
    assert analytic == pytest.approx(3.051, abs=0.001)  # |v_E| at position 10 on the plan (152.5 mm × 0.02)
    assert diagram == pytest.approx(2.61, abs=0.01)
    assert "нпр. 24" in page


def test_no_peak_note_where_the_chords_are_close():
    """The offset slider-crank at 12 positions: the chords within 5 % (2.7 % at most): no such note."""
    doc = built("slider-crank", 12, "en")
    page = doc.source[doc.source.index("Kinematic diagrams of the output link"):]
    assert "flatten the fastest part" not in page
    assert "tangent" not in page


@pytest.mark.parametrize("lang", ["en", "sr", "ru", "bg", "sl"])
def test_the_new_notes_exist_in_every_language(lang):
    from plans.i18n import term

    for key in ("kd_plans_signs", "kd_no_plan", "kd_no_acceleration_plan", "kd_peak_note", "kd_extreme_reading"):
        words = term(key, lang)
        assert words.strip()
        if lang != "en":
            assert words != term(key, "en")
        if lang in ("sr", "ru", "bg"):  # (Slovenian is written in Latin letters)
            latin = {w for w in re.findall(r"[A-Za-z]{3,}", re.sub(r"\{\w+\}", "", words))}  # (not the {placeholders})
            assert not latin, (key, lang, latin)


def test_the_analytic_curve_is_held_by_the_frames(quick_return):
    """Quick-return at 12 positions: the return stroke's analytic peak (v_E = 3.05 m/s at position 10, a_E ≈ −23.5 m/s²
    near position 11) lies above the chords' range; each dashed curve is drawn whole (one unbroken run) inside its
    diagram's ordinate, its peak at the stated μ, and the frame stays at least 40 mm tall and within the page."""
    import xml.etree.ElementTree as ET

    svg_ns = "{http://www.w3.org/2000/svg}"
    pt = 25.4 / 72

    def paths(svg, gid):
        out = []
        for g in ET.fromstring(svg).iter(f"{svg_ns}g"):
            if re.fullmatch(rf"{gid}(-\d+)?", g.get("id", "")):
                for path in g.iter(f"{svg_ns}path"):
                    numbers = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", path.get("d", ""))]
                    out.append([complex(numbers[k], -numbers[k + 1]) * pt for k in range(0, len(numbers) - 1, 2)])
        return out

    doc = quick_return
    for key, symbol, peak in (("v", "v", 3.051), ("a", "a", None)):
        svg = doc.images[f"kinematic-{key}"]
        runs = paths(svg, f"kd-{key}-analytic")
        assert len(runs) == 1, (key, len(runs))  # not cut anywhere
        assert not paths(svg, f"kd-{key}-analytic-cut")
        (ordinate,) = paths(svg, f"kd-{key}-ordinate")[:1]
        bottom, top = min(z.imag for z in ordinate), max(z.imag for z in ordinate)
        assert 40.0 <= top - bottom <= 251.0
        ys = [z.imag for z in runs[0]]
        assert bottom - 0.01 <= min(ys) and max(ys) <= top + 0.01, key
        if peak is not None:
            mu = float(re.search(r'\$mu_\(v ?\)\$#" = (?:"[^\n]*?#"\) = )?([0-9.,]+) ', doc.source).group(1).replace(",", "."))
            abscissa = paths(svg, f"kd-{key}-abscissa")[0][0].imag
            assert (max(ys) - abscissa) * mu == pytest.approx(peak, abs=0.03)
    assert "▲, ▼" not in doc.source  # nothing cut: no such note


def _svg_texts(svg: bytes) -> list[str]:
    import xml.etree.ElementTree as ET

    return ["".join(t.itertext()) for t in ET.fromstring(svg).iter("{http://www.w3.org/2000/svg}text")]


def test_s_in_metres_on_the_cycle_page_as_on_the_kinematic_page(quick_return):
    """One unit for s: the kinematic page writes s [m] at μ_s [m/mm]; the cycle page's sliding pairs say s [m] too,
    and its ticks are metres: the ram E runs between 0.455 m and −0.07 m along its guide (|s| < 1 m, not hundreds)."""
    texts = _svg_texts(quick_return.images["diagram-sliders"])
    joined = " ".join(texts)
    assert "s [m]" in joined and "[mm]" not in joined
    ticks = [float(t.replace("\u2212", "-").replace(",", ".")) for t in texts if re.fullmatch(r"[\u2212-]?\d+(?:,\d+)?", t)]
    s_ticks = [v for v in ticks if v != int(v)]  # (the positions' numbers and the angles are whole)
    assert s_ticks and max(abs(v) for v in s_ticks) < 1.0
    table = quick_return.source[quick_return.source.index("Излазни члан у сваком положају"):]
    assert '[#"[m]"]' in table


def test_a_linear_drivers_axis_in_metres_in_the_courses_letters():
    doc = built("linear-arm", 8, "bg")
    joined = " ".join(_svg_texts(doc.images["diagram-sliders"]))
    assert "s [м]" in joined and "мм" not in joined and "[m]" not in joined
    assert "−0,100" in joined or "−0,10" in joined or "−0,1" in joined  # the stroke's end, −100 mm, in metres


def test_the_table_page_is_not_left_two_thirds_empty(quick_return):
    """Quick-return, 12 positions: the three diagrams fill a page; the table and its notes take about a third of the
    next, and the page of cycle diagrams with the fewest panels (the points': |v|, |a|) is set under them, not on a
    page of its own; the other cycle pages follow, each on its own page."""
    import base64

    from plans.pages.typesetting import query_document

    doc = quick_return
    pages = doc.pages("svg")

    def page_of(key: str) -> int:
        data = doc.images[key]
        found = [k for k, page in enumerate(pages, start=1)
                 if any(base64.b64decode(m) == data for m in re.findall(rb'data:image/svg\+xml;base64,([^"]+)"', page))]
        assert len(found) == 1, key
        return found[0]

    diagrams = page_of("kinematic-a")
    assert page_of("kinematic-s") == diagrams
    marks = {m["name"]: m for m in query_document(doc.source, doc.images, "<plans-mark>")}
    table_end = marks["kinematic-end"]
    assert table_end["page"] == diagrams + 1
    assert page_of("diagram-points") == diagrams + 1  # under the table
    assert {page_of("diagram-links"), page_of("diagram-sliders")} == {diagrams + 2, diagrams + 3}
    # the cycle page under the table keeps its panels readable: its figure at least 100 mm tall
    assert doc.drawn["diagram-points"][1] >= 100.0


def test_fewer_plan_positions_than_diagram_positions():
    """A handout of 6 positions differentiates over 12 (a course project's least is 8): its plans are those of
    rows 0, 2, 4 …, each row's plan value the plan of the handout's position at the same crank angle (|v_B| read at
    the plate's k_v), the rows between "—", said in a note."""
    doc = handout(plans.load(plans.example_path("slider-crank")), positions=6, lang="en")
    rows = _table(doc.source, "The output link at every position")
    assert len(rows) == 12
    k_v = doc.scales["k_v"]
    for h in doc.runs:
        v_b = {v.label: v.value for v in h.graphical.velocity_plan.vectors}.get("v_B", 0.0)
        row = rows[2 * h.index]
        assert row[4].lstrip("-") == ("0" if v_b == 0 else _read(v_b, k_v)), (h.index, row)
        assert rows[2 * h.index + 1][4] == "—"
    assert "—: this plate draws no plan of that position" in doc.source


def test_readings_headings_have_one_colon(quick_return):
    """Round 12: "Положај 4: План брзина: очитавања" read as a double colon; the position and its plan are joined by a
    dash, the plan's name in lower case after it."""
    source = quick_return.source
    for k in quick_return.accelerations:
        assert f"Положај {k} — план брзина: очитавања" in source and f"Положај {k} — план убрзања: очитавања" in source
    assert "План брзина: очитавања" not in source and not re.search(r"Положај \d+: План", source)
