"""Plans drawn as the textbook draws them, legible: link images, lettered
component ends, one arrow for identical vectors, slender heads, short vectors
as points, components beside the absolute vectors they lie on, and no label
over another label or an arrowhead (measured with matplotlib's renderer).

Expected geometry comes from the plan data (images, vectors) that the
construction produced and the tests read independently of the drawing code.
"""

from __future__ import annotations


import pytest
from matplotlib.colors import to_rgb
from matplotlib.patches import Polygon
from shapely.geometry import LineString, box

from plans.drawing import draw_mechanism, draw_plan
from plans.drawing._canvas import Obstacles
from plans.drawing.style import VECTOR_STYLE
from plans.graphical import construct
from plans.scene import example_names, example_path, load, loads

from plandraw_chain import chain_toml
from plandraw_overlaps import overlaps


@pytest.fixture(scope="module")
def solutions():
    return {name: construct(load(example_path(name))) for name in example_names()}


def _by_gid(artists, gid):
    return next(a for a in artists if a.get_gid() == gid)


def _drawings(solution):
    yield "mechanism", draw_mechanism(solution)
    yield "velocity", draw_plan(solution.velocity_plan)
    if solution.acceleration_plan is not None:
        yield "acceleration", draw_plan(solution.acceleration_plan)


@pytest.mark.parametrize("name", example_names())
def test_no_label_overlaps_a_label_or_an_arrowhead(solutions, name):
    for kind, artists in _drawings(solutions[name]):
        found = overlaps(artists[0].figure)
        assert found == [], (name, kind, found)


def test_a_long_chain_draws_with_no_overlapping_labels():
    solution = construct(loads(chain_toml(12)))
    for kind, artists in _drawings(solution):
        # every image of the chain is labelled
        if kind == "velocity":
            labelled = {a.get_gid() for a in artists if (a.get_gid() or "").startswith("vel-image-")}
            assert {f"vel-image-p{k}" for k in range(1, 13)} <= labelled
        assert overlaps(artists[0].figure) == [], kind


def test_obstacle_grid_finds_what_a_full_search_finds():
    import random

    rng = random.Random(7)
    shapes = Obstacles()
    for _ in range(300):
        x, y = rng.uniform(-80, 80), rng.uniform(-80, 80)
        if rng.random() < 0.5:
            shapes.append(box(x, y, x + rng.uniform(0, 30), y + rng.uniform(0, 5)))
        else:
            shapes.append(LineString([(x, y), (x + rng.uniform(-60, 60), y + rng.uniform(-60, 60))]))
    for _ in range(50):
        x, y, w, h = rng.uniform(-90, 90), rng.uniform(-90, 90), rng.uniform(0, 20), rng.uniform(0, 20)
        q = box(x, y, x + w, y + h)
        brute = [s for s in shapes if box(*s.bounds).intersects(q)]
        assert shapes.near(x, y, x + w, y + h) == brute


def test_identical_vectors_are_drawn_once_and_their_label_names_every_image(solutions):
    plan = solutions["wedge"].velocity_plan
    tips = [v for v in plan.vectors if v.kind == "absolute" and abs(v.tip - plan.images["w"]) < 1e-9]
    assert len(tips) >= 3  # v_W, v_T, v_U are one vector
    artists = draw_plan(plan)
    heads = [a for a in artists if isinstance(a, Polygon) and (a.get_gid() or "").endswith("-head") and "legend" not in a.get_gid()]
    at_w = [h for h in heads if abs(complex(*h.get_xy()[0]) - plan.images["w"]) < 1e-6 and "absolute" in h.get_gid()]
    assert len(at_w) == 1
    names = {a.get_text() for a in artists if (a.get_gid() or "").startswith("vel-image-")}
    assert {"w", "t", "u"} <= names


def test_images_of_links_are_drawn(solutions):
    # six-bar: b, e5 and m of link 5 lie on one segment, drawn through them
    plan = solutions["six-bar"].velocity_plan
    seg = _by_gid(draw_plan(plan), "vel-figure-5")
    xs, ys = seg.get_data()
    line = LineString(list(zip(xs, ys)))
    for name in ("b", "e5", "m"):
        z = plan.images[name]
        assert line.distance(LineString([(z.real, z.imag), (z.real, z.imag)]).centroid) < 1e-6, name
    # linear-arm: h₃′ sits on the image f′ g′ of link 3; f′ is the pole (a_F = 0), so that image lies along the drawn
    # absolute vector π g′ end to end and is not drawn again (round 28: a segment under a vector, named in the legend,
    # that nobody could see); its velocity image f h₃ g, along no vector, is drawn
    plan = solutions["linear-arm"].acceleration_plan
    f, g, h3 = plan.images["f′"], plan.images["g′"], plan.images["h3′"]
    assert abs(f) < 1e-9 and any(v.kind == "absolute" and abs(v.tip - g) < 1e-9 and abs(v.tail) < 1e-9 for v in plan.vectors)
    assert not [a for a in draw_plan(plan)[0].figure.findobj(lambda a: a.get_gid() == "acc-figure-3")]
    assert abs(((h3 - f) / (g - f)).imag) * abs(g - f) < 1e-6  # on the line f′ g′
    plan = solutions["linear-arm"].velocity_plan
    seg = _by_gid(draw_plan(plan), "vel-figure-3")
    ends = {complex(x, y) for x, y in zip(*seg.get_data())}
    assert any(abs(e - plan.images["f"]) < 1e-6 for e in ends) and any(abs(e - plan.images["g"]) < 1e-6 for e in ends)
    # four-bar: the triangle a′ b′ m′ is a filled figure with those corners
    plan = solutions["four-bar"].acceleration_plan
    tri = _by_gid(draw_plan(plan), "acc-figure-3")
    corners = [complex(*xy) for xy in tri.get_xy()]
    for name in ("a′", "b′", "m′"):
        assert min(abs(c - plan.images[name]) for c in corners) < 1e-9


def test_ends_of_normal_and_coriolis_components_are_lettered(solutions):
    plan = solutions["six-bar"].acceleration_plan
    artists = draw_plan(plan)
    text = {a.get_gid(): a.get_text() for a in artists if hasattr(a, "get_text") and a.get_gid()}
    assert text["acc-end-a_n_CD"] in {"n₁", "n₂", "n₃"}
    assert text["acc-end-a_k_E5E6"] == "k"
    letters = sorted(text[g] for g in text if g.startswith("acc-end-a_n"))
    assert letters == ["n₁", "n₂", "n₃"]
    # the letter sits near the component's end on the plan
    k = next(v for v in plan.vectors if v.label == "a^k_E5E6")
    label = _by_gid(artists, "acc-end-a_k_E5E6")
    assert abs(complex(*label.get_position()) - k.tip) < 20.0


def test_a_vector_too_short_for_an_arrow_is_a_point_with_a_note(solutions):
    plan = solutions["six-bar"].acceleration_plan
    short = next(v for v in plan.vectors if v.label == "a^n_CA")
    assert short.length < 1.0  # 0.19 mm in the committed drawing
    artists = draw_plan(plan)
    gids = {a.get_gid() for a in artists}
    assert "acc-normal-a_n_CA-head" not in gids
    note = _by_gid(artists, "acc-short-a_n_CA").get_text()
    assert f"{short.length:.2f} mm" in note


@pytest.mark.parametrize("name", example_names())
def test_arrowheads_are_slender_and_never_longer_than_a_third_of_their_vector(solutions, name):
    solution = solutions[name]
    for plan in (solution.velocity_plan, solution.acceleration_plan):
        if plan is None:
            continue
        artists = draw_plan(plan)
        lengths = {}
        for v in plan.vectors:
            lengths.setdefault(v.label.replace("^", "_"), v.length)
        for a in artists:
            gid = a.get_gid() or ""
            if not (isinstance(a, Polygon) and gid.endswith("-head")) or "legend" in gid:
                continue
            if "-detail-" in gid:
                continue  # drawn enlarged (test_scheme_plans checks the detail's heads)
            tip, p1, p2 = (complex(*xy) for xy in a.get_xy()[:3])
            length = abs(tip - (p1 + p2) / 2)
            width = abs(p1 - p2)
            label = gid.split("-", 2)[2][: -len("-head")]
            assert length <= lengths[label] / 3 + 1e-9, gid
            if lengths[label] >= 10.0:  # a head of full size: about 3:1
                assert length / width == pytest.approx(3.0, rel=0.05), gid


def test_a_component_along_an_absolute_vector_is_drawn_beside_it(solutions):
    plan = solutions["six-bar"].acceleration_plan
    a_b = next(v for v in plan.vectors if v.label == "a_B")
    n = next(v for v in plan.vectors if v.label == "a^n_E5B")
    u = (a_b.tip - a_b.tail) / abs(a_b.tip - a_b.tail)
    # the data lie on π b′: unseen if drawn there
    assert abs(((n.tip - a_b.tail) * u.conjugate()).imag) < 0.8
    shaft = _by_gid(draw_plan(plan), "acc-normal-a_n_E5B")
    xs, ys = shaft.get_data()
    for x, y in zip(xs, ys):
        off = abs(((complex(x, y) - a_b.tail) * u.conjugate()).imag)
        assert off >= 1.2 - 1e-9


def test_every_vector_kind_differs_in_greyscale_and_coriolis_is_dark():
    styles = {(lw, tuple(d) if d else None) for _, lw, d, _ in VECTOR_STYLE.values()}
    assert len(styles) == len(VECTOR_STYLE)
    r, g, b = to_rgb(VECTOR_STYLE["coriolis"][0])
    assert 0.299 * r + 0.587 * g + 0.114 * b < 0.45


def _anchor(plan, text_gid):
    """The plan point a label names, from its gid (image-b, end-a_n_CA, pole-label)."""
    prefix = "vel-" if plan.kind == "velocity" else "acc-"
    name = text_gid.split(":")[0][len(prefix):]
    if name.startswith("pole-label"):
        return 0j
    if name.startswith("image-"):
        image = name[len("image-"):]  # a gid drops the prime: a′ → a
        return plan.images.get(image, plan.images.get(image + "′"))
    if name.startswith("end-"):
        label = name[len("end-"):]
        return next(v.tip for v in plan.vectors if v.label.replace("^", "_") == label)
    return None


@pytest.mark.parametrize("name", example_names())
def test_no_label_lies_on_a_vector_or_link_image_it_does_not_belong_to(solutions, name):
    from plandraw_overlaps import SLIVER_MM2, label_boxes, shafts

    for plan in (solutions[name].velocity_plan, solutions[name].acceleration_plan):
        if plan is None:
            continue
        fig = draw_plan(plan)[0].figure
        prefix = "vel-" if plan.kind == "velocity" else "acc-"
        vectors = {v.label.replace("^", "_"): v for v in plan.vectors}
        bad = []
        for text_gid, label_box in label_boxes(fig):
            at = _anchor(plan, text_gid)
            if at is None:
                continue  # caption, legend
            for gid, outline in shafts(fig):
                if label_box.intersection(outline).area <= SLIVER_MM2:
                    continue
                rest = gid[len(prefix):]
                if rest.startswith("figure-"):
                    link = rest[len("figure-"):]
                    if any(abs(plan.images[i] - at) < 1e-6 for i in plan.links.get(link, ())):
                        continue
                else:
                    kind, _, label = rest.partition("-")
                    label = label.removesuffix("-tick")
                    v = vectors.get(label)
                    if v is not None and min(abs(v.tail - at), abs(v.tip - at)) < 1e-6:
                        continue
                bad.append(f"{text_gid} on {gid}")
        assert bad == [], (name, plan.kind, bad)
