"""The force pages after a teacher's review of the Russian handout (issue 20, branch force-minors).

Expected values come from outside the code under test: the offset slider-crank of domain.md §11 (O = 0, OA = 0.1 m,
AB = 0.3 m, B on y = 0.02 m, φ₂ = 60°, S₃ 100 mm from A, a_S3 = (−1044.53339, −1299.03811) m/s², J₃ = 0.025 kg·m²),
the luminance of a colour as black-and-white print renders it, shapely's geometry of the drawn arrows, and the
course's words typed here.
"""

from __future__ import annotations

import cmath
import io
import math
import re
import unicodedata

import pypdf
import pytest
from matplotlib.colors import to_rgb

from plans.scene import example_path, load
from review_handouts import built_pdf

OA, AB, E, PHI = 0.1, 0.3, 0.02, math.radians(60.0)
A_S3 = complex(-1044.53339, -1299.03811)


def _geometry() -> dict[str, complex]:
    """O, A, B, S₃ [m] of the worked example, by hand."""
    a = OA * cmath.exp(1j * PHI)
    b = complex(a.real + math.sqrt(AB ** 2 - (a.imag - E) ** 2), E)
    return {"O": 0j, "A": a, "B": b, "S3": a + (b - a) / 3}


def _grey(colour) -> float:
    """The grey a colour prints as in black and white (ITU-R BT.601 luma)."""
    r, g, b = to_rgb(colour)
    return 0.299 * r + 0.587 * g + 0.114 * b


def _head_print(head) -> tuple[bool, float]:
    """What a black-and-white print shows of an arrowhead: whether it is open (its inside lighter than its outline
    by more than a print tells apart), and its outline's grey."""
    face, edge = _grey(head.get_facecolor()), _grey(head.get_edgecolor())
    return face - edge > 0.25, round(edge, 2)


@pytest.fixture(scope="module")
def slider_crank():
    from plans.forces.force_plans import construct_force_plans
    from plans.graphical import construct

    g = construct(load(example_path("slider-crank-loads")), precision=0.1)
    return g, construct_force_plans(g)


def _by_gid(artists) -> dict:
    return {a.get_gid(): a for a in artists if a.get_gid()}


# 1. G and Φ told apart in black-and-white print ------------------------------------------------------------------


def test_weight_and_inertia_force_differ_in_print_on_free_bodies_and_lever(slider_crank):
    from plans.drawing.force_drawing import draw_free_bodies, draw_lever
    from plans.forces.lever import joukowski_lever

    g, plans = slider_crank
    for prefix, artists in (("fbody-force-", draw_free_bodies(plans)), ("lever-force-", draw_lever(joukowski_lever(g)))):
        heads = _by_gid(artists)
        for body in "34" if prefix == "lever-force-" else "234":
            weight, inertia = _head_print(heads[f"{prefix}G_{body}-head"]), _head_print(heads[f"{prefix}F_Phi{body}-head"])
            assert weight[0] and not inertia[0], (prefix, body, weight, inertia)  # G open, Φ filled: not a colour


def test_the_legends_sample_of_the_weight_is_open_as_drawn():
    from plans.drawing.force_blocks import force_key_svg

    def fills(kind: str) -> tuple[str, str]:
        svg = force_key_svg(kind).svg
        svg = svg.decode() if isinstance(svg, bytes) else svg
        head = re.findall(r'<g id="fkey-key-%s-head">\s*<path[^>]*style="([^"]*)"' % kind, svg)
        assert head, svg
        fill = re.search(r"fill: ?(#[0-9a-fA-F]{6})", head[0])[1].lower()
        stroke = re.search(r"stroke: ?(#[0-9a-fA-F]{6})", head[0])[1].lower()
        return fill, stroke

    fill, stroke = fills("weight")
    assert _grey(fill) - _grey(stroke) > 0.25  # the legend's G: an open head, as on the drawings
    fill, stroke = fills("inertia")
    assert fill == stroke


# 2. the arms h of the moment equations drawn on the free bodies ---------------------------------------------------


def test_each_arm_the_equations_use_is_drawn_square_to_its_force_with_its_length(slider_crank):
    from plans.drawing.force_drawing import draw_free_bodies
    from plans.forces.plan_equations import plan_equations

    g, plans = slider_crank
    equations = plan_equations(plans)
    artists = _by_gid(draw_free_bodies(plans, equations=equations))
    p = _geometry()
    s3, b = (complex(*artists[gid].center) for gid in ("fbody-centre-3", "fbody-pin-B"))
    k_l = abs(p["S3"] - p["B"]) / abs(s3 - b)  # the drawing's k_l, from S₃B drawn
    # group 3–4, ΣM_B over link 3: G₃ (down, through S₃) and Φ₃ (along −a_S3, through S₃), in that order: h₁, h₂
    u_phi = -A_S3 / abs(A_S3)
    expected = {1: (p["S3"] - p["B"]).real, 2: abs(((p["S3"] - p["B"]) * u_phi.conjugate()).imag)}
    directions = {1: -1j, 2: u_phi}
    for k, h in expected.items():
        (x0, x1), (y0, y1) = artists[f"fbody-arm-h{k}"].get_data()
        c, f = complex(x0, y0), complex(x1, y1)
        assert abs(f - c) == pytest.approx(abs(h) / k_l, abs=0.15), k
        assert abs(((f - c) * directions[k].conjugate()).real) < 1e-6 * abs(f - c), k  # square to the line of action
        label = artists[f"fbody-arm-label-h{k}"].get_text()
        assert label.startswith(f"$h_{{{k}}}$ = ") and label.endswith(" mm"), label
        assert float(label.split("= ")[1].split()[0]) == pytest.approx(abs(f - c), abs=0.1)
    # the driver's ΣM_O: Φ₂ acts along OA (a_S2 is centripetal, ω₂ constant) through O, its arm 0 and not drawn; every
    # other arm the equations name is drawn, each name once
    numbers = [t.number for e in equations for m in e.moments for t in m.terms if t.arm is not None]
    numbers += [t.number for e in equations for t in e.balancing if t.arm is not None]
    assert sorted(numbers) == list(range(1, len(numbers) + 1))  # h₁ … h₅, one name each over the page
    phi2 = [t.number for e in equations for t in e.balancing if t.label == "F_Φ2"]
    drawn = sorted(int(gid[len("fbody-arm-h"):]) for gid in artists if re.fullmatch(r"fbody-arm-h\d+", gid))
    assert drawn == [n for n in numbers if n not in phi2] and len(phi2) == 1


def test_the_pages_equations_name_the_arms_as_the_free_bodies_do():
    from plans.forces.compare import kinetostatics
    from plans.pages.forces import force_document

    doc = force_document(kinetostatics(load(example_path("four-bar-loads"))), "ru")[0]
    source = doc.source()
    named = [int(k) for k in re.findall(r" dot h_(\d+)", source)]
    assert named and sorted(named) == list(range(1, len(named) + 1))  # two groups' and the driver's equations: no h twice
    svg = doc.images["forces-free-bodies"]
    svg = svg.decode() if isinstance(svg, bytes) else svg
    drawn = sorted(int(k) for k in re.findall(r'<g id="fbody-arm-h(\d+)"', svg))
    assert drawn and set(drawn) <= set(named) and len(drawn) >= len(named) - 2


# 3. coincident arrows on the lever ------------------------------------------------------------------------------


def test_no_arrow_on_the_lever_lies_over_another(slider_crank):
    from shapely.geometry import LineString

    from plans.drawing.force_drawing import draw_lever
    from plans.forces.lever import joukowski_lever

    g, _ = slider_crank
    lever = joukowski_lever(g)
    artists = _by_gid(draw_lever(lever))
    arrows = {}
    for gid, a in artists.items():
        if re.fullmatch(r"lever-force-(?!label-).*", gid) and not gid.endswith("-head"):
            xs, ys = a.get_data()
            tip = complex(*artists[gid + "-head"].get_xy()[0])
            arrows[gid] = (complex(xs[0], ys[0]), tip)
    assert {"lever-force-F_Phi4", "lever-force-F_r"} <= set(arrows)  # Φ₄ and the resistance, both at b along +x
    b = complex(lever.images["b"])
    for gid in ("lever-force-F_Phi4", "lever-force-F_r"):
        tail, tip = arrows[gid]
        u = (tip - tail) / abs(tip - tail)
        assert abs(((tail - b) * u.conjugate()).imag) < 1e-9  # on its line of action through b: its arm unchanged
    def past_tail(tail: complex, tip: complex) -> LineString:  # an arrow but its first 2 mm (two from one image part there)
        start = tail + 2.0 * (tip - tail) / abs(tip - tail)
        return LineString([(start.real, start.imag), (tip.real, tip.imag)])

    for first, (t1, h1) in arrows.items():
        for second, (t2, h2) in arrows.items():
            if first < second:
                shared = past_tail(t1, h1).intersection(past_tail(t2, h2).buffer(0.3)).length
                assert shared < 0.5, (first, second, shared)  # no shaft along another's
                assert abs(h1 - h2) > 2.0, (first, second)  # each head by itself


# 4, 5. the title blocks' scales and one number for one quantity, on the Russian handout -------------------------


@pytest.fixture(scope="module")
def handout_ru():
    pdf = built_pdf("slider-crank-loads", None, "ru", forces=True)
    return [re.sub(r"[ \t]+", " ", unicodedata.normalize("NFKC", p.extract_text() or "")) for p in pypdf.PdfReader(io.BytesIO(pdf)).pages]


def test_every_force_page_states_mu_f_in_its_title_block(handout_ru):
    force_pages = [t for t in handout_ru if "Кинетостатический анализ —" in t]
    mu = re.search(r"планы сил; μF = ([0-9,]+) Н/мм", "\n".join(force_pages))[1]
    assert len(force_pages) >= 3
    for page in force_pages:  # the last one, the lever's, too
        block = page[page.rindex("Масштабы:"):]
        assert f"μF = {mu} Н/мм" in block, block


def test_the_lever_pages_state_the_levers_own_k_v():
    from plans.handout import handout

    doc = handout(load(example_path("six-bar-loads")), forces=True, lang="ru")
    texts = [re.sub(r"\s+", " ", unicodedata.normalize("NFKC", p.extract_text() or "")) for p in pypdf.PdfReader(io.BytesIO(doc.pdf())).pages]
    first = next(k for k, t in enumerate(texts) if "Кинетостатический анализ — Рычаг Жуковского" in t)
    own = re.search(r"Рычаг Жуковского kv = ([0-9,]+) \(м/с\)/мм; план скоростей", texts[first])[1]
    rest = [t for t in texts[first:] if "Моменты относительно полюса" in t or t is texts[first]]
    for page in rest:  # the lever's page and the page of its moments (h in mm at the lever's k_v)
        block = page[page.rindex("Масштабы:"):]
        assert f"Рычаг Жуковского: kv = {own} (м/с)/мм" in block and "μF =" in block, block


def test_a_point_read_off_the_plan_prints_one_number(handout_ru):
    text = "\n".join(handout_ru)
    compared = re.search(r"aS3 \[м/с2\] ([0-9,]+) ∠ ([0-9,]+)° ([0-9,]+) ∠", text)
    read = re.search(r"aS3 π s3′ ([0-9,]+) × ([0-9,]+) ([0-9,]+) м/с2", text)
    assert compared and read
    assert compared[1] == read[3]  # the comparison table's "по плану" is the readings table's value
    mm, k = (float(x.replace(",", ".")) for x in read.group(1, 2))
    assert abs(mm * k - float(read[3].replace(",", "."))) <= 0.5 + 1e-9  # 111,1 × 15 = 1666,5: the value printed from it
    # and the analytic a_S3 of domain.md §11 within the reading's resolution (0.1 mm × 15)
    assert abs(float(compared[3].replace(",", ".")) - abs(A_S3)) <= 0.5


def test_the_levers_pair_is_what_the_printed_couple_gives(handout_ru):
    text = "\n".join(handout_ru)
    rows = re.findall(r"Ф′+3 [ab] ([0-9,]+) −?[0-9,]+ −?[0-9]+ = MФ3/lAB = ([0-9,]+) Н·м / ([0-9,]+) м", text)
    assert len(rows) == 2, text
    for force, couple, length in rows:
        f, m, l = (float(x.replace(",", ".")) for x in (force, couple, length))
        decimals = len(force.partition(",")[2])
        assert round(m / l, decimals) == pytest.approx(f), (force, couple, length)
    # M_Φ3 = J₃·ε₃ read off the plan (130,2 mm × 15 (м/с²)/мм ÷ 0,3 м = 6510 рад/с²): 0,025 · 6510 = 162,75 Н·м, one text
    # in the loads' table, in the moment equation and on the lever
    assert rows[0][1] == "162,75"
    assert re.search(r"MФ3 3 момент сил инерции −162,75 Н·м", text)
    assert re.search(r"− 162,75 = 0", text)


def test_two_balancing_moments_say_which_method_gave_each(handout_ru):
    text = "\n".join(handout_ru)
    plans_line = re.search(r"Mур = ([0-9,]+) Н·м ↺ \(уравновешивающий момент, по планам сил\)", text)
    lever_line = re.search(r"= ([0-9,]+) Н·м ↺ \(уравновешивающий момент, по рычагу Жуковского\)", text)
    assert plans_line and lever_line
    # both M_b = 620.218316 N·m of domain.md §11 to the drafting precision
    for line in (plans_line, lever_line):
        assert float(line[1].replace(",", ".")) == pytest.approx(620.218316, rel=0.005)
