"""Slots and guides drawn over the travel the cycle uses (issue 10 §4), measured from the SVG by gid.

Expected travels come from the examples' own geometry, worked here:

* quick-return: the block A rides the lever's slot at |CA| from C; A runs on
  a circle of radius r = 120 mm about O, |OC| = 250 mm, so |CA| runs over
  [|OC| − r, |OC| + r] = [130, 370] mm in a turn.
* quick-return ram: the lever swings between its tangents to the crank
  circle, α ∈ 90° ± asin(r/|OC|); D = 550 mm·(cos α, sin α) from C, and E
  on the ram line y = 520 mm with |DE| = 200 mm to the right of D, so
  E.x = D.x + √(0.2² − (0.52 − D.y)²), its range over that swing.
* scotch yoke: A = O + 100 mm·e^{iφ}; along the vertical slot through Y on
  the rail through O, A is at r·sin φ: [−100, 100] mm.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from plans.cli import main
from review_handouts import drawn_sheet

SVG = "{http://www.w3.org/2000/svg}"


def _groups(path, gid: str) -> list[list[complex]]:
    """The points of every path in the groups whose id is *gid* or *gid*-N (SVG user units, y down)."""
    out = []
    for g in ET.parse(path).iter(f"{SVG}g"):
        if re.fullmatch(re.escape(gid) + r"(-\d+)?", g.get("id") or ""):
            for p in g.iter(f"{SVG}path"):
                nums = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", p.get("d", ""))]
                out.append([complex(x, y) for x, y in zip(nums[0::2], nums[1::2])])
    return out


def _centre(path, gid: str) -> complex:
    pts = _groups(path, gid)[0]
    xs, ys = [z.real for z in pts], [z.imag for z in pts]
    return complex((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2)


def _span(points, origin: complex, u: complex, per_metre: float) -> tuple[float, float]:
    """Smallest and largest coordinate [m] of *points* along *u* from *origin*."""
    t = [((z - origin) * u.conjugate()).real / per_metre for z in points]
    return min(t), max(t)


def _quick_return_ram() -> tuple[float, float]:
    """E.x [m] over the lever's swing (see the module docstring)."""
    half = math.asin(0.12 / 0.25)
    alpha = np.linspace(math.pi / 2 - half, math.pi / 2 + half, 200001)
    dx, dy = 0.55 * np.cos(alpha), 0.55 * np.sin(alpha)
    ex = dx + np.sqrt(0.2**2 - (0.52 - dy) ** 2)
    return float(ex.min()), float(ex.max())


def _check_quick_return(svg, prefix: str = "mech", ram: bool = True) -> None:
    C, D = _centre(svg, f"{prefix}-pin-C"), _centre(svg, f"{prefix}-pin-D")
    per_metre = abs(D - C) / 0.55  # SVG units per metre of the mechanism
    u = (D - C) / abs(D - C)
    slot_lo, slot_hi = _span(_groups(svg, f"{prefix}-slot-4-slot")[0], C, u, per_metre)
    A = _centre(svg, f"{prefix}-pin-A")
    block_lo, block_hi = _span(_groups(svg, f"{prefix}-block-3")[0], A, u, per_metre)
    # the slot holds the block at both ends of its travel, and ends there (within 2 mm of paper)
    slack = 2.0 * 72 / 25.4 / per_metre
    assert 0.13 + block_lo - slack <= slot_lo <= 0.13 + block_lo + 1e-6
    assert 0.37 + block_hi - 1e-6 <= slot_hi <= 0.37 + block_hi + slack
    if not ram:
        return
    # the ram guideway covers the block E over the whole stroke
    e_lo, e_hi = _quick_return_ram()
    E = _centre(svg, f"{prefix}-pin-E")
    x = complex(1, 0)
    blk_lo, blk_hi = _span(_groups(svg, f"{prefix}-block-6")[0], E, x, per_metre)
    guide = [z for pts in _groups(svg, f"{prefix}-guide-ram") for z in pts]
    g_lo, g_hi = _span(guide, C, x, per_metre)  # C is at x = 0
    assert g_lo <= e_lo + blk_lo and g_hi >= e_hi + blk_hi
    assert g_lo >= e_lo + blk_lo - 0.2 and g_hi <= e_hi + blk_hi + 0.2  # and not much more (no other rider reaches past)


def test_the_ram_extremes_worked_here_are_the_lever_s_tangent_positions():
    # a check of the hand geometry itself: E at the lever's extremes is within the range found
    lo, hi = _quick_return_ram()
    assert -0.07 < lo < -0.06 and 0.45 < hi < 0.47


def test_plans_draw_draws_the_slot_and_the_ram_guide_over_the_cycle():
    _check_quick_return(drawn_sheet("quick-return") / "mechanism.svg")


def test_draw_positions_sheets_draw_the_slot_over_the_cycle(tmp_path):
    assert main(["draw", "--example", "quick-return", "--positions", "3", "-o", str(tmp_path)]) == 0
    from sheet_pages import unpack

    for name in ("sheet-00.svg", "sheet-01.svg", "sheet-02.svg"):
        _check_quick_return(unpack(tmp_path / name, "mechanism"))


def test_handout_drawings_draw_the_slot_over_the_cycle_and_the_plan_of_positions_the_ram_s_stroke(tmp_path):
    import plans
    from plans.handout import handout

    scene = plans.load(plans.example_path("quick-return"))
    positions = tmp_path / "positions.svg"  # the drawings as the handout places them (its SVG blocks)
    positions.write_bytes(handout(scene, positions=3).images["positions"])
    _check_quick_return(positions, prefix="positions")  # every position's block E on the guide
    mechanism = tmp_path / "mechanism.svg"
    mechanism.write_bytes(handout(scene).images["mechanism"])
    assert _groups(mechanism, "mech-slot-4-slot")
    # (one position's mechanism keeps the ram's guide around the block's present place: the velocity plan needs the room)
    _check_quick_return(mechanism, ram=False)


def test_the_scotch_yoke_slot_covers_the_crank_pin_over_a_turn():
    svg = drawn_sheet("scotch-yoke") / "mechanism.svg"
    O, A = _centre(svg, "mech-pin-O"), _centre(svg, "mech-pin-A")
    per_metre = abs(A - O) / 0.1
    u = complex(0, -1)  # up the page (SVG y runs down)
    Y = O + (A - O).real  # the slot runs through Y, on the rail through O, under A
    slot_lo, slot_hi = _span(_groups(svg, "mech-slot-4-slot")[0], Y, u, per_metre)
    block_lo, block_hi = _span(_groups(svg, "mech-block-3")[0], A, u, per_metre)
    slack = 2.0 * 72 / 25.4 / per_metre
    assert -0.1 + block_lo - slack <= slot_lo <= -0.1 + block_lo + 1e-6
    assert 0.1 + block_hi - 1e-6 <= slot_hi <= 0.1 + block_hi + slack


def test_line_travel_reads_the_slot_travel_of_the_sweep():
    import plans
    from plans.analytic import solve
    from plans.positions import cycle_positions
    from plans.sweep import line_travel

    scene = plans.load(plans.example_path("quick-return"))
    travel = line_travel(solve(scene, np.asarray(cycle_positions(scene, 720, start="scene")), allow_partial=True))
    assert travel["4.slot"] == pytest.approx((0.13, 0.37), abs=1e-9)  # A passes through both ends on the grid
    lo, hi = _quick_return_ram()
    assert travel["frame.ram"] == pytest.approx((lo, hi), abs=2e-4)  # within the grid's step


def test_a_travel_running_off_towards_infinity_is_cut_to_the_mechanism_s_reach():
    # near parallel guides a pin runs off far: the drawing follows it no further than the mechanism's size
    import time

    import plans
    from plans.drawing import draw_mechanism
    from plans.graphical import construct

    graphical = construct(plans.load(plans.example_path("quick-return")))
    start = time.process_time()
    artists = draw_mechanism(graphical, slots={"4.slot": (-1e9, 1e9), "frame.ram": (-1e12, 1e12)})
    assert time.process_time() - start < 20.0  # (a 1e12 m guide hatched every 2.2 mm would never end)
    fig = artists[0].figure
    width, height = fig.get_size_inches() * 25.4
    size = abs(complex(*np.ptp([[z.real, z.imag] for z in graphical.positions.values()], axis=0))) / graphical.scales["k_l"]
    assert max(width, height) < 5 * size  # the mechanism's points span `size` mm; slot and guide stay near them
