"""The plate's velocity plans large enough to measure, one k_v kept (issue: plans too small at a k_v set by the
one largest plan), and graphical accelerations only where an acceleration plan is drawn.

Expected sizes come from the analytic solution, not from the plans: a point's speed |v| [m/s] divided by the
plate's k_v [(m/s)/mm] is the length [mm] of its vector from the pole.
"""

from __future__ import annotations

import re
import statistics

import pytest

import plans
from plans.handout import handout
from plans.pages.handout import TEXT_WIDTH
from plans.scene import example_path
from review_handouts import built

pytestmark = pytest.mark.filterwarnings("ignore")


@pytest.fixture(scope="module")
def plates():
    return {name: built(name, 12, "sr")
            for name in ("quick-return", "six-bar", "slider-crank")}


def _longest_mm(doc) -> list[float]:
    """The longest absolute velocity of every position [mm at the plate's k_v], from the analytic speeds."""
    k_v = doc.scales["k_v"]
    return [max(abs(p.v[0]) for p in r.analytic.points.values()) / k_v for r in doc.runs]


@pytest.mark.parametrize("name, median_mm, smallest_mm", [("quick-return", 40.0, 30.0), ("six-bar", 45.0, 45.0),
                                                          ("slider-crank", 45.0, 45.0)])
def test_velocity_plans_large_enough_to_measure(plates, name, median_mm, smallest_mm):
    doc = plates[name]
    assert {r.graphical.scales["k_v"] for r in doc.runs} == {doc.scales["k_v"]}  # one k_v over the plate
    lengths = _longest_mm(doc)
    assert statistics.median(lengths) >= median_mm, (doc.scales["k_v"], lengths)
    assert min(lengths) >= smallest_mm, (doc.scales["k_v"], lengths)
    for r in doc.runs:  # and every plan still on the page
        assert doc.drawn[f"v-{r.index}"][0] <= TEXT_WIDTH + 0.5


def test_the_quick_return_stroke_takes_a_row_of_its_own(plates):
    """The quick-return's fast return stroke (its ram ≈ 3 m/s against ≈ 1 m/s on the working stroke) gets a row
    across the page, so the rest are not drawn at the scale its plan needs in a half cell."""
    doc = plates["quick-return"]
    lengths = _longest_mm(doc)
    largest = doc.runs[lengths.index(max(lengths))].index
    assert doc.drawn[f"v-{largest}"][0] > TEXT_WIDTH / 2
    assert "grid.cell(colspan: 2)" in doc.source
    assert max(lengths) > 2.5 * statistics.median(lengths)


#: a table's caption
_HEADING = re.compile(r'block\(breakable: false, width: 100%\)\[#text\(weight: "bold", size: [0-9.]+pt\)\[#"([^"]*)"\]')
#: a graphical acceleration's row in a table: a, ε, aʳ, aᵏ (typeset symbols)
_ACCELERATION_ROW = re.compile(r"\$(a_|a\^|epsilon)")


def test_graphical_accelerations_only_where_their_plan_is_drawn(plates):
    for name, doc in plates.items():
        start = doc.source.find("#grid(columns: (1fr, 1fr)")  # the comparison tables (the readings' are the next grid)
        parts = _HEADING.split(doc.source[start:doc.source.find("#grid(columns: (1fr, 1fr)", start + 1)])
        tables = dict(zip(parts[1::2], parts[2::2]))
        assert len(tables) == len(doc.runs), name
        with_accelerations = set()
        for heading, table in tables.items():
            index = int(re.match(r"\D*(\d+)", heading).group(1))
            assert re.search(r"\$(v_|omega)", table), (name, heading)  # the velocities every position has
            if _ACCELERATION_ROW.search(table):
                with_accelerations.add(index)
        assert with_accelerations == set(doc.accelerations), name
        assert {k[2:] for k in doc.images if k.startswith("a-")} == {str(k) for k in doc.accelerations}


# --- the instant centres' pages: one k_l ---------------------------------------------------------


def test_one_k_l_over_the_centres_pages_stated_in_their_title_block():
    """The quick-return's centres pages: one k_l for all of them (the plate's where it fits, else the coarsest any
    needs), and their title blocks say it; the other sheets keep the plate's."""
    import io
    import unicodedata

    from pypdf import PdfReader

    doc = handout(plans.load(example_path("quick-return")), positions=4, lang="sr", centres=True)
    pages = [unicodedata.normalize("NFKC", p.extract_text() or "") for p in PdfReader(io.BytesIO(doc.pdf())).pages]
    title_block = [re.findall(r"Размере:\s*k\s*l\s*=\s*([0-9,]+)", p) for p in pages]
    assert all(len(t) == 1 for t in title_block), title_block
    # the method's page (Kennedy's theorem) and the positions' pages (their heading: instant centres — position)
    centres = [n for n, p in enumerate(pages) if "тренутн" in p.lower() and ("Кенеди" in p or re.search(r"полови брзина\s*—\s*Положај", p))]
    assert len(centres) == 1 + 4  # the method's page (Kennedy's theorem, the circle diagram), then a page a position
    on_centres = {title_block[n][0] for n in centres}
    elsewhere = {title_block[n][0] for n in range(len(pages)) if n not in centres}
    plate = f"{doc.scales['k_l']:g}".replace(".", ",")
    assert elsewhere == {plate}
    assert len(on_centres) == 1
    k_centres = float(on_centres.pop().replace(",", "."))
    assert k_centres >= doc.scales["k_l"]
    for n in centres[1:]:  # the drawing on each position's page states the same k_l
        drawing = re.sub(r"\s+", "", pages[n].split("Размере")[0])
        assert f"kl={k_centres:g}".replace(".", ",") in drawing
    widths = {doc.drawn[f"centres-{r.index}"][0] for r in doc.runs}
    assert all(w <= TEXT_WIDTH + 0.5 for w in widths)
