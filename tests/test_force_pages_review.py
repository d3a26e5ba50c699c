"""The force pages of the handout as a teacher's second review found them (issues 20 and 22, branch r2-forces).

Expected values come from outside the code under test: the scene files as typed (read with tomllib here), the
worked example of domain.md §11 (R₂₃ = 8353.55006 N at 192.098702°, M_b = 620.218316 N·m, the geometry of the
offset slider-crank), and the course's symbols (M_ур, F_ур, F_пс on a Russian page).
"""

from __future__ import annotations

import cmath
import io
import math
import re
import tomllib
import unicodedata

import pypdf
import pytest

from plans.i18n import term
from plans.scene import example_path
from review_handouts import built, built_pdf

# domain.md §11: the worked example
R_23 = 8353.55006
R_23_ANGLE = 192.098702
M_B = 620.218316
OA, AB, E, PHI, OMEGA = 0.1, 0.3, 0.02, math.radians(60.0), 150.0


def _texts(doc) -> list[str]:
    """The pages' text of *doc* (a Handout, or its PDF)."""
    pdf = doc if isinstance(doc, bytes) else doc.pdf()
    return [re.sub(r"[ \t]+", " ", unicodedata.normalize("NFKC", p.extract_text() or "")) for p in pypdf.PdfReader(io.BytesIO(pdf)).pages]


def _number(text: str) -> float:
    return float(text.replace(",", ".").replace("−", "-"))


@pytest.fixture(scope="module")
def slider_crank_ru():
    return built("slider-crank-loads", None, "ru", forces=True), _texts(built_pdf("slider-crank-loads", None, "ru", forces=True))


@pytest.fixture(scope="module")
def six_bar_en():
    return built("six-bar-loads", None, "en", forces=True), _texts(built_pdf("six-bar-loads", None, "en", forces=True))


def _force_pages(texts, lang):
    return [t for t in texts if term("kinetostatics", lang) in t]


def _title_block_scale(page: str, lang: str, key: str) -> str:
    block = page[page.rindex(term("scale_factors", lang)):]
    found = re.search(rf"k{key} = ([0-9.,]+)", block)
    assert found, block
    return found[1]


# 1. one k_l on every page ----------------------------------------------------------------------------------------


@pytest.mark.parametrize("which, lang", [("slider_crank_ru", "ru"), ("six_bar_en", "en")])
def test_every_force_page_states_the_plates_k_l(which, lang, request):
    doc, texts = request.getfixturevalue(which)
    plate = _title_block_scale(texts[0], lang, "l")
    force = _force_pages(texts, lang)
    assert len(force) >= 3
    for page in force:
        assert _title_block_scale(page, lang, "l") == plate, page
    # and the free bodies are drawn at it: the line under them states the same k_l
    under = re.search(r"kl = ([0-9.,]+) (?:m|м)/(?:mm|мм);", force[0])
    assert under and under[1] == plate, force[0]


# 2. the input data of the force analysis ---------------------------------------------------------------------


def _as_typed(value: str, lang: str) -> str:
    """ "2 kg" -> "2", "0.004 kg*m^2" -> "0,004" (the page's decimal sign)."""
    number = value.split()[0]
    return number.replace(".", ",") if lang != "en" else number


def test_the_first_force_page_states_the_data_as_typed(slider_crank_ru):
    doc, texts = slider_crank_ru
    with open(example_path("slider-crank-loads"), "rb") as f:
        scene = tomllib.load(f)
    page = _force_pages(texts, "ru")[0]
    assert "Исходные данные для силового расчёта" in page
    assert "m [кг]" in page and "м [кг]" not in page  # the mass m, not the metre's Cyrillic м
    lines = page.splitlines()
    for link, table in scene["link"].items():
        mass, inertia = _as_typed(table["mass"], "ru"), _as_typed(table["inertia"], "ru")
        assert any(re.fullmatch(rf"{link} {re.escape(mass)} .+ {re.escape(inertia)}", line.strip()) for line in lines), (link, page)
    # the piston: its mass, its centre at its pin, no J
    slider = scene["slider"][0]
    assert any(re.fullmatch(rf"\d+ {_as_typed(slider['mass'], 'ru')} S\S* ≡ {slider['pin']} 0", line.strip()) for line in lines), page
    # the centre of the crank as typed (40 mm along OA) and of the rod (its point S3, 100 mm from A)
    assert re.search(r"lOS2 = 40 мм", page) and re.search(r"lAS3 = 100 мм", page), page
    # gravity, the resistance (its magnitude, point and what it opposes), the offset e of the guide
    assert f"g = {_as_typed(scene['gravity']['g'], 'ru')} м/с2, вниз" in page  # (NFKC: ² read as 2)
    load_ = scene["load"][0]
    assert f"{load_['force']['magnitude'].split()[0]} Н, в точке {load_['at']} звена {load_['link']}, против скорости точки {load_['at']}" in page
    through = scene["frame"]["lines"]["cylinder"]["through"][1]
    assert f"дезаксаж e = {through.split()[0]} мм" in page


# 3. the course's subscripts on a Russian page ---------------------------------------------------------------


def test_no_latin_subscript_of_the_balancing_moment_or_resistance_on_a_russian_page(slider_crank_ru):
    doc, texts = slider_crank_ru
    force = "\n".join(_force_pages(texts, "ru"))
    assert "Mур" in force and "Fпс" in force
    assert re.search(r"ΣMp ?= ?ΣF ?⋅ ?h ?\+ ?Fур ?⋅ ?hур ?= ?0", force), force  # the lever's equation, whole
    assert not re.search(r"(?<![A-Za-z])(?:M|F|h) ?[br](?![A-Za-zа-я])", force), re.findall(r".{20}(?<![A-Za-z])(?:M|F|h) ?[br](?![A-Za-zа-я]).{5}", force)
    # the drawings (their labels kept in the SVG as the mathtext they were set from)
    labels = []
    for key, svg in doc.images.items():
        if key.startswith("forces-"):
            labels += re.findall(r"<!-- (\$[^$]*\$) -->", svg.decode() if isinstance(svg, bytes) else svg)
    assert any(r"\mathrm{ур}" in label for label in labels) and any(r"\mathrm{пс}" in label for label in labels)
    assert not [label for label in labels if re.search(r"_\{\\mathrm\{[br]\}\}", label)]


def test_an_english_page_keeps_b_and_r(six_bar_en):
    doc, texts = six_bar_en
    assert "Mb" in "\n".join(_force_pages(texts, "en"))


# 4. the force plans' equations --------------------------------------------------------------------------------


def _rt_23_of_the_worked_example() -> float:
    """|Rᵗ₂₃| of §11: R₂₃ resolved across AB (B on y = e to the right of A)."""
    a = OA * cmath.exp(1j * PHI)
    b = complex(a.real + math.sqrt(AB ** 2 - (E - a.imag) ** 2), E)
    along = (b - a) / abs(b - a)
    r = cmath.rect(R_23, math.radians(R_23_ANGLE))
    return abs((r * along.conjugate()).imag)


def test_the_moment_equation_gives_the_tangential_component_of_the_worked_example(slider_crank_ru):
    doc, texts = slider_crank_ru
    source = doc.source
    # the numbers' line: Rᵗ₂₃·l + Σ ±|F|·h (+ couples) = 0 ⇒ Rᵗ₂₃ = … Н
    line = next(l for l in re.findall(r"\[\$([^$]*⇒[^$]*)\$\]", source) if 'R^(t )_("23" )' in l)
    lhs, _, result = line.partition("= 0 quad ⇒")
    terms = re.findall(r"(^|[+−]) ?(R\^\(t \)_\(\"23\" \) dot |\"[0-9,]+\" dot )?\"([0-9,]+)\"", lhs.strip())
    length = sign_r = None
    total = 0.0
    for sign, head, number in terms:
        s = -1.0 if sign == "−" else 1.0
        if head.startswith("R^"):
            sign_r, length = s, _number(number)
        elif head:
            total += s * _number(head.split('"')[1]) * _number(number)
        else:
            total += s * _number(number)
    assert length == pytest.approx(AB)
    written = -total / (sign_r * length)  # what the written equation gives
    stated = _number(re.search(r'= "([0-9,]+)" "Н"', result)[1])
    assert written == pytest.approx(stated, rel=1e-3)  # the page's result is its equation's
    assert written == pytest.approx(_rt_23_of_the_worked_example(), rel=0.005)  # §11, within drafting precision
    # the polygon's vector equation, the known parts underlined once (direction) and twice (magnitude and direction)
    end = source.index('underline(R^(n )_("23" )) = 0$]')  # Rⁿ₂₃ closes the polygon: its direction known, once
    polygon = source[source.rindex("[$", 0, end):end]
    # twice: a thin second rule 1.8 pt below the first's bounds (the double underline's stated gap, issue 20's review)
    twice = '#box(stroke: (bottom: 0.4pt), outset: (bottom: 1.8pt), {set text(bottom-edge: "bounds"); $underline(%s)$})'
    for known in ('R^(t )_("23" )', 'G_("3" )', 'Ф_("3" )', 'F_("пс" )'):  # Rᵗ from its moment equation, and the loads: twice
        assert twice % known in polygon, (known, polygon)
    assert "+ underline(R_(\"14\" ))" in polygon  # the guide's normal force: its direction known, once
    assert "Σ M_(\"B\") (\"3\") = 0" in source


# 5. centres of mass and their images subscripted ---------------------------------------------------------------


def test_centres_of_mass_are_spelt_as_the_scene_writes_them(slider_crank_ru):
    doc, texts = slider_crank_ru
    texts_of = {}
    for key in ("forces-0-free-bodies", "forces-0-lever"):
        svg = doc.images[key]
        texts_of[key] = re.findall(r"<text[^>]*>([^<]*)</text>", svg.decode() if isinstance(svg, bytes) else svg)
    # the scene writes S3 (its kinematic pages print it so): every page spells the centres alike (issue 20, forces-ru)
    assert "S3" in texts_of["forces-0-free-bodies"] and "S2" in texts_of["forces-0-free-bodies"]
    assert "S₃" not in texts_of["forces-0-free-bodies"]
    assert "s3" in texts_of["forces-0-lever"] and "s₃" not in texts_of["forces-0-lever"]
    # the lever's table of moments names the images as the drawing does
    lever = doc.source[doc.source.index(term("joukowski_lever", "ru")):]
    assert '"s3"' in lever and '"s2"' in lever and '"s₃"' not in lever and '"s₂"' not in lever


# 6. the three methods at the digits a reading justifies --------------------------------------------------------


def _decimals(text: str) -> int:
    return len(text.replace("−", "").partition(",")[2])


def test_the_graphical_values_have_only_the_digits_their_reading_justifies(slider_crank_ru):
    doc, texts = slider_crank_ru
    page = next(t for t in texts if term("force_methods", "ru").split(":")[0] in t)
    row = re.search(r"Mур \[Н·м\] ([0-9,]+) ([0-9,]+) ([0-9,]+) ([0-9,]+) ([0-9,]+)", page)
    assert row, page
    analytic, plans_value, _, lever_value, _ = row.groups()
    mu = _number(re.search(r"μF = ([0-9,]+) Н/мм", "\n".join(texts))[1])
    k_v = _number(_title_block_scale(texts[0], "ru", "v"))
    step_plans = 0.1 * mu * OA  # a 0.1 mm step of R₃₂ at μ_F, times its arm at most l_OA
    step_lever = M_B * 0.1 / (OMEGA * OA / k_v)  # a 0.1 mm step of the balancing force's arm |pa| = v_A / k_v
    assert _decimals(plans_value) <= max(0, -math.floor(math.log10(step_plans)))
    assert _decimals(lever_value) <= max(0, -math.floor(math.log10(step_lever)))
    assert len(analytic.replace(",", "").lstrip("0")) <= 4  # the analytic value to 4 significant figures
    assert _number(plans_value) == pytest.approx(M_B, rel=0.01) and _number(lever_value) == pytest.approx(M_B, rel=0.005)


# 7. the lever's page states the k_v it is drawn at -----------------------------------------------------------


def test_the_lever_page_title_block_states_k_v(slider_crank_ru):
    doc, texts = slider_crank_ru
    page = next(t for t in texts if term("joukowski_lever", "ru") in t)
    stated = re.search(r"kv = ([0-9,]+) \(м/с\)/мм;", page)
    assert stated and _title_block_scale(page, "ru", "v") == stated[1]
    # and μ_F: the page's three methods' table reads the force plans at it (issue 20: missing there before)
    assert "μF = 80 Н/мм" in page[page.rindex(term("scale_factors", "ru")):]


def test_a_couple_enters_the_moment_equation_by_its_magnitude():
    """A review read 'R·l + G·h − F_Φ3·h − M_Φ3 = 0' with the table's signed M_Φ3 = −162,8 N·m put in: the couple is
    written |M_Φ3| (its sense is the term's sign), so the number put in is the magnitude."""
    import re as _re

    doc = built("slider-crank-loads", None, "ru", forces=True)
    letters = [line for line in doc.source.split("], [") if "Σ M_(\"B\")" in line]
    assert letters and 'abs(M_("Ф3" ))' in letters[0], letters
    numbers = doc.source.split(letters[0], 1)[1].split("], [", 2)[1]
    # |M_Φ3| = J_S3·|ε3| = 0.025 kg·m² · 6510 rad/s² (ε3 read 130.2 mm × 15 / 0.3 m) = 162.75 N·m, with the term's minus:
    # to five figures, the number the lever's pair M_Φ3/l_AB is computed from (issue 20: 162,8 / 0,3 ≠ 542,5)
    assert _re.search(r'− "162,75" = 0', numbers), numbers
