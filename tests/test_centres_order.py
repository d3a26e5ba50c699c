"""The centres pages' tables read in the order they are derived (issue 20, the teacher's review of the Serbian
quick-return handout: at positions 4–9 ω₅ was read as v₆ / P₁₅P₅₆ through the ram 6, whose v₆ = ω₂·P₁₂P₂₆ was
never printed, and ω₄ through P₄₆ likewise).

Every row of a centres table uses only what rows above it give, starting from the driver: a link found through
the centre P_jk uses link k's row (its ω, or its v where k translates); a translating link's velocity has a row of
its own, printed before any row that uses it; a point's v uses its link's ω (or v).  What a row prints it was
read from gives its value (a student recomputes it from the printed numbers and the page's k_l), and the values
are those of finite differences of the analytic positions (not the velocity solver, not the centres).

The typeset tables are read from the PDF as a reader's tool gives them (pdftotext); the tables of the bundled
examples that no handout here prints are read from :func:`plans.drawing.centres_page.centres_page_table`.
"""

from __future__ import annotations

import cmath
import math
import re
import subprocess
import tempfile
import unicodedata
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest

import plans
from plans.analytic import solve
from plans.centres import instant_centres
from plans.compare import compare_centres
from plans.drawing.centres_page import centres_page_table, centres_rules
from plans.i18n import term
from plans.positions import cycle_positions
from plans.scene import Crank, example_path, load
from review_handouts import built_pdf

# --- reading a table ------------------------------------------------------------------------------------------------

_VALUE = r"−?[\d.,]+(?:·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?(?: ∠ [\d.,]+°)?"
_ROW = re.compile(rf"^\s*(?P<q>[ωv])(?P<sub>\w+) \[[^\]]+\]\s+(?P<p>P\d+(?: ∞)?)\s+(?P<reading>.*?)\s*"
                  rf"(?P<c>{_VALUE})\s+(?P<a>{_VALUE})\s+(?P<e>\S+)\s*$")


def _number(text: str) -> float:
    return float(text.replace("−", "-").replace(",", "."))


def _value(text: str) -> complex | float:
    """``0,8496 ∠ 180,0°`` as a complex number, ``−1,375`` as a float."""
    magnitude, _, angle = text.partition(" ∠ ")
    if angle:
        return cmath.rect(_number(magnitude), math.radians(_number(angle.rstrip("°"))))
    return _number(magnitude)


def _plain(cell: str) -> str:
    """A cell of centres_page_table as the PDF's text reads it: ``$\\omega_{2}$`` ω2, ``$v_{6}$`` v6, P₁₂ P12, kl."""
    cell = re.sub(r"\$\\omega_\{(\w+)\}\$", r"ω\1", cell)
    cell = re.sub(r"\$v_\{(\w+)\}\$", r"v\1", cell)
    cell = cell.replace("$k_l$", "kl")
    return unicodedata.normalize("NFKC", cell)


def _rows_of_table(table: list[list[str]]) -> list[dict]:
    rows = []
    for cells in table[1:]:
        label = _plain(cells[0])
        m = re.match(r"([ωv])(\w+) \[", label)
        rows.append({"q": m.group(1), "sub": m.group(2), "p": _plain(cells[1]), "reading": _plain(cells[2]),
                     "c": _plain(cells[3]), "a": _plain(cells[4])})
    return rows


def _pdf_pages(pdf: bytes) -> list[str]:
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "h.pdf"
        path.write_bytes(pdf)
        text = subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True, text=True, check=True).stdout
    return [unicodedata.normalize("NFKC", page) for page in text.split("\f")]


def _centres_tables(pdf: bytes, lang: str) -> list[tuple[str, float, list[dict]]]:
    """(heading, k_l [m/mm], rows) of every centres page of a handout, as its text reads."""
    out = []
    quantity = term("quantity", lang)
    for page in _pdf_pages(pdf):
        lines = page.splitlines()
        header = next((k for k, line in enumerate(lines) if re.match(rf"\s*{quantity}\s+P1j\s", line)), None)
        if header is None:
            continue
        heading = next(line.strip() for line in lines if line.strip())
        k_l = _number(re.search(r"kl = ([\d,.]+) (?:m|м)/(?:mm|мм)", page).group(1))
        rows = []
        for line in lines[header + 1:]:
            m = _ROW.match(line)
            if m is None:
                break
            rows.append({key: m.group(key) for key in ("q", "sub", "p", "reading", "c", "a")})
        out.append((heading, k_l, rows))
    return out


# --- what a row uses ------------------------------------------------------------------------------------------------


def _check_order(rows: list[dict], scene, frame: str) -> dict:
    """Assert that every row uses only quantities of rows above it; returns the rows by (quantity, subscript).

    A row of link j uses what its reading names (ω_k, v_k) and the link k of every centre P_jk it reads (its ω row,
    or its v row where k translates: its ω row's P_1k is at infinity); a point's row uses its link's ω (or v where
    the link translates, P_1j ∞)."""
    links = set(scene.links)
    defined: dict = {}
    translating: set = set()
    for n, row in enumerate(rows):
        q, sub, reading = row["q"], row["sub"], row["reading"]
        used = {(s, k) for s, k in re.findall(r"([ωv])(\d+)", reading) if k in links}  # (v₄₃ relative: no row)
        if sub in links:
            for a, b in re.findall(r"P(\d)(\d)", reading):
                others = {a, b} - {frame, sub}
                for k in others:
                    used.add(("v" if k in translating else "ω", k))
        else:  # a point: v_M = ω_j · P_1jM, or v_j where its link j translates
            j = row["p"].split()[0][1 + len(frame):]
            used.add(("v" if row["p"].endswith("∞") else "ω", j))
        missing = used - set(defined)
        assert not missing, f"row {n + 1} ({q}{sub}: {reading!r}) uses {sorted(missing)} before any row gives it"
        if sub in links and q == "ω" and row["p"].endswith("∞"):
            translating.add(sub)
        defined[(q, sub)] = row
    for j in translating:  # a translating link's velocity is printed (where it is used: checked above)
        assert ("v", j) in defined, f"link {j} translates (P{frame}{j} ∞): no row of v{j}"
    assert [r["sub"] for r in rows if r["q"] == "ω"][0] == scene.driver.link  # from the driver
    return defined


def _check_readings(defined: dict, k_l: float) -> int:
    """Each link's value recomputed from what its row prints (the printed values it names, its lengths [mm] × k_l);
    returns how many rows were recomputed."""
    checked = 0
    value = {key: _value(row["c"]) for key, row in defined.items()}
    for (q, sub), row in defined.items():
        reading, mine = row["reading"], value[(q, sub)]
        m = re.fullmatch(r"(−?)ω(\d+) · P\d+P\d+ / P\d+P\d+ = (−?)ω\2 · ([\d,.]+) / ([\d,.]+)", reading)
        if m:  # ω_j = ±ω_k · P_1kP_jk / P_1jP_jk
            assert m.group(1) == m.group(3)
            sign = -1.0 if m.group(1) else 1.0
            want = sign * value[("ω", m.group(2))] * _number(m.group(4)) / _number(m.group(5))
            assert mine == pytest.approx(want, rel=1.5e-3, abs=1e-6), (q, sub, reading)
            checked += 1
            continue
        m = re.fullmatch(r"(−?)v(\d+) / P\d+P\d+ = \1v\2 / \(([\d,.]+) · kl ?\)", reading)
        if m:  # ω_j = ±|v_k| / (P_1jP_jk · k_l), the sign printed
            want = abs(value[("v", m.group(2))]) / (_number(m.group(3)) * k_l) * (-1.0 if m.group(1) else 1.0)
            assert mine == pytest.approx(want, rel=1.5e-3, abs=1e-6), (q, sub, reading)
            checked += 1
            continue
        m = re.fullmatch(r"ω(\d+) · P\d+P\d+ = ω\1 · ([\d,.]+) · kl", reading)
        if m:  # |v_j| = |ω_k| · P_1kP_jk · k_l
            assert q == "v"
            want = abs(value[("ω", m.group(1))]) * _number(m.group(2)) * k_l
            assert abs(mine) == pytest.approx(want, rel=1.5e-3, abs=1e-6), (q, sub, reading)
            checked += 1
            continue
        m = re.fullmatch(r"ω(\d+) \(P\d+ ∞\)", reading)
        if m:  # turns with k
            assert mine == value[("ω", m.group(1))], (q, sub, reading)
            checked += 1
    return checked


@lru_cache(maxsize=None)
def _differences(source: str, position: float) -> tuple[dict, dict]:
    """ω [rad/s] of every link and v [m/s] of every point at *position* by central differences of the analytic
    positions (their rates × the driver's ω or v)."""
    scene = load(source).at(position)
    d = scene.driver
    h = 1e-6
    rate = d.omega if isinstance(d, Crank) else d.velocity
    sol = solve(scene, [position - h, position + h])
    omega = {k: float(np.diff(np.unwrap(sol.links[k].phi))[0]) / (2 * h) * rate for k in scene.links}
    v = {p: complex(sol.points[p].r[1] - sol.points[p].r[0]) / (2 * h) * rate for p in sol.points}
    return omega, v


def _check_values(defined: dict, scene, position: float) -> None:
    """Every ω and v printed from the centres against finite differences (the drawing's readings: within 1 %)."""
    omega, v = _differences(str(scene.source), position)
    top_omega = max(abs(x) for x in omega.values())
    top_v = max(abs(x) for x in v.values())
    for (q, sub), row in defined.items():
        got = _value(row["c"])
        if q == "ω":
            assert got == pytest.approx(omega[sub], rel=1e-2, abs=2e-3 * top_omega), (q, sub, row)
        else:
            point = sub if sub in v else next(iter(scene.bodies[sub].points))  # a translating link: any point of it
            assert abs(complex(got) - v[point]) <= 1e-2 * abs(v[point]) + 2e-3 * top_v, (q, sub, row, v[point])


# --- the reviewed handout -------------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def quick_return_sr():
    scene = load(example_path("quick-return"))
    return scene, built_pdf("quick-return", 12, "sr", centres=True)


def test_quick_return_sr_every_row_uses_only_rows_above(quick_return_sr):
    scene, pdf = quick_return_sr
    tables = _centres_tables(pdf, "sr")
    assert len(tables) == 12
    cycle = cycle_positions(scene, 12)
    through_ram = 0
    for n, (heading, k_l, rows) in enumerate(tables):
        assert heading.startswith(f"{term('instant_centres', 'sr')} — {term('position', 'sr')} {n}:"), heading
        phi = cycle[n]
        assert f"{math.degrees(phi) % 360:.1f}".replace(".", ",") in heading
        defined = _check_order(rows, scene, scene.frame_number)
        assert _check_readings(defined, k_l) >= 3, rows
        _check_values(defined, scene, phi)
        if 4 <= n <= 9:  # the reviewed positions: the ram's v₆ printed, and ω₄ and ω₅ read through it at most of them
            assert ("v", "6") in defined
            through_ram += sum(1 for r in rows if r["q"] == "ω" and r["reading"].startswith("v6 / "))
    assert through_ram >= 6


def test_quick_return_sr_ram_row_reads_v6_from_the_crank(quick_return_sr):
    """Position 6 (φ₂ = 151.3°), the review's example: v₆ = ω₂ · P₁₂P₂₆ (in mm × k_l) printed above ω₄ and ω₅."""
    scene, pdf = quick_return_sr
    _, k_l, rows = _centres_tables(pdf, "sr")[6]
    order = [r["q"] + r["sub"] for r in rows]
    assert order.index("v6") < order.index("ω4") and order.index("v6") < order.index("ω5"), order
    ram = rows[order.index("v6")]
    m = re.fullmatch(r"ω2 · P12P26 = ω2 · ([\d,]+) · kl", ram["reading"])
    assert m, ram
    # P₁₂P₂₆ measured independently: P₂₆ on the vertical through O (P₁₂P₁₆) and on the line P₂₅P₅₆; as the velocity
    # of the ram is ω₂ × P₁₂P₂₆, P₁₂P₂₆ = |v_E| / ω₂ by finite differences
    _, v = _differences(str(scene.source), cycle_positions(scene, 12)[6])
    assert _number(m.group(1)) * k_l == pytest.approx(abs(v["E"]) / 6.0, abs=0.06 * k_l)
    assert _value(ram["c"]) == pytest.approx(v["E"], rel=2e-3)
    assert _value(ram["a"]) == pytest.approx(v["E"], rel=2e-4)  # the analytic column: the ram's pin E


def test_quick_return_sr_method_page_states_the_sense_and_the_ram_rule_once(quick_return_sr):
    _, pdf = quick_return_sr
    text = " ".join(" ".join(page.split()) for page in _pdf_pages(pdf))
    # hand-written: the sense of the ratio theorem and the step through a translating link, in Serbian
    assert text.count("Смер обртања:") == 1
    assert text.count("лежи ван дужи") == 1 and "супротан када лежи унутар ње" in text
    assert text.count("Члан који се креће транслаторно") == 1


def test_the_minus_of_a_reading_is_the_sense_by_finite_differences(quick_return_sr):
    """Where a row reads ω_j from ω_k, its sign (−ω_k …) is the sign of ω_j/ω_k by finite differences."""
    scene, pdf = quick_return_sr
    checked = 0
    for n, (_, _, rows) in enumerate(_centres_tables(pdf, "sr")):
        omega, _ = _differences(str(scene.source), cycle_positions(scene, 12)[n])
        for row in rows:
            m = re.match(r"(−?)ω(\d+) · P", row["reading"])
            if m and row["q"] == "ω" and abs(omega[row["sub"]]) > 1e-3 and abs(omega[m.group(2)]) > 1e-3:
                assert (m.group(1) == "−") == (omega[row["sub"]] * omega[m.group(2)] < 0), row
                checked += 1
    assert checked >= 4


# --- the other handouts ---------------------------------------------------------------------------------------------


@pytest.mark.parametrize("name, positions, lang", [("six-bar", None, "en"), ("four-bar", None, "ru"),
                                                   ("slider-crank", None, "sl"), ("linear-arm", None, "bg")])
def test_handout_centres_tables_read_in_order(name, positions, lang):
    scene = load(example_path(name))
    pdf = built_pdf(name, positions, lang, centres=True)
    tables = _centres_tables(pdf, lang)
    values = cycle_positions(scene, positions) if positions else [scene.driver.phi if isinstance(scene.driver, Crank) else scene.driver.s]
    assert len(tables) == len(values)
    for (_, k_l, rows), position in zip(tables, values):
        defined = _check_order(rows, scene, scene.frame_number)
        assert _check_readings(defined, k_l) >= 2, rows
        _check_values(defined, scene, position)
        if name == "slider-crank":  # the slider 4 translates: its v₄ = ω₂ · P₁₂P₂₄
            assert re.fullmatch(r"ω2 · P12P24 = ω2 · [\d,]+ · kl", defined[("v", "4")]["reading"]), rows
    # no edge arrow points to a centre "0 mm" beyond its tip (the six-bar's P₄₆ lies inside the page's box: a dot)
    assert not any(re.search(r"P\d+ 0 (?:mm|мм)", page) for page in _pdf_pages(pdf))


# --- every bundled example, the table as the page sets it -----------------------------------------------------------


@pytest.mark.parametrize("name", ["four-bar", "six-bar", "slider-crank", "quick-return", "linear-arm", "scotch-yoke",
                                  "wedge", "ladder", "rocker-limit"])
def test_every_example_table_reads_in_order(name):
    scene0 = load(example_path(name))
    for position in cycle_positions(scene0, 6):
        scene = scene0.at(position)
        exact = instant_centres(scene)
        k_l = exact.size / 120.0  # the mechanism about 120 mm on the drawing
        read = instant_centres(scene, k_l=k_l, precision=0.1)
        table = centres_page_table(read, compare_centres(solve(scene), read, translations=True), "en", k_l)
        defined = _check_order(_rows_of_table(table), scene, scene.frame_number)
        _check_readings(defined, k_l)
        _check_values(defined, scene, position)
        for j in scene.links:  # one ω row per link, a v row for each that translates
            assert ("ω", j) in defined and (("v", j) in defined) == read.translates(j)


def test_the_sense_rule_in_every_language():
    scene = load(example_path("quick-return"))
    numbers = instant_centres(scene).numbers
    words = {"en": "turns the same way as", "sr": "има исти смер као", "ru": "того же направления", "bg": "има посоката на",
             "sl": "ima isti smisel kot"}
    for lang, said in words.items():
        rules = centres_rules(lang, "1", scene.driver, numbers, translating=True)
        sense = [r for r in rules if said in r]
        assert len(sense) == 1 and "$P_{1j}P_{1k}$" in sense[0], rules
        assert any(r"$v_j = \omega_k \cdot P_{1k}P_{jk}$" in r for r in rules)
    assert not any(r"v_j = \omega_k" in r for r in centres_rules("en", "1", scene.driver, numbers))  # only where one translates


def test_plans_centres_lists_links_in_order_with_the_slider_velocity(capsys):
    """domain.md §8, E2: the slider's velocity is that of P₂₄ as a point of the crank, −16.0407 m/s along x; the
    links listed in the order they are found (the slider 4 from the crank, after it)."""
    from plans.cli import main

    assert main(["centres", "--example", "slider-crank", "--no-drawing"]) == 0
    out = capsys.readouterr().out
    table = out.splitlines()
    start = next(k for k, line in enumerate(table) if line.startswith("link ") and "ω [rad/s]" in line)
    lines = table[start + 1:start + 4]
    assert [line.split()[0] for line in lines][0] == "2"
    slider = next(line for line in lines if line.startswith("4 "))
    assert re.search(r"P14 \(translates: v = 16\.0407 m/s, 180\.000°\)", slider), slider


def test_quick_return_sr_points_read_from_a_centre_on_the_drawing(quick_return_sr):
    """A point's v is read as P_1jM off the drawing only where P_1j is on it: the ram's pin E, where P₁₅ is an
    arrow at the edge (4306 mm beyond it at position 4), is read as v₆ (E rides on the ram 6), not as 4424 mm."""
    scene, pdf = quick_return_sr
    pages = [page for page in _pdf_pages(pdf) if re.search(rf"^\s*{term('quantity', 'sr')}\s+P1j\s", page, re.MULTILINE)]
    tables = _centres_tables(pdf, "sr")
    assert len(pages) == len(tables) == 12
    through_ram = 0
    for page, (_, _, rows) in zip(pages, tables):
        off = set(re.findall(r"(P\d+) \d+ mm", page))  # the edge arrows' labels: centres off the drawing
        for row in rows:
            if row["sub"] not in scene.links:
                assert row["p"] not in off, (row, off)
        if "P15" in off:
            e = next(r for r in rows if r["sub"] == "E")
            assert (e["p"], e["reading"]) == ("P16 ∞", "v6"), e
            through_ram += 1
    assert through_ram >= 3
