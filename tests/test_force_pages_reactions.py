"""The handout's kinetostatic pages, read as the reader reads them (the compiled PDF's text).

Action and reaction: a reaction found on one force plan and carried to the next
(R_ji = −R_ij) states the same magnitude there, to the reading precision; every
plan of a position is drawn at the one μ_F its page's heading states, and the
title block of that page states it too.
"""

from __future__ import annotations

import io
import re
import unicodedata

import pypdf
import pytest

from review_handouts import built_pdf

FOUND = re.compile(r"R(\d\d) = ([0-9.]+) mm · ([0-9.]+) N/mm = ([0-9.]+) N")
CARRIED = re.compile(r"R(\d\d) = −R(\d\d) = ([0-9.]+) N → ([0-9.]+) mm")
HEADING = re.compile(r"Kinetostatic analysis — force plans; μF = ([0-9.]+) N/mm")
TITLE_BLOCK = re.compile(r"Scale factors: [^\n]*μF = ([0-9.]+) N/mm")


@pytest.fixture(scope="module", params=["six-bar-loads", "quick-return-loads"])
def pages(request):
    pdf = built_pdf(request.param, 6, "en", forces=True)  # (built once per test run: tests/review_handouts.py)
    texts = [re.sub(r"[ \t]+", " ", unicodedata.normalize("NFKC", p.extract_text() or "")) for p in pypdf.PdfReader(io.BytesIO(pdf)).pages]
    plans_pages = [t for t in texts if HEADING.search(t)]
    assert len(plans_pages) == 2  # the two positions whose acceleration plans are drawn: a page of force plans each
    return plans_pages


def test_a_reaction_carried_to_the_next_plan_equals_the_one_found(pages):
    carried_seen = 0
    for page in pages:
        found = {m[1]: (float(m[4]), float(m[3])) for m in FOUND.finditer(page)}
        carried = [(m[1], m[2], float(m[3]), float(m[4])) for m in CARRIED.finditer(page)]
        assert carried, page
        for ji, ij, value, length in carried:
            assert ji == ij[::-1]  # R_ji = −R_ij: the same pair, the other way round
            value_found, mu = found[ij]
            assert value == pytest.approx(value_found, abs=0.05 * mu), (ji, value, value_found)
            assert length * mu == pytest.approx(value, abs=0.05 * mu)  # drawn at the same μ_F
            carried_seen += 1
    assert carried_seen >= 2


def test_one_force_scale_per_position_stated_in_the_heading_and_the_title_block(pages):
    for page in pages:
        stated = float(HEADING.search(page)[1])
        used = {float(m[3]) for m in FOUND.finditer(page)}
        assert used == {stated}, (used, stated)
        assert float(TITLE_BLOCK.search(page)[1]) == stated
