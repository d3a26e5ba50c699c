"""The handout's plate pages in the course's words (issue 20, the teacher's leftover findings).

Expected values from independent sources: finite differences of the analytic
positions, the scene's own data (the driver's stroke), the i18n tables only for
words a test plants a bug in.
"""

import re

import numpy as np
import pytest

from plans.analytic import solve
from plans.centres import instant_centres
from plans.drawing.centres_page import centres_rules
from plans.scene import example_path, load


# --- 1. the centres page's ω rule for a sliding driver ------------------------------------------------------


def test_centres_rule_of_a_sliding_driver_starts_from_its_velocity():
    scene = load(example_path("linear-arm"))
    result = instant_centres(scene)
    for lang in ("en", "sr", "ru", "bg", "sl"):
        omega_rule = centres_rules(lang, scene.frame_number, scene.driver, result.numbers)[0]
        assert "v_{A}" in omega_rule and r"\omega_j / \omega_k" not in omega_rule, omega_rule
        assert "P_{1k}P_{2k}" in omega_rule, omega_rule  # through P_1k and the centre of the driver (2) and k
    crank = load(example_path("quick-return"))
    rule = centres_rules("en", crank.frame_number, crank.driver, instant_centres(crank).numbers)[0]
    assert r"\omega_j / \omega_k" in rule


def test_sliding_driver_rule_gives_each_links_omega():
    """ω_k = v_A / P_1kP_2k (the rule the page states) equals dφ_k/dt by finite differences of the analytic positions."""
    scene = load(example_path("linear-arm"))
    d = scene.driver
    result = instant_centres(scene)
    h = 1e-6
    positions = solve(scene, [d.s - h, d.s + h])
    checked = 0
    for k in scene.links:
        if k == d.link:
            continue
        p1k, pdk = result.centre("frame", k), result.centre(d.link, k)
        if p1k.point is None or pdk.point is None:
            continue
        by_rule = abs(d.velocity) / abs(p1k.point - pdk.point)
        phi = np.unwrap(positions.links[k].phi)
        by_differences = abs((phi[1] - phi[0]) / (2 * h) * d.velocity)
        assert by_rule == pytest.approx(by_differences, rel=1e-5), k
        assert abs(result.links[k]) == pytest.approx(by_differences, rel=1e-5), k  # the value the page's table states
        checked += 1
    assert checked >= 3


# --- the three handouts the teacher read (built once) -------------------------------------------------------

import functools
import io

import plans
from plans.i18n import term
from review_handouts import built, built_pdf

#: (example, positions, language) of the handouts the teacher reviewed
HANDOUTS = {"quick-return": (12, "sr"), "linear-arm": (8, "bg"), "six-bar": (None, "en")}


@functools.lru_cache(maxsize=None)
def _built(name: str):
    positions, lang = HANDOUTS[name]
    return built(name, positions, lang, centres=True)


@functools.lru_cache(maxsize=None)
def _page_texts(name: str) -> tuple[str, ...]:
    from pypdf import PdfReader

    positions, lang = HANDOUTS[name]
    reader = PdfReader(io.BytesIO(built_pdf(name, positions, lang, centres=True)))
    return tuple(page.extract_text() for page in reader.pages)


def _own_pages(name: str) -> list[str]:
    """The page texts of the sections this work owns: not the cycle or kinematic diagrams' pages (nor forces: built
    without them), told by their headings."""
    lang = HANDOUTS[name][1]
    skip = (term("cycle_diagrams", lang), term("kinematic_diagrams", lang))
    return [text for text in _page_texts(name) if not any(words in text for words in skip)]


# --- 2. a sliding driver's cycle is its stroke, one way ---------------------------------------------------


def test_a_linear_drivers_pages_speak_of_its_stroke_not_of_the_cranks_strokes():
    lang = "bg"
    doc = _built("linear-arm")
    text = "\n".join(_page_texts("linear-arm"))  # every page, the diagrams' too
    for crank_words in ("extreme_positions", "working_stroke", "idle_stroke"):
        assert term(crank_words, lang) not in text, crank_words
    assert not re.search(r"(?<!\w)K =", text) and "θ =" not in text
    assert term("driver_stroke_ends", lang) in text
    stroke = plans.load(example_path("linear-arm")).driver.stroke  # the scene's own stroke [m]
    length = f"{abs(stroke[1] - stroke[0]) * 1e3:g} мм"
    assert length in text.replace("\u00a0", " "), length
    # the acceleration plans: two along the stroke (its thirds), none chosen as an "idle stroke"
    indices = [r.index for r in doc.runs]
    assert doc.accelerations == [indices[len(indices) // 3], indices[2 * len(indices) // 3]]


def test_a_crank_keeps_its_working_and_idle_strokes():
    text = "\n".join(_own_pages("quick-return"))
    for words in ("extreme_positions", "working_stroke", "idle_stroke"):
        assert term(words, "sr") in text, words
    assert re.search(r"(?<!\w)K =", text)


# --- 3. units as the Russian and Bulgarian courses write them, in the drawings too -------------------------

import base64

#: a Latin unit symbol as a page or a drawing would print it (after a number or in a scale)
_LATIN_UNIT = re.compile(r"(?<![A-Za-z])(m/mm|m/s²|m/s|rad/s|mm)(?![A-Za-z])")


def _drawing_texts(page_svg: bytes) -> list[str]:
    """The text of every drawing a Typst SVG page embeds (base64 ``data:image/svg+xml``), each drawing's text nodes
    joined (matplotlib sets a text with math glyph by glyph, one node each)."""
    out = []
    for data in re.findall(rb"data:image/svg\+xml;base64,([A-Za-z0-9+/=]+)", page_svg):
        svg = base64.b64decode(data).decode("utf-8")
        svg = re.sub(r"<metadata>.*?</metadata>|<style.*?</style>", "", svg, flags=re.S)
        texts = re.findall(r"<text[^>]*>(.*?)</text>", svg, flags=re.S)  # a plain text, or a math one's tspans
        out.append("".join(re.sub(r"<[^>]*>|\n\s*", "", t) for t in texts))
    return out


def test_no_latin_unit_on_a_bulgarian_page_nor_in_its_drawings():
    doc = _built("linear-arm")
    for number, text in enumerate(_page_texts("linear-arm"), start=1):
        assert not _LATIN_UNIT.search(text), (number, _LATIN_UNIT.search(text).group(0))
    pages = doc.pages("svg")
    seen = 0
    for number, page in enumerate(pages, start=1):
        for text in _drawing_texts(page):
            seen += 1
            found = _LATIN_UNIT.search(text)
            assert not found, (number, found.group(0), text[max(0, found.start() - 30):found.end() + 10])
    assert seen >= 10
    # and the drawings do say their units, in Cyrillic: the plan's notes, the centres' scale and distances
    drawn = "".join(t for page in pages for t in _drawing_texts(page))
    assert "м/мм" in drawn and "мм" in drawn


# --- 5. every named point's absolute velocity and acceleration the plans draw, in the results table -------------

from plans.compare import compare
from plans.graphical import construct
from plans.report import sheet_table


def _point_of_link_by_differences(scene, point: str, link: str, ref: str):
    """(v, a) of the point of *link* under *point* at the scene's position, by five-point central differences in time
    of the analytic positions (the driver at constant ω, ε = 0 in these scenes): r(t) = r_R(t) + (r_P(0) − r_R(0))·
    e^{i(φ(t) − φ(0))}, R a point of the link."""
    d = scene.driver
    assert d.epsilon == 0
    h = 1e-4
    ts = np.array([-2, -1, 0, 1, 2]) * h
    sol = solve(scene, d.phi + d.omega * ts)
    r_ref = np.asarray(sol.points[ref].r)
    phi = np.unwrap(np.asarray(sol.links[link].phi))
    arm0 = complex(sol.points[point].r[2]) - complex(r_ref[2])
    r = r_ref + arm0 * np.exp(1j * (phi - phi[2]))
    v = (r[0] - 8 * r[1] + 8 * r[3] - r[4]) / (12 * h)
    a = (-r[0] + 16 * r[1] - 30 * r[2] + 16 * r[3] - r[4]) / (12 * h * h)
    return complex(v), complex(a)


def _vector_cell(text: str) -> complex:
    """``1.565 ∠ 196.1°`` → the complex number it states."""
    m = re.fullmatch(r"([0-9.]+) ∠ ([0-9.]+)°", text)
    assert m, text
    return float(m.group(1)) * np.exp(1j * np.radians(float(m.group(2))))


@pytest.mark.parametrize("example, point, link, ref", [("quick-return", "A", "4", "C"), ("six-bar", "E", "5", "B")])
def test_results_table_holds_every_drawn_points_absolute_velocity_and_acceleration(example, point, link, ref):
    scene = plans.load(example_path(example))
    analytic, graphical = solve(scene), construct(scene)
    table = sheet_table(compare(analytic, graphical), graphical, analytic, points_of_links=True)
    cells = {row[0]: row for row in table[1:]}
    v, a = _point_of_link_by_differences(scene, point, link, ref)
    for symbol, expected in ((f"$v_{{{point}{link}}}$ [m/s]", v), (f"$a_{{{point}{link}}}$ [m/s²]", a)):
        assert symbol in cells, (symbol, list(cells))
        _, drawn, worked, _ = cells[symbol]
        for value in (_vector_cell(drawn), _vector_cell(worked)):  # 4 significant digits, the angle to 0.1°
            assert abs(value) == pytest.approx(abs(expected), rel=2e-3), symbol
            assert abs(np.angle(value / expected, deg=True)) < 0.06, symbol
    # a position whose acceleration plan is not on the plate: its velocity only
    velocities = [c for c in compare(analytic, graphical) if c.quantity in ("v", "omega", "v_rel")]
    rows = [row[0] for row in sheet_table(velocities, graphical, analytic, points_of_links=True)]
    assert f"$v_{{{point}{link}}}$ [m/s]" in rows and not any(r.startswith("$a") for r in rows)


def test_handouts_results_tables_hold_a_A4_and_a_E5():
    """The handout's table of every position holds v_A4 (quick-return), its acceleration where its plan is drawn;
    the six-bar's holds a_E5."""
    qr = _built("quick-return").source
    moving = [r for r in _built("quick-return").runs if abs(r.analytic.links["4"].omega[0]) > 1e-6]  # at rest: no row
    assert qr.count('$v_(A 4 )$#" [m/s]"') == len(moving) >= 10
    assert qr.count('$a_(A 4 )$#" [m/s²]"') == len(_built("quick-return").accelerations)
    assert _built("six-bar").source.count('$a_(E 5 )$#" [m/s²]"') == 1


# --- 7. no program token on a page; a group named one way -------------------------------------------------------

#: what the program writes and a page must not: a group's kind token, an assembly's sign, a guide's key, a name's "_"
_TOKENS = re.compile(r"\b[RP]{3}\(|\(\+1\)|\(−1\)|\(-1\)|\bframe\.|[A-Za-z]_[A-Za-z0-9]")
#: a group named as a structural formula names it (II₁(3,4)): only in the structural formula (a detail's
#: "Детайл II (4 : 1)" is a scale, not a group)
_ASSUR = re.compile(r"\bII ?[₁-₅1-5]? ?\(\d+ ?,")


@pytest.mark.parametrize("name", list(HANDOUTS))
def test_no_program_token_on_the_plate_pages(name):
    pages = _own_pages(name)
    assert len(pages) >= 5
    lang = HANDOUTS[name][1]
    formula = term("structural_formula", lang)
    for number, text in enumerate(pages, start=1):
        found = _TOKENS.search(text)
        assert not found, (name, number, text[max(0, found.start() - 60):found.end() + 30])
        for line in text.splitlines():
            if _ASSUR.search(line):
                assert line.startswith(formula), (name, number, line)  # elsewhere a group is "group 3–4"


# --- 4. the centres' pages: the circle diagram once, headings of one line, no label over another --------------

from svg_text_boxes import overlaps, text_boxes


def _centres_pages(name: str) -> list[str]:
    lang = HANDOUTS[name][1]
    pages = _page_texts(name)
    # (the method's block heads a page, or flows on under the end of the loop equations where that page holds it)
    first = next(k for k, text in enumerate(pages) if any(line.strip() == term("centres_page", lang) for line in text.splitlines()))
    text = pages[first]
    return [text[text.index(term("centres_page", lang)):]] + list(pages[first + 1:])


@pytest.mark.parametrize("name", list(HANDOUTS))
def test_centres_pages_draw_the_circle_diagram_once_and_head_each_page_in_one_line(name):
    doc = _built(name)
    lang = HANDOUTS[name][1]
    assert len([key for key in doc.images if key.startswith("circle-")]) == 1
    pages = _centres_pages(name)
    assert len(pages) == len(doc.runs) + 1  # the method's page, then one a position
    assert pages[0].splitlines()[0].strip() == term("centres_page", lang)
    for h, text in zip(doc.runs, pages[1:]):
        heading = text.splitlines()[0]
        assert heading.startswith(term("instant_centres", lang)), heading
        if HANDOUTS[name][0] is not None:  # several positions: each page names its own
            assert f"{term('position', lang)} {h.index}:" in heading, heading
        number = re.search(r"[−-]?[0-9]+[.,][0-9]+", h.label).group(0).replace(".", "," if lang != "en" else ".")
        assert number in heading, (heading, h.label)  # the whole heading on its first line: not wrapped


def _numbers_joined(boxes):
    """The plan of positions sets a number as its letter, its index (``…-A`` and ``…-A-index``, the index in digits at
    the small size, tests/position_numbers.py) and, where numbers on one mark are set together (D₄, D₈), the comma after
    it (``…-A-comma``): read each as one label, A₀ or D₈,, with one box."""
    parts = ("-index", "-comma")
    gids = {gid for gid, _, _ in boxes}
    out = []
    for gid, text, box in boxes:
        if gid.endswith(parts) and gid.rsplit("-", 1)[0] in gids:
            continue
        for part in parts:
            for g, t, b in boxes:
                if g == gid + part:
                    text += t.translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")) if part == "-index" else t
                    box = (min(box[0], b[0]), min(box[1], b[1]), max(box[2], b[2]), max(box[3], b[3]))
        out.append((gid, text, box))
    return out


@pytest.mark.parametrize("name", list(HANDOUTS))
def test_no_label_over_another_on_the_centres_and_positions_drawings(name):
    doc = _built(name)
    checked = 0
    for key, svg in doc.images.items():
        if key.startswith(("centres-", "positions", "circle-")):
            boxes = _numbers_joined(text_boxes(svg)) if key.startswith("positions") else text_boxes(svg)
            assert len(boxes) >= 6, key
            assert not overlaps(boxes, clear=-0.5), (name, key, overlaps(boxes, clear=-0.5)[:3])  # half a point apart
            checked += 1
    assert checked >= 2


def test_centres_drawing_large_enough_to_read():
    """The linear-arm's centres (bg) were drawn at k_l 0.03 m/mm, the mechanism some 35 mm across under 16 labels:
    at least 60 mm now (its points' extent at the pages' k_l)."""
    doc = _built("linear-arm")
    k = float(re.search(r'plate-kl\.update\(\[(?:#box\[)?\$k_\(l \)\$#" = ([0-9,]+) ', doc.source).group(1).replace(",", "."))
    for h in doc.runs:
        zs = list(h.analytic.points.values())
        xs = [complex(p.r[0]).real for p in zs]
        ys = [complex(p.r[0]).imag for p in zs]
        assert max(max(xs) - min(xs), max(ys) - min(ys)) / k >= 60.0, (h.index, k)
