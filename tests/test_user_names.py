"""Names from the scene are set as written, never read as math (issue 21).

A point, link or line name may hold ``_`` (``A_1_2``): in a math label it
must not become a (double) subscript, which matplotlib's parser refuses.
"""

import re

import pytest

from plans.cli import main
from plans._text import math_name

HOSTILE = """
title = "Six-bar, names with underscores"
[frame]
points = { O_1 = [0, 0], D_0 = ["-450 mm", "350 mm"], E_1_2 = ["-200 mm", "-150 mm"] }
[link.k_2]
points = { O_1 = [0, 0], A_1_2 = ["150 mm", 0] }
[link.c_3]
points = { A_1_2 = [0, 0], B_x = ["450 mm", 0], C_1_2 = ["600 mm", 0] }
[link.4]
points = { D_0 = [0, 0], C_1_2 = ["400 mm", 0] }
[link.r_5_1]
points = { B_x = [0, 0], M_1_2 = ["800 mm", 0] }
lines = { my_rod = { through = "B_x", angle = 0 } }
[[slider]]
pin = "E_1_2"
on = "r_5_1.my_rod"
name = "s_6_1"
[driver]
crank = "k_2"
angle = "55 deg"
omega = "-10 rad/s"
[assembly]
C_1_2 = [-0.3, 0.7]
"""


def _texts(svg: str) -> list[str]:
    return re.findall(r"<text[^>]*>([^<]*)</text>", svg)


@pytest.fixture
def scene(tmp_path):
    path = tmp_path / "hostile.toml"
    path.write_text(HOSTILE)
    return path


def test_math_name_escapes_what_math_would_read():
    assert math_name("CA") == "CA"
    assert math_name("A_1_2") == r"\text{A\_1\_2}"
    from matplotlib.mathtext import MathTextParser

    glyphs = MathTextParser("path").parse(rf"$v_{{\mathrm{{{math_name('A_1_2')}}}}}$").glyphs
    assert "".join(chr(g[2]) for g in glyphs) == "vA_1_2"


def test_draw_with_underscored_names(scene, tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["draw", str(scene), "-o", str(out)]) == 0
    mechanism = _texts((out / "mechanism.svg").read_text())
    for name in ("A_1_2", "C_1_2", "E_1_2", "M_1_2", "O_1", "D_0"):
        assert name in mechanism  # the point's label, as written
    # ω of link k_2: symbol, then the link's name as written as its subscript
    assert "k_2" in mechanism
    from sheet_pages import embedded_text

    sheet = embedded_text(out / "sheet.svg")  # the sheet's drawings: the points' labels as written
    assert "A_1_2" in sheet


def test_draw_positions_with_underscored_names(scene, tmp_path):
    out = tmp_path / "pos"
    assert main(["draw", str(scene), "--positions", "2", "-o", str(out)]) == 0
    assert (out / "sheet-01.svg").exists()
