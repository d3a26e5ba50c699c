"""The handout's first page as a teacher's second review read it (issue 20): the data said once, the positions
whose acceleration plans are drawn named as such, the frame's words, headings that do not break a formula."""

import re

import pytest

import plans
from plans.motion import driver_cycle
from plans.pages.words import cycle_lines, scene_data_lines
from plans.positions import run_positions

from accelerating_scenes import linear_arm_accelerating


def _first_lines(example, n, lang):
    scene = example if isinstance(example, plans.Scene) else plans.load(plans.example_path(example))
    run = run_positions(scene, n)
    law = run.motion.law
    return scene_data_lines(run.scene, lang, law) + cycle_lines(run, lang, rate=law.kind != "constant"), law


def test_quick_return_states_omega_and_epsilon_once():
    """quick-return.toml: ω = 6 rad/s, no ε; constant law: "ω₂ = 6 rad/s" once, "ε₂ = 0" once."""
    lines, law = _first_lines("quick-return", 12, "sr")
    text = "\n".join(lines)
    assert law.kind == "constant"
    assert text.count("ω₂ = 6 rad/s") == 1, text
    assert len(re.findall(r"ε₂ = 0\b", text)) == 1, text


@pytest.mark.parametrize("scene", ["linear-arm", "accelerating"])
def test_linear_arm_driver_line_gives_what_the_cycle_uses(scene):
    """linear-arm.toml: v = 0.5 m/s and no acceleration (constant speed, the course project's driver); the same
    mechanism written with a = 2 m/s² at its instant: the cycle runs at constant v (a = 0) in both.  The driver's
    line gives v only, the law a₂ = 0; the 2 m/s² is not in the driver's line, and a remark beside the law says it is
    not used only where the scene gives it (none for the bundled example: nothing to explain)."""
    given = scene == "accelerating"
    lines, law = _first_lines(linear_arm_accelerating() if given else scene, 8, "bg")
    driver = lines[0]
    assert "v = 0,5 m/s" in driver.replace("м/с", "m/s") or "v = 0.5 m/s" in driver
    assert "a = 2" not in driver and "a = " not in driver, driver
    (law_line,) = [line for line in lines if line.startswith("закон на движение")]
    assert law_line.endswith("постоянна скорост, a₂ = 0"), law_line
    if given:  # the instant's 2 m/s² said once, as a remark (beside the law on the page)
        assert law.given_note("bg", "2") == "зададеното a₂ = 2 m/s² не се използва: цикълът следва този закон"
    else:
        assert law.given_note("bg", "2") == ""
        assert not [line for line in lines if "не се използва" in line], lines


def test_one_position_data_keep_the_given_acceleration():
    """Without a cycle (one position) the driver's line gives the scene's a as it is: 2 m/s² where it is given, 0 in
    the bundled example that gives none."""
    scene = linear_arm_accelerating()
    assert "a = 2 m/s²" in scene_data_lines(scene, "en")[0]
    assert driver_cycle(scene, 8).law.describe("en", "2").endswith("v₂ = 0.5 m/s, a₂ = 0")
    assert "a = 0 m/s²" in scene_data_lines(plans.load(plans.example_path("linear-arm")), "en")[0]


def test_the_positions_list_names_the_acceleration_plans():
    """quick-return, 12 positions: position 4 (φ₂ = 91,3°) is the working stroke's acceleration plan; the list says
    "план убрзања — радни ход", not a bare "(радни ход)" (which reads as if the other positions had no stroke)."""
    from plans.i18n import term
    from plans.pages.handout import position_entry

    run = run_positions(plans.load(plans.example_path("quick-return")), 12)
    r = run.runs[4]
    words = {"sr": ("План убрзања", "радни ход"), "en": ("Acceleration plan", "working stroke"),
             "ru": ("План ускорений", "рабочий ход"), "bg": ("План на ускоренията", "работен ход"),
             "sl": ("Načrt pospeškov", "delovni hod")}
    for lang, (plan, stroke) in words.items():
        assert term("acceleration_plan", lang) == plan
        text = position_entry(r, lang, True, term("working_stroke", lang))
        assert text.endswith(f"({plan.lower()} — {stroke})"), text
    assert position_entry(r, "sr") == "4:  φ₂ = 91.3°"  # (the page sets the decimal comma)


def test_linear_arm_bulgarian_words():
    """The frame's guide is the "стойка" (the fixed link), not "под" (floor); the sleeve's line named by the points
    on it in its direction (F, K on the rod/sleeve line, G further along: from linear-arm.toml's assembly, G near
    (0.49, 0.25) m, beyond K ≈ (0.41, 0.22) m from F = (0, 0.15) m); K said as the coefficient, not a bare "K"."""
    from plans.i18n import term
    from plans.pages.words import assembly_lines

    run = run_positions(plans.load(plans.example_path("linear-arm")), 8)
    driver = scene_data_lines(run.scene, "bg", run.motion.law)[0]
    assert "стойка ∥ 0°" in driver and "под" not in driver, driver
    s = run.runs[0]
    words = assembly_lines(s.analytic.branches, run.scene, "bg", s.graphical.positions)
    assert words[0] == "група 3–4: посока на втулката: F → K → G", words
    assert "без K" not in term("one_way_stroke", "bg") and "коефициент" in term("one_way_stroke", "bg")
    assert term("stroke_time", "bg") == "време на хода"
    assert term("stroke_diagrams", "bg") == "Кинематични диаграми за един ход"


def test_a_formula_does_not_break():
    """"ω₂ = 6 rad/s" is one unit on a page, set in one box (the kinematic page's heading broke it as
    "ω₂ / = 6 rad/s"); math pieces whole."""
    from plans.pages.document import formula_parts

    assert formula_parts("при ω₂ = 6 rad/s, t = 0,69 s") == [("при ", False), ("ω₂ = 6 rad/s", True), (", ", False), ("t = 0,69 s", True)]
    assert formula_parts("$k_v$ = 0,02 (m/s)/mm; x") == [("$k_v$ = 0,02 (m/s)/mm", True), ("; x", False)]
    # math standing alone: a short formula whole too (the Bulgarian centres rule broke "ω_k =" / "±v_A / P₁ₖP₂ₖ"),
    # a long one (over 60 characters) as Typst breaks math
    assert formula_parts("$a = b$ c") == [("$a = b$", True), (" c", False)]
    long = "$" + " + ".join(f"x_{n}" for n in range(12)) + " = y$"
    assert formula_parts(long + " c") == [(long + " c", False)]
    # a number without a unit is a formula too (|a_A| = 0 was broken in a Bulgarian diagram's note); a number run into
    # what follows (331,3°) is left as it is
    assert formula_parts("v = 0 over the cycle") == [("v = 0", True), (" over the cycle", False)]
    assert formula_parts("φ₂ = 331,3°") == [("φ₂ = 331,3°", False)]


def test_the_page_sets_a_formula_in_a_box():
    from plans.pages.document import Document

    doc = Document(plans.load(plans.example_path("quick-return")), "sr")
    assert '#box[#"ω₂ = 6 rad/s"]' in doc.words("при ω₂ = 6 rad/s"), doc.words("при ω₂ = 6 rad/s")
