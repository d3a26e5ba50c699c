"""The centres pages' table: the sign of ω read through a link that translates is written in the formula and is the
one the method page's rule gives (teacher's review: "ω₄ = v₆ / P₁₄P₄₆ = v₆ / (88,8·k_l) = −0,1568" with v₆ = 0,08352 ∠ 0°),
the reading column says what it holds, and the numbers' columns are right-aligned.

The rule (centres_sign_rule_translating): ω_l = ±v_j / P_1lP_jl, + when v_j at P_jl turns anticlockwise about P_1l.
Applied here to the true centres and velocities of the analytic solution, not to the method's own numbers.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from plans.analytic import solve
from plans.centres import instant_centres
from plans.compare import compare_centres
from plans.drawing.centres_page import centres_page_table, centres_rules
from plans.handout import handout
from plans.positions import cycle_positions
from plans.scene import example_path, load

from analytic_centres import true_centres

_DIGITS = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")
EXAMPLES = ["four-bar", "six-bar", "slider-crank", "quick-return", "linear-arm", "scotch-yoke", "wedge", "ladder", "rocker-limit"]


def _body_velocity(scene, solution, body: str) -> complex:
    """v [m/s] of a translating body (every point alike): its first point's."""
    point = next(iter(scene.bodies[body].points))
    return complex(np.ravel(solution.points[point].v)[0])


def _number(text: str) -> float:
    return float(text.replace("−", "-").replace(",", ".").split()[0])


@pytest.mark.parametrize("name", EXAMPLES)
def test_the_sign_through_a_translating_link_follows_the_rule(name):
    scene0 = load(example_path(name))
    signs = []
    for position in cycle_positions(scene0, 6):
        scene = scene0.at(position)
        solution = solve(scene)
        truth = true_centres(scene)
        result = instant_centres(scene)
        by_number = {n: body for body, n in result.numbers.items()}
        exact = instant_centres(scene)
        k_l = exact.size / 120.0
        read = instant_centres(scene, k_l=k_l, precision=0.1)
        table = centres_page_table(read, compare_centres(solution, read, translations=True), "en", k_l)
        for row in table[1:]:
            m = re.fullmatch(r"(−?)\$v_\{(\w+)\}\$ / (P[₀-₉]{2})(P[₀-₉]{2}) = (−?)\$v_\{\2\}\$ / \(([\d.]+) · \$k_l\$\)", row[2])
            if not m:
                continue
            assert m.group(1) == m.group(5), row
            j = re.fullmatch(r"\$\\omega_\{(\w+)\}\$ \[rad/s\]", row[0]).group(1)
            k = m.group(2)  # the translating link
            p1j, pjk = (truth[p.translate(_DIGITS)][0] for p in (m.group(3), m.group(4)))
            v = _body_velocity(scene, solution, k)
            anticlockwise = ((pjk - p1j).conjugate() * v).imag > 0  # (P_jk − P_1j) × v_k
            printed_minus = m.group(1) == "−"
            assert printed_minus == (not anticlockwise), (name, position, row)
            # and the value printed has the formula's sign
            assert (_number(row[3]) < 0) == printed_minus, row
            # the length printed is |P_1jP_jk| on the drawing [mm]
            assert float(m.group(6)) == pytest.approx(abs(pjk - p1j) / k_l, abs=0.06), row
            assert k in result.numbers and j in result.numbers and by_number
            signs.append(printed_minus)
    if name in ("linear-arm", "quick-return"):  # both senses occur over their cycles
        assert True in signs and False in signs, signs


def test_the_method_page_states_the_sign_through_a_translating_link():
    scene = load(example_path("linear-arm"))
    numbers = instant_centres(scene).numbers
    said = {"en": "turns anticlockwise about", "sr": "супротно од казаљке на сату", "ru": "против часовой стрелки",
            "bg": "обратно на часовниковата стрелка", "sl": "v nasprotni smeri urinega kazalca"}
    for lang, words in said.items():
        rules = centres_rules(lang, "1", scene.driver, numbers)
        assert any(r"\pm v_{A}" in r for r in rules), rules  # ω_k = ±v_A / P_1kP_2k
        assert any(words in r and r"$\omega_k = \pm v_{A} / P_{1k}P_{2k}$" in r for r in rules), rules
        rules = centres_rules(lang, "1", None, None, translating=True)
        assert any(r"\omega_l = \pm v_j" in r for r in rules), rules
        assert any(words in r and r"\omega_l = \pm v_j / P_{1l}P_{jl}" in r for r in rules), rules


def test_the_reading_column_says_what_it_holds():
    """Formulas and lengths, not millimetres alone: "from the drawing (lengths in mm)" in the reader's language."""
    scene = load(example_path("quick-return"))
    read = instant_centres(scene, k_l=0.005, precision=0.1)
    heading = {"en": "from the drawing (lengths in mm)", "sr": "са цртежа (дужине у mm)", "ru": "по чертежу (длины в мм)",
               "bg": "от чертежа (дължини в мм)", "sl": "z risbe (dolžine v mm)"}
    for lang, words in heading.items():
        table = centres_page_table(read, compare_centres(solve(scene), read, translations=True), lang, 0.005)
        assert table[0][2] == words


def test_the_centres_table_numbers_right_aligned():
    """Every column after the quantity and the centre (the reading, the two values, the relative error) to the right:
    the rel. error column was left-aligned (an alignment list one short of the six columns, Typst cycles it)."""
    doc = handout(load(example_path("six-bar")), centres=True)
    source = doc.source
    tables = re.findall(r"table\(columns: 6, [^)]*\), align: (\([^)]*\))", source)
    assert tables, "the centres table"
    for aligns in tables:
        assert aligns == "(left, left, right, right, right, right)", aligns
