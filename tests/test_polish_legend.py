"""The legend lists a kind of vector only when an arrow of that kind is drawn (issue 10 §3 leftover).

A kind whose every vector is shorter than 3 mm is drawn as lettered points
with notes ("|aⁿ| = 2.63 mm"): listing it in the legend names a line style
the plan does not show.  Measured from the SVGs: the arrows drawn (gid
``normal-…``, the notes ``short-…``) against the legend's rows (``legend-normal``).
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import pytest

from plans.cli import main

SVG = "{http://www.w3.org/2000/svg}"


def _ids(path) -> list[str]:
    return [g.get("id") for g in ET.parse(path).iter(f"{SVG}g") if g.get("id")]


def _arrows(ids, kind: str) -> list[str]:
    """The arrows of *kind* drawn on a plan (gid ``acc-normal-…``), leaving out the legend's sample."""
    return [i for i in ids if re.match(rf"^(vel|acc)-{kind}-", i)]


@pytest.fixture(scope="module")
def drawn(tmp_path_factory):
    out = {}
    for example in ("linear-arm", "six-bar"):
        d = tmp_path_factory.mktemp(example)
        assert main(["draw", "--example", example, "-o", str(d)]) == 0
        out[example] = d
    return out


def test_a_kind_drawn_only_as_notes_is_not_in_the_legend(drawn):
    # linear-arm at its own position: both normal components are 2–3 mm, notes only
    ids = _ids(drawn["linear-arm"] / "acceleration.svg")
    assert [i for i in ids if i.startswith("acc-short-a_n")], "the normal components are notes here"
    assert not _arrows(ids, "normal")
    assert not [i for i in ids if i.startswith("acc-legend-normal") or i.startswith("acc-legend-text-normal")]
    # while the kinds drawn as arrows are listed
    assert _arrows(ids, "tangential") and [i for i in ids if i.startswith("acc-legend-tangential")]


def test_a_kind_with_one_arrow_drawn_is_in_the_legend(drawn):
    ids = _ids(drawn["six-bar"] / "acceleration.svg")
    assert _arrows(ids, "normal")
    assert [i for i in ids if i.startswith("acc-legend-normal")]


def test_the_sheet_legend_follows_the_arrows_too(drawn):
    from sheet_pages import drawings

    placed = drawings((drawn["linear-arm"] / "sheet.svg").read_bytes())  # the page's drawings, the legend one of them
    ids = [g.get("id") for d in placed for g in d.root.iter(f"{SVG}g") if g.get("id")]
    assert _arrows(ids, "tangential") and not _arrows(ids, "normal")  # the sheet's plans, as drawn
    legend_kinds = {i.split("-")[-1] for i in ids if re.match(r"^.*legend-(absolute|relative|normal|tangential|coriolis)$", i)}
    assert "normal" not in legend_kinds, legend_kinds
    assert "tangential" in legend_kinds


def _page_legend(example: str) -> set[str]:
    """The kinds a page's legend block (one legend for the page's plans) lists, at the sheet's scales."""
    import plans
    from plans.drawing._canvas import sketch_on
    from plans.drawing.blocks import legend_block
    from plans.graphical import construct
    from plans.positions import at_page_precision

    g = construct(at_page_precision(plans.load(plans.example_path(example))))
    block = legend_block(g, "en", plans=("acceleration",))
    artists = sketch_on(None, "page", lambda sketch: block.place(sketch, 0.0, 0.0, (210.0, 297.0)))
    return {a.get_gid()[len("page-legend-"):] for a in artists if re.fullmatch(r"page-legend-[a-z]+", a.get_gid() or "")}


def test_a_page_legend_lists_only_the_kinds_drawn_as_arrows():
    assert "normal" not in _page_legend("linear-arm")
    assert {"normal", "tangential", "coriolis"} <= _page_legend("six-bar")
