"""Issue 20: the A3 sheet keeps a plan's enlarged detail (six-bar: the a–b–c cluster of the velocity plan, whose
ab = 7.5·450/600 mm at k_v = 0.02 cannot be measured on the plan itself) instead of redrawing the plan without it.

Expected values from the scene file's numbers: v_A = |ω₂|·OA = 10 · 0.15 = 1.5 m/s; AB/AC = 450/600.
"""

from __future__ import annotations

import re

import pytest

from test_tables_readings import sheet_lines
from review_handouts import drawn_sheet


@pytest.fixture(scope="module")
def six_bar_lines():
    return sheet_lines(drawn_sheet("six-bar", output="sheet.pdf"))


def test_the_velocity_plans_detail_is_on_the_sheet(six_bar_lines):
    captions = [line for line in six_bar_lines if re.fullmatch(r"Detail [IVX]+ \(\d+ : 1\)", line)]
    assert captions, "no enlarged detail (its caption 'Detail I (n : 1)') on the six-bar sheet"
    ratio = int(re.search(r"\((\d+) : 1\)", captions[0]).group(1))
    k_v = float(re.search(r"\bkv = ([\d.]+) \(m/s\)/mm", " ".join(six_bar_lines)).group(1))
    # ab on the plan is |v_BA| / k_v with |v_BA| = ω₃·AB; the sheet's printed ω₃ = 0.25 rad/s gives 0.1125 m/s
    ab_mm = 0.25 * 0.45 / k_v
    assert ab_mm * ratio >= 10.0  # measurable on the detail (under 5 mm on the plan)


def test_the_plan_still_reaches_its_least_size(six_bar_lines):
    # the plan made a round factor coarser for its detail, not shrunk to a third: |pa| = v_A / k_v ≥ 60 mm
    k_v = float(re.search(r"\bkv = ([\d.]+) \(m/s\)/mm", " ".join(six_bar_lines)).group(1))
    assert 1.5 / k_v >= 60.0 - 1e-9
