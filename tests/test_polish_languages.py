"""No English on an sr/ru/bg/sl page: the reason a position is not solved, and the branch words (issue 11 §5).

The solvers write their reasons in English (the CLI's stderr keeps them); a
page in another language says them in its words (:func:`plans.i18n.reason_text`),
names, numbers and positions kept.  The English words of each message are
read off the message itself, and none may be left on the page: plant one
in a template and these tests fail.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import plans
from plans.analytic import solve
from plans.cli import main
from plans.errors import AssemblyError, SingularPositionError
from plans.i18n import branch_text, reason_text
from plans.scene import example_path, loads

LANGS = ("sr", "ru", "bg", "sl")
SVG = "{http://www.w3.org/2000/svg}"


def english_words(message: str) -> set[str]:
    """The English words of a message: its words of three letters or more that are not names (``frame.cylinder``)."""
    names = {part for key in re.findall(r"\w+(?:\.\w+)+", message) for part in key.split(".")}
    return {w.lower() for w in re.findall(r"[A-Za-z]{3,}", message) if w not in names and not w.isupper()} - {"sin"}


def _error(scene, positions=None) -> str:
    with pytest.raises((AssemblyError, SingularPositionError)) as caught:
        solve(scene, positions)
    return str(caught.value)


FOUR_BAR = """
[frame]
points = {{ O = [0, 0], D = [{D}, 0] }}
[link.2]
points = {{ O = [0, 0], A = [0.1, 0] }}
[link.3]
points = {{ A = [0, 0], B = [0.3, 0] }}
[link.4]
points = {{ B = [0, 0], D = [0.35, 0] }}
[driver]
crank = "2"
angle = "{angle}"
omega = "1 rad/s"
[assembly]
B = [0.3, 0.3]
"""


def _messages() -> list[tuple[str, str]]:
    """(cause, message) of every form the analytic solver writes, from mechanisms that fail each way."""
    out = []
    out.append(("no_assembly", _error(loads(FOUR_BAR.format(D="0.8", angle="180 deg")))))  # |AD| > AB + BD
    out.append(("no_assembly", _error(loads(FOUR_BAR.format(D="0.1", angle="0 deg")))))  # |AD| < |AB − BD|
    out.append(("dead_centre", _error(loads(FOUR_BAR.format(D="0.55", angle="180 deg")))))  # A, B, D in line
    slider = example_path("slider-crank").read_text(encoding="utf-8").replace('through = [0, "50 mm"]', 'through = [0, "400 mm"]')
    out.append(("no_assembly", _error(loads(slider))))  # RRP out of reach
    wedge = example_path("wedge").read_text(encoding="utf-8").replace('angle = "90 deg"', 'angle = "30 deg"')
    out.append(("dead_centre", _error(loads(wedge))))  # PRP guides parallel
    rpr = loads(
        """
[frame]
points = { O = [0, 0], E = [0.05, 0.02] }
[link.2]
points = { O = [0, 0], A = [0.1, 0] }
[link.5]
points = { A = [0, 0] }
lines = { rod = { through = [0, 0.2], angle = 0 } }
[[slider]]
pin = "E"
on = "5.rod"
name = "6"
[driver]
crank = "2"
angle = "0 deg"
omega = "1 rad/s"
"""
    )
    out.append(("no_assembly", _error(rpr)))  # RPR offset line out of reach
    return out


MESSAGES = _messages()


def test_the_messages_are_the_solver_s_english_forms():
    # the cases above do give the forms they are meant to (else the other tests would prove nothing)
    text = " | ".join(m for _, m in MESSAGES)
    for form in ("> AB + BD", "< |AB − BD|", "dead centre at", "runs on (parallel to", "are parallel", "the offset"):
        assert form in text, form


@pytest.mark.parametrize("lang", LANGS)
def test_every_reason_is_said_in_the_page_s_language_with_its_numbers(lang):
    for cause, message in MESSAGES:
        said = reason_text(message, lang, cause)
        left = {w for w in english_words(message) if re.search(rf"\b{w}\b", said, re.IGNORECASE)}
        assert not left, (lang, message, said, left)
        # the names and numbers stay: every number of the message is on the page
        for number in re.findall(r"\d+(?:\.\d+)?", message):
            assert number in said, (lang, message, said, number)


@pytest.mark.parametrize("lang", LANGS)
def test_an_unknown_form_is_said_by_its_group_and_cause_never_in_english(lang):
    said = reason_text("RRR(3,4): something new went wrong at φ = 10.0°", lang, "no_assembly")
    assert said == "RRR(3,4): " + plans.i18n.term("no_assembly", lang)


def _page_texts(path) -> str:
    return " ".join(t.text or "" for t in ET.parse(path).iter(f"{SVG}text"))


@pytest.mark.parametrize("lang", ("sr", "bg"))
def test_the_rocker_limit_handout_says_why_in_its_language(tmp_path, lang):
    # positions of a turn (the input swings ±56.39°, so 90°, 180°, 270° cannot assemble; --positions 4 would space
    # them over its swing, every one solved: issue 19)
    from pypdf import PdfReader

    assert main(["handout", "--example", "rocker-limit", "--at", "0,90,180,270 deg", "--lang", lang, "-o", str(tmp_path / "rl.pdf"), "--quiet"]) == 0
    scene = plans.load(example_path("rocker-limit"))
    english = set()
    for phi in np.radians([90.0, 180.0, 270.0]):
        english |= english_words(_error(scene, [phi]))
    assert {"joint", "cannot", "assemble", "gap"} <= english
    text = " ".join(" ".join(page.extract_text() for page in PdfReader(tmp_path / "rl.pdf").pages).split())
    left = {w for w in english if re.search(rf"\b{w}\b", text, re.IGNORECASE)}
    assert not left, left
    # where each unsolved position's plan would be: why, in the reader's words, with the numbers
    assert len(re.findall(r"\|AD\| = 0,\d+ [mм] > AB \+ BD = 0,650 [mм]", text)) == 3, text  # (metres as the course writes them)


@pytest.mark.parametrize("example", ["six-bar", "quick-return", "linear-arm", "slider-crank"])
@pytest.mark.parametrize("lang", LANGS)
def test_branch_words_are_translated(example, lang):
    from plans.drawing.sheet import branch_lines

    analytic = solve(plans.load(example_path(example)))
    english = [b for b in analytic.branches if b.sign]
    assert english
    lines = branch_lines(analytic.branches, lang)
    assert len(lines) == len(english)
    for b, line in zip(english, lines):
        words = english_words(b.words)
        left = {w for w in words if re.search(rf"\b{w}\b", line, re.IGNORECASE)}
        assert not left, (lang, b.words, line)
        assert branch_text(b.words, lang) is not None and len(line) > len(f"{b.group}: (+1)") + 3, line


def test_the_sheet_says_the_assembly_in_words(tmp_path):
    from sheet_pages import text as pdf_text

    assert main(["draw", "--example", "six-bar", "--lang", "ru", "-o", str(tmp_path / "page.pdf")]) == 0
    text = " ".join(pdf_text((tmp_path / "page.pdf").read_bytes()).split())
    assert "справа от" in text or "слева от" in text, text
    assert not re.search(r"\b(left|right|pointing|towards)\b", text), text
