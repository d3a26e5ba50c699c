"""Review findings 10–13 on the plans (review.md): a vector from the pole that lies along a
longer absolute vector is drawn on it with its head standing out (not hidden under the
shaft, not a doubled line beside it).  Expected geometry comes from the plan data."""

from __future__ import annotations

import pytest
from shapely.geometry import LineString, Polygon

from plans.drawing import draw_plan
from plans.drawing.style import MM_PER_PT, VECTOR_STYLE
from plans.graphical import construct
from plans.scene import example_path, load


@pytest.fixture(scope="module")
def six_bar():
    return construct(load(example_path("six-bar")))


@pytest.fixture(scope="module")
def quick_return():
    return construct(load(example_path("quick-return")))


def _by_gid(artists, gid):
    return next(a for a in artists if a.get_gid() == gid)


def _vector(plan, label):
    return next(v for v in plan.vectors if v.label == label)


def _off_line(z, tail, tip):
    u = (tip - tail) / abs(tip - tail)
    return abs(((z - tail) * u.conjugate()).imag)


def _head_stands_out(artists, head_gid, under_gid):
    """The head is drawn above the longer shaft, within a white rim that covers the head."""
    head = _by_gid(artists, head_gid)
    under = _by_gid(artists, under_gid)
    rims = [a for a in artists if a.get_gid() == head_gid.removesuffix("-head") + "-rim"]
    assert head.get_zorder() > under.get_zorder()
    assert rims, "no rim around the head"
    rim = rims[0]
    assert rim.get_zorder() > under.get_zorder() and rim.get_zorder() < head.get_zorder()
    assert rim.get_facecolor()[:3] == (1.0, 1.0, 1.0)
    assert Polygon(rim.get_xy()).buffer(1e-9).contains(Polygon(head.get_xy()[:3]))
    # the head is wider than the shaft it stands on
    tip, b1, b2 = (complex(*p) for p in head.get_xy()[:3])
    assert abs(b1 - b2) > under.get_linewidth() * MM_PER_PT * 1.5


def test_six_bar_m_on_the_line_of_a_shows_its_head(six_bar):
    # finding 10: m′ lies on π a′ (within the absolute shaft's neighbourhood) in the data
    plan = six_bar.acceleration_plan
    a, m = _vector(plan, "a_A"), _vector(plan, "a_M")
    assert _off_line(m.tip, a.tail, a.tip) < 1.0
    artists = draw_plan(plan)
    _head_stands_out(artists, "acc-absolute-a_M-head", "acc-absolute-a_A")


def test_quick_return_relative_along_pd_is_drawn_on_it_not_beside(quick_return):
    # finding 12: v_A4C = p→a₄ lies along p→d; it was drawn 1.2 mm beside (a doubled line)
    plan = quick_return.velocity_plan
    d, rel = _vector(plan, "v_D"), _vector(plan, "v_A4C")
    assert _off_line(rel.tip, d.tail, d.tip) < 0.1
    artists = draw_plan(plan)
    shaft = _by_gid(artists, "vel-relative-v_A4C")
    half = VECTOR_STYLE["absolute"][1] * MM_PER_PT / 2
    for x, y in zip(*shaft.get_data()):
        assert _off_line(complex(x, y), d.tail, d.tip) <= half  # under the thick shaft, not a line beside it
    assert not [a for a in artists if a.get_gid() == "vel-relative-v_A4C-tick"]
    _head_stands_out(artists, "vel-relative-v_A4C-head", "vel-absolute-v_D")


def test_linear_arm_short_normal_components_are_points_with_notes():
    # finding 13: aⁿ_F4D (2.6 mm) and aⁿ_HQ (2.3 mm) were drawn as arrows with heads under 1 mm
    # and no note, while the six-bar's 0.19 mm aⁿ_CA had one: the same rule applies to both
    plan = construct(load(example_path("linear-arm"))).acceleration_plan
    short = [v for v in plan.vectors if v.kind == "normal" and 0 < v.length < 3.0]
    assert {v.label for v in short} == {"a^n_F4D", "a^n_HQ"}
    artists = draw_plan(plan)
    gids = {a.get_gid() for a in artists}
    for v in short:
        gid = v.label.replace("^", "_")
        assert f"acc-normal-{gid}" not in gids and f"acc-normal-{gid}-head" not in gids
        note = _by_gid(artists, f"acc-short-{gid}").get_text()
        assert f"{v.length:.2f} mm" in note
        assert f"acc-end-{gid}" in gids  # its end is still lettered (n₁, n₂)
