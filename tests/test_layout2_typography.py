"""Typography of the drawings' captions and the page equations (issue 11 §5): scale factors typeset
(k with a subscript, no literal underscore), the language's decimal comma, true minus signs, and guides
named as the scene names them (no "frame." or "4." prefix) on sr/ru/bg pages."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import pytest

import plans
from plans.drawing.mechanism import draw_mechanism
from plans.drawing.plan_drawing import draw_plan
from plans.handout import write_handout
from plans.positions import position_text

SVG = "{http://www.w3.org/2000/svg}"


def _texts(path) -> list[str]:
    return ["".join(t.itertext()) for t in ET.parse(path).getroot().iter(f"{SVG}text")]


@pytest.mark.parametrize("example, lang", [("quick-return", "sr"), ("six-bar", "ru"), ("linear-arm", "bg")])
def test_pages_in_a_decimal_comma_language_print_no_underscore_no_hyphen_minus_and_no_internal_guide_names(example, lang, tmp_path):
    from pypdf import PdfReader

    paths = write_handout(plans.load(plans.example_path(example)), tmp_path / "h.pdf", lang=lang)
    joined = "\n".join(page.extract_text() for page in PdfReader(paths[0]).pages)
    assert "_" not in joined  # k_l, k_v, k_a typeset, never spelled with an underscore
    assert not re.search(r"-\s?\d", joined)  # a minus before a number is U+2212, not the hyphen-minus
    assert "frame." not in joined
    assert not re.search(r"(?<![\w.,])\d+\.[^\W\d]", joined)  # no "4.slot", "5.rod"
    assert "∥" in joined  # the equations with guides are there


@pytest.mark.parametrize("lang, mark", [("en", "."), ("sr", ","), ("sl", ",")])
def test_scale_captions_are_typeset_with_the_languages_decimal_mark(lang, mark):
    scene = plans.load(plans.example_path("six-bar"))
    g = plans.construct(scene)
    captions = {}
    for kind, artists in (("k_l", draw_mechanism(g, lang=lang)), ("k_v", draw_plan(g.velocity_plan, lang=lang)), ("k_a", draw_plan(g.acceleration_plan, lang=lang))):
        ax = artists[0].axes
        [text] = [t.get_text() for t in ax.texts if (t.get_gid() or "").endswith("scale")]
        captions[kind] = text
    for key, text in captions.items():
        symbol, sub = key.split("_")
        assert text.startswith(f"${symbol}_{{{sub}}}$ = "), text  # mathtext: k with a subscript
        value = g.scales[key]
        # the value as a textbook writes it in that language, written here by hand
        expected = repr(value) if value >= 1e-3 else None
        if expected is not None:
            assert f"= {expected.replace('.', mark)} " in text, (text, expected)
        assert ("." in text.split("=")[1]) == (mark == "."), text


def test_a_negative_slider_position_has_a_true_minus_sign():
    scene = plans.load(plans.example_path("linear-arm"))
    text = position_text(scene, -0.1)
    assert text == "s₂ = \u2212100.0 mm" and "-" not in text
