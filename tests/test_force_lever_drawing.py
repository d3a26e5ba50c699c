"""The lever drawing read as a teacher reads it: every image label at the image it names, every arrow at its point.

The images are computed here independently of the lever, from the analytic
velocities: the image of X on the lever is v_X / k_v turned by 90°
counter-clockwise (the plan's own k_v, a chosen scale, not a result).
"""

from __future__ import annotations

import pytest

import plans
from plans.drawing.force_drawing import draw_lever
from plans.forces.lever import joukowski_lever
from plans.graphical import construct
from plans.scene import example_path, load


def _label_centres(artists) -> dict[str, complex]:
    """gid -> the centre of the text's box [mm, data units]."""
    fig = artists[0].figure
    ax = fig.axes[0]
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    renderer = FigureCanvasAgg(fig).get_renderer()
    inverse = ax.transData.inverted()
    out = {}
    for a in artists:
        gid = a.get_gid()
        if gid and hasattr(a, "get_text"):
            (x0, y0), (x1, y1) = inverse.transform(a.get_window_extent(renderer).get_points())
            out[gid] = complex((x0 + x1) / 2, (y0 + y1) / 2)
    return out


def _analytic_images(scene, k_v: float) -> dict[str, complex]:
    """Image label -> i·v_X/k_v [mm] for every named point of every moving link (analytic velocities)."""
    solution = plans.solve(scene)
    images = {}
    for body, link in scene.bodies.items():
        if body == "1":
            continue
        for name, local in link.points.items():
            v = complex(solution.motion_of(body, local).v[0])
            images.setdefault(name.lower(), 1j * v / k_v)
    return images


@pytest.mark.parametrize("name", ["six-bar-loads", "quick-return-loads", "slider-crank-loads"])
def test_every_image_label_stands_nearest_its_own_image(name):
    scene = load(example_path(name))
    lever = joukowski_lever(construct(scene, precision=None))
    truth = _analytic_images(scene, lever.k_v)
    artists = draw_lever(lever)
    centres = _label_centres(artists)
    dots = {label: complex(z) for label, z in lever.images.items()}
    checked = 0
    for label, z in dots.items():
        if label in truth:
            assert z == pytest.approx(truth[label], abs=1e-6), label  # the image is where the velocity says
        gid = f"lever-image-{label}"
        if gid not in centres:
            continue
        centre = centres[gid]
        nearest = min(dots.values(), key=lambda q: abs(q - centre))
        assert abs(nearest - z) < 1e-6, f"{label}: its label is nearer another image ({nearest}) than its own ({z})"
        checked += 1
    assert checked >= 3


def _arrows(artists) -> dict[str, tuple[complex, complex, str]]:
    """gid of a force arrow's shaft -> (tail, tip of its head, colour)."""
    out = {}
    by_gid = {a.get_gid(): a for a in artists if a.get_gid()}
    for gid, a in by_gid.items():
        if gid.startswith("lever-force-") and not gid.startswith("lever-force-label-") and not gid.endswith("-head"):
            xs, ys = a.get_data()
            head = by_gid[gid + "-head"]
            tip = complex(*head.get_xy()[0])
            out[gid] = (complex(xs[0], ys[0]), tip, a.get_color())
    return out


@pytest.mark.parametrize("name", ["quick-return-loads", "six-bar-loads"])
def test_every_arrow_starts_at_its_image_and_carries_its_own_label_in_its_colour(name):
    from matplotlib.colors import to_hex

    scene = load(example_path(name))
    lever = joukowski_lever(construct(scene, precision=0.1))
    truth = _analytic_images(scene, lever.k_v)
    artists = draw_lever(lever)
    arrows = _arrows(artists)
    centres = _label_centres(artists)
    texts = {a.get_gid(): a for a in artists if a.get_gid() and hasattr(a, "get_text")}
    assert len(arrows) == len([f for f in lever.forces + (lever.balancing_force,) if abs(f.force)])
    tails = list(complex(f.point) for f in lever.forces + (lever.balancing_force,) if abs(f.force))
    for gid, (tail, tip, colour) in arrows.items():
        # the arm is the arrow's place: it starts at an image, not beside it, or (a second arrow along the same line at
        # one image, issue 20's review) on its line of action through the image, past the first one's head
        u = (tip - tail) / abs(tip - tail)
        assert min(abs(((tail - t) * u.conjugate()).imag) + max(0.0, -((tail - t) * u.conjugate()).real) for t in tails) < 1e-9, gid
        label_gid = gid.replace("lever-force-", "lever-force-label-")
        assert to_hex(texts[label_gid].get_color()) == to_hex(colour), gid
        nearest = min(arrows.values(), key=lambda a: abs(a[1] - centres[label_gid]))
        assert nearest[1] == tip, f"{label_gid} stands nearer another arrow's head than its own"
    # at e (= s6 on the quick-return lever) the weight G6 starts at e itself: i·v_E/k_v
    if name == "quick-return-loads":
        tail, tip, _ = arrows["lever-force-G_6"]
        u = (tip - tail) / abs(tip - tail)
        assert abs(((tail - truth["e"]) * u.conjugate()).imag) < 1e-6 and ((tail - truth["e"]) * u.conjugate()).real > -1e-6


def test_a_couple_on_the_lever_is_its_pair_of_forces_named_and_valued():
    scene = load(example_path("six-bar-loads"))
    lever = joukowski_lever(construct(scene, precision=0.1))
    artists = draw_lever(lever)
    texts = {a.get_gid(): a.get_text() for a in artists if a.get_gid() and hasattr(a, "get_text")}
    assert texts["lever-force-label-Fp_Phi3"].startswith("$F′_") and texts["lever-force-label-Fpp_Phi3"].startswith("$F″_")
    assert "lever-force-label-Fp_Phi3" in texts and "lever-force-label-Fpp_Phi3" in texts
    assert not any(g.startswith("lever-force-label-M_") for g in texts)
    # link 3: A–C = 0.6 m; M_Φ3 = J_S3·ε3 read here from the pair's own force: F = M/l
    line = texts["lever-moment-Fp_Phi3"]
    assert "/$l_{\\mathrm{" in line and "0.6 m" in line
    # the block's couple M_Φ6 enters as its moment, said so
    assert "without an arm" in texts["lever-moment-M_Phi6"]


@pytest.mark.parametrize("lang", ["en", "sr", "ru", "bg", "sl"])
def test_the_balancing_moment_states_its_sense_and_the_turn_is_stated(lang):
    from plans.i18n import term

    scene = load(example_path("six-bar-loads"))
    exact = float(plans.forces(scene).balancing[0])
    lever = joukowski_lever(construct(scene, precision=0.1))
    texts = {a.get_gid(): a.get_text() for a in draw_lever(lever, lang=lang) if a.get_gid() and hasattr(a, "get_text")}
    assert texts["lever-result"].split("N·m", 1)[1].startswith(" ↺" if exact > 0 else " ↻")
    assert "↺" in texts["lever-turn"] and "90°" in texts["lever-turn"]  # TURN = +i: counter-clockwise
    assert texts["lever-arm-rule"] == term("lever_arm_rule", lang)
    assert "−" not in texts["lever-moment-F_b"].split("·", 1)[1].split("=")[0].replace("(−", "")  # a negative arm in brackets


def _segment_distance(z: complex, a: complex, b: complex) -> float:
    d = b - a
    t = min(1.0, max(0.0, ((z - a) * d.conjugate()).real / abs(d) ** 2)) if abs(d) else 0.0
    return abs(z - (a + t * d))


def _twins(v, w) -> bool:
    dv, dw = complex(v.tip - v.tail), complex(w.tip - w.tail)
    middle = complex(v.tail + v.tip) / 2
    return abs((dv * dw.conjugate()).imag) <= 0.15 * abs(dv) * abs(dw) and _segment_distance(middle, complex(w.tail), complex(w.tip)) < 2.5


@pytest.fixture(scope="module")
def six_bar_plans():
    from plans.forces.force_plans import construct_force_plans

    return construct_force_plans(construct(load(example_path("six-bar-loads")), precision=0.1))


@pytest.mark.parametrize("name", ["six-bar-loads", "quick-return-loads"])
def test_every_force_plan_label_stands_by_its_own_vector(name):
    from plans.drawing.force_drawing import draw_force_plan
    from plans.forces.force_plans import construct_force_plans

    forces = construct_force_plans(construct(load(example_path(name)), precision=0.1))
    for plan in forces.plans:
        artists = draw_force_plan(plan)
        centres = _label_centres(artists)
        vectors = [v for v in plan.vectors if v.length >= 3.0]
        for v in vectors:
            gid = "fplan-label-" + v.label.replace("Φ", "Phi").replace("^", "_")
            match = [g for g in centres if g.replace("^", "_") == gid]
            assert match, (gid, sorted(centres))
            c = centres[match[0]]
            own = _segment_distance(c, complex(v.tail), complex(v.tip))
            for w in vectors:
                # a vector all but retracing another (R^n_14 along R_14): its label stands by both; it is placed
                # along it, away from the other's (checked below)
                if w is not v and abs(complex(w.tip) - complex(w.tail)) > 1e-9 and not _twins(v, w):
                    assert own <= _segment_distance(c, complex(w.tail), complex(w.tip)) + 1e-9, f"{plan.group}: {v.label}'s label nearer {w.label}"
                elif w is not v and _twins(v, w):
                    other = [g for g in centres if g.replace("^", "_") == "fplan-label-" + w.label.replace("Φ", "Phi").replace("^", "_")]
                    assert abs(centres[other[0]] - c) > 4.0, f"{plan.group}: {v.label} and {w.label} labelled at one place"


def test_a_force_plan_lists_its_known_loads_with_newtons_and_drawn_millimetres(six_bar_plans):
    from plans.drawing.force_drawing import draw_force_plan, found_scales, given_loads

    plan = next(p for p in six_bar_plans.plans if p.group == "RRR(3,4)")
    artists = draw_force_plan(plan, found_at=found_scales(six_bar_plans.plans), given=given_loads(six_bar_plans))
    texts = {a.get_gid(): a.get_text() for a in artists if a.get_gid() and hasattr(a, "get_text")}
    # G_3 = m3·g = 3 kg · 9.81 m/s² = 29.43 N, at μ_F = 2 N/mm: 14.7 mm
    assert "29.43 N" in texts["fplan-known-G_3"] and "14.7 mm" in texts["fplan-known-G_3"]
    assert "carried" in texts["fplan-known-R_53"]
    assert "found first" in texts["fplan-found-first"] and texts["fplan-reading-R_t_23"].endswith(" mm") and "14.0 N" in texts["fplan-reading-R_t_23"]
    assert texts["fplan-short-R_t_14"].endswith(" N)")  # a vector under 3 mm: its value in N too
    driver = next(p for p in six_bar_plans.plans if p.group == "driver")
    texts = {a.get_gid(): a.get_text() for a in draw_force_plan(driver, found_at=found_scales(six_bar_plans.plans)) if a.get_gid() and hasattr(a, "get_text")}
    # R_32 found as R_23 on RRR(3,4) at 2 N/mm, redrawn on the driver's plan at its own μ_F
    assert driver.scale != plan.scale and r"$\mu_F$ = 2 N/mm" in texts["fplan-known-R_32"]


def _free(name):
    from plans.drawing.force_drawing import draw_free_bodies
    from plans.forces.force_plans import construct_force_plans

    forces = construct_force_plans(construct(load(example_path(name)), precision=0.1))
    return forces, draw_free_bodies(forces)


def _inside_polygon(z: complex, corners) -> bool:
    from shapely.geometry import Point, Polygon

    return Polygon([(c[0], c[1]) for c in corners]).buffer(1e-9).contains(Point(z.real, z.imag))


def test_the_ram_is_drawn_to_its_centre_of_mass_and_no_arrow_hides_in_a_block():
    forces, artists = _free("quick-return-loads")
    by_gid = {a.get_gid(): a for a in artists if a.get_gid()}
    ram = by_gid["fbody-link-6"].get_xy()
    s6 = complex(*by_gid["fbody-centre-6"].center)
    assert _inside_polygon(s6, ram)  # S6 is on the ram's body, not floating beside a small block at E
    block = by_gid["fbody-link-3"].get_xy()  # the block on the crank pin A
    tip = complex(*by_gid["fbody-force-R_23-head"].get_xy()[0])
    assert not _inside_polygon(tip, block)  # R_23's head outside the block
    a = complex(*by_gid["fbody-pin-A"].center)
    assert abs(tip - a) > 2.0


def test_an_arrow_along_a_bar_is_drawn_beside_it():
    forces, artists = _free("six-bar-loads")
    by_gid = {a.get_gid(): a for a in artists if a.get_gid()}
    xs, ys = by_gid["fbody-link-5"].get_data()
    b, m = complex(xs[0], ys[0]), complex(xs[-1], ys[-1])
    sx, sy = by_gid["fbody-force-R_35"].get_data()
    for z in (complex(sx[0], sy[0]), complex(sx[-1], sy[-1])):
        assert _segment_distance(z, b, m) >= 1.0  # R_35 (almost along rod 5) not on top of the rod


@pytest.mark.parametrize("name", ["six-bar-loads", "quick-return-loads"])
def test_free_body_labels_stand_clear_of_each_other_and_of_the_arrows(name):
    from shapely.geometry import LineString, box
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    forces, artists = _free(name)
    fig = artists[0].figure
    renderer = FigureCanvasAgg(fig).get_renderer()
    inverse = fig.axes[0].transData.inverted()
    boxes = []
    for a in artists:
        gid = a.get_gid() or ""
        if hasattr(a, "get_text") and ("label" in gid or "point-" in gid):
            (x0, y0), (x1, y1) = inverse.transform(a.get_window_extent(renderer).get_points())
            boxes.append((gid, x0, y0, x1, y1))
    assert len(boxes) > 10
    for k, (g1, a0, b0, a1, b1) in enumerate(boxes):
        for g2, c0, d0, c1, d1 in boxes[k + 1:]:
            overlap = min(a1, c1) - max(a0, c0) > 0.1 and min(b1, d1) - max(b0, d0) > 0.1
            assert not overlap, (g1, g2)
    shafts = {}
    for a in artists:
        gid = a.get_gid() or ""
        if gid.startswith("fbody-force-") and not gid.startswith("fbody-force-label") and not gid.endswith("-head"):
            xs, ys = a.get_data()
            shafts[gid] = LineString(list(zip(xs, ys)))
    for g1, x0, y0, x1, y1 in boxes:
        for g2, shaft in shafts.items():
            assert not box(x0, y0, x1, y1).buffer(-0.2).intersects(shaft), (g1, g2)
