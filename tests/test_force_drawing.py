"""Drawings of the force plans and free bodies (plans.drawing.force_drawing): artists' data and SVG text, not pixels.

A hand-made force plan (a 3-4-5 triangle at μ_F = 10 N/mm) checks where the
arrows end, what the captions read and in which language; the loaded
examples check the free bodies and the files.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest

from plans.drawing.force_drawing import (
    draw_force_plan,
    draw_free_bodies,
    force_figures,
    force_math,
    write_force_drawings,
)
from plans.drawing.svg import render_svg
from plans.forces.force_plans import ForcePlan, PlanForce, construct_force_plans
from plans.graphical import construct
from plans.graphical.plan import ConstructionLine
from plans.i18n import LANGUAGES, term
from plans.scene import example_path, load

#: a load 30 mm along x, the found reaction R_12 40 mm up, R_02 closing back: 300 N, 400 N, 500 N
TRIANGLE = ForcePlan(
    group="RRR(1,2)",
    links=("1", "2"),
    scale=10.0,
    vectors=(
        PlanForce(0j, 30 + 0j, "external", "F_c", 300.0),
        PlanForce(30 + 0j, 30 + 40j, "reaction", "R_12", 400.0),
        PlanForce(30 + 40j, 0j, "reaction", "R_02", 500.0),
    ),
    lines=(ConstructionLine(30 + 0j, 1j, "∥ BC"), ConstructionLine(0j, (0.6 + 0.8j), "∥ DC")),
    equations=("F_c + R_12 + R_02 = 0",),
    points={"a": 0j, "b": 30 + 0j, "c": 30 + 40j},
    found=("R_12", "R_02"),
    precision=0.1,
)


def _by_gid(artists, gid):
    found = [a for a in artists if a.get_gid() == gid]
    assert found, f"no artist {gid}: {sorted(str(a.get_gid()) for a in artists)}"
    return found[0]


def _texts(artists) -> dict[str, str]:
    return {a.get_gid(): a.get_text() for a in artists if hasattr(a, "get_text") and a.get_gid()}


def test_arrow_heads_end_at_the_plan_points():
    artists = draw_force_plan(TRIANGLE)
    for v in TRIANGLE.vectors:
        head = _by_gid(artists, f"fplan-{v.kind}-{v.label}-head")
        x, y = head.get_xy()[0]
        assert complex(x, y) == pytest.approx(v.tip, abs=1e-9), v.label
    # the polygon closes: the last tip is the first tail
    assert TRIANGLE.vectors[-1].tip == TRIANGLE.vectors[0].tail


def test_closing_lines_pass_through_their_intersection():
    artists = draw_force_plan(TRIANGLE)
    ends = []
    for n in range(2):
        line = _by_gid(artists, f"fplan-line-{n}")
        xs, ys = line.get_data()
        ends.append((complex(xs[0], ys[0]), complex(xs[-1], ys[-1])))
    meet = 30 + 40j  # x = 30 (∥ y through b) meets the line through a along 0.6 + 0.8i
    for a, b in ends:
        d = b - a
        assert abs(((meet - a) * d.conjugate()).imag) / abs(d) < 1e-9
        t = ((meet - a) * d.conjugate()).real / abs(d) ** 2
        assert 0 < t < 1  # drawn past the intersection


def test_caption_states_the_scale_and_the_readings():
    texts = _texts(draw_force_plan(TRIANGLE))
    assert texts["fplan-scale"] == r"$\mu_{F}$ = 10 N/mm"
    # read to 0.1 mm × 10 N/mm = 1 N: no decimals
    assert texts["fplan-reading-R_12"] == r"$R_{\mathrm{12}}$ = 40.0 mm · 10 N/mm = 400 N"
    assert texts["fplan-reading-R_02"] == r"$R_{\mathrm{02}}$ = 50.0 mm · 10 N/mm = 500 N"
    assert "fplan-reading-F_c" not in texts  # a load is not read off the plan
    assert texts["fplan-heading"] == "Force plan: RRR(1,2)"


@pytest.mark.parametrize("lang", sorted(LANGUAGES))
def test_words_in_every_language(lang):
    texts = _texts(draw_force_plan(TRIANGLE, lang=lang, balancing_moment=12.5))
    assert texts["fplan-heading"].startswith(term("force_plan", lang) + ":")
    words = term("balancing_moment", lang)
    assert words[:1].lower() + words[1:] in texts["fplan-reading-M_b"]
    assert texts["fplan-legend-text-reaction"] == term("force_reaction", lang)
    mark = "," if lang != "en" else "."
    assert f"12{mark}50 N·m" in texts["fplan-reading-M_b"]


def test_a_load_name_is_never_mathtext():
    assert force_math("F_$x^2$") == r"$F_{\mathrm{\$x\^2\$}}$"
    assert force_math(r"\alpha_1") == r"$alpha_{\mathrm{1}}$"
    assert force_math("R^t_23") == r"$R^{t}_{\mathrm{23}}$"


@pytest.fixture(scope="module")
def worked():
    scene = load(example_path("slider-crank-loads"))
    return construct_force_plans(construct(scene, precision=0.1))


def test_free_bodies_draw_every_load_and_outer_reaction(worked):
    artists = draw_free_bodies(worked)
    gids = {a.get_gid() for a in artists}
    for label in ("G_3", "F_Phi3", "G_4", "F_Phi4", "F_r", "R_23", "R_14", "G_2", "F_Phi2", "R_32", "R_12"):
        assert f"fbody-force-{label}" in gids, label
    # the inner reaction of the group cancels on its free body: not drawn
    assert not any(g.startswith("fbody-force-R_34") or g.startswith("fbody-force-R_43") for g in gids if g)
    assert {"fbody-couple-M_Phi3", "fbody-couple-M_b"} <= gids
    texts = _texts(artists)
    assert texts["fbody-heading-RRP_3_4"] == "RRP(3,4)"
    assert texts["fbody-heading-driver"] == "driving link 2 (crank)"


def test_a_reaction_points_into_its_joint(worked):
    artists = draw_free_bodies(worked)
    k_l = worked.graphical.scales["k_l"]
    head = _by_gid(artists, "fbody-force-R_23-head")
    tip = complex(*head.get_xy()[0])
    shaft = _by_gid(artists, "fbody-force-R_23")
    xs, ys = shaft.get_data()
    direction = tip - complex(xs[0], ys[0])
    force = worked.reactions["R_23"].force
    assert abs((direction * force.conjugate()).imag) <= 1e-9 * abs(direction) * abs(force)  # parallel
    assert (direction * force.conjugate()).real > 0  # same sense
    # the free body of the group is shifted as a whole: A's pin and R_23's tip 1.2 mm apart
    pin = _by_gid(artists, "fbody-pin-A")
    assert abs(complex(*pin.center) - tip) == pytest.approx(1.2, abs=1e-9)
    assert k_l == 0.005


def test_files_all_formats_and_deterministic(worked, tmp_path):
    written = write_force_drawings(worked, tmp_path, formats=("svg", "png", "pdf"))
    names = sorted(p.name for p in written)
    assert names == sorted(f"{n}.{f}" for n in ("free-bodies", "force-plan-1", "force-plan-driver") for f in ("svg", "png", "pdf"))
    svg = (tmp_path / "force-plan-1.svg").read_bytes()
    root = ET.fromstring(svg)
    assert root.get("width").endswith("mm") or root.get("width").endswith("pt")
    again = render_svg(force_figures(worked)[1][1])
    assert again == svg


def test_lever_forces_stand_at_their_turned_images():
    from plans.drawing.force_drawing import draw_lever
    from plans.forces.lever import joukowski_lever

    g = construct(load(example_path("slider-crank-loads")), precision=0.1)
    lever = joukowski_lever(g)
    artists = draw_lever(lever)
    # F_b at the turned image of the crank pin A: i·(image a on the velocity plan), ⊥ OA
    shaft = _by_gid(artists, "lever-force-F_b")
    xs, ys = shaft.get_data()
    assert complex(xs[0], ys[0]) == pytest.approx(1j * g.velocity_plan.images["a"], abs=1e-9)
    oa = g.positions["A"] - g.positions["O"]
    direction = complex(xs[-1] - xs[0], ys[-1] - ys[0])
    assert abs((direction * oa.conjugate()).real) <= 1e-9 * abs(direction) * abs(oa)
    texts = _texts(artists)
    assert "M_{\\mathrm{b}}" in texts["lever-result"] and "620" in texts["lever-result"]  # §11: 620.218316 N·m
    assert not any("−0.0 mm" in t for t in texts.values())


#: domain.md §11's table, typed here: the heading of a force plan in each language
FORCE_PLAN_WORDS = {"en": "Force plan", "sr": "План сила", "ru": "План сил", "bg": "План на силите", "sl": "Načrt sil"}


@pytest.mark.parametrize("lang", sorted(FORCE_PLAN_WORDS))
def test_the_heading_is_the_textbooks_word(lang):
    texts = _texts(draw_force_plan(TRIANGLE, lang=lang))
    assert texts["fplan-heading"] == f"{FORCE_PLAN_WORDS[lang]}: RRR(1,2)"
    decimal = "," if lang != "en" else "."
    assert texts["fplan-reading-R_12"] == rf"$R_{{\mathrm{{12}}}}$ = 40{decimal}0 mm · 10 N/mm = 400 N"
