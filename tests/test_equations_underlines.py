"""The underlines of the plans' vector equations (issue review, pf-equations).

Hand-worked expectations: in a step ``v_E = v_D + v_ED (v_ED ⊥ DE)`` the
point D's velocity is known in full before the step (twice), v_ED only in
direction (once), whatever its length at the position (zero at a dead
centre); the sought v_E on the left carries no underline.
"""

import pytest

from plans.pages.equations import equation_math, once, step_lines, twice
from plans.positions import run_positions
from plans.scene import example_path, load
from review_handouts import built_pdf



def _marks(math: str, body: str) -> int:
    """How many underlines wrap *body* in *math* (0, 1 or 2)."""
    if twice(body) in math:
        return 2
    if once(body) in math:
        return 1
    assert body in math
    return 0


def test_four_bar_textbook():
    m = equation_math("v_C = v_B + v_CB", condition="v_CB ⊥ BC")
    assert _marks(m, "arrow(v)_(B)") == 2
    assert _marks(m, "arrow(v)_(C B)") == 1
    assert m.startswith("arrow(v)_(C) =")  # the sought vector: no underline


def test_normal_and_coriolis_twice_tangential_relative_once():
    m = equation_math("a_A4 = a_A3 + a^k_A4A3 + a^r_A4A3", condition="a^k_A4A3 = 2 ω3 × v_A4A3, a^r_A4A3 ∥ 4.slot")
    assert _marks(m, "arrow(a)^k_(A 4 A 3)") == 2 and _marks(m, "arrow(a)^r_(A 4 A 3)") == 1
    m = equation_math("a_E = a_D + a^n_ED + a^t_ED", condition="a^n_ED ∥ ED, a^t_ED ⊥ DE")
    assert _marks(m, "arrow(a)^n_(E D)") == 2 and _marks(m, "arrow(a)^t_(E D)") == 1


def test_linear_driver_acceleration_is_known():
    """The driver's given right side is underlined twice; the sought left side, as the key says, not at all."""
    assert equation_math("a_A = a") == "arrow(a)_(A) = " + twice("a")
    assert equation_math("v_A = ω2 × OA") == "arrow(v)_(A) = " + twice("ω_2 times O A")


def _steps(example, n, k):
    run = run_positions(load(example_path(example)), n)
    return run.runs[k].graphical


@pytest.mark.parametrize("k", [0, 3])
def test_quick_return_ram_step(k):
    g = _steps("quick-return", 12, k)
    lines = [e for st in g.velocity_plan.steps for e, _ in step_lines(st)]
    (ed,) = [e for e in lines if "arrow(v)_(E D)" in e]
    (ee0,) = [e for e in lines if "arrow(v)_(E E 1)" in e]  # the frame is 1 where the crank is 2 (issue 20 §3.5)
    assert _marks(ed, "arrow(v)_(E D)") == 1 and _marks(ed, "arrow(v)_(D)") == 2
    assert _marks(ee0, "arrow(v)_(E E 1)") == 1 and _marks(ee0, "arrow(v)_(E 1)") == 2
    (a4c,) = [e for e in lines if "arrow(v)_(A 4 C)" in e]
    assert _marks(a4c, "arrow(v)_(C)") == 2 and _marks(a4c, "arrow(v)_(A 4 C)") == 1


def test_six_bar_e5b_once():
    g = _steps("six-bar", 12, 0)
    lines = [e for st in g.velocity_plan.steps for e, _ in step_lines(st)]
    (e5b,) = [e for e in lines if "arrow(v)_(E 5 B)" in e]
    assert _marks(e5b, "arrow(v)_(E 5 B)") == 1 and _marks(e5b, "arrow(v)_(B)") == 2


def test_linear_arm_driver_steps():
    g = _steps("linear-arm", 8, 1)
    first = [step_lines(p.steps[0])[0][0] for p in (g.velocity_plan, g.acceleration_plan)]
    assert [e.partition(" = ")[0] for e in first] == ["arrow(v)_(A)", "arrow(a)_(A)"]
    assert "underline" in first[0].partition(" = ")[2] and first[1].partition(" = ")[2] == "0"  # constant speed: a_A = 0


def test_quick_return_driver_line_and_modulus():
    """Issue 20 review: the driver's line ``v_A = ω₂ × OA (⊥ OA, |ω₂|·OA)``: v_A bare, ω₂ × OA twice, the modulus as abs()."""
    g = _steps("quick-return", 12, 0)
    ((eq, cond),) = step_lines(g.velocity_plan.steps[0])
    assert eq == "arrow(v)_(A) = " + twice("ω_2 times O A")
    assert "abs(ω_2)" in cond and "|" not in cond


def test_double_underline_rules_apart():
    """The Typst source of a double underline: a thin second rule with a clear gap ≥ 1.5 pt below the first (two rules
    at 100 dpi: at 1.1 pt round 18's reviewer read the bg linear-arm's v_GF as underlined once)."""
    import re

    src = twice("arrow(v)_(B)")
    stroke = float(re.search(r"stroke: \(bottom: ([0-9.]+)pt\)", src).group(1))
    offset = float(re.search(r"outset: \(bottom: ([0-9.]+)pt\)", src).group(1))
    assert stroke <= 0.5  # thin
    assert offset - stroke / 2 >= 1.5  # the clear gap below the bounds of the first rule
    assert 'bottom-edge: "bounds"' in src and "$underline(arrow(v)_(B))$" in src


def test_legend_states_the_left_side_convention():
    """The legend line says the sought vector is not underlined, in every language, and the equations keep to it."""
    from plans.i18n import term

    words = {"en": "not underlined", "sr": "није подвучен", "ru": "не подчёркнут", "bg": "не е подчертан", "sl": "ni podčrtan"}
    for lang, w in words.items():
        assert w in term("underlines", lang)
    assert equation_math("a_C = a_B + a^n_CB + a^t_CB", condition="a^n_CB ∥ CB, a^t_CB ⊥ BC").startswith("arrow(a)_(C) = ")


def _rules(body: str, dpi: int):
    """The dark rows of the typeset double underline of *body* (9.5 pt, the pages' fonts) rendered at *dpi* by poppler:
    (the grey profile of the columns under the symbol, rows from the top; the runs of rows dark across those columns)."""
    import pathlib
    import shutil
    import subprocess
    import tempfile

    import numpy as np

    from plans.pages.typesetting import FONT, MATH_FONT, compile_document

    if shutil.which("pdftoppm") is None:
        pytest.skip("poppler's pdftoppm renders the page")
    src = (f'#set page(width: 40mm, height: 14mm, margin: 4mm)\n#set text(font: "{FONT}", size: 9.5pt)\n'
           f'#show math.equation: set text(font: "{MATH_FONT}")\n${twice(body)}$\n')
    with tempfile.TemporaryDirectory() as tmp:
        d = pathlib.Path(tmp)
        (d / "u.pdf").write_bytes(compile_document(src, {}, "pdf"))
        subprocess.run(["pdftoppm", "-r", str(dpi), "-gray", str(d / "u.pdf"), str(d / "p")], check=True)
        _, size, _, data = next(d.glob("p*.pgm")).read_bytes().split(b"\n", 3)
    w, h = map(int, size.split())
    img = np.frombuffer(data, dtype=np.uint8).reshape(h, w)
    dark = (img < 128).sum(axis=1)
    ruled = np.flatnonzero(dark >= 0.9 * dark.max())  # the rules: the longest dark rows
    columns = np.flatnonzero((img[ruled] < 128).all(axis=0))  # the columns both rules cross
    runs = np.split(ruled, np.flatnonzero(np.diff(ruled) > 1) + 1)
    return img[:, columns].min(axis=1), [(int(r[0]), int(r[-1])) for r in runs]


@pytest.mark.parametrize("body", ["arrow(v)_(B)", "arrow(a)^k_(E 5 E 6)", "ω_2 times O A", "arrow(v)_(A 4 A 3)"])
def test_double_underline_typeset_two_rules_a_point_apart(body):
    """On the typeset PDF (rendered at 1440 dpi: 20 px a point) the two rules of a double underline are two runs of
    dark rows with a clear gap of at least 1.0 pt between them; at 150 dpi a row between them stays light (the paper
    shows: two lines, not one thick bar)."""
    _, runs = _rules(body, 1440)
    assert len(runs) == 2, runs
    gap_pt = (runs[1][0] - runs[0][1] - 1) * 72 / 1440
    assert gap_pt >= 1.0, gap_pt
    profile, runs = _rules(body, 150)
    assert len(runs) == 2, runs
    assert profile[runs[0][1] + 1:runs[1][0]].max() >= 200, profile[runs[0][0]:runs[1][1] + 1]


def test_double_underlines_on_the_handout_page_are_two_rules(tmp_path):
    """The rules as the handout sets them, in its equation table (the review of the six-bar handout saw one thick
    bar under v_A, v_D, v_B, v_E6 and ω₂ × OA: the table's unbreakable group cells dropped the second rule).  Page 1
    rendered at 600 dpi; under the heading of the velocity equations, every thin horizontal rule is found, and the
    double underlines are pairs of rules of one extent a little apart: the five magnitude-and-direction terms of the
    six-bar's velocity equations (ω₂ × OA, v_A, v_D, v_B, v_E6)."""
    import re
    import shutil
    import subprocess

    import numpy as np

    if shutil.which("pdftoppm") is None or shutil.which("pdftotext") is None:
        pytest.skip("poppler renders and reads the page")
    pdf = tmp_path / "h.pdf"
    pdf.write_bytes(built_pdf("six-bar", centres=False))
    words = subprocess.run(["pdftotext", "-f", "1", "-l", "1", "-bbox", str(pdf), "-"], capture_output=True, text=True,
                           check=True).stdout
    tops = [float(m.group(1)) for m in re.finditer(r'yMin="([\d.]+)"[^>]*>equations:</word>', words)]
    assert tops, "the velocity equations' heading on page 1"
    dpi, top = 600, tops[0]
    subprocess.run(["pdftoppm", "-r", str(dpi), "-gray", "-f", "1", "-l", "1", "-y", str(int(top * dpi / 72)),
                    "-H", str(int(70 / 25.4 * dpi)), "-x", "0", "-W", str(int(130 / 25.4 * dpi)), str(pdf), str(tmp_path / "p")],
                   check=True)
    _, size, _, data = next(tmp_path.glob("p*.pgm")).read_bytes().split(b"\n", 3)
    w, h = map(int, size.split())
    dark = np.frombuffer(data, dtype=np.uint8).reshape(h, w) < 128
    runs = []  # (row, first column, last column) of every dark run ≥ 2.2 mm long
    for y in range(h):
        cols = np.flatnonzero(dark[y])
        for part in np.split(cols, np.flatnonzero(np.diff(cols) > 1) + 1):
            if part.size and part[-1] - part[0] >= 2.2 * dpi / 25.4:  # longer than a vector arrow (1.5 mm)
                runs.append((y, int(part[0]), int(part[-1])))
    rules = []  # runs of consecutive rows with one extent: (first row, last row, x0, x1)
    for y, x0, x1 in runs:
        for r in rules:
            if r[1] == y - 1 and abs(r[2] - x0) <= 2 and abs(r[3] - x1) <= 2:
                r[1] = y
                break
        else:
            rules.append([y, y, x0, x1])
    thin = [r for r in rules if r[1] - r[0] <= 0.6 * dpi / 72]  # a rule, not a glyph's stroke
    pairs = [(a, b) for a in thin for b in thin if a is not b and abs(a[2] - b[2]) <= 4 and abs(a[3] - b[3]) <= 4
             and 0 < b[0] - a[1] <= 3.0 * dpi / 72]
    assert len(pairs) >= 5, (len(pairs), thin[:12])


def test_the_drivers_tangential_component_with_epsilon_given_is_known_twice():
    # the teacher's review of the Russian four-bar sheet: ε₂ = 5 rad/s² is given, so a^t_AO = ε₂·OA ⊥ OA is known in
    # magnitude and direction, underlined twice like a^n_AO (its condition "⊥ OA" repeats a direction it knows)
    from plans.pages.equations import twice, vector_math

    line = equation_math("a_A = a^n_AO + a^t_AO", known={"a^n_AO", "a^t_AO"},
                         condition="a^n_AO ∥ AO, ω2²·OA; a^t_AO ⊥ OA, |ε2|·OA")
    assert line.endswith(" + " + twice(vector_math("a", "t", "AO"))), line


def test_a_driver_at_constant_speed_is_said_to_have_no_acceleration():
    """The bundled linear-arm's slide runs at constant speed (domain.md §10): its step says a_A = 0, nothing underlined
    (not "a_A = a" with a twice-underlined a that is zero); the same slide given a = 2 m/s² keeps its given term."""
    from accelerating_scenes import linear_arm_accelerating

    steady = run_positions(load(example_path("linear-arm")), 4).runs[1].graphical.acceleration_plan.steps[0]
    assert [e for e, _ in step_lines(steady)] == ["arrow(a)_(A) = 0"]
    from plans.graphical.construct import construct

    given = construct(linear_arm_accelerating()).acceleration_plan.steps[0]  # at the scene's instant, a = 2 m/s²
    assert [e for e, _ in step_lines(given)] == ["arrow(a)_(A) = " + twice("a")]
    assert [e for e, _ in step_lines(construct(load(example_path("linear-arm"))).acceleration_plan.steps[0])] == ["arrow(a)_(A) = 0"]
