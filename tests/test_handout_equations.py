"""The handout's vector equations as the course writes them (issue 20, flow2 item 2): every image on a plan has its
step (those placed by similarity their proportion), the heading in plain English, a word's space after a comma
between conditions in every language.

Expected values are worked by hand from the six-bar's scene (B on link 3 between A and C: b on ac; M on link 5 with
B and E: m from b and e₅) and from the typographic rule (a word space, about a quarter em, after a comma), read off
the typeset PDF by poppler's ``pdftotext``.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import tempfile
import unicodedata
from pathlib import Path

import pytest

import plans
from plans.pages.document import Document
from plans.pages.typesetting import compile_document
from review_handouts import built_pdf

pytestmark = [pytest.mark.filterwarnings("ignore"),
              pytest.mark.skipif(shutil.which("pdftotext") is None, reason="poppler's pdftotext reads the pages")]


def _pdftotext(pdf: bytes, *args: str) -> str:
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "h.pdf"
        path.write_bytes(pdf)
        return subprocess.run(["pdftotext", *args, str(path), "-"], capture_output=True, text=True, check=True).stdout


@pytest.fixture(scope="module")
def six_bar_en():
    return unicodedata.normalize("NFKC", _pdftotext(built_pdf("six-bar", None, "en")))


def test_every_image_of_the_six_bar_plans_has_its_step(six_bar_en):
    """b lies on ac (AB / AC), m is found from b and e₅ (BM / BE): each a similarity row in the velocity and in the
    acceleration equations (the velocity equations had no step for m)."""
    lines = [line.strip() for line in six_bar_en.splitlines()]
    rows = [line for line in lines if line.startswith("by similarity")]
    assert "by similarity ab / ac = AB / AC" in rows, rows
    assert "by similarity bm / b e5 = BM / BE" in rows, rows
    assert "by similarity a′ b′ / a′ c′ = AB / AC" in rows, rows
    assert "by similarity b′ m′ / b′ e5′ = BM / BE" in rows, rows
    # m's row after group 5–6's equations (it needs e₅), b's before them (group 5–6 uses v_B)
    velocity = lines[lines.index("Vector equations: velocity plan"):]
    assert velocity.index("by similarity ab / ac = AB / AC") < velocity.index("group 5–6") < velocity.index("by similarity bm / b e5 = BM / BE")


def test_the_equations_heading_is_plain_english(six_bar_en):
    assert "Vector equations: velocity plan" in six_bar_en
    assert "Vector equations: acceleration plan" in six_bar_en
    assert "of the plans" not in six_bar_en


@pytest.mark.parametrize("lang", ["en", "sr", "ru", "bg", "sl"])
def test_a_word_space_after_a_comma_between_conditions(lang):
    """``a^n_BA ∥ BA, a^t_BA ⊥ AB``: after the comma a gap of at least a word space (≥ 2.2 pt at 9.5 pt: about a
    quarter em) before the next condition, measured between the word boxes of the typeset PDF (it was 1.6 pt: the
    comma set against the next vector)."""
    from plans.positions import run_positions

    scene = plans.load(plans.example_path("four-bar"))
    steps = run_positions(scene, None).runs[0].graphical.acceleration_plan.steps
    doc = Document(scene, lang)
    doc.plate = {"k_l": 0.002}
    doc.equations("x", steps, lambda w: w)
    out = _pdftotext(compile_document(doc.source(), doc.images, "pdf"), "-bbox")
    words = re.findall(r'<word xMin="([0-9.]+)" yMin="[0-9.]+" xMax="([0-9.]+)" yMax="[0-9.]+">([^<]*)</word>', out)
    at = [k for k, (_, _, w) in enumerate(words) if unicodedata.normalize("NFKC", w) == "BA,"]
    assert at, [w for _, _, w in words]
    gap = float(words[at[0] + 1][0]) - float(words[at[0]][1])
    assert gap >= 2.2, gap


def test_the_images_by_similarity_are_written_with_their_numbers(six_bar_en):
    """Under the plans' readings: ``bm / b e₅ = BM / BE:  bm = be₅ · BM / BE = … mm`` with the scene's BM = 800 mm and
    AB = 450, AC = 600 mm (the six-bar's data), the product worked out (to the 0.1 mm written)."""
    text = " ".join(six_bar_en.split())
    for seg, given, whole in (("bm", 800.0, None), ("ab", 450.0, 600.0), ("b′ m′", 800.0, None), ("a′ b′", 450.0, 600.0)):
        m = re.search(re.escape(seg) + r" = ([0-9.]+) · ([0-9.]+) / ([0-9.]+) = ([0-9.]+) mm", text)
        assert m, seg
        on_plan, real, base, result = map(float, m.groups())
        assert real == given and (whole is None or base == whole), m.group(0)
        assert abs(on_plan * real / base - result) <= 0.06, m.group(0)
