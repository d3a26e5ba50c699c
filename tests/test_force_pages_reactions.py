"""The handout's kinetostatic pages, read as the reader reads them (the rendered SVG's texts).

Action and reaction: a reaction found on one force plan and carried to the next
(R_ji = −R_ij) states the same magnitude there, to the reading precision; every
plan of a position is drawn at the one μ_F its page's heading states.
"""

from __future__ import annotations

import re

import pytest

from plans.handout import handout
from plans.scene import example_path, load

#: a text's group in the page's SVG: its gid, then its source text as a comment
ITEM = re.compile(r'<g id="fplan-(reading|known)-(R_\w+)">\s*<!-- (.*?) -->')
FOUND = re.compile(r"^\$R_\{\\mathrm\{(\w+)\}\}\$ = ([0-9.]+) mm · ([0-9.]+) N/mm = ([0-9.]+) N$")
CARRIED = re.compile(r"^\$R_\{\\mathrm\{(\w+)\}\}\$ = −\$R_\{\\mathrm\{(\w+)\}\}\$ = ([0-9.]+) N → ([0-9.]+) mm$")
HEADING = re.compile(r'<g id="page-page-data[-0-9]*">\s*<text[^>]*>[^<]*μ</text>\s*<text[^>]*>F</text>\s*<text[^>]*> = ([0-9.]+) N/mm</text>')


def _texts(svg) -> list[str]:
    """The page's texts (their source, as the SVG's comments keep it) and the heading's."""
    svg = svg.decode() if isinstance(svg, bytes) else svg
    return [m[3] for m in ITEM.finditer(svg)] + [f"mu_F {m[1]}" for m in HEADING.finditer(svg)]


@pytest.fixture(scope="module", params=["six-bar-loads", "quick-return-loads"])
def pages(request):
    doc = handout(load(example_path(request.param)), positions=12, forces=True)
    by_position: dict[str, list[list[str]]] = {}
    for name, svg in doc.images.items():
        if name.startswith("forces-"):
            by_position.setdefault(name.split("-")[1], []).append(_texts(svg))
    assert len(by_position) == 2  # the two positions whose acceleration plans are drawn
    by_position["source"] = doc.source
    return by_position


def _positions(pages):
    return {k: v for k, v in pages.items() if k != "source"}


def test_a_reaction_carried_to_the_next_plan_equals_the_one_found(pages):
    carried_seen = 0
    for position, texts in _positions(pages).items():
        found, carried = {}, []
        for page in texts:
            for t in page:
                if m := FOUND.match(t):
                    found[m[1]] = (float(m[4]), float(m[3]))
                elif m := CARRIED.match(t):
                    carried.append((m[1], m[2], float(m[3]), float(m[4])))
        assert carried, (position, texts)
        for ji, ij, value, length in carried:
            assert ji == ij[::-1]  # R_ji = −R_ij: the same pair, the other way round
            value_found, mu = found[ij]
            assert value == pytest.approx(value_found, abs=0.05 * mu), (position, ji, value, value_found)
            assert length * mu == pytest.approx(value, abs=0.05 * mu)  # drawn at the same μ_F
            carried_seen += 1
    assert carried_seen >= 2


def test_one_force_scale_per_position_stated_in_the_heading(pages):
    for position, texts in _positions(pages).items():
        stated = [float(t.split()[1]) for page in texts for t in page if t.startswith("mu_F ")]
        assert len(stated) == 1, (position, stated)  # once, on the plans' page
        used = {float(m[3]) for page in texts for t in page if (m := FOUND.match(t))}
        assert used == {stated[0]}, (position, used, stated)


def test_the_title_block_of_a_plans_page_states_its_force_scale(pages):
    """Each plans' page leaves its μ_F for the title block, which adds the note found on its own page."""
    source = pages["source"]
    stated = [float(t.split()[1]) for texts in _positions(pages).values() for page in texts for t in page if t.startswith("mu_F ")]
    notes = [float(m[1]) for m in re.finditer(r'#metadata\(\[\$μ_\(F ?\)\$#" = ([0-9.]+) N/mm"\]\) <plans-page-scale>', source)]
    assert notes == stated
    assert "query(<plans-page-scale>)" in source and "here().page()" in source
