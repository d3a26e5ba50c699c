"""The force pages and the forces table after the second teacher's review (issue 20, branch forces2).

Expected words and units are typed here from the courses (the useful resistance: сила полезного сопротивления,
сила на полезното съпротивление, сила корисног отпора, sila koristnega upora; Н, Н·м, рад/с, Вт in the Russian and
Bulgarian courses), never read from the program's own tables.
"""

from __future__ import annotations

import re

import pytest

import plans
from plans.scene import example_path

USEFUL_RESISTANCE = {"en": "useful resistance", "sr": "сила корисног отпора", "ru": "сила полезного сопротивления",
                     "bg": "сила на полезното съпротивление", "sl": "sila koristnega upora"}


@pytest.fixture(scope="module")
def run():
    from plans.forces.compare import kinetostatics

    return kinetostatics(plans.load(example_path("slider-crank-loads")))


@pytest.mark.parametrize("lang", ["en", "sr", "ru", "bg", "sl"])
def test_the_resistance_is_named_the_useful_resistance_on_the_data_page(run, lang):
    from plans.pages.forces import force_document

    source = force_document(run, lang)[0].source()
    cell = r'text\(weight: "regular"\)\[([^\]]*)\]'
    # the loads' table: the resistance's row (on the slider, link 4) says what the load is in the course's words
    rows = re.findall(r'text\(weight: "regular"\)\[\$F_[^$]*\$\], ' + cell + ", " + cell, source)
    kinds = [kind for link, kind in rows if link == '#"4"']  # (en: the inertia force F_Φ4 first)
    assert kinds[-1] == f'#"{USEFUL_RESISTANCE[lang]}"' and len(kinds) <= 2
    # and the input data's line of it
    assert re.search(re.escape(f'#"{USEFUL_RESISTANCE[lang]} "') + r"#box\[\$F_", source)


def _table(run, lang):
    from plans.forces.report import forces_table

    return forces_table(run, lang)


@pytest.mark.parametrize("lang", ["ru", "bg"])
def test_the_forces_table_writes_the_units_as_the_course_does(run, lang):
    table = _table(run, lang)
    lines = table.splitlines()
    assert "ω = 150 рад/с, ε = 0 рад/с²" in lines[2]
    loads = next(line for line in lines if line.endswith("[Н, Н·м]"))
    assert loads
    assert re.search(r"x \[м\] +y \[м\]", table)
    assert re.search(r"\[Н\]; R_ij", table)
    assert "N = -2077.57 Н ∥" in table and ") м\n" in table
    assert re.search(r"M_ур \[Н·м\]", table)
    assert re.search(r"\[Вт\]: M_ур·ω = ", table)
    # no English unit symbol left outside the symbols of quantities (N: the normal force, Fx, ω…)
    words = re.sub(r"\bN = ", "", table)
    assert not re.search(r"(?<![\w/])(N|N·m|W|rad/s²?|m/s²?|m)(?![\w/])", words)


@pytest.mark.parametrize("lang", ["en", "sr", "sl"])
def test_the_forces_table_keeps_the_international_units_elsewhere(run, lang):
    table = _table(run, lang)
    assert "ω = 150 rad/s" in table and "[N, N·m]" in table and "[W]:" in table and "[N·m]" in table


def test_the_json_keys_do_not_follow_the_language(run):
    from plans.forces.report import forces_json

    doc = forces_json(run)
    assert {"reactions", "balancing"} <= set(doc)
    assert "R_23" in doc["reactions"]


def test_a_colon_after_a_math_name_in_the_loop_block_sits_outside_math():
    from types import SimpleNamespace

    from plans.pages.document import Document

    doc = Document(plans.load(example_path("quick-return")), "sr")
    doc.loop_block(SimpleNamespace(title="група 5–6", lines=["$z_{Q_E}$ = 0,52 i m"], origins=["E"]))
    line = next(piece for piece in doc.body if "тачка вођице" in piece)
    # Q_E in math, the colon in the text after it (a colon in math is a relation: a space before it)
    assert re.search(r'\$Q_\(?E ?\)?\$#": тачка вођице', line), line
    assert not re.search(r":[^$]*\$#\" тачка", line)


# labels clear of the bodies' names and of each other --------------------------------------------------------------


def _drawing_words(pdf: bytes):
    """The words of the free bodies' drawing on the first page (pdftotext -bbox, mm): under the page's heading and
    over the line that states the drawing's k_l."""
    from sheet_pages import words

    found = words(pdf)
    heading = found[0][1][3]
    scale = min(box[1] for word, box in found if re.search(r"/(mm|мм);", word))
    return [(word, box) for word, box in found if box[1] > heading + 0.5 and box[3] < scale - 0.5]


@pytest.mark.parametrize("example, lang, k_l", [("slider-crank-loads", "ru", 0.003), ("six-bar-loads", "en", 0.008),
                                                ("quick-return-loads", "bg", 0.005), ("scotch-yoke-loads", "ru", 0.003)])
def test_no_label_on_the_free_bodies_overlaps_a_name_or_another_label(example, lang, k_l):
    """At each handout's plate k_l (the review's R₂₃ on "group 3–4 (II₂)" of the Russian slider-crank fails)."""
    from sheet_pages import overlap

    from plans.forces.compare import kinetostatics
    from plans.pages.forces import force_document

    from plans.pages.typesetting import compile_document

    doc = force_document(kinetostatics(plans.load(example_path(example)), k_l=k_l), lang)[0]
    drawn = _drawing_words(compile_document(doc.source(), doc.images, "pdf"))
    assert len(drawn) > 10
    # two words overlap when their boxes share more than 0.4 mm both ways (a letter and its subscript only touch)
    hits = [(a[0], b[0]) for k, a in enumerate(drawn) for b in drawn[k + 1:] if overlap(a[1], b[1], 0.4)]
    assert not hits, hits


# the crank's free body: arrows and arcs clear of each other and of the bars ---------------------------------------


def _free_body_shapes(k_l: float):
    """The Russian slider-crank's free bodies as the handout draws them at *k_l*: {gid: shapely shape} of the bars
    (centre lines), the force arrows' shafts (centre lines) and heads, and the couples' arcs and heads [mm]."""
    from shapely.geometry import LineString, Polygon

    from plans.drawing._canvas import sketch_on
    from plans.drawing.force_drawing import draw_free_bodies_into
    from plans.forces.compare import kinetostatics
    from plans.forces.force_plans import construct_force_plans
    from plans.pages.forces import drawn_group_names

    run = kinetostatics(plans.load(example_path("slider-crank-loads")), k_l=k_l)
    forces = construct_force_plans(run.graphical, mu_F=80.0)
    names = drawn_group_names(forces.plans, "ru")
    artists = sketch_on(None, "fbody", lambda sketch: draw_free_bodies_into(sketch, forces, lang="ru", k_l=k_l, names=names))
    shapes = {}
    for a in artists:
        gid = a.get_gid() or ""
        if not gid.startswith(("fbody-force-", "fbody-couple-", "fbody-link-")) or "label" in gid:
            continue
        if hasattr(a, "get_xy") and gid.endswith("-head"):
            shapes[gid] = Polygon(a.get_xy())
        elif hasattr(a, "get_data"):
            xs, ys = a.get_data()
            shapes[gid] = LineString(list(zip(xs, ys)))
    return shapes


@pytest.mark.parametrize("k_l", [0.003, 0.005])
def test_an_arrow_along_a_bar_is_drawn_clear_of_it(k_l):
    """F_Ф2 (Ф₂) acts at S₂ along the crank: it is drawn beside the bar, its head a visible gap (≥ 1 mm) off the
    bar's edge (the bar 2.2 pt wide: 0.39 mm a side)."""
    shapes = _free_body_shapes(k_l)
    bar, head, shaft = shapes["fbody-link-2"], shapes["fbody-force-F_Phi2-head"], shapes["fbody-force-F_Phi2"]
    assert shaft.distance(bar) > 0  # drawn beside it, not on it
    assert head.distance(bar) - 0.39 >= 1.0


@pytest.mark.parametrize("k_l", [0.003, 0.005])
def test_a_couples_arrowhead_lands_on_no_arrow(k_l):
    """The review's M_Ф3 head running into G₃: every couple's head, and the way it points for a head's length more
    (2.6 mm), stands off every force arrow (shaft and head) by ≥ 1 mm (a gap that reads at print size)."""
    from shapely.geometry import LineString

    shapes = _free_body_shapes(k_l)
    arrows = {gid: s for gid, s in shapes.items() if gid.startswith("fbody-force-")}
    heads = {gid: s for gid, s in shapes.items() if gid.startswith("fbody-couple-") and gid.endswith("-head")}
    assert {"fbody-couple-M_Phi3-head", "fbody-couple-M_b-head"} <= set(heads)
    near = []
    for h, head in heads.items():
        tip, left, right = (complex(x, y) for x, y in list(head.exterior.coords)[:3])
        u = (tip - (left + right) / 2) / abs(tip - (left + right) / 2)
        ahead = LineString([(tip.real, tip.imag), ((tip + 2.6 * u).real, (tip + 2.6 * u).imag)]).union(head)
        near += [(h, a, round(ahead.distance(t), 2)) for a, t in arrows.items() if ahead.distance(t) < 1.0]
    assert not near


# the pages flow --------------------------------------------------------------------------------------------------


def test_the_force_plans_follow_the_free_bodies_and_each_title_block_states_its_page(tmp_path):
    """The scotch-yoke's free bodies (a coarser k_l than the plate's 0.003 m/mm: 0.005) leave half their page empty:
    the force plans start under them; that page's title block states the free bodies' k_l and μ_F, the next the
    plate's k_l; no heading stands at a page's foot (the lever's heading is on the page of its drawing)."""
    import io

    import pypdf

    from plans.forces.compare import kinetostatics
    from plans.pages.forces import force_document
    from plans.pages.typesetting import compile_document

    doc = force_document(kinetostatics(plans.load(example_path("scotch-yoke-loads")), k_l=0.003), "ru")[0]
    pages = [" ".join((p.extract_text() or "").split()) for p in pypdf.PdfReader(io.BytesIO(compile_document(doc.source(), doc.images, "pdf"))).pages]
    first = pages[0]
    assert "нагрузки и реакции групп" in first and "планы сил" in first
    assert first.index("нагрузки и реакции групп") < first.index("планы сил")
    scale = [re.search(r"Масштабы: (.*)", p)[1] for p in pages]
    assert re.search(r"0,005 м/мм", scale[0]) and "2,5 Н/мм" in scale[0]
    assert all("0,003 м/мм" in s for s in scale[1:])
    lever = next(p for p in pages if "Рычаг Жуковского" in p)
    assert "Моменты относительно полюса" in lever
