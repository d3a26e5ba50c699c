"""The mechanism as a kinematic scheme: supports turned away from their links,
no ground hatched twice, no rod over a guide's hatching, the sleeve's support
visible, the driver's arcs no bigger than the crank, link numbers beside their
own link.  Expected geometry is the scene's, read here from the solution."""

from __future__ import annotations

import math

import pytest
from matplotlib.collections import LineCollection
from shapely.geometry import LineString, Point, Polygon

from plans.drawing import draw_mechanism
from plans.graphical import construct
from plans.scene import example_path, load


def _solve(name, degrees=None):
    scene = load(example_path(name))
    if degrees is not None:
        scene = scene.at(math.radians(degrees))
    return construct(scene)


def _gid(artists, gid):
    return next(a for a in artists if a.get_gid() == gid)


def _mm(solution, point):
    z = solution.positions[point] / solution.scales["k_l"]
    return complex(z)


def test_a_ground_support_turns_away_from_the_crank_it_carries():
    # six-bar at 325°: the crank points down-right, where a support drawn straight down would be
    solution = _solve("six-bar", 325)
    artists = draw_mechanism(solution)
    o, a = _mm(solution, "O"), _mm(solution, "A")
    support = Polygon(_gid(artists, "mech-ground-O").get_xy())
    crank = LineString([(o.real, o.imag), (a.real, a.imag)])
    # only the apex touches the crank (at the pivot)
    assert support.intersection(crank).length < 0.05
    # and the ω arc does not cross the support
    xs, ys = _gid(artists, "mech-omega").get_data()
    assert LineString(list(zip(xs, ys))).distance(support) > 0.0
    # nor does the support come near the coupler AB passing by
    b = _mm(solution, "B")
    assert support.distance(LineString([(a.real, a.imag), (b.real, b.imag)])) > 2.0


def test_a_pivot_on_a_hatched_guide_stands_on_it_without_a_second_hatching():
    solution = _solve("linear-arm")
    artists = draw_mechanism(solution)
    q = _mm(solution, "Q")
    triangle = [complex(*xy) for xy in _gid(artists, "mech-ground-Q").get_xy()]
    # the floor is y = 0 (frame line through O at angle 0): the triangle's base lies on it
    assert min(abs(z.imag) for z in triangle) < 1e-9
    # no hatch stroke starts within the support's width around Q except the floor's own
    hatches = [a for a in artists if isinstance(a, LineCollection) and (a.get_gid() or "").startswith("mech-hatch")]
    starts = [complex(*seg[0]) for h in hatches for seg in h.get_segments()]
    below_q = [z for z in starts if abs(z.real - q.real) < 4.0]
    assert all(abs(z.imag) < 1e-9 for z in below_q)  # every stroke there starts on the floor line


def test_a_rod_lying_along_a_guide_is_not_drawn_over_its_hatching():
    # quick-return: the ram's rod DE lies on the guide of slider E
    solution = _solve("quick-return")
    artists = draw_mechanism(solution)
    d, e = _mm(solution, "D"), _mm(solution, "E")
    guide = [a for a in artists if (a.get_gid() or "").startswith("mech-guide-")][0]
    xs, ys = guide.get_data()
    g = LineString(list(zip(xs, ys)))
    rod = LineString([(d.real, d.imag), (e.real, e.imag)])
    assert g.intersection(rod.buffer(0.5)).length < 0.5 * abs(e - d) * 0.1


def test_a_swinging_sleeve_shows_its_support_beyond_the_block():
    solution = _solve("six-bar")
    artists = draw_mechanism(solution)
    support = Polygon(_gid(artists, "mech-ground-E").get_xy())
    block = Polygon(_gid(artists, "mech-block-6").get_xy())
    assert support.difference(block).area > 0.5 * support.area


@pytest.mark.parametrize("name", ["rocker-limit", "slider-crank", "four-bar", "six-bar"])
def test_the_driver_arcs_are_no_bigger_than_the_crank(name):
    solution = _solve(name)
    artists = draw_mechanism(solution)
    driver = solution.scene.driver
    o = _mm(solution, driver.pivot)
    crank = max(abs(_mm(solution, p) - o) for p in solution.scene.bodies[driver.link].points)
    for gid in ("mech-omega", "mech-epsilon"):
        try:
            arc = _gid(artists, gid)
        except StopIteration:
            continue
        xs, ys = arc.get_data()
        assert max(abs(complex(x, y) - o) for x, y in zip(xs, ys)) <= crank + 1e-9, gid


def test_a_block_number_is_nearer_its_own_block_than_the_block_beside_it():
    solution = _solve("wedge")
    artists = draw_mechanism(solution)
    for own, other in (("3", "4"), ("4", "3")):
        label = Point(*_gid(artists, f"mech-number-{own}").get_position())
        mine = Polygon(_gid(artists, f"mech-block-{own}").get_xy())
        theirs = Polygon(_gid(artists, f"mech-block-{other}").get_xy())
        assert label.distance(mine) < label.distance(theirs), own


def test_a_yoke_on_its_rail_is_drawn_with_a_slide_bearing_not_lying_on_hatching():
    solution = _solve("scotch-yoke")
    artists = draw_mechanism(solution)
    y, r = _mm(solution, "Y"), _mm(solution, "R")
    guides = [a for a in artists if (a.get_gid() or "").startswith("mech-guide-")]
    assert len(guides) == 2  # the two sides of the bearing
    offsets = []
    for g in guides:
        xs, ys = g.get_data()
        # parallel to the rail (y = 0 in the scene), beside the bar, within its length
        assert ys[0] == pytest.approx(ys[1])
        offsets.append(ys[0])
        assert min(y.real, r.real) <= min(xs) and max(xs) <= max(y.real, r.real)
    assert min(offsets) < 0 < max(offsets)
    assert all(abs(o) < 2.0 for o in offsets)


def test_a_slot_covers_the_travel_passed_in_and_the_block_fits_in_it():
    solution = _solve("quick-return")
    k_l = solution.scales["k_l"]
    plain = draw_mechanism(solution)
    slot = Polygon(_gid(plain, "mech-slot-4-slot").get_xy())
    block = Polygon(_gid(plain, "mech-block-3").get_xy())
    assert slot.buffer(1e-6).contains(block)
    # a travel of 0.15 … 0.45 m along the lever's slot (from C): the slot reaches both ends
    artists = draw_mechanism(solution, slots={"4.slot": (0.15, 0.45)})
    ring = [complex(*xy) for xy in _gid(artists, "mech-slot-4-slot").get_xy()]
    c, d = _mm(solution, "C"), _mm(solution, "D")
    u = (d - c) / abs(d - c)
    along = [((z - c) * u.conjugate()).real for z in ring]
    assert min(along) <= 0.15 / k_l and max(along) >= 0.45 / k_l


def test_a_swinging_sleeve_is_not_drawn_as_a_slot_and_a_slotted_link_shows_no_bar_inside_its_slot():
    six = draw_mechanism(_solve("six-bar"))
    assert not any((a.get_gid() or "").startswith("mech-slot-") for a in six)  # rod 5 slides through sleeve 6
    solution = _solve("quick-return")
    artists = draw_mechanism(solution)
    slot = Polygon(_gid(artists, "mech-slot-4-slot").get_xy())
    for bar in (a for a in artists if (a.get_gid() or "").startswith("mech-link-4")):
        xs, ys = bar.get_data()
        assert LineString(list(zip(xs, ys))).intersection(slot.buffer(-0.5)).length < 1e-6
    # the block's number sits beside it, not at the far end of the lever
    label = Point(*_gid(artists, "mech-number-3").get_position())
    assert label.distance(Polygon(_gid(artists, "mech-block-3").get_xy())) < 6.0


def test_a_block_on_a_wedge_sits_on_the_incline_and_the_follower_stands_on_it():
    solution = _solve("wedge")
    artists = draw_mechanism(solution)
    plate = Polygon([(z.real, z.imag) for z in (_mm(solution, p) for p in ("W", "T", "U"))])
    block3 = Polygon(_gid(artists, "mech-block-3").get_xy())
    block4 = Polygon(_gid(artists, "mech-block-4").get_xy())
    c = _mm(solution, "C")
    assert block3.intersection(plate).area < 1e-6  # on the incline, not across it
    assert block3.exterior.distance(Point(c.real, c.imag)) < 1e-6  # the pin on its sliding side
    assert block4.intersection(block3).area < 1e-6
    assert block4.centroid.y > block3.centroid.y  # the follower above, on its guide


def test_a_linear_driver_label_is_not_on_the_other_arrow():
    from plandraw_overlaps import SLIVER_MM2, label_boxes, measured

    fig = draw_mechanism(_solve("wedge"))[0].figure

    def arrows(renderer, k):
        ax = fig.axes[0]
        out = {}
        for line in ax.lines:
            if line.get_gid() in ("mech-velocity", "mech-acceleration"):
                xy = ax.transData.transform(list(zip(*line.get_data()))) * k
                out[line.get_gid()] = LineString(xy).buffer(line.get_linewidth() * 25.4 / 72 / 2)
        return out

    shafts = measured(fig, arrows)
    assert set(shafts) == {"mech-velocity", "mech-acceleration"}
    boxes = dict(label_boxes(fig))
    v_label = next(b for g, b in boxes.items() if g.startswith("mech-velocity-label"))
    a_label = next(b for g, b in boxes.items() if g.startswith("mech-acceleration-label"))
    assert v_label.intersection(shafts["mech-acceleration"]).area <= SLIVER_MM2
    assert a_label.intersection(shafts["mech-velocity"]).area <= SLIVER_MM2
