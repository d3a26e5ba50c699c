"""Promises no test held before issue 21: the solve table's error columns, the branch of every group kind
against its geometry, each language's branch words against the English they translate, and Kennedy's
theorem taking the best-conditioned pair of lines."""

import math
import re

import pytest

import plans
from plans.cli import main
from plans.i18n import branch_text
from plans.scene import example_path


# --- (a) the abs. and rel. error columns of the plans solve table ------------------------------


def test_solve_table_error_columns_are_the_absolute_then_the_relative_difference(capsys):
    # drafting precision 0.5 mm: differences of about 1e-3 relative, far from round-off
    assert main(["solve", "--example", "slider-crank", "--precision", "0.5", "--no-centres"]) == 0
    out = capsys.readouterr().out
    points = out.split("\nPoints")[1].split("\nLinks")[0].splitlines()
    checked = 0
    analytic = None
    for line in points:
        cells = line.split()
        if "analytic" in cells:
            at = cells.index("analytic")
            analytic = complex(float(cells[at + 1]), float(cells[at + 2]))
        elif cells and cells[0] == "graphical" and analytic is not None:
            graphical = complex(float(cells[1]), float(cells[2]))
            abs_err, rel_err = float(cells[-2]), float(cells[-1])
            difference = abs(graphical - analytic)  # from the table's own (6-digit) numbers
            if difference > 1e-3 * abs(analytic):
                assert abs_err == pytest.approx(difference, rel=0.02), line
                assert rel_err == pytest.approx(difference / abs(analytic), rel=0.02), line
                checked += 1
    assert checked >= 3  # v and a of A and of B, at least (|a| ≈ 4000 m/s²: the columns cannot be confused)
    links = out.split("\nLinks")[1].split("\nSliders")[0]
    rows = re.findall(r"^(\S+)\s+analytic\s+\S+\s+(\S+)\s+(\S+)\n\s+graphical\s+(\S+)\s+(\S+)\n\s+error\s+ω (\S+) \((\S+) rel\), ε (\S+) \((\S+) rel\)",
                      links, re.MULTILINE)
    assert rows
    for name, om_a, ep_a, om_g, ep_g, om_abs, om_rel, ep_abs, ep_rel in rows:
        for a, g, e_abs, e_rel in ((om_a, om_g, om_abs, om_rel), (ep_a, ep_g, ep_abs, ep_rel)):
            a, g, e_abs, e_rel = map(float, (a, g, e_abs, e_rel))
            if abs(g - a) > 1e-3 * abs(a) and a:
                assert e_abs == pytest.approx(abs(g - a), rel=0.05), name
                assert e_rel == pytest.approx(abs(g - a) / abs(a), rel=0.05), name


# --- (b) the branch of every group kind against its geometry -----------------------------------

SLIDER_CRANK = example_path("slider-crank").read_text().split("[assembly]")[0]


@pytest.mark.parametrize("sign", [1, -1])
def test_rrp_branch_against_geometry(sign):
    # B on the cylinder line y = 0.05 m, |AB| = 0.25 m: the two intersections are x = A.x ± sqrt(0.25² − (0.05 − A.y)²)
    solution = plans.solve(plans.loads(SLIDER_CRANK + f"[assembly]\nB = {sign}\n"))
    (branch,) = solution.branches
    a, b = complex(solution.points["A"].r[0]), complex(solution.points["B"].r[0])
    reach = math.sqrt(0.25 ** 2 - (0.05 - a.imag) ** 2)
    further = a.real + reach  # further along the guide's direction (+x)
    assert b.real == pytest.approx(further if sign > 0 else a.real - reach, abs=1e-12)
    assert branch.sign == sign
    assert branch.words == ("B at the intersection further along frame.cylinder (of the two the circle about A meets)" if sign > 0
                            else "B at the intersection nearer the start of frame.cylinder (of the two the circle about A meets)")


@pytest.mark.parametrize("sign", [1, -1])
def test_rpr_branch_against_geometry(sign):
    # six-bar: RPR(5,6), rod 5 (line "rod" along its own x axis, through B) slides in the sleeve 6 pinned at E;
    # +1: the rod's direction points from B towards E
    text = example_path("six-bar").read_text() + f"M = {sign}\n"
    solution = plans.solve(plans.loads(text))
    branch = next(b for b in solution.branches if b.group == "RPR(5,6)")
    b, e = complex(solution.points["B"].r[0]), complex(solution.points["E"].r[0])
    m = complex(solution.points["M"].r[0])
    u = (m - b) / abs(m - b)  # the rod's direction: M lies at +0.8 m along it from B
    towards = ((e - b) * u.conjugate()).real > 0
    assert towards == (sign > 0)
    assert branch.sign == sign
    assert branch.words == ("line 5.rod pointing from B towards E" if sign > 0 else "line 5.rod pointing from E towards B")


@pytest.mark.parametrize("example, group", [("wedge", "PRP(3,4)"), ("scotch-yoke", "RPP(3,4)")])
def test_groups_with_one_assembly_report_no_branch(example, group):
    (branch,) = plans.solve(plans.load(example_path(example))).branches
    assert (branch.group, branch.sign, branch.words, branch.other_assembly) == (group, 0, "one assembly only", False)


@pytest.mark.parametrize("sign", [1, -1])
def test_rrr_branch_words_follow_the_side(sign):
    text = example_path("four-bar").read_text().split("[assembly]")[0] + f"[assembly]\nB = {sign}\n"
    solution = plans.solve(plans.loads(text))
    (branch,) = solution.branches
    a, b, d = (complex(solution.points[n].r[0]) for n in "ABD")
    left = ((d - a).conjugate() * (b - a)).imag > 0
    assert left == (sign > 0) and branch.sign == sign
    assert branch.words == f"B to the {'left' if left else 'right'} of A→D"


# --- (c) each language's branch words against the English they translate ----------------------

#: the words of each English form in each language (from the courses' textbooks), and those of its opposite
BRANCH_WORDS = {
    "left": {"sr": "лево од", "ru": "слева от", "bg": "вляво от", "sl": "levo od"},
    "right": {"sr": "десно од", "ru": "справа от", "bg": "вдясно от", "sl": "desno od"},
    "further": {"sr": "даље дуж", "ru": "дальше вдоль", "bg": "по-нататък по", "sl": "dlje vzdolž"},
    "nearer": {"sr": "ближе почетку", "ru": "ближе к началу", "bg": "по-близо до началото", "sl": "bliže začetku"},
}
OPPOSITE = {"left": "right", "right": "left", "further": "nearer", "nearer": "further"}
ENGLISH = {
    "left": "C to the left of B→D",
    "right": "C to the right of B→D",
    "further": "C at the intersection further along frame.g (of the two the circle about B meets)",
    "nearer": "C at the intersection nearer the start of frame.g (of the two the circle about B meets)",
}


@pytest.mark.parametrize("lang", ["sr", "ru", "bg", "sl"])
@pytest.mark.parametrize("form", list(ENGLISH))
def test_branch_words_translate_their_english_form(form, lang):
    text = branch_text(ENGLISH[form], lang)
    assert text is not None
    assert BRANCH_WORDS[form][lang] in text, (lang, text)
    assert BRANCH_WORDS[OPPOSITE[form]][lang] not in text, (lang, text)
    names = re.findall(r"\b(?:B|C|D|frame\.g)\b", text)
    assert names[0] == "C"  # the names kept, in the English order for the side: C, then B→D
    if form in ("left", "right"):
        assert "B→D" in text


@pytest.mark.parametrize("lang", ["sr", "ru", "bg", "sl"])
def test_a_direction_from_one_pin_to_the_other_keeps_its_order(lang):
    one, other = branch_text("line 5.rod pointing from B towards E", lang), branch_text("line 5.rod pointing from E towards B", lang)
    assert one.index("B") < one.index("E") and other.index("E") < other.index("B")


# --- (d) Kennedy's theorem: the best-conditioned pair of lines -----------------------------------


def _line(p, q):
    """A line through two centres, each a point (complex) or a direction at infinity (unit complex, flagged)."""
    (pz, p_inf), (qz, q_inf) = p, q
    if p_inf and q_inf:
        return None
    if p_inf:
        return qz, pz
    if q_inf:
        return pz, qz
    if abs(qz - pz) < 1e-12:
        return None
    return pz, (qz - pz) / abs(qz - pz)


def test_kennedy_takes_the_best_conditioned_pair_of_lines_on_the_six_bar():
    """The construction redone by hand from the centres' places: the centres found one at a time, each the
    first (in label order) that two Kennedy lines of known centres give, where the two lines that cross
    at the widest angle meet; the lines reported must be those."""
    from plans.centres import instant_centres

    result = instant_centres(plans.load(example_path("six-bar")))
    numbers = {c.label: c for c in result.centres}
    place = {}
    for c in result.centres:
        place[c.label] = (c.point, False) if c.point is not None else (c.direction / abs(c.direction), True)
    n = len(result.numbers)
    bodies = sorted(result.numbers.values(), key=int)

    def label(a, b):
        a, b = sorted((a, b), key=int)
        return f"P{a}{b}"

    known = {c.label for c in result.centres if c.found_by != "kennedy"}
    expected = {}
    while len(known) < n * (n - 1) // 2:
        for a, c in ((a, c) for k, a in enumerate(bodies) for c in bodies[k + 1:]):
            target = label(a, c)
            if target in known:
                continue
            lines = []
            for b in bodies:
                if b not in (a, c) and label(a, b) in known and label(b, c) in known:
                    line = _line(place[label(a, b)], place[label(b, c)])
                    if line is not None:
                        lines.append(((label(a, b), label(b, c)), line))
            pairs = [(abs((l1[1].conjugate() * l2[1]).imag), n1, n2) for k, (n1, l1) in enumerate(lines) for n2, l2 in lines[k + 1:]]
            pairs = [p for p in pairs if p[0] > 1e-9]  # two lines that are one line give no point
            if pairs:
                expected[target] = {frozenset((n1, n2)): sine for sine, n1, n2 in pairs}
                known.add(target)
                break
        else:
            break
    assert expected.keys() == {c.label for c in result.centres if c.found_by == "kennedy"}
    clear = 0
    for target, sines in expected.items():
        lines = numbers[target].lines
        chosen = sines.get(frozenset((tuple(lines[0]), tuple(lines[1]))))
        assert chosen is not None, (target, lines)  # two of the lines known when the centre was found
        best, worst = max(sines.values()), min(sines.values())
        assert chosen >= best - 1e-9, (target, lines, chosen, best)  # the widest angle (a tie: either)
        clear += worst < 0.5 * best
    assert clear >= 2  # centres where the worst pair is far worse than the best, so a wrong choice shows
