"""Issue 20, a teacher's second review of the plans (en six-bar, sr quick-return, ru four-bar, bg linear-arm).

1. No label is crossed by a drawn line, construction lines and leaders included (six-bar: the leader to "e₅′" ran
   into its prime, which read as the leader's stroke: "e₅"); a leader stops short of its label.
2. The six-bar's velocity images a b c, 10 mm across with b 2.5 mm from c at the handout's k_v, are drawn again
   enlarged in a detail where they stand apart.
3. The four-bar's p m, 0.44° off p a (149.6° and 150.0°) and 158 mm long on the A3 sheet (k_v 0.004), gets a note
   with both directions and an enlarged detail, as the acceleration plan's π m′ does.

Expected values: the directions and lengths from the analytic solution and the scale factors the pages print;
what is drawn is read back from the SVG or measured with matplotlib's renderer.
"""

from __future__ import annotations

import cmath
import math
import re
import xml.etree.ElementTree as ET

import matplotlib.pyplot as plt
import numpy as np
import pytest
from shapely.geometry import LineString

import plans
from plans.drawing.plan_drawing import draw_plan
from plans.drawing.svgblocks import plan_svg
from plans.scene import example_path

from plandraw_overlaps import measured, texts_in
from review_handouts import REVIEWED, reviewed_handouts

pytestmark = pytest.mark.filterwarnings("ignore")

SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def handouts():
    return reviewed_handouts()


def _labels_and_lines(fig):
    """(labels, lines): (gid:text, box [mm]) of every plan label and (gid, LineString [mm]) of every drawn line."""

    def measure(renderer, k):
        texts, lines = [], []
        for ax in fig.axes:
            texts += texts_in(ax, renderer, k)
            for line in ax.lines:
                gid = line.get_gid() or ""
                xy = ax.transData.transform(list(zip(*line.get_data()))) * k
                if "legend" not in gid and len(xy) >= 2:
                    lines.append((gid, LineString(xy)))
        return texts, lines

    return measured(fig, measure)


def _drawn(doc):
    for r in doc.runs:
        yield r.index, r.graphical.velocity_plan
        if f"a-{r.index}" in doc.images:
            yield r.index, r.graphical.acceleration_plan


@pytest.mark.parametrize("name", [n for n, _, _ in REVIEWED])
def test_no_label_is_crossed_by_a_line_and_leaders_stop_short(handouts, name):
    doc, lang = handouts[name]
    leaders = 0
    for index, plan in _drawn(doc):
        fig = draw_plan(plan, lang=lang, legend=False, detail=True)[0].figure
        labels, lines = _labels_and_lines(fig)
        plt.close(fig)
        for text, b in labels:
            for gid, line in lines:
                assert not line.intersects(b), f"{name} {index} {plan.kind}: {gid} crosses the label {text!r}"
                if "leader" in gid:
                    # a leader (a pen's width and a clear gap) short of every label, its own included
                    assert line.distance(b) >= 0.5, f"{name} {index} {plan.kind}: {gid} runs into {text!r} ({line.distance(b):.2f} mm)"
        leaders += sum("leader" in gid for gid, _ in lines)
    assert leaders > 0


def _svg(svg: bytes):
    root = ET.fromstring(svg)
    per_mm = float(root.get("viewBox").split()[2]) / float(root.get("width").removesuffix("mm"))
    return root, per_mm


def _texts(root) -> dict[str, str]:
    return {g.get("id"): "".join(t.text or "" for t in g.iter(f"{SVG}text")) for g in root.iter(f"{SVG}g") if g.get("id")}


def _centre(root, gid: str) -> complex:
    g = next(g for g in root.iter(f"{SVG}g") if g.get("id") == gid)
    numbers = [float(x) for x in re.findall(r"-?[0-9]+(?:\.[0-9]+)?", next(g.iter(f"{SVG}path")).get("d"))]
    xs, ys = numbers[0::2], numbers[1::2]
    return complex((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2)


def _gids(root) -> set[str]:
    return {g.get("id") for g in root.iter(f"{SVG}g") if g.get("id")}


def _at(name: str, **ks):
    scene = plans.load(example_path(name))
    return scene, plans.construct(scene, check_scales=False, **ks)


def test_the_crowded_velocity_images_a_b_c_are_detailed_apart():
    # the review's handout scale: k_v 0.015 (m/s)/mm; a b c then within 10 mm, b 2.5 mm from c
    scene, g = _at("six-bar", k_l=0.008, k_v=0.015, k_a=0.08)
    sol = plans.solve(scene)
    v = {p: complex(np.ravel(sol.points[p].v)[0]) / 0.015 for p in "ABC"}  # mm on the plan, from the analytic solution
    assert abs(v["B"] - v["C"]) < 4.0 and abs(v["A"] - v["C"]) < 12.0
    root, per_mm = _svg(plan_svg(g.velocity_plan, "en").svg)
    gids = _gids(root)
    assert {"vel-detail-dot-a", "vel-detail-dot-b", "vel-detail-dot-c"} <= gids
    dots = {p: _centre(root, f"vel-detail-dot-{p.lower()}") for p in "ABC"}
    ratio = abs(dots["A"] - dots["C"]) / per_mm / abs(v["A"] - v["C"])
    assert ratio >= 2.0
    for p, q in (("A", "B"), ("B", "C"), ("A", "C")):
        drawn = abs(dots[p] - dots[q]) / per_mm
        assert drawn == pytest.approx(ratio * abs(v[p] - v[q]), rel=0.02)  # the detail is the plan enlarged
        assert drawn >= 7.0  # two arrowheads (3.6 mm) apart
    texts = _texts(root)
    assert {texts[f"vel-detail-image-{p}"] for p in "abc"} == {"a", "b", "c"}


def test_near_coincident_velocity_vectors_get_a_note_and_a_detail():
    # the Russian four-bar's A3 sheet: k_v 0.004 (m/s)/mm
    scene, g = _at("four-bar", k_l=0.002, k_v=0.004, k_a=0.15)
    sol = plans.solve(scene)
    vm, va = (complex(np.ravel(sol.points[p].v)[0]) for p in "MA")
    deg = {p: math.degrees(cmath.phase(z)) % 360 for p, z in (("m", vm), ("a", va))}
    assert abs(deg["m"] - deg["a"]) < 1.0 and abs(vm) / 0.004 > 150  # the review's case: 158 mm, 0.4° apart
    root, per_mm = _svg(plan_svg(g.velocity_plan, "ru").svg)
    texts = _texts(root)
    notes = [t for gid, t in texts.items() if gid.startswith("vel-along-")]
    assert f"∠(pm) = {deg['m']:.1f}°".replace(".", ",") in notes
    assert f"∠(pa) = {deg['a']:.1f}°".replace(".", ",") in notes
    gids = _gids(root)
    assert "vel-detail-ring" in gids and "vel-detail-dot-m" in gids
    # in the detail the tip m stands clear of p a's shaft: its distance from that line, enlarged, at least 3 mm
    off = abs((vm * (va / abs(va)).conjugate()).imag) / 0.004
    ring = texts["vel-detail-name"]
    n = float(re.search(r"\((\d+(?:[.,]\d+)?) : 1\)", ring).group(1).replace(",", "."))
    assert off * n >= 3.0
