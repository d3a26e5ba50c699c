"""The legend lists every kind of vector the plan draws (issue 20 §3.2; issue 10 §3 had listed arrows only).

A kind whose every vector is shorter than 3 mm is drawn as lettered points
with notes ("d′ n₁ = 2,63 mm"): it is still a vector of the plan, named in its
equations and readings, and the teacher's review of the Serbian quick-return
found its Coriolis component missing from the legend that the other pages had.
Measured from the SVGs: the vectors drawn (arrows, gid ``normal-…``, or notes
``short-…``) against the legend's rows (``legend-normal``).
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import pytest

from plans.cli import main

from accelerating_scenes import write_linear_arm_accelerating
from review_handouts import built, drawn_sheet

SVG = "{http://www.w3.org/2000/svg}"


def _ids(path) -> list[str]:
    return [g.get("id") for g in ET.parse(path).iter(f"{SVG}g") if g.get("id")]


def _arrows(ids, kind: str) -> list[str]:
    """The arrows of *kind* drawn on a plan (gid ``acc-normal-…``), leaving out the legend's sample."""
    return [i for i in ids if re.match(rf"^(vel|acc)-{kind}-", i)]


@pytest.fixture(scope="module")
def drawn(tmp_path_factory):
    out = {}
    for example in ("linear-arm-accelerating", "six-bar"):
        if example == "six-bar":
            d = drawn_sheet(example)
        else:  # the linear-arm with a = 2 m/s² at its instant (the bundled example's a = 0 draws longer normals)
            d = tmp_path_factory.mktemp(example)
            # at the k_a its sheet had chosen (the sheet's factor follows its text column's length: given here)
            assert main(["draw", str(write_linear_arm_accelerating(tmp_path_factory.mktemp("scene"))), "--k-a", "0.03", "-o", str(d)]) == 0
        out[example] = d
    return out


def test_a_kind_drawn_only_as_notes_is_in_the_legend_too(drawn):
    # linear-arm at its own position with a = 2 m/s²: both normal components are 2–3 mm, notes only
    ids = _ids(drawn["linear-arm-accelerating"] / "acceleration.svg")
    assert [i for i in ids if i.startswith("acc-short-a_n")], "the normal components are notes here"
    assert not _arrows(ids, "normal")
    assert [i for i in ids if i.startswith("acc-legend-normal")] and [i for i in ids if i.startswith("acc-legend-text-normal")]
    assert _arrows(ids, "tangential") and [i for i in ids if i.startswith("acc-legend-tangential")]
    # and no kind the plan does not hold (the velocity plan has no components)
    ids = _ids(drawn["linear-arm-accelerating"] / "velocity.svg")
    assert not [i for i in ids if re.match(r"^vel-legend-(normal|tangential|coriolis)", i)]


def test_a_kind_with_one_arrow_drawn_is_in_the_legend(drawn):
    ids = _ids(drawn["six-bar"] / "acceleration.svg")
    assert _arrows(ids, "normal")
    assert [i for i in ids if i.startswith("acc-legend-normal")]


def test_the_sheet_legend_follows_the_plans_too(drawn):
    from sheet_pages import drawings

    placed = drawings((drawn["linear-arm-accelerating"] / "sheet.svg").read_bytes())  # the page's drawings, the legend one of them
    ids = [g.get("id") for d in placed for g in d.root.iter(f"{SVG}g") if g.get("id")]
    legend_kinds = {i.split("-")[-1] for i in ids if re.match(r"^.*legend-(absolute|relative|normal|tangential|coriolis)$", i)}
    assert {"normal", "tangential", "coriolis"} <= legend_kinds, legend_kinds


def _page_legend(example: str) -> set[str]:
    """The kinds a page's legend (one legend for the page's plans, the block the pages place) lists, at the sheet's
    scales."""
    import plans
    from plans.drawing.svgblocks import legend_svg
    from plans.graphical import construct
    from plans.positions import at_page_precision

    g = construct(at_page_precision(plans.load(plans.example_path(example))))
    block = legend_svg((g.acceleration_plan,), "en")
    return set(re.findall(r'id="legend-legend-([a-z]+)"', block.svg.decode()))


def test_a_page_legend_lists_every_kind_drawn():
    assert {"normal", "tangential", "coriolis"} <= _page_legend("linear-arm")
    assert {"normal", "tangential", "coriolis"} <= _page_legend("six-bar")


def test_a_coriolis_component_too_short_for_an_arrow_is_in_the_legend():
    """The Serbian quick-return's handout legend (positions 4 and 10): both Coriolis components are under 3 mm at the
    plate's k_a (0,29 and 2,34 mm), notes only; the legend still names the Coriolis component."""
    from plans.drawing.plan_drawing import SHORT_MM
    from plans.drawing.svgblocks import legend_svg

    doc = built("quick-return", 12, "sr", accelerations=(4, 10))  # (the review's positions: the lever upright)
    plans_a = [r.graphical.acceleration_plan for r in doc.runs if r.index in doc.accelerations]
    coriolis = [v for p in plans_a for v in p.vectors if v.kind == "coriolis"]
    assert coriolis and all(v.length < SHORT_MM for v in coriolis)
    text = legend_svg(plans_a, "sr").svg.decode()
    assert "Кориолисово убрзање" in text


def _velocity_legend(example: str, lang: str = "en") -> str:
    """The page legend of *example*'s velocity plan at its own position (the block the pages place), as SVG text."""
    import plans
    from plans.drawing.svgblocks import legend_svg
    from plans.graphical import construct
    from plans.positions import at_page_precision

    g = construct(at_page_precision(plans.load(plans.example_path(example))))
    return legend_svg((g.velocity_plan,), lang).svg.decode()


def test_a_links_image_on_the_plan_is_in_the_legend():
    """Round 20 (bg linear-arm): the velocity plans draw rod 3's image, the thin segment f h₃ g (the rod carries F, H
    and G: similarity), and the four-bar's coupler image a b m as a grey triangle; neither was in the legend. Its
    sample is what the plan draws (rounds 23, 24: a triangle beside plans whose links are bars and their images
    segments): the six-bar's a thin segment (b e₅ m of link 5), the four-bar's and the linear-arm's (sleeve 4's d k f₄)
    a triangle. Images a drawn vector already joins end to end have no segment of their own: the scotch yoke none, the
    slider-crank's a s₃ b lying under v_BA none (round 28: its legend named a thin line nobody could see)."""
    assert 'id="legend-legend-figure"' in _velocity_legend("linear-arm", "bg")
    segment = _velocity_legend("six-bar", "bg")
    assert 'id="legend-legend-figure_segment"' in segment and 'id="legend-legend-figure"' not in segment
    assert "образ на звено" in segment
    triangle = _velocity_legend("four-bar", "bg")
    assert 'id="legend-legend-figure"' in triangle and "образ на звено" in triangle
    assert "legend-legend-figure" not in _velocity_legend("scotch-yoke")
    assert "legend-legend-figure" not in _velocity_legend("slider-crank-loads", "ru")
