"""The guides' names on a page as the course writes them (issue 20 §2, the teacher's review of the rendered pages).

A guide named in words (``[names]``) reads in the reader's language and in the form its sentence needs
("∥ направляющей ползуна", "по направлението на пръта"), never in quotes, never in a subscript: a slider's
relative travel and velocity are written with the two coincident points (s_F3F4), and a plate's title is
the course's short wording.  Expected words are typed here, as a teacher writes them.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

import plans
from plans.errors import PlansError
from plans.i18n import LANGUAGES
from plans.positions import run_positions
from plans.pages.words import assembly_lines, namer, scene_data_lines
from plans.scene import example_names, example_path, loads

EXAMPLES = example_names() + example_names(loads=True)


def _scene(name):
    return plans.load(example_path(name))


def _equation_markup(scene, lang):
    """The vector equations of the velocity and acceleration plans as a page sets them (Typst markup)."""
    from plans.pages.document import Document

    g = run_positions(scene, 1).runs[0].graphical
    doc = Document(scene, lang)
    name = namer(scene, lang, "parallel")
    doc.equations("v", g.velocity_plan.steps, name)
    doc.equations("a", g.acceleration_plan.steps, name)
    return "\n".join(doc.body)


# --- the slider-crank's guide (finding 1) ----------------------------------------------------------------------


def test_a_russian_equation_says_parallel_to_the_sliders_guide_in_the_dative():
    text = _equation_markup(_scene("slider-crank"), "ru")
    assert text.count('"направляющей ползуна"') == 2  # v_BB1 ∥ …, a^r_BB1 ∥ …
    assert "цилиндр" not in text and "cylinder" not in text


def test_the_serbian_slider_crank_and_quick_return_name_the_sliders_guide_alike():
    sc, qr = _scene("slider-crank"), _scene("quick-return")
    assert sc.name_in("cylinder", "sr") == qr.name_in("ram", "sr") == "вођица клизача"
    text = _equation_markup(sc, "sr")
    assert text.count('"вођица клизача"') == 2 and "цилиндар" not in text


def test_the_slider_cranks_given_data_name_the_guide_and_its_angle_in_words():
    lines = scene_data_lines(_scene("slider-crank-loads"), "ru")
    assert "направляющая ползуна под углом 0°, e = 20 mm от O" in lines[2]
    assert "цилиндр" not in " ".join(lines) and "∠" not in lines[2]


# --- the linear-arm's sleeve and rod (finding 2) -------------------------------------------------------------


def test_the_bulgarian_assembly_line_names_the_guides_without_quotes_in_their_form():
    scene = _scene("linear-arm")
    r = run_positions(scene, 1).runs[0]
    lines = assembly_lines(r.analytic.branches, scene, "bg", r.graphical.positions)
    assert lines == ["група 3–4: посока на втулката: F → K → G", "група 5–6: плъзгач H пред Q по направлението на пръта"]


def test_the_bulgarian_equations_say_parallel_to_the_axis_of_the_sleeve_and_of_the_rod():
    text = _equation_markup(_scene("linear-arm"), "bg")
    assert text.count('"оста на втулката"') == 2 and text.count('"оста на пръта"') == 2
    assert "„" not in text and '"втулка"' not in text and '"прът"' not in text


def test_a_guide_welded_at_an_angle_is_said_in_words_not_with_an_angle_sign_before_a_name():
    lines = scene_data_lines(_scene("linear-arm"), "bg")
    assert "4: DK = 100, втулка под ъгъл 60°" in lines[1]
    assert "стойка под ъгъл 0°" in lines[2]  # the linear driver's guide is the frame, "стойка" (an earlier review)
    assert not re.search(r"∠\w", " ".join(lines))


def test_a_sliders_relative_motion_is_subscripted_with_the_two_coincident_points():
    scene = _scene("linear-arm")
    # rod 3 slides in sleeve 4 through F: the rod's point F3 relative to the sleeve's F4, the sense of s
    assert scene.pair_label("sleeve") == "F3F4"
    assert scene.pair_label("H") == "H"  # a block's pair goes by its pin, as before
    assert _scene("scotch-yoke").pair_label("yoke") == "Y4Y1"  # the yoke 4 on the frame's rail (frame 1)


def test_the_loop_equations_write_the_sleeves_travel_with_points_not_a_word():
    from plans.loops import loop_equations

    scene = _scene("linear-arm")
    lines = [line for block in loop_equations(plans.solve(scene, [0.0])) for line in block.lines]
    text = " ".join(lines)
    assert r"s_{F3F4}" in text and r"\dot{s}_{F3F4}" in text and r"\ddot{s}_{F3F4}" in text
    assert "sleeve" not in text


@pytest.mark.parametrize("lang", ["bg", "en"])
def test_the_kinematic_diagrams_legend_writes_the_sleeves_travel_with_points(lang):
    from plans.drawing.diagrams import draw_cycle_diagrams

    scene = _scene("linear-arm")
    run = plans.solve(scene, np.linspace(*scene.driver.stroke, 5), allow_partial=True)
    texts = []
    for _, fig in draw_cycle_diagrams(run, lang=lang):
        texts += [t.get_text() for t in fig.findobj(lambda a: hasattr(a, "get_text"))]
    joined = " ".join(texts)
    assert "F3F4" in joined
    assert not re.search(r"_\{?(?:\\mathrm\{)?(?:втулка|sleeve)", joined)  # no word in a subscript


# --- every bundled example's names and titles ----------------------------------------------------------------


@pytest.mark.parametrize("example", EXAMPLES)
def test_every_bundled_name_is_given_in_every_language_and_in_the_readers_script(example):
    scene = _scene(example)
    for key in scene.names:
        for lang in LANGUAGES:
            for form in ("name", "parallel", "of"):
                word = scene.name_in(key, lang, form)
                assert word != key or lang == "en", (example, key, lang, form)
                if lang in ("sr", "ru", "bg"):
                    assert re.fullmatch(r"[\u0400-\u04ff ]+", word), (example, key, lang, form, word)
                elif lang == "sl":
                    assert not re.search(r"[\u0400-\u04ff]", word), (example, key, lang, form, word)


RUSSIAN_PARALLEL = {"slider-crank": {"cylinder": "направляющей ползуна"}, "quick-return": {"ram": "направляющей ползуна", "slot": "кулисе"},
                    "linear-arm": {"rod": "оси стержня", "sleeve": "оси втулки"}, "ladder": {"wall": "стене", "floor": "полу"}}


@pytest.mark.parametrize("example", sorted(RUSSIAN_PARALLEL))
def test_a_russian_name_after_the_parallel_sign_is_in_the_dative(example):
    scene = _scene(example)
    for key, word in RUSSIAN_PARALLEL[example].items():
        assert scene.name_in(key, "ru", "parallel") == word


@pytest.mark.parametrize("example", EXAMPLES)
def test_a_plates_title_is_short(example):
    scene = _scene(example)
    for lang in ("sr", "ru", "bg", "sl"):
        title = scene.title_in(lang)
        assert len(title) <= 90, (example, lang, title)


def test_the_linear_arms_title_is_the_courses_wording():
    scene = _scene("linear-arm")
    assert scene.title_in("bg") == "Шестзвенен кулисен механизъм с постъпателно водещо звено"
    assert scene.title_in("ru") == "Шестизвенный кулисный механизм с поступательным ведущим звеном"
    for lang in ("sr", "ru", "bg", "sl"):
        assert not re.search(r"завар|приварен|privarjen|заварен", scene.title_in(lang))


# --- the scene's forms of a name ------------------------------------------------------------------------------

BASE = '''
title = "t"
[names]
slot = {{ en = "slot", ru = {ru} }}
[frame]
points = {{ O = [0, 0] }}
lines = {{ slot = {{ through = [0, 0.05], angle = 0 }} }}
[link.2]
points = {{ O = [0, 0], A = [0.1, 0] }}
[link.3]
points = {{ A = [0, 0], B = [0.25, 0] }}
[[slider]]
pin = "B"
on = "frame.slot"
[driver]
crank = "2"
angle = "45 deg"
omega = "10 rad/s"
[assembly]
B = [0.32, 0.05]
'''


def test_a_name_gives_its_forms_each_defaulting_to_the_name():
    scene = loads(BASE.format(ru='{ name = "кулиса", parallel = "кулисе" }'))
    assert scene.name_in("slot", "ru") == "кулиса"
    assert scene.name_in("slot", "ru", "parallel") == "кулисе"
    assert scene.name_in("slot", "ru", "of") == "кулиса"  # not given: the name itself
    assert scene.name_in("slot", "bg", "parallel") == "slot"  # no Bulgarian: as written


@pytest.mark.parametrize("ru, words", [
    ('{ name = "кулиса", dative = "кулисе" }', ["names.slot.ru.dative", "unknown form 'dative'", "name, parallel, of"]),
    ('{ parallel = "кулисе" }', ["names.slot.ru", "name ="]),
    ('{ name = "" }', ["names.slot.ru.name", "expected text"]),
])
def test_a_wrong_form_is_refused_naming_the_key(ru, words):
    with pytest.raises(PlansError) as err:
        loads(BASE.format(ru=ru))
    for word in words:
        assert word in str(err.value)


def test_a_slider_blocks_own_line_is_said_by_the_guide_it_slides_in():
    """The scotch yoke's block 3 carries an implicit line "guide" (a [[slider]]'s block): its relative velocity was
    written "v_A4A ∥ guide", English on a Serbian page.  It is said by the slot it slides in, in the scene's words."""
    import io

    from pypdf import PdfReader

    from review_handouts import built_pdf

    text = " ".join(page.extract_text() for page in PdfReader(io.BytesIO(built_pdf("scotch-yoke", None, "sr"))).pages)
    assert not re.search(r"\bguide\b", text)
    assert len(re.findall(r"∥ кулиса", text)) >= 2  # the velocity and the acceleration equations of the group
