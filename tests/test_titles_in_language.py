"""Every page that names the scene names it in the reader's language (issue 20 §2): the scene's own title there.

Expected values: the bundled examples' titles as typed in their files (five languages each), read here with tomllib.
"""

from __future__ import annotations

import tomllib

import pytest

import plans
from plans.cli import main
from plans.scene import example_path


def _title(name: str, lang: str) -> str:
    return tomllib.loads(example_path(name).read_text(encoding="utf-8"))["title"][lang]


def test_the_kinematic_diagrams_from_sweep_plot_carry_the_serbian_title(tmp_path):
    assert main(["sweep", "--example", "slider-crank", "--steps", "24", "-o", str(tmp_path / "s.csv"), "--plot", str(tmp_path / "d"), "--lang", "sr"]) == 0
    text = (tmp_path / "d" / "kinematic.svg").read_text(encoding="utf-8")
    assert _title("slider-crank", "sr") in text and _title("slider-crank", "en") not in text


def test_the_centres_drawing_carries_the_bulgarian_title(tmp_path):
    assert main(["centres", "--example", "four-bar", "-o", str(tmp_path), "--lang", "bg"]) == 0
    text = (tmp_path / "centres.svg").read_text(encoding="utf-8")
    assert _title("four-bar", "bg") in text and _title("four-bar", "en") not in text


def test_the_forces_table_and_pages_carry_the_russian_title(capsys):
    assert main(["forces", "--example", "slider-crank-loads", "--lang", "ru", "--analytic-only"]) == 0
    out = capsys.readouterr().out
    scene = plans.load(example_path("slider-crank-loads"))
    assert scene.title_in("ru") != scene.title_in("en")
    assert out.splitlines()[0] == scene.title_in("ru")


def test_the_force_pages_of_a_russian_handout_carry_the_russian_title():
    import io

    import pypdf

    from plans.handout import handout

    scene = plans.load(example_path("slider-crank-loads"))
    pdf = handout(scene, positions=2, lang="ru", forces=True).pdf()
    pages = [page.extract_text() or "" for page in pypdf.PdfReader(io.BytesIO(pdf)).pages]
    assert all(scene.title_in("en") not in page for page in pages)
