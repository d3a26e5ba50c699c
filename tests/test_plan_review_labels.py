"""Issue 20, a teacher's review of the plate's plans (sr quick-return 12 positions, bg linear-arm 8, en six-bar).

1. The quick-return's position-4 acceleration plan, 22 mm at k_a = 0.2 (the plate's k_a when the review saw it), is
   drawn again whole beside itself, enlarged 5 : 1, headed "detail I (5 : 1)" in the reader's language; the plan itself
   stays at the plate's k_a.  (The plate now draws its acceleration plans on the rest of the page the velocity plans
   end on, at k_a = 0.3: there the plan is 15 mm, its images crowd, and it has the crowd's detail instead.)
2. No plan label runs into another (linear-arm position 2: "π, d′, q′, a′, f′" over n₁).
3. Beside the image k′ of the linear-arm's point K, the Coriolis ends are named by the component's symbol (aᵏ₁, aᵏ₂),
   the same on the plan and in the readings, never κ.
4. The six-bar's frame point E, which its equations call E6 (v_E6 = 0), is lettered e₆ at the pole; π m′, 0.6° off
   π a′, is drawn apart in an enlarged detail.

Expected values come from the analytic solution (|a_A|, a_M, a_E) and the scale factors the pages print, never from
the drawing's own numbers; what is drawn is read back from the SVG (dots by their ids, texts) or measured with
matplotlib's renderer.
"""

from __future__ import annotations

import cmath
import itertools
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from plans.drawing.plan_drawing import draw_plan
from plans.drawing.svgblocks import plan_svg

from plandraw_overlaps import SLIVER_MM2, label_boxes
from review_handouts import REVIEWED, built, reviewed_handouts

pytestmark = pytest.mark.filterwarnings("ignore")

SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def handouts():
    return reviewed_handouts()


@pytest.fixture(scope="module")
def at_review_k_a():
    """The sr quick-return handout with the plate's k_a given as the review saw it, 0.2 (m/s²)/mm, and its positions
    (4 and 10: the lever upright, the plans collapsed; the default now draws 2 and 9)."""
    return built("quick-return", 12, "sr", k_a=0.2, accelerations=(4, 10))


def _svg(svg: bytes):
    root = ET.fromstring(svg)
    per_mm = float(root.get("viewBox").split()[2]) / float(root.get("width").removesuffix("mm"))
    return root, per_mm


def _centre(root, gid: str) -> complex:
    """The centre [SVG units] of the drawn element *gid* (a dot: its path's bounding box)."""
    return _circle(root, gid)[0]


def _circle(root, gid: str) -> tuple[complex, float]:
    """(centre, half width) [SVG units] of the element drawn as *gid*, a dot or a circle (its path's bounding box)."""
    g = next(g for g in root.iter(f"{SVG}g") if g.get("id") == gid)
    numbers = [float(x) for x in re.findall(r"-?[0-9]+(?:\.[0-9]+)?", next(g.iter(f"{SVG}path")).get("d"))]
    xs, ys = numbers[0::2], numbers[1::2]
    return complex((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2), (max(xs) - min(xs)) / 2


def _texts(root) -> dict[str, str]:
    return {g.get("id"): "".join(t.text or "" for t in g.iter(f"{SVG}text")) for g in root.iter(f"{SVG}g") if g.get("id")}


def _first(x) -> complex:
    return complex(np.ravel(x)[0])


def _run(doc, index: int):
    return next(r for r in doc.runs if r.index == index)


# --- 1. a small plan's enlarged detail -----------------------------------------------------------------------------

def test_the_small_acceleration_plan_is_drawn_again_enlarged_beside_itself(at_review_k_a):
    doc = at_review_k_a
    k_a = doc.scales["k_a"]
    assert k_a == pytest.approx(0.2)  # the plate's one k_a, as given and as the page prints it
    a_a = abs(_first(_run(doc, 4).analytic.points["A"].a))  # |a_A| = ω₂²·OA, the analytic solution
    root, per_mm = _svg(doc.images["a-4"])
    texts = _texts(root)
    assert texts["acc-detail-name"] == "Детаљ I (5 : 1)"  # (as every detail's title: round 20)
    # the plan at k_a: π a′ = |a_A| / k_a (22 mm); its detail five times that
    drawn = abs(_centre(root, "acc-dot-a") - _centre(root, "acc-pole")) / per_mm
    enlarged = abs(_centre(root, "acc-detail-dot-a") - _centre(root, "acc-detail-pole")) / per_mm
    assert drawn == pytest.approx(a_a / k_a, abs=0.1)
    assert enlarged == pytest.approx(5 * a_a / k_a, abs=0.3)
    # the detail beside the plan, its top level with the plan's
    assert _centre(root, "acc-detail-pole").real > _centre(root, "acc-dot-a").real + 10 * per_mm
    assert abs(_centre(root, "acc-detail-pole").imag - _centre(root, "acc-pole").imag) < 15 * per_mm
    # and, being a short component on the plan, π e′ is an arrow there: |a_E| / k_a · 5 long
    a_e = abs(_first(_run(doc, 4).analytic.points["E"].a))
    assert abs(_centre(root, "acc-detail-dot-e") - _centre(root, "acc-detail-pole")) / per_mm == pytest.approx(5 * a_e / k_a, abs=0.2)


def test_the_small_plan_at_the_plates_own_k_a_is_enlarged_in_a_detail(handouts):
    """At the plate's k_a as chosen (fitted to the idle stroke's plan, five times as large), the working stroke's plan
    (position 2) is under 30 mm and its normal component aⁿ_ED under 3 mm, given in a note: it is drawn again whole,
    enlarged at the ratio its heading states, where aⁿ_ED is an arrow (in the height position 9's plan leaves)."""
    doc = handouts["quick-return"][0]
    k_a = doc.scales["k_a"]
    r = _run(doc, 2)
    a = r.analytic
    a_a = abs(_first(a.points["A"].a))  # |a_A| = ω₂²·OA
    a_n_ed = _first(a.links["5"].omega).real ** 2 * abs(_first(a.points["E"].r) - _first(a.points["D"].r))  # ω₅²·ED
    assert a_a / k_a < 30.0 and a_n_ed / k_a < 3.0  # a small plan, aⁿ_ED too short for an arrow on it
    root, per_mm = _svg(doc.images["a-2"])
    assert abs(_centre(root, "acc-dot-a") - _centre(root, "acc-pole")) / per_mm == pytest.approx(a_a / k_a, abs=0.1)
    ratio = float(re.search(r"I \(([0-9.,]+) : 1\)$", " ".join(t for gid, t in _texts(root).items() if gid.startswith("acc-detail-name"))).group(1).replace(",", "."))
    assert ratio >= 2
    drawn = abs(_centre(root, "acc-detail-dot-a") - _centre(root, "acc-detail-pole")) / per_mm
    assert drawn == pytest.approx(ratio * a_a / k_a, abs=0.2)
    assert ratio * a_n_ed / k_a >= 3.0  # an arrow there


@pytest.mark.parametrize("lang, words", [("en", "Detail I (5 : 1)"), ("sr", "Детаљ I (5 : 1)"), ("ru", "Выносной элемент I (5 : 1)"),
                                         ("bg", "Детайл I (5 : 1)"), ("sl", "Detajl I (5 : 1)")])
def test_the_enlarged_detail_is_headed_in_the_readers_language(at_review_k_a, lang, words):
    plan = _run(at_review_k_a, 4).graphical.acceleration_plan
    root, _ = _svg(plan_svg(plan, lang, room=(85.0, 200.0)).svg)
    texts = _texts(root)
    assert " ".join(t for t in (texts["acc-detail-name"], texts.get("acc-detail-name-ratio")) if t) == words


def test_no_enlarged_copy_without_room_or_for_a_plan_of_fair_size(at_review_k_a):
    doc = at_review_k_a
    small = _run(doc, 4).graphical.acceleration_plan
    assert "acc-detail-name" not in _texts(_svg(plan_svg(small, "sr", room=(40.0, 200.0)).svg)[0])  # no room beside it
    assert "acc-detail-name" not in _texts(_svg(plan_svg(small, "sr").svg)[0])  # a sheet's plan: no cell given
    large = _run(doc, 10).graphical.acceleration_plan  # 95 mm on the page
    assert "acc-detail-name" not in _texts(_svg(plan_svg(large, "sr", room=(200.0, 250.0)).svg)[0])


# --- 2. no label on another ----------------------------------------------------------------------------------------

@pytest.mark.parametrize("name", [n for n, _, _ in REVIEWED])
def test_no_plan_label_runs_into_another(handouts, name):
    doc, lang = handouts[name]
    for r in doc.runs:
        drawn = [r.graphical.velocity_plan] + ([r.graphical.acceleration_plan] if f"a-{r.index}" in doc.images else [])
        for plan in drawn:
            fig = draw_plan(plan, lang=lang, legend=False)[0].figure
            boxes = label_boxes(fig)
            for (g1, b1), (g2, b2) in itertools.combinations(boxes, 2):
                assert b1.intersection(b2).area <= SLIVER_MM2, (name, r.index, plan.kind, g1, g2)


# --- 3. the Coriolis ends beside k′ ----------------------------------------------------------------------------------

def test_coriolis_ends_beside_the_image_of_k_are_named_by_the_component(handouts):
    doc = handouts["linear-arm"][0]
    for key in ("a-2", "a-5"):
        texts = _texts(_svg(doc.images[key])[0])
        assert texts["acc-image-k"] == "k′"  # the scene's point K, as written
        ends = sorted(t for gid, t in texts.items() if gid.startswith("acc-end-a_k_"))
        assert ends == ["aᵏ₁", "aᵏ₂"]
        assert not any("κ" in t for t in texts.values())
    # the readings measure the same segments: from f′ (F at the pole) to the first Coriolis end, thence to f₄′
    source = doc.source
    assert "κ" not in source
    assert "f′ aᵏ₁" in source and "aᵏ₁ f₄′" in source and "h₃′ aᵏ₂" in source and "aᵏ₂ h′" in source


# --- 4. the six-bar's pole and π m′ --------------------------------------------------------------------------------

def test_the_frame_point_at_the_pole_is_lettered_as_the_equations_name_it(handouts):
    doc = handouts["six-bar"][0]
    assert re.search(r"v_\(?E ?6\)?|v_\(E6\)|E 6|E6", doc.source)  # the equations' v_E6 (the sleeve's point at E)
    v = _texts(_svg(doc.images["v-0"])[0])
    a = _texts(_svg(doc.images["a-0"])[0])
    assert v["vel-pole-label"] == "p" and v["vel-image-e"] == "e₆" and a["acc-image-e"] == "e₆′"
    assert '"p e₅"' in doc.source  # v_E5 = v_E5E6 read once, from the pole


def test_a_vector_along_another_is_drawn_apart_in_a_detail(handouts):
    doc = handouts["six-bar"][0]
    k_a = doc.scales["k_a"]
    r = _run(doc, 0)
    a_a, a_m = _first(r.analytic.points["A"].a), _first(r.analytic.points["M"].a)
    off = abs((a_m * (a_a / abs(a_a)).conjugate()).imag) / k_a  # m′ off the line π a′ [mm on the plan]: under a millimetre
    assert 0.3 < off < 1.2
    turn = abs(np.degrees(cmath.phase(a_m / a_a)))
    assert 0.3 < turn < 1.0
    root, per_mm = _svg(doc.images["a-0"])
    texts = _texts(root)
    ratio = float(re.fullmatch(r"Detail I \(([0-9.]+) : 1\)", texts["acc-detail-name"]).group(1))  # (titled as every detail)
    assert ratio >= 5
    # in the detail, m′ stands off the enlarged shaft of π a′ by ratio × off
    g = next(g for g in root.iter(f"{SVG}g") if g.get("id") == "acc-detail-a_A")
    numbers = [float(x) for x in re.findall(r"-?[0-9]+(?:\.[0-9]+)?", next(g.iter(f"{SVG}path")).get("d"))]
    p, q = complex(numbers[0], numbers[1]), complex(numbers[-2], numbers[-1])
    m = _centre(root, "acc-detail-dot-m")
    u = (q - p) / abs(q - p)
    assert abs(((m - p) * u.conjugate()).imag) / per_mm == pytest.approx(ratio * off, abs=0.25)


def test_a_crowded_pole_is_drawn_again_enlarged_under_its_plan():
    """Round 17 (bg linear-arm, position 2, 36 mm at the plate's k_a): round the pole, the normal components d′n₁ and
    q′n₂ (2.3 mm, notes only), n₁, n₂, k′, h′, aᵏ₂ and two Coriolis lines within 10 mm; nothing to re-measure.  The pole's
    neighbourhood is ringed and drawn again under the plan, enlarged at the ratio its heading states, where d′n₁ is an
    arrow |aⁿ_F4D| / k_a × n long (ω₄²·DF from the analytic solution)."""
    doc = built("linear-arm", 8, "bg")
    k_a = doc.scales["k_a"]
    r = _run(doc, 2)
    a = r.analytic
    omega4 = _first(a.links["4"].omega).real
    df = abs(_first(a.points["F"].r) - _first(a.points["D"].r))
    assert omega4 ** 2 * df / k_a < 3.0  # a note on the plan
    root, per_mm = _svg(doc.images["a-2"])
    texts = _texts(root)
    ratio = float(re.search(r"\(([0-9.]+) : 1\)$", texts["acc-detail-name"]).group(1))
    drawn = abs(_centre(root, "acc-detail-end-dot-a_n_F4D") - _centre(root, "acc-detail-pole")) / per_mm
    assert drawn == pytest.approx(ratio * omega4 ** 2 * df / k_a, abs=0.2)
    assert drawn >= 3.0  # an arrow there
    assert _centre(root, "acc-detail-pole").imag > _centre(root, "acc-pole").imag + 10 * per_mm  # under the plan (SVG y down)


def test_a_detail_rings_name_keeps_its_leader_off_the_labels():
    """Round 20 (bg linear-arm, position 2's acceleration plan): the ring of the pole's crowd was named "I" 12 mm off,
    on a leader through the "d′" of the pole's label "π, d′, q′, a′, f′". The name stands by its ring, and a leader to
    it crosses no label."""
    from shapely.geometry import LineString, box

    from svg_text_boxes import text_boxes

    doc = built("linear-arm", 8, "bg")
    svg = doc.images["a-2"]
    boxes = [(gid, text, box(*b)) for gid, text, b in text_boxes(svg)]  # (measured with matplotlib's font metrics)
    name = next(b for gid, text, b in boxes if gid == "acc-detail-mark")
    others = [(gid, text, b) for gid, text, b in boxes if gid != "acc-detail-mark" and (text or "").strip(" ,")]
    leaders = []
    for g in ET.fromstring(svg).iter(f"{SVG}g"):
        if re.fullmatch(r"acc-leader(-\d+)?", g.get("id") or ""):
            xy = [float(v) for v in re.findall(r"-?[0-9]+(?:\.[0-9]+)?", next(g.iter(f"{SVG}path")).get("d"))]
            leaders.append(LineString([(xy[0], xy[1]), (xy[-2], xy[-1])]))
    root, per_mm = _svg(svg)
    centre, r = _circle(root, "acc-detail-ring")
    # its leader: from the ring's edge to within reach of its box (it stops 0.6 mm short of the box plans reckons)
    mine = [line for line in leaders
            if min(abs(abs(complex(*xy) - centre) - r) for xy in line.coords) <= 0.8 * per_mm and line.distance(name) <= 2.5 * per_mm]
    for line in mine:
        crossed = [(gid, text) for gid, text, b in others if line.intersects(b.buffer(-0.2))]
        assert not crossed, crossed


def test_a_detail_stands_clear_of_the_ring_it_enlarges_and_of_the_plans_labels():
    """Round 25 (en six-bar handout, the acceleration plan): "Detail I (10 : 1)" touched the ring at m′ it enlarges,
    the ring's name "I" lay on the detail's edge and the plan's "m′" inside its circle, two m′ at two scales in one
    circle. The detail stands 6 mm clear of its ring, and no text of the plan lies in its circle."""
    from shapely.geometry import Point, box

    from svg_text_boxes import text_boxes

    svg = built("six-bar", None, "en", centres=True).images["a-0"]
    root, per_mm = _svg(svg)
    (detail, big), (ring, r) = _circle(root, "acc-detail"), _circle(root, "acc-detail-ring")
    assert abs(detail - ring) - big - r >= 5.9 * per_mm, (abs(detail - ring) - big - r) / per_mm
    disk = Point(detail.real, detail.imag).buffer(big)
    inside = [(gid, text) for gid, text, b in text_boxes(svg) if not gid.startswith("acc-detail-") and disk.intersects(box(*b))]
    assert not inside, inside
