"""The Russian handout's force pages as a teacher's review found them (issue 20, branch forces-ru).

Expected values come from outside the code under test: the scene file as typed (read with tomllib here), the
worked example of domain.md §11 (R₂₃ = 8353.55006 N at 192.098702°, v_B < 0 so the resistance acts along +x), the
geometry of the offset slider-crank (OA = 0.1 m, AB = 0.3 m, e = 0.02 m, φ₂ = 60°), the course's letters (Ф₃ and
M_Ф3 for the inertia force and couple, M_ур, F_пс; дезаксаж), and shapely's geometry of the drawn arrows.
"""

from __future__ import annotations

import io
import math
import re
import tomllib
import unicodedata

import pypdf
import pytest

from plans.i18n import term
from plans.scene import example_path, load
from review_handouts import built, built_pdf

R_23, R_23_ANGLE = 8353.55006, 192.098702
OA, AB, E, PHI = 0.1, 0.3, 0.02, math.radians(60.0)


def _texts(doc, form: str = "NFKC") -> list[str]:
    """The pages' text of *doc* (a Handout, or its PDF): NFKC (math italics read as letters, subscripts as digits) or
    NFC (subscripts kept)."""
    pdf = doc if isinstance(doc, bytes) else doc.pdf()
    return [re.sub(r"[ \t]+", " ", unicodedata.normalize(form, p.extract_text() or "")) for p in pypdf.PdfReader(io.BytesIO(pdf)).pages]


def _svg(doc, key: str) -> str:
    svg = doc.images[key]
    return svg.decode() if isinstance(svg, bytes) else svg


def _svg_texts(doc, key: str) -> list[str]:
    return re.findall(r"<text[^>]*>([^<]*)</text>", _svg(doc, key))


@pytest.fixture(scope="module")
def scl_ru():
    return built("slider-crank-loads", None, "ru", forces=True), _texts(built_pdf("slider-crank-loads", None, "ru", forces=True))


def _force_pages(texts):
    return [t for t in texts if term("kinetostatics", "ru") in t]


# 1. what Q_B is, and the load as input data ----------------------------------------------------------------------


def test_the_guide_point_q_b_is_said_in_words_and_the_load_is_input_data(scl_ru):
    doc, texts = scl_ru
    loops = next(t for t in texts if "точка направляющей" in t)
    assert re.search(r"QB — точка направляющей, от которой отсчитывается перемещение sB ползуна", loops), loops
    assert loops.index("zQB (sB = 0)") < loops.index("QB — точка направляющей")
    first = _force_pages(texts)[0]
    scene = tomllib.loads(example_path("slider-crank-loads").read_text(encoding="utf-8"))
    load_ = scene["load"][0]
    # the resistance as the scene gives it: 1500 N at B of link 4, against B's velocity; v_B < 0 here (domain.md
    # §11) so it acts along +x: 0°
    magnitude = load_["force"]["magnitude"].split()[0]
    assert re.search(rf"сила полезного сопротивления Fпс = {magnitude} Н, в точке {load_['at']} звена {load_['link']}, против скорости точки {load_['at']} \(∠ 0,0°\)", " ".join(first.split())), first


# 2. each plan's equations before it; one value of Rᵗ --------------------------------------------------------------


def test_each_plans_equations_come_before_its_drawing(scl_ru):
    doc, _ = scl_ru
    source = doc.source
    plans = [m.start() for m in re.finditer(r"forces-0-plan-(?:1|driver)", source)]
    # the moment equation of group 3–4 (ΣM_B) and the driver's (ΣM_O) precede their plans' images, in order
    group, driver = source.index('Σ M_("B")'), source.index('Σ M_("O")')
    first_plan = min(p for p in plans if "plan-1" in source[p:p + 20])
    driver_plan = min(p for p in plans if "plan-driver" in source[p:p + 25])
    assert group < first_plan < driver < driver_plan


def test_the_tangential_component_has_one_value_everywhere(scl_ru):
    _, texts = scl_ru
    plans_page = next(t for t in _force_pages(texts) if "Σ" in t or "ΣM" in t.replace(" ", ""))
    flat = plans_page.replace("\n", " ")
    equation = re.search(r"⇒\s*R\s*t?\s*23\s*t?\s*=\s*([0-9]+)\s*Н", flat)
    found = re.search(r"найдено первым[^:]*:\s*R\s*t?\s*23\s*t?\s*=\s*([0-9]+)\s*Н", flat)
    assert equation and found, flat
    assert equation[1] == found[1]
    # the worked example's R₂₃ across AB: Rᵗ = |R₂₃|·|sin(∠R₂₃ − φ₃)|, φ₃ from the offset slider-crank
    phi3 = math.asin((E - OA * math.sin(PHI)) / AB)
    expected = R_23 * abs(math.sin(math.radians(R_23_ANGLE) - phi3))
    assert float(found[1]) == pytest.approx(expected, rel=2e-3)


# 3. one spelling of the centres of mass ---------------------------------------------------------------------------


def test_the_centres_are_spelt_as_the_scene_writes_them_on_every_page(scl_ru):
    doc, texts = scl_ru
    scene = tomllib.loads(example_path("slider-crank-loads").read_text(encoding="utf-8"))
    named = scene["link"]["3"]["centre"]  # "S3" as typed
    assert named == "S3"
    kinematic = _texts(built_pdf("slider-crank-loads", None, "ru", forces=True), "NFC")
    assert named in kinematic[0]
    bodies = _svg_texts(doc, "forces-0-free-bodies")
    lever = _svg_texts(doc, "forces-0-lever")
    assert "S3" in bodies and "S2" in bodies and not {"S₂", "S₃"} & set(bodies)
    assert "s3" in lever and "s2" in lever and not {"s₂", "s₃"} & set(lever)
    for page in _force_pages(kinematic):
        assert not re.search("[Ss][₂₃₄]", page), page


def _free_body_texts(example: str, lang: str) -> list[str]:
    from plans.drawing.force_drawing import draw_free_bodies
    from plans.forces.compare import kinetostatics
    from plans.forces.force_plans import construct_force_plans

    run = kinetostatics(load(example_path(example)))
    return [a.get_text() for a in draw_free_bodies(construct_force_plans(run.graphical, mu_F=None), lang=lang) if hasattr(a, "get_text")]


def test_centres_the_scene_does_not_name_keep_the_courses_subscript():
    texts = _free_body_texts("four-bar-loads", "en")
    assert "S₂" in texts and "S2" not in texts


# 4., 7. the course's letters -------------------------------------------------------------------------------------


def test_the_russian_pages_write_the_inertia_force_and_couple_as_the_course_does(scl_ru):
    doc, texts = scl_ru
    for page in _force_pages(texts):
        assert "Φ" not in page, page  # the Greek capital phi of the program's F_Φ
    flat = " ".join(_force_pages(texts))
    assert "Ф" in flat
    for key in ("forces-0-free-bodies", "forces-0-lever"):
        drawn = _svg(doc, key)
        assert "Ф" in drawn and "Φ" not in drawn, key
    source = doc.source
    assert 'abs(M_("Ф3" ))' in source and 'Ф_("3" )' in source and "Φ" not in source[source.index("forces-0-free-bodies"):]


def test_an_english_drawing_keeps_f_phi():
    drawn = " ".join(_free_body_texts("slider-crank-loads", "en"))
    assert "Φ" in drawn and "Ф" not in drawn
    assert "Ф" in " ".join(_free_body_texts("slider-crank-loads", "ru"))


def test_the_russian_text_output_uses_the_courses_letters(capsys):
    from plans.cli import main

    assert main(["forces", "--example", "slider-crank-loads", "--lang", "ru"]) == 0
    out = capsys.readouterr().out
    for word in ("M_ур", "F_пс", "Ф_3", "M_Ф3"):
        assert word in out, word
    for word in ("M_b", "F_r ", "F_Φ", "M_Φ"):
        assert word not in out, word


def test_offset_is_the_courses_word(scl_ru):
    _, texts = scl_ru
    first = _force_pages(texts)[0]
    assert f"дезаксаж e = {E * 1000:.0f} мм" in first and "дезаксиал " not in first


# 6. no arrow across another on a free body -----------------------------------------------------------------------


def _circumcentre(p: complex, q: complex, r: complex) -> complex:
    """The centre of the circle through three points (a couple's arc)."""
    w = (r - p) / (q - p)
    return (q - p) * (w - abs(w) ** 2) / (2j * w.imag) + p


@pytest.mark.parametrize("k_l", [0.003, 0.005])
def test_no_arrow_crosses_another_on_the_free_bodies(k_l):
    """Two arrows may touch only at the point both act at (near an end of each: a joint's reaction and the loads
    at it); a couple's arc may cross only an arrow that acts at its own centre.  The review's R₁₂ across G₂ fails."""
    from shapely.geometry import LineString, Point, Polygon

    from plans.drawing.force_drawing import draw_free_bodies
    from plans.forces.compare import kinetostatics
    from plans.forces.force_plans import construct_force_plans

    run = kinetostatics(load(example_path("slider-crank-loads")), k_l=k_l)
    artists = draw_free_bodies(construct_force_plans(run.graphical, mu_F=100.0))
    shapes, ends, centres = {}, {}, {}
    for a in artists:
        gid = a.get_gid() or ""
        if not gid.startswith(("fbody-force-", "fbody-couple-")):
            continue
        name = gid.removesuffix("-head")
        if gid.endswith("-head"):
            shape = Polygon(a.get_xy())
        elif not hasattr(a, "get_data"):
            continue  # its name (placed clear of every mark)
        else:
            xs, ys = a.get_data()
            zs = [complex(x, y) for x, y in zip(xs, ys)]
            shape = LineString([(z.real, z.imag) for z in zs]).buffer(0.2)
            if name.startswith("fbody-couple-"):
                centres[name] = _circumcentre(zs[0], zs[len(zs) // 2], zs[-1])
            else:
                ends[name] = (zs[0], zs[-1])
        shapes[name] = shape if name not in shapes else shapes[name].union(shape)
    assert "fbody-force-R_12" in ends and "fbody-force-G_2" in ends and "fbody-couple-M_b" in centres
    names = sorted(shapes)
    crossing = []
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            meet = shapes[a].intersection(shapes[b])
            if meet.is_empty:
                continue
            where = complex(meet.centroid.x, meet.centroid.y)
            couple = next((n for n in (a, b) if n in centres), None)
            if couple is not None:
                other = b if couple == a else a
                if other in centres or min(abs(z - centres[couple]) for z in ends[other]) > 2.0:
                    crossing.append((a, b))
            elif not all(min(abs(where - z) for z in ends[n]) <= 4.0 for n in (a, b)):
                crossing.append((a, b))
    assert not crossing


# 8. one k_l per plate, or the page says why ------------------------------------------------------------------------


def test_the_scotch_yokes_free_bodies_say_why_their_k_l_is_coarser():
    from plans.pages.forces import FREE_BODIES_BOX

    doc = built("scotch-yoke-loads", None, "ru", forces=True)
    texts = _texts(built_pdf("scotch-yoke-loads", None, "ru", forces=True))
    plate = re.search(r"k ?l = ([0-9,]+) м/мм", texts[0])[1]
    first = _force_pages(texts)[0]
    drawn = re.search(r"k ?l = ([0-9,]+) м/мм; стрелки не в масштабе", first)[1]
    if drawn != plate:
        assert f"при масштабе плана" in first and plate in first.split("стрелки не в масштабе", 1)[1][:120], first
        # and truly: the free bodies at the plate's k_l are wider than the text (one body a row, the narrowest)
        from plans.drawing.force_blocks import free_bodies_svg
        from plans.forces.compare import kinetostatics
        from plans.forces.force_plans import construct_force_plans

        k = float(plate.replace(",", "."))
        run = kinetostatics(load(example_path("scotch-yoke-loads")), k_l=k)
        block = free_bodies_svg(construct_force_plans(run.graphical, mu_F=2.5), k, "ru", 1, None)
        assert block.width > FREE_BODIES_BOX[0]
