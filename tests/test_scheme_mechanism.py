"""Review findings 14–16, 23–25 on the kinematic scheme (review.md).  Expected places come
from the pins drawn at the solved positions (gid ``mech-pin-X``) and the scene's data."""

from __future__ import annotations

import pytest
from shapely.geometry import LineString, Point, Polygon

from plans.drawing import draw_mechanism
from plans.graphical import construct
from plans.scene import example_path, load


def _draw(name):
    return draw_mechanism(construct(load(example_path(name))))


def _gid(artists, gid):
    return next(a for a in artists if a.get_gid() == gid)


def _pin(artists, name):
    return complex(*_gid(artists, f"mech-pin-{name}").center)


def _text_centre(artists, gid):
    t = _gid(artists, gid)
    return complex(*t.get_position())


def _segment(a, b):
    return LineString([(a.real, a.imag), (b.real, b.imag)])


def test_linear_arm_block_5_is_one_block_on_the_rod_and_link_6_reaches_pin_h():
    # finding 15: block 5 (on "3.rod") was drawn in a slot: a double rectangle, link 6 ending on its edge
    artists = _draw("linear-arm")
    gids = {a.get_gid() for a in artists}
    assert not any((g or "").startswith("mech-slot-") for g in gids)
    h = _pin(artists, "H")
    block = _gid(artists, "mech-block-5")
    assert Polygon(block.get_xy()).contains(Point(h.real, h.imag))
    reach = _gid(artists, "mech-link-6-to-pin")
    xs, ys = reach.get_data()
    ends = [complex(x, y) for x, y in zip(xs, ys)]
    assert min(abs(e - h) for e in ends) < 1e-6  # it ends at the pin
    assert reach.get_zorder() > block.get_zorder()  # drawn over the block
    q = _pin(artists, "Q")
    other = max(ends, key=lambda e: abs(e - h))
    assert abs(((other - h) / (q - h)).imag) < 1e-6 * abs(other - h)  # along link 6, towards Q


def test_linear_arm_number_3_stands_by_rod_fg_not_by_rocker_dk():
    solution = construct(load(example_path("linear-arm")))
    artists = draw_mechanism(solution)
    f, g, d, k = (complex(solution.positions[n] / solution.scales["k_l"]) for n in "FGDK")
    three = _text_centre(artists, "mech-number-3")
    p = Point(three.real, three.imag)
    to_rod = p.distance(_segment(f, g))
    assert to_rod < 4.0
    assert p.distance(_segment(d, k)) > 2 * to_rod
    # and not between the rocker's number and K
    four = _text_centre(artists, "mech-number-4")
    assert abs(three - four) > 8.0


def test_scotch_yoke_block_number_is_outside_the_yoke_with_a_leader():
    # finding 25: "3" stood inside the yoke (link 4), above the block
    artists = _draw("scotch-yoke")
    slot = Polygon(_gid(artists, "mech-slot-4-slot").get_xy())
    three = _gid(artists, "mech-number-3")
    c = complex(*three.get_position())
    assert not slot.contains(Point(c.real, c.imag))
    a = _pin(artists, "A")
    leaders = [x for x in artists if x.get_gid() == "mech-leader"]
    near = [ln for ln in leaders if min(abs(complex(x, y) - a) for x, y in zip(*ln.get_data())) < 1.0]
    assert near, "no leader from block 3 to its number"


def test_quick_return_ram_guide_is_a_guideway_over_the_rod_and_past_the_block():
    # finding 16: the ram guide was a short hatched stub to the right of E
    solution = construct(load(example_path("quick-return")))
    artists = draw_mechanism(solution)
    d, e = (complex(solution.positions[n] / solution.scales["k_l"]) for n in "DE")
    lines = [a for a in artists if (a.get_gid() or "").split("-")[:3] == ["mech", "guide", "ram"] and hasattr(a, "get_data")]
    assert len(lines) >= 2
    xs = [x for ln in lines for x in ln.get_data()[0]]
    assert min(xs) < min(d.real, e.real) - 2.0 and max(xs) > max(d.real, e.real) + 5.0
    rod = LineString([(d.real, d.imag), (e.real, e.imag)])
    ys = set()
    for ln in lines:
        pts = list(zip(*ln.get_data()))
        assert not LineString(pts).intersects(rod)  # the rod runs between the lines, on no hatching
        ys.add(round(pts[0][1] - e.imag, 6))
    assert any(y > 0 for y in ys) and any(y < 0 for y in ys)  # either side of the ram's line


def test_six_bar_sleeve_support_reaches_pin_e_over_the_block():
    # finding 24: the support triangle, drawn under block 6, seemed to lean on the block's edge
    solution = construct(load(example_path("six-bar")))
    artists = draw_mechanism(solution)
    e = complex(solution.positions["E"] / solution.scales["k_l"])
    block = _gid(artists, "mech-block-6")
    sides = _gid(artists, "mech-ground-E-sides")
    pts = [complex(x, y) for x, y in zip(*sides.get_data())]
    assert pts[1] == pytest.approx(e, abs=1e-6)  # the apex is the pin
    assert sides.get_zorder() > block.get_zorder()
    # both sides run from the pin out past the block to the support's base
    outline = Polygon(block.get_xy())
    for end in (pts[0], pts[2]):
        assert not outline.contains(Point(end.real, end.imag))


def test_ladder_guides_pass_through_their_pins():
    # finding 23 (checked: already so on this branch's base): floor through A, wall through B
    solution = construct(load(example_path("ladder")))
    artists = draw_mechanism(solution)
    a, b = (complex(solution.positions[n] / solution.scales["k_l"]) for n in "AB")
    floor = _gid(artists, "mech-guide-floor").get_data()
    wall = _gid(artists, "mech-guide-wall").get_data()
    assert all(abs(y - a.imag) < 1e-6 for y in floor[1])
    assert all(abs(x - b.real) < 1e-6 for x in wall[0])
    assert min(wall[1]) < b.imag < max(wall[1])


def test_wedge_follower_joins_block_3_at_pin_c_over_the_block():
    # finding 14: follower 4 joined block 3's top through a stub (its stem ran under block 3),
    # so pin C seemed to join block 3 to the incline (a sliding pair)
    solution = construct(load(example_path("wedge")))
    artists = draw_mechanism(solution)
    c = complex(solution.positions["C"] / solution.scales["k_l"])
    stem = _gid(artists, "mech-stem-4")
    ends = [complex(x, y) for x, y in zip(*stem.get_data())]
    assert min(abs(e - c) for e in ends) < 1e-6  # the stem reaches the pin
    assert stem.get_zorder() > _gid(artists, "mech-block-3").get_zorder()  # over block 3
    far = max(ends, key=lambda e: abs(e - c))
    block4 = Polygon(_gid(artists, "mech-block-4").get_xy())
    assert block4.exterior.distance(Point(far.real, far.imag)) < 1e-6  # up to block 4's edge


def test_quick_return_crank_reaches_its_pin_over_the_slotted_rocker():
    # the review of the Serbian quick-return sheet: crank 2 stopped at the edge of rocker 4's slot (its white fill over
    # the crank), pin A drawn apart from it inside block 3: the crank is drawn from O to A over the slot and the block
    artists = _draw("quick-return")
    o, a = _pin(artists, "O"), _pin(artists, "A")
    crank = _gid(artists, "mech-link-2-over-slot")
    xs, ys = crank.get_data()
    ends = {complex(x, y) for x, y in zip(xs, ys)}
    assert min(abs(e - a) for e in ends) < 1e-6 and min(abs(e - o) for e in ends) < 1e-6  # from O to A
    covers = [x for x in artists if (x.get_gid() or "").startswith(("mech-slot-", "mech-block-3"))]
    assert covers and all(crank.get_zorder() > x.get_zorder() for x in covers)
