"""Issue 20 §3: plans drawn by the convention, every time.

* absolute vectors run from the pole, heavy; a relative vector that is the same vector as an
  absolute one (its reference point at rest: quick-return v_A4C with c at the pole, linear-arm
  v_HQ) is drawn once, as the absolute vector, and the readings name it both ways;
* every image on a plan has its absolute vector (quick-return a_A4, six-bar a_E5), drawn and read;
* two vectors from the pole that lie nearly one along the other (six-bar πm′ on πa′) are both
  told apart by a note that gives both directions;
* a user's point names are lettered as written (O2 → o2, not o₂), and no two things on a plan
  share a label (the pole p and the image of a point named P).

Expected values come from the plan data the construction produced (images, vectors), read
independently of the drawing code, and from the analytic solution.
"""

from __future__ import annotations

import cmath
import math
import re

import pytest
from matplotlib.colors import to_rgb
from matplotlib.text import Text

from plans.drawing import draw_plan
from plans.drawing.readings import plan_readings
from plans.drawing.style import VECTOR_STYLE
from plans.graphical import construct
from plans.scene import example_path, load, loads


@pytest.fixture(scope="module")
def solutions():
    return {name: construct(load(example_path(name))) for name in ("quick-return", "six-bar", "linear-arm")}


def _plans(solution):
    yield solution.velocity_plan
    if solution.acceleration_plan is not None:
        yield solution.acceleration_plan


def _shafts(artists, prefix: str) -> dict[str, tuple[complex, complex]]:
    """gid -> (first, last point) of every vector shaft drawn (heads, rims and ticks left out)."""
    out = {}
    for a in artists:
        gid = a.get_gid() or ""
        if gid.startswith(prefix) and not gid.endswith(("-head", "-rim", "-tick")) and hasattr(a, "get_xdata"):
            xs, ys = a.get_xdata(), a.get_ydata()
            out[gid] = (complex(xs[0], ys[0]), complex(xs[-1], ys[-1]))
    return out


@pytest.mark.parametrize("name", ["quick-return", "six-bar", "linear-arm"])
def test_every_image_has_its_absolute_vector_from_the_pole(solutions, name):
    """Every image off the pole is the tip of a heavy black vector from the pole (a₄′, e₅′ were not)."""
    for plan in _plans(solutions[name]):
        tag = "vel" if plan.kind == "velocity" else "acc"
        artists = draw_plan(plan)
        shafts = _shafts(artists, f"{tag}-absolute-")
        heads = {a.get_gid(): a for a in artists if (a.get_gid() or "").startswith(f"{tag}-absolute-") and (a.get_gid() or "").endswith("-head")}
        for image, z in plan.images.items():
            if abs(z) < 1e-3:
                continue
            tips = [gid for gid, head in heads.items() if abs(complex(*head.get_xy()[0]) - z) < 1e-3]
            assert tips, (name, plan.kind, image)
            shaft = shafts[tips[0].removesuffix("-head")]
            assert abs(shaft[0]) < 1e-3  # from the pole
            assert to_rgb(heads[tips[0]].get_facecolor()) == to_rgb(VECTOR_STYLE["absolute"][0])


def test_the_issue_s_missing_absolute_accelerations_are_drawn(solutions):
    qr = draw_plan(solutions["quick-return"].acceleration_plan)
    sb = draw_plan(solutions["six-bar"].acceleration_plan)
    assert "acc-absolute-a_A4" in _shafts(qr, "acc-absolute-")
    assert "acc-absolute-a_E5" in _shafts(sb, "acc-absolute-")


@pytest.mark.parametrize("name", ["quick-return", "six-bar", "linear-arm"])
def test_no_relative_vector_is_drawn_where_an_absolute_one_is(solutions, name):
    """Relative vectors only between images: none drawn (blue, or under another name) over an absolute one."""
    for plan in _plans(solutions[name]):
        tag = "vel" if plan.kind == "velocity" else "acc"
        artists = draw_plan(plan)
        absolute = list(_shafts(artists, f"{tag}-absolute-").values())
        for gid, (a, b) in _shafts(artists, f"{tag}-").items():
            if "-absolute-" in gid or "-construction-" in gid or "-figure-" in gid or "legend" in gid:
                continue
            same = [w for w in absolute if abs(w[0] - a) < 1e-3 and abs(w[1] - b) < 0.6]
            assert not same, (name, gid)


def test_quick_return_v_a4c_is_the_black_v_a4_named_both_ways(solutions):
    plan = solutions["quick-return"].velocity_plan
    artists = draw_plan(plan)
    gids = {a.get_gid() for a in artists}
    assert "vel-absolute-v_A4" in gids
    assert not any(g and g.startswith("vel-relative-v_A4C") for g in gids)
    rows = plan_readings(solutions["quick-return"], "velocity")
    symbols = [r[0] for r in rows]
    assert "$v_{A4} = v_{A4C}$" in symbols
    assert not any(s == "$v_{A4C}$" for s in symbols)


def test_linear_arm_v_h_is_named_v_hq_too(solutions):
    rows = plan_readings(solutions["linear-arm"], "velocity")
    row = next(r for r in rows if r[0].startswith("$v_{H}"))
    assert row[0] == "$v_{H} = v_{HQ}$"
    assert row[1] == "ph"


@pytest.mark.parametrize("name,point", [("quick-return", "A4"), ("six-bar", "E5")])
def test_the_points_of_links_are_read_in_the_acceleration_table(solutions, name, point):
    """a_A4 and a_E5 are tabulated, with the value a = a_O + (iε − ω²)(P − O) of the link's rigid motion."""
    import plans

    solution = solutions[name]
    rows = plan_readings(solution, "acceleration")
    row = next(r for r in rows if r[0].startswith(f"$a_{{{point}}}"))
    analytic = plans.solve(load(example_path(name)))
    letters, link = point[:-1], point[-1]
    body = analytic.scene.bodies[link]
    other = next(p for p in body.points if p != letters and p in analytic.points)
    o, p = analytic.points[other], analytic.points[letters]
    expected = complex(o.a[0]) + (1j * analytic.links[link].epsilon[0] - analytic.links[link].omega[0] ** 2) * (p.r[0] - o.r[0])
    value = float(row[4].split()[0])
    assert value == pytest.approx(abs(expected), rel=2e-3)


def test_six_bar_m_along_a_has_a_note_with_both_directions(solutions):
    plan = solutions["six-bar"].acceleration_plan
    artists = draw_plan(plan)
    a = next(v for v in plan.vectors if v.label == "a_A")
    m = next(v for v in plan.vectors if v.label == "a_M")
    notes = [t.get_text() for t in artists if isinstance(t, Text) and (t.get_gid() or "").startswith("acc-along-")]
    # each direction once, named as the plan's segment (issue 20 §3.1: "∠(πm′) = 235,6°")
    assert sorted(notes) == sorted(set(notes)) and len(notes) == 2, notes
    angles = [float(x) for x in re.findall(r"= ([0-9.]+)°", " ".join(notes))]
    expected = sorted(round(math.degrees(cmath.phase(v.tip)) % 360.0, 1) for v in (a, m))
    assert sorted(angles) == expected
    assert expected[0] != expected[1]
    assert {n.split(" =")[0] for n in notes} == {"∠(πm′)", "∠(πa′)"}


def test_collinear_images_of_one_link_get_no_note(solutions):
    """a₄ lies exactly on p d (link 4's images): the rim of its head shows it, no note is needed."""
    artists = draw_plan(solutions["quick-return"].velocity_plan)
    assert not [a for a in artists if (a.get_gid() or "").startswith("vel-along-")]


def _renamed_four_bar() -> str:
    text = example_path("four-bar").read_text()
    text = re.sub(r"\bO =", "O2 =", text)
    text = re.sub(r"\bD =", "O4 =", text)
    text = re.sub(r"\bB =", "C4 =", text)
    text = re.sub(r"\bM =", "P =", text)
    return text


def test_a_users_names_are_lettered_as_written_and_no_label_is_shared():
    solution = construct(loads(_renamed_four_bar()))
    for plan in _plans(solution):
        tag = "vel" if plan.kind == "velocity" else "acc"
        artists = draw_plan(plan)
        texts = {a.get_gid(): a.get_text() for a in artists if isinstance(a, Text) and (a.get_gid() or "").startswith(f"{tag}-image-")}
        prime = "′" if plan.kind == "acceleration" else ""
        c4 = next(t for g, t in texts.items() if g.startswith(f"{tag}-image-c4"))
        assert c4 == "c4" + prime  # not c₄, the point C of link 4
        assert "₄" not in "".join(texts.values()) and "₂" not in "".join(texts.values())
        pole = next(a.get_text() for a in artists if a.get_gid() == f"{tag}-pole-label")
        # every label on the plan names one thing: the pole, each image (those at the pole share its label)
        drawn = {a.get_gid(): a.get_text() for a in artists if isinstance(a, Text) and re.match(f"{tag}-(image|end|pole-label)", a.get_gid() or "")}
        assert len(set(drawn.values())) == len(drawn), drawn
        if plan.kind == "velocity":
            assert pole != "p" and texts[f"{tag}-image-p"] == "p"  # the image of P is p; the pole pᵥ


def test_four_bar_pm_and_pa_at_149_6_and_150_degrees_are_told_apart():
    """The issue's p m / p a (149.6° and 150°): the velocity plan's note gives both directions."""
    plan = construct(load(example_path("four-bar"))).velocity_plan
    artists = draw_plan(plan)
    notes = [t.get_text() for t in artists if isinstance(t, Text) and (t.get_gid() or "").startswith("vel-along-")]
    a = next(v for v in plan.vectors if v.label == "v_A")
    m = next(v for v in plan.vectors if v.label == "v_M")
    expected = {f"∠(p{x}) = {math.degrees(cmath.phase(v.tip)) % 360.0:.1f}°" for x, v in (("a", a), ("m", m))}
    assert expected <= set(notes), (notes, expected)
