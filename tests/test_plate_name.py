"""The title block names what its page is: kinematic analysis on the kinematic pages, kinetostatic analysis on the
force pages (and back on the centres pages after them), in the reader's language."""

import subprocess

import pytest

from plans.handout import handout
from plans.scene import example_path, load

# the plate names as the courses write them (typed here, not read from plans.i18n)
KINEMATIC = {"en": "Kinematic analysis of the mechanism", "sr": "Кинематичка анализа механизма"}
KINETOSTATIC = {"en": "Kinetostatic analysis", "sr": "Кинетостатичка анализа"}


def _page_texts(pdf: bytes, tmp_path) -> list[str]:
    path = tmp_path / "h.pdf"
    path.write_bytes(pdf)
    out = subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True, check=True).stdout.decode()
    return out.split("\f")[:-1]


@pytest.mark.parametrize("lang", ["en", "sr"])
def test_title_block_names_the_section(lang, tmp_path):
    pages = _page_texts(handout(load(example_path("slider-crank-loads")), forces=True, centres=True, lang=lang).pdf(), tmp_path)
    kinds = []
    for text in pages:
        foot = "\n".join(text.rstrip().splitlines()[-8:])  # the title block
        kinds.append("forces" if KINETOSTATIC[lang] in foot else "kinematics" if KINEMATIC[lang] in foot else "?")
    assert "?" not in kinds, kinds
    assert kinds[0] == "kinematics" and "forces" in kinds, kinds
    first, last = kinds.index("forces"), len(kinds) - 1 - kinds[::-1].index("forces")
    assert set(kinds[first:last + 1]) == {"forces"}, kinds  # one run of force pages
    assert kinds[-1] == "kinematics", kinds  # the centres pages after them are kinematics again
