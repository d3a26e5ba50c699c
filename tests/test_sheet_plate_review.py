"""The A3 sheet's plate, as a teacher reviewed it (issue 20): one arrangement, the comparison table's decimals,
the driver's position in the given data, the driver's acceleration drawn as an absolute vector, the title block's
student fields, the proportions of the plans' similar images."""

from __future__ import annotations

from plans.compare import Comparison
from plans.report import sheet_table


def test_analytic_column_keeps_the_graphical_decimals():
    # hand rows: ω₃ analytic exactly 0.25 rad/s, read 0.2504 at no resolution (4 significant digits: 0.2504);
    # ε₃ analytic 2 rad/s², read 2.001: the analytic one is printed 2.000, never 2; v_C 1.5 m/s along 90°
    rows = [Comparison("links", "3", "omega", 0.25, 0.2504, 4e-4, 1.6e-3),
            Comparison("links", "3", "epsilon", 2.0, 2.001, 1e-3, 5e-4),
            Comparison("points", "C", "v", 1.5j, 1.512j, 0.012, 8e-3)]
    table = sheet_table(rows)
    cells = {row[0]: (row[1], row[2]) for row in table[1:]}
    omega = next(v for k, v in cells.items() if "omega" in k)
    epsilon = next(v for k, v in cells.items() if "varepsilon" in k)
    velocity = next(v for k, v in cells.items() if "v_" in k)
    assert omega == ("0.2504", "0.2500")
    assert epsilon == ("2.001", "2.000")
    assert velocity == ("1.512 ∠ 90.0°", "1.500 ∠ 90.0°")
    # and no decimals the graphical one does not have: 6 beside 6, 0.72 beside 0.72
    same = sheet_table([Comparison("links", "2", "omega", 6.0, 6.0, 0.0, 0.0), Comparison("points", "A", "v", 0.72j, 0.72j, 0.0, 0.0)])
    assert [row[1:3] for row in same[1:]] == [["6", "6"], ["0.72 ∠ 90.0°", "0.72 ∠ 90.0°"]] or \
        [row[1:3] for row in same[1:]] == [["0.72 ∠ 90.0°", "0.72 ∠ 90.0°"], ["6", "6"]]


def test_the_sliding_drivers_acceleration_is_drawn_solid_as_an_absolute_vector():
    # the scheme's a_A is the driver point's given absolute acceleration: a solid shaft as the plans' legend draws
    # an absolute vector (a dashed one reads as a component); the linear-arm with a = 2 m/s² at its instant (the
    # bundled example runs at constant speed, a = 0: no a_A to draw)
    from plans.drawing import draw_mechanism
    from plans.graphical import construct

    from accelerating_scenes import linear_arm_accelerating

    artists = draw_mechanism(construct(linear_arm_accelerating()))
    shafts = {a.get_gid(): a for a in artists if a.get_gid() in ("mech-velocity", "mech-acceleration")}
    assert set(shafts) == {"mech-velocity", "mech-acceleration"}
    for shaft in shafts.values():
        assert shaft.get_linestyle() == "-", shaft.get_gid()


def _arm_at(s: float):
    import dataclasses

    from plans.graphical import construct
    from plans.scene import example_path, load

    scene = load(example_path("linear-arm"))
    scene = dataclasses.replace(scene, driver=dataclasses.replace(scene.driver, s=s))
    return construct(scene)


def test_the_sliding_drivers_position_is_in_the_given_data():
    # the Bulgarian linear-arm sheet at s = 25 mm along the floor: the driver's line says so (decimal comma, мм)
    from plans.pages.sheet import sheet_at

    source = sheet_at(_arm_at(0.025), lang="bg").source
    driver_line = next(line for line in source.splitlines() if "Водещо звено" in line)
    assert "s = 25,0 мм" in driver_line.replace("#box[", "").replace("]", "")


import pytest
from review_handouts import drawn_sheet

#: the title block's student fields as a course plate writes them (the words written out here, not read from i18n)
STUDENT_FIELDS = {
    "en": ("Institution", "Drawn by", "Student no.", "Group", "Checked by", "Date"),
    "sr": ("Установа", "Цртао", "Бр. индекса", "Група", "Прегледао", "Датум"),
    "ru": ("Учебное заведение", "Разработал", "№ зач. книжки", "Группа", "Проверил", "Дата"),
    "bg": ("Учебно заведение", "Изработил", "Фак. №", "Група", "Проверил", "Дата"),
    "sl": ("Ustanova", "Risal", "Vpisna št.", "Skupina", "Pregledal", "Datum"),
}


@pytest.mark.parametrize("lang", sorted(STUDENT_FIELDS))
@pytest.mark.parametrize("page", ["A3_LANDSCAPE", "A4_PORTRAIT"])
def test_title_block_has_the_students_fields(lang, page):
    # the same title block on a sheet (A3) and a handout page (A4): set, compiled, and its words read off the PDF
    import io

    from pypdf import PdfReader

    from plans.pages import document
    from plans.pages.typesetting import compile_document
    from plans.scene import example_path, load

    doc = document.Document(load(example_path("four-bar")), lang, getattr(document, page))
    doc.line("x")
    pdf = compile_document(doc.source(), doc.images, "pdf")
    words = " ".join(PdfReader(io.BytesIO(pdf)).pages[0].extract_text().split())
    for field in STUDENT_FIELDS[lang]:
        assert f"{field}:" in words, (lang, field)


def test_the_quick_returns_plans_state_the_proportion_of_images():
    # D is placed on the velocity plan by similarity: pd / pa₄ = CD / CA (C at the pole).  By hand: O (0, 250) mm,
    # OA = 120 mm at φ = 30°: A = (103.92, 310.0), CA = 326.96 mm; CD = 550 mm.  |v_A4| = ω₄·CA, |v_D| = ω₄·CD with
    # ω₄ from the analytic solution (the other method): the numbers printed are these over k_v
    import re

    import plans
    from plans.drawing.readings import similarity_lines
    from plans.graphical import construct

    scene = plans.load(plans.example_path("quick-return"))
    g = construct(scene)
    omega4 = abs(float(plans.solve(scene).links["4"].omega[0]))
    ca = abs(complex(120 * 3 ** 0.5 / 2, 250 + 60))
    (line,) = similarity_lines(g, "velocity")
    assert line.startswith("pd / p a₄ = CD / CA:  pd = ")
    pa4, cd, ca_printed, pd = (float(x) for x in re.findall(r"\d+\.\d", line.split(":  ")[1]))
    k_v = g.scales["k_v"]
    assert (cd, ca_printed) == (550.0, round(ca, 1))
    assert abs(pa4 - omega4 * ca / 1e3 / k_v) <= 0.06
    assert abs(pd - omega4 * 0.55 / k_v) <= 0.1
    (accel,) = similarity_lines(g, "acceleration")
    assert accel.startswith("π d′ / π a₄′ = CD / CA:  π d′ = ")


def test_a_triangle_of_images_states_both_sides():
    # four-bar's M on coupler 3 (A, B, M not on a line): the triangle abm similar to ABM, am = ab·AM/AB and bm = ba·BM/BA
    import re

    import plans
    from plans.drawing.readings import similarity_lines
    from plans.graphical import construct

    scene = plans.load(plans.example_path("four-bar"))
    g = construct(scene)
    (line,) = similarity_lines(g, "velocity")
    assert line.startswith("am / ab = AM / AB:  am = ")
    assert ";  bm / ba = BM / BA:  bm = " in line
    numbers = [float(x) for x in re.findall(r"\d+\.\d", line)]
    ab, am_len, ab_len, am_mm, _, bm_len, _, bm_mm = numbers
    # the printed side equals the plan's segment measured between the images
    assert abs(am_mm - abs(g.velocity_plan.images["a"] - g.velocity_plan.images["m"])) <= 0.06
    assert abs(bm_mm - abs(g.velocity_plan.images["b"] - g.velocity_plan.images["m"])) <= 0.06
    # the link's sides from the scene's data (link 3: A (0, 0), B (250, 0), M (100, 60) mm)
    assert (ab_len, am_len, bm_len) == (250.0, round((100 ** 2 + 60 ** 2) ** 0.5, 1), round((150 ** 2 + 60 ** 2) ** 0.5, 1))


@pytest.mark.parametrize("example, lang", [("six-bar", "en"), ("quick-return", "sr")])
def test_the_scheme_is_in_the_sheets_top_left_corner(example, lang):
    # one place for the scheme on every sheet, whatever its shape (the six-bar's tall one had its plans beside it and
    # stood in the middle of the left column; the quick-return's over its plans): the drawings' room starts at the text
    # area's top left corner (25 mm from the page's left edge, 10 mm from its top), the scheme 10.5 mm under it (its
    # name and k_l over it)
    import sheet_pages

    placed = {d.kind: d for d in sheet_pages.drawings(drawn_sheet(example, lang, "sheet.svg").read_bytes())}
    mechanism = placed["mechanism"]
    assert abs(mechanism.x - 25.0) < 0.05 and abs(mechanism.y - (10.0 + 10.5)) < 0.05, (mechanism.x, mechanism.y)
    # the plans after it in reading order: to its right or under it, never above it or left of it
    for kind in ("velocity", "acceleration"):
        plan = placed[kind]
        assert plan.x >= mechanism.x + mechanism.width - 0.5 or plan.y >= mechanism.y + mechanism.height - 0.5, kind
