"""The cycle diagrams read on the printed page (review 3, items 13 and 19).

* Every link's angle that swings more than 1° spans at least 30 % of its panel's height (one 0…380° axis for
  φ₄ ≈ 60…120° and φ₅ ≈ 350…370° made both look flat), and what the curve says is the link's angle: the
  plotted value plus the middle named in the legend is φ from the solver, up to whole turns.
* Every text on the diagram pages is at least 7 pt as printed (the PDF's font size times its text matrix's
  scale; a mathtext subscript is 70 % of its text, which is then 8 pt), and the diagrams' own texts (ticks,
  legends, notes, position numbers, axis words) at least 8 pt.
* Every position line has the same width: in the figure, in the PDF's stroke, and as pdftoppm draws it at
  70, 110 and 150 dpi (a 0.7 pt line came out one pixel wide at some places and two at others: the line at 90°
  read heavier).

Everything is measured in the figure or the PDF, against the solver's angles.
"""

from __future__ import annotations

import math
import re
import shutil
import subprocess

import numpy as np
import pytest

import plans
from plans.drawing.diagrams import draw_cycle_diagrams
from plans.positions import run_positions

EXAMPLES = ("quick-return", "linear-arm", "six-bar", "four-bar", "rocker-limit")


def _curves(ax):
    return {line.get_label(): line for line in ax.get_lines() if not line.get_label().startswith("_")}


def _links_page(name, positions=4, steps=180, lang="en"):
    scene = plans.load(plans.example_path(name))
    run = run_positions(scene, positions, cycle_steps=steps)
    return scene, run, dict(draw_cycle_diagrams(run.cycle, marked=run.positions, lang=lang))


def _key(x: float, crank: bool) -> float:
    return round(float(x) % 360.0, 6) % 360.0 if crank else round(float(x), 6)


def _middle(label: str) -> float:
    """The middle of the swing the legend names: 'φ₄ − 112.3°' → 112.3, 'φ₄ + 5.0°' → −5.0, 'φ₄' → 0."""
    m = re.search(r"([\u2212+]) ([\d.,]+)°\s*$", label)
    if not m:
        return 0.0
    value = float(m.group(2).replace(",", "."))
    return value if m.group(1) == "\u2212" else -value


@pytest.mark.parametrize("name", EXAMPLES)
def test_every_angle_spans_a_readable_share_of_its_panel(name):
    scene, run, figures = _links_page(name)
    cycle = run.cycle
    crank = isinstance(scene.driver, plans.scene.Crank)
    sense = -1.0 if getattr(scene.driver, "omega", 1.0) < 0 else 1.0
    driver = np.asarray(cycle.driver, dtype=float)
    driver_x = np.degrees(sense * (driver - driver[0])) if crank else driver  # (a linear driver's s [m])
    seen = set()
    for ax in figures["links"].axes:
        if not ax.get_ylabel().startswith("φ"):
            continue
        bottom, top = ax.get_ylim()
        for label, line in _curves(ax).items():
            y = np.asarray(line.get_ydata(), dtype=float)
            swing = float(np.nanmax(y) - np.nanmin(y))
            if swing > 1.0:
                assert swing >= 0.3 * (top - bottom), (name, label, swing, (bottom, top))
            # each name on the curve (links that turn together share one: 'φ₃ − 15.5° = φ₄ − 315.5°')
            for part in label.split("="):
                part = part.strip()
                link = part[1:].split(" ")[0].translate(str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789"))
                solver = np.degrees(np.asarray(cycle.links[link].phi, dtype=float))  # NaN where it cannot assemble
                # the curve at its x is the solver's angle at the driver position that x is (a crank's sweep
                # over one arc is drawn from where that arc starts: x is found by its angle, mod 360°)
                at = {_key(v, crank): k for k, v in enumerate(driver_x)}
                rows = np.array([at[_key(v, crank)] for v in np.asarray(line.get_xdata(), dtype=float)])
                ok = np.isfinite(y) & np.isfinite(solver[rows])
                assert ok.sum() > 10 and np.array_equal(ok, np.isfinite(y))
                turns = (y[ok] + _middle(part) - solver[rows[ok]]) / 360.0
                assert np.allclose(turns, np.round(turns), atol=1e-6), (name, part)
                seen.add(link)
    # every moving link's angle is drawn (or written, when constant) once
    moving = {n for n in scene.links if not scene.bodies[n].block and n != scene.driver.link
              and np.nanmax(np.asarray(cycle.links[n].phi, dtype=float)) - np.nanmin(np.asarray(cycle.links[n].phi, dtype=float)) > 1e-9}
    assert seen == moving, name


def test_the_quick_return_angles_no_longer_share_one_axis():
    """φ₄ swings about 60° and φ₅ about 20° (the review's sr p 18): φ₅ has a panel of its own, over its swing."""
    scene, run, figures = _links_page("quick-return")
    phi5 = np.degrees(np.unwrap(np.asarray(run.cycle.links["5"].phi, dtype=float)))
    (ax,) = [ax for ax in figures["links"].axes if "φ₅" in " ".join(_curves(ax))]
    bottom, top = ax.get_ylim()
    assert top - bottom < 1.5 * np.ptp(phi5)  # not a 0…380° axis
    assert list(_curves(ax)) == ["φ₅"]


def _handout_diagram_pdf(name, lang, tmp_path):
    """The handout's diagram pages as the handout draws them (its text area, placed at 100 %), as a PDF of their own."""
    from plans.drawing.diagrams import draw_cycle_diagrams
    from plans.drawing.formats import render_pdf
    from plans.pages.handout import DIAGRAM_PAGE
    from plans.positions import run_positions

    scene = plans.load(plans.example_path(name))
    run = run_positions(scene, 4)
    pages = draw_cycle_diagrams(run.cycle, marked=run.motion if run.motion is not None else run.positions, lang=lang,
                                cycle=run.dense, size=DIAGRAM_PAGE)
    figures = [fig for _, fig in pages]
    assert len(figures) == 3  # links, points, sliders
    path = tmp_path / f"{name}-{lang}.pdf"
    path.write_bytes(render_pdf(figures))
    return figures, path


def test_the_handout_places_its_diagram_pages_at_100_percent():
    from plans.handout import handout
    from plans.pages.handout import DIAGRAM_PAGE

    doc = handout(plans.load(plans.example_path("four-bar")), positions=4)
    for key in ("diagram-links", "diagram-points"):
        width, height = doc.drawn[key]  # 8 pt type prints at 8 pt: the figure placed at its own size
        assert width == pytest.approx(DIAGRAM_PAGE[0], abs=0.01), key
        # under its heading and words, set by Typst; the points' page (fewest panels) may follow the kinematic
        # diagrams' table on its page, each panel at least 32 mm tall
        least = 32.0 if key == "diagram-points" else DIAGRAM_PAGE[1] - 40.0
        assert least <= height <= DIAGRAM_PAGE[1], key
        assert f'image(bytes(sys.inputs.at("{key}")), format: "svg", width: {width:.3f}mm)' in doc.source


TEXT_RUN = re.compile(rb"([-\d.]+) ([-\d.]+) ([-\d.]+) ([-\d.]+) [-\d.]+ [-\d.]+ cm\s*BT(.*?)ET", re.S)


@pytest.mark.parametrize("name, lang", [("quick-return", "sr"), ("linear-arm", "bg")])
def test_every_text_on_the_diagram_pages_is_at_least_7_pt(name, lang, tmp_path):
    pypdf = pytest.importorskip("pypdf")
    figures, path = _handout_diagram_pdf(name, lang, tmp_path)
    reader = pypdf.PdfReader(str(path))
    for number, page in enumerate(reader.pages, start=1):
        content = page.get_contents().get_data()
        every = re.findall(rb"/F\d+ ([\d.]+) Tf", content)
        runs = TEXT_RUN.findall(content)
        assert every and sum(len(re.findall(rb" Tf", run[-1])) for run in runs) == len(every), (name, number)  # each in a block placed by a matrix
        for a, b, c, d, block in runs:
            scale = math.hypot(float(a), float(b))  # the matrix's scale along the text
            sizes = [float(size) * scale for size in re.findall(rb"/F\d+ ([\d.]+) Tf", block)]
            assert max(sizes) >= 7.0 - 1e-6, (name, lang, number, sizes)
            # a mathtext sub- or superscript ($v_{\mathrm{M}}$) is set at 70 % of its text: of 8 pt text
            assert min(sizes) >= 0.7 * 8.0 - 1e-6 and (min(sizes) >= 7.0 - 1e-6 or max(sizes) >= 8.0 - 1e-6), (name, lang, number, sizes)
    # the diagrams' own texts (all but the page's title, subtitle and page number): at least 8 pt
    for fig in figures:
        for ax in fig.axes:
            texts = [t for t in ax.texts] + ax.get_xticklabels() + ax.get_yticklabels() + [ax.yaxis.label, ax.xaxis.label]
            legend = ax.get_legend()
            if legend is not None:
                texts += legend.get_texts()
            for t in texts:
                if t.get_visible() and t.get_text().strip():
                    assert t.get_fontsize() >= 8.0, (name, t.get_text(), t.get_fontsize())
        for legend in fig.legends:
            assert all(t.get_fontsize() >= 8.0 for t in legend.get_texts())


def _position_lines(ax):
    return [line for line in ax.get_lines() if line.get_linestyle() == "--" and len(set(np.asarray(line.get_xdata(), dtype=float))) == 1
            and line.get_label().startswith("_")]


@pytest.mark.parametrize("name, lang", [("quick-return", "sr"), ("six-bar", "en")])
def test_every_position_line_has_the_same_width(name, lang, tmp_path):
    pypdf = pytest.importorskip("pypdf")
    figures, path = _handout_diagram_pdf(name, lang, tmp_path)
    widths = {line.get_linewidth() for fig in figures for ax in fig.axes for line in _position_lines(ax)}
    assert len(widths) == 1
    # in the PDF: every dashed vertical stroke (the positions' lines) has one width
    reader = pypdf.PdfReader(str(path))
    strokes = set()
    for page in reader.pages:
        content = page.get_contents().get_data().decode("latin-1")
        for w, x0, x1 in re.findall(r"([\d.]+) w \[ [\d. ]+ \] [\d.]+ d [^\n]*\n([\d.]+) [\d.]+ m\n([\d.]+) [\d.]+ l\n", content):
            if abs(float(x0) - float(x1)) < 1e-6:
                strokes.add(float(w))
    assert len(strokes) == 1 and strokes == widths


@pytest.mark.skipif(shutil.which("pdftoppm") is None, reason="pdftoppm (poppler-utils) is not installed")
@pytest.mark.parametrize("name, lang", [("quick-return", "sr"), ("six-bar", "en")])
def test_every_position_line_prints_equally_wide(name, lang, tmp_path):
    """Rasterised by pdftoppm (what a teacher prints from), every position line is the same number of pixels
    wide at 70, 110 and 150 dpi."""
    from PIL import Image

    figures, path = _handout_diagram_pdf(name, lang, tmp_path)
    fig = figures[0]
    ax = fig.axes[-1]  # the bottom panel: nothing drawn across the lines but the curves
    height = fig.get_size_inches()[1] * 72.0
    box = ax.get_window_extent()  # points at the figure's 72 dpi
    xs = [float(line.get_xdata()[0]) for line in _position_lines(ax)]
    lo, hi = ax.get_xlim()
    xs = [x for x in xs if lo + 1e-6 < x < hi - 1e-6]  # (one on the frame reads with the frame)
    assert len(xs) >= 3
    for dpi in (70, 110, 150):
        subprocess.run(["pdftoppm", "-r", str(dpi), "-gray", "-png", "-f", "1", "-l", "1", "-singlefile", str(path), str(tmp_path / "page")], check=True)
        ink = 1.0 - np.asarray(Image.open(tmp_path / "page.png"), dtype=float) / 255.0
        k = dpi / 72.0
        rows = slice(int((height - box.y1) * k) + 3, int((height - box.y0) * k) - 3)
        drawn = []
        for x in xs:
            px = (box.x0 + (x - lo) / (hi - lo) * box.width) * k
            columns = [float(np.median(ink[rows, c])) for c in range(int(px) - 3, int(px) + 4)]
            drawn.append(sum(1 for v in columns if v > 0.25))  # pixels wide (a dash's median over the panel)
        assert len(set(drawn)) == 1 and drawn[0] >= 1, (name, dpi, drawn)
