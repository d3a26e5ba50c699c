"""Every proportion placing an image by similarity computes from its numbers as printed (issue 20, fourth review).

"π d′ = 4,7 · 550,0 / 370,0 = 6,9 mm" gives 7,0 by hand: the result was the unrounded segments' quotient. A student
redoing the arithmetic, and the teacher marking it, must get the printed last digit.  The check is the arithmetic
itself, done here on the printed numbers (one decimal, half away from zero as a student rounds).
"""

from __future__ import annotations

import re
from decimal import ROUND_HALF_UP, Decimal

import pytest

import plans
from plans.drawing.readings import similarity_lines
from plans.graphical import construct

_EQUATION = re.compile(r"= ([0-9]+\.[0-9]) · ([0-9]+\.[0-9]) / ([0-9]+\.[0-9]) = ([0-9]+\.[0-9]) mm")


def _checked(lines) -> int:
    n = 0
    for line in lines:
        for read, a, b, result in _EQUATION.findall(line):
            exact = Decimal(read) * Decimal(a) / Decimal(b)
            by_hand = exact.quantize(Decimal("0.1"), rounding=ROUND_HALF_UP)
            # (a quotient on the half: either neighbour is a fair rounding)
            on_half = abs(exact - by_hand) == Decimal("0.05")
            assert Decimal(result) == by_hand or on_half, line
            n += 1
    return n


@pytest.mark.parametrize("example", ["six-bar", "quick-return", "four-bar", "linear-arm"])
def test_a_proportions_result_is_its_printed_numbers_arithmetic(example):
    scene = plans.load(plans.example_path(example))
    total = 0
    for k_v, k_a in ((None, None), (0.005, 0.05), (0.013, 0.17)):  # the scene's factors and two others
        g = construct(scene, k_v=k_v, k_a=k_a) if k_v else construct(scene)
        total += sum(_checked(similarity_lines(g, kind)) for kind in ("velocity", "acceleration"))
    assert total >= 3, example  # every one of these examples places images by similarity on both plans


_PROPORTION = re.compile(r"(?P<seg>[^:;]+?) / (?P<base>[^=]+?) = [^:]+:  (?P=seg) = (?P<read>[0-9]+[.,][0-9]) · [0-9]+[.,][0-9] / [0-9]+[.,][0-9]"
                         r" = (?P<result>[0-9]+[.,][0-9]) mm(?: \((?:на плана|на плану|on the plan) (?P<plan>[0-9]+[.,][0-9]) mm\))?")


@pytest.mark.parametrize("example, positions, lang", [("linear-arm", 8, "bg"), ("quick-return", 12, "sr"), ("six-bar", 12, "en")])
def test_a_segment_found_by_proportion_is_the_number_read_after_it(example, positions, lang):
    """Rounds 13–16 (bg linear-arm): "fg = 10,7 · 550,0 / 329,0 = 17,9 мм", then "f h₃ = 17,8 · 198,7 / 550,0": the next
    proportion reads fg off the plan, drawn exactly (17,8), not the rounded inputs' 17,9.  Where they differ the result
    says what the plan measures ("17,9 мм (на плана 17,8 мм)"), and that is the number read after it."""
    from plans.positions import run_positions

    run = run_positions(plans.load(plans.example_path(example)), positions)
    chained = 0
    for r in run.runs:
        for kind in ("velocity", "acceleration"):
            found = {}
            for line in similarity_lines(r.graphical, kind, lang):
                for m in _PROPORTION.finditer(line):
                    base = m["base"].strip()
                    if base in found:
                        assert m["read"] == found[base], (example, r.index, kind, base, found[base], line)
                        chained += 1
                    found[m["seg"].strip()] = m["plan"] or m["result"]
    assert chained >= 1 or example != "linear-arm"


def test_a_triangles_two_proportions_are_set_apart_on_the_page():
    """Rounds 12–16 (bg linear-arm, "Образи по подобие"): "… = 2,4 мм f₄ k / f₄ p = …", two proportions run together:
    the ";" between them, right after a box, was read by the typesetter as the end of an expression.  On the page each
    is ended by its ";"."""
    import io

    from pypdf import PdfReader

    from review_handouts import built_pdf

    text = " ".join(page.extract_text() for page in PdfReader(io.BytesIO(built_pdf("linear-arm", 8, "bg"))).pages)
    text = " ".join(text.split())
    joined = re.findall(r"мм\)? f₄ k / f₄ p", text)
    apart = re.findall(r"мм\)?; f₄ k / f₄ p", text)
    assert not joined and len(apart) >= 8, (joined, len(apart))


def test_the_stroke_time_reads_as_the_data_states_it():
    """Round 20 (bg linear-arm): the data block says the stroke takes "t = 0,4 с", the diagrams' page "T = 0,4000 с".
    One value, one way of writing it: the time the scene gives (200 mm at 0.5 m/s), without trailing zeros."""
    import io

    from pypdf import PdfReader

    from review_handouts import built_pdf

    text = " ".join(" ".join(page.extract_text() for page in PdfReader(io.BytesIO(built_pdf("linear-arm", 8, "bg"))).pages).split())
    assert "t = 0,4 с" in text  # the data block
    assert "T = 0,4 с" in text and "T = 0,4000" not in text
