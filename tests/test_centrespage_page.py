"""The handout's instant-centre page (``plans handout … --centres``) and ``plans centres --lang``.

Expected values come from plans.centres and plans.analytic called here, not from the page's code.
"""

import re
import subprocess
import sys
from pathlib import Path

import pytest

import plans
from plans.analytic import solve
from plans.centres import instant_centres
from plans.drawing.centres_page import draw_centres_page
from plans.handout import handout_pages
from plans.i18n import TERMS

ROOT = Path(__file__).resolve().parents[1]
CENTRES_KEYS = [key for key in TERMS if key in (
    "instant_centres", "centres_page", "kennedy_theorem", "kennedy_statement", "circle_diagram", "circle_diagram_legend",
    "centres_legend", "centres_edge_legend", "centre_undetermined", "centre_undetermined_why", "by_centres",
    "centres_results", "centres_omega_rule", "centres_v_rule")]
SUPERSCRIPT = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


@pytest.fixture(scope="module")
def six_bar():
    scene = plans.load(plans.example_path("six-bar"))
    record = []
    pages = handout_pages(scene, positions=2, centres=True, record=record)
    return scene, pages, dict(record)


def _texts(fig) -> list:
    """Every text artist of a figure: (text, x, y [mm], gid) of the page axes and the drawings' axes."""
    out = []
    for ax in fig.axes:
        for t in ax.texts:
            x, y = t.get_position()
            out.append((t.get_text(), x, y, t.get_gid() or ""))
    out += [(t.get_text(), 0.0, 0.0, t.get_gid() or "") for t in fig.texts]
    for t in fig.artists:  # page text is typeset (a Text, or a line of runs) on the figure, placed in the page's mm
        if hasattr(t, "get_text") and hasattr(t, "get_position"):
            x, y = t.get_position()
            out.append((t.get_text(), x, y, t.get_gid() or ""))
    return out


def _table_rows(fig) -> list[str]:
    """The table's rows (cells joined left to right), grouped by height on the page."""
    cells = sorted((t for t in _texts(fig) if "table-cell" in t[3]), key=lambda t: -t[2])
    rows, current, last = [], [], None
    for text, x, y, _ in cells:
        if last is not None and last - y > 2.0:
            rows.append(current)
            current = []
        current.append((x, text))
        last = y
    rows.append(current)
    return [" ".join(text for _, text in sorted(row)) for row in rows]


def _numbers(row: str) -> list[float]:
    row = row.replace(",", ".").replace("−", "-")
    out = []
    for m in re.finditer(r"-?\d+(?:\.\d+)?(?:·10[-0-9⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?", row):
        text = m.group(0)
        if "·10" in text:
            mantissa, exponent = text.split("·10")
            out.append(float(mantissa) * 10 ** int(exponent.translate(SUPERSCRIPT)))
        else:
            out.append(float(text))
    return out


def test_the_page_follows_each_position_with_centres_and_not_without(six_bar):
    _, pages, _ = six_bar
    names = [name for name, _ in pages]
    for k in (0, 1):
        assert f"centres-{k}" in names
        own = [i for i, n in enumerate(names) if n.split("-")[1:2] == [str(k)]]  # position-K, acceleration-K, check-K(-2) …
        # right after the position's own pages (its check page and any continuation), before the next position
        assert names.index(f"centres-{k}") == max(i for i in own if not names[i].startswith("centres")) + 1
    scene = plans.load(plans.example_path("slider-crank"))
    without = [name for name, _ in handout_pages(scene)]
    assert not [name for name in without if name.startswith("centres")]
    assert [name for name, _ in handout_pages(scene, centres=True)] == without + ["centres-0"]


def test_table_numbers_are_the_centres_velocities_and_their_error_against_analytic(six_bar):
    scene, pages, record = six_bar
    for k in (0, 1):
        run = record[f"position-{k}"]
        result = instant_centres(run.scene)  # the third method, called here
        analytic = solve(run.scene)  # the analytic reference, computed here
        rows = _table_rows(dict(pages)[f"centres-{k}"])
        omega_rows = [r for r in rows if r.startswith("ω")]
        v_rows = [r for r in rows if r.startswith("v")]
        assert len(omega_rows) == len(scene.links) and len(v_rows) == len(scene.report)
        largest_omega = max(abs(analytic.links[n].omega[0]) for n in scene.links)
        for row, name in zip(omega_rows, scene.links):
            nums = _numbers(row)  # the link's name, P_1j's digits ("P₁₃" has subscript digits, not read), centres, analytic, error
            assert nums[0] == float(name)
            by_centres, by_analytic, error = nums[-3:]
            c, a = result.links[name], analytic.links[name].omega[0]
            # printed to 4 significant digits, as every table (issue 20 §4: one rounding everywhere)
            assert by_centres == pytest.approx(c, rel=5.01e-4, abs=1e-5 * largest_omega)
            assert by_analytic == pytest.approx(a, rel=5.01e-4, abs=1e-5 * largest_omega)
            expected = abs(c - a) / max(abs(a), 1e-9 * largest_omega)
            assert error == pytest.approx(expected, rel=0.06, abs=1e-30) or (error == 0 and expected == 0)
        for row, name in zip(v_rows, scene.report):
            assert name in row
            c, a = complex(result.points[name]), complex(analytic.points[name].v[0])
            nums = _numbers(row.split("]", 1)[1])
            magnitude_c, _, magnitude_a, _, error = nums[-5:]
            assert magnitude_c == pytest.approx(abs(c), rel=5.01e-4)
            assert magnitude_a == pytest.approx(abs(a), rel=5.01e-4)
            expected = abs(c - a) / abs(a)
            assert error == pytest.approx(expected, rel=0.06, abs=1e-30) or (error == 0 and expected == 0)
            assert error < 1e-12


@pytest.mark.parametrize("lang", ["sr", "ru", "bg", "sl"])
def test_every_language_has_no_english_centres_words_and_a_decimal_comma(six_bar, lang):
    _, _, record = six_bar
    fig = draw_centres_page(record["position-1"], lang=lang)
    text = " ".join(t[0] for t in _texts(fig))
    english = {w.lower() for key in CENTRES_KEYS for w in re.findall(r"[A-Za-z']{5,}", TERMS[key]["en"])}
    english |= {"mechanism", "centre", "centres", "kennedy's"}
    if lang == "sl":
        english -= {"kennedy", "diagram"}  # Kennedyjev izrek, krožni diagram
    found = {w for w in re.findall(r"[A-Za-z']+", text) if w.lower() in english}
    assert not found, found
    assert TERMS["circle_diagram"][lang] in text
    # (the mechanism's own caption "k_l = 0.02 m/mm" is mechanism.py's, not this page's: left to its owner)
    ours = " ".join(t[0] for t in _texts(fig) if not t[0].startswith("k_l = "))
    assert not re.search(r"\d\.\d", ours), re.findall(r"\S*\d\.\d\S*", ours)


def test_a_centre_at_infinity_is_an_arrow_slider_crank_p14():
    scene = plans.load(plans.example_path("slider-crank"))
    fig = dict(handout_pages(scene, centres=True))["centres-0"]
    arrows = [p for ax in fig.axes for p in ax.patches + ax.lines if (p.get_gid() or "").endswith("edge-P14")]
    assert arrows, "P14 is drawn as an edge arrow"
    labels = [t for t in _texts(fig) if t[3].endswith("label-P14")]
    assert [t[0] for t in labels] == ["P₁₄ ∞"]
    # the slider's guide is horizontal: P14 lies at infinity straight up or down, and so does its arrow
    xs, ys = [], []
    for a in arrows:
        if hasattr(a, "get_xdata"):
            xs += list(a.get_xdata())
            ys += list(a.get_ydata())
    if xs:
        assert max(xs) - min(xs) < 0.05 * (max(ys) - min(ys))


def test_plans_centres_draws_in_the_language_asked(tmp_path):
    out = subprocess.run([sys.executable, "-m", "plans", "centres", "--example", "slider-crank", "--lang", "sr", "-o", str(tmp_path)],
                         cwd=ROOT, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    svg = (tmp_path / "centres.svg").read_text()
    assert "кружни дијаграм" in svg and "Тренутни полови брзина" in svg
    assert "circle diagram" not in svg


@pytest.mark.parametrize("example", ["four-bar", "scotch-yoke", "quick-return"])
def test_the_drawings_are_inside_the_page_apart_from_each_other_and_from_the_table(example):
    from plans.drawing.layout import A4, PAGE_MARGIN

    scene = plans.load(plans.example_path(example))
    fig = dict(handout_pages(scene, centres=True, lang="ru"))["centres-0"]
    boxes = []
    for ax in sorted(fig.axes[1:], key=lambda ax: not any("label-P" in (t.get_gid() or "") for t in ax.texts)):
        x0, y0, w, h = ax.get_position().bounds  # (the first is the page's paper; the mechanism with its labelled centres first)
        boxes.append((x0 * A4[0], y0 * A4[1], (x0 + w) * A4[0], (y0 + h) * A4[1]))
    assert len(boxes) == 2  # the mechanism with its centres, and the circle diagram
    for x0, y0, x1, y1 in boxes:
        assert PAGE_MARGIN - 0.5 <= x0 and x1 <= A4[0] - PAGE_MARGIN + 0.5 and PAGE_MARGIN <= y0 and y1 <= A4[1] - PAGE_MARGIN
    (a0, b0, a1, b1), (c0, d0, c1, d1) = boxes
    assert a1 <= c0 or c1 <= a0 or b1 <= d0 or d1 <= b0, boxes
    table_top = max(y for text, x, y, gid in _texts(fig) if "table-heading" in gid)
    mechanism = boxes[0]
    assert mechanism[1] > table_top, (mechanism, table_top)
