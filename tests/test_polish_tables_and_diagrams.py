"""Review findings 26–28: table rows in link order, true minus in bg pages, rocker-limit diagrams over where it assembles.

Expected values worked here: the rocker-limit four-bar (OA = 100, AB = 450,
BD = 200, OD = 700 mm) assembles while |AD| ≤ AB + BD = 650 mm;
|AD|² = 0.1² + 0.7² − 2·0.1·0.7·cos φ gives cos φ = 0.0775/0.14, φ = ±56.39°:
from position 0 at 30°, Δφ from −86.39° to +26.39°.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import plans
from plans.analytic import solve
from plans.cli import main
from plans.drawing.diagrams import draw_cycle_diagrams, plot_cycle
from plans.positions import cycle_positions

SVG = "{http://www.w3.org/2000/svg}"
LIMIT = math.degrees(math.acos((0.1**2 + 0.7**2 - 0.65**2) / (2 * 0.1 * 0.7)))  # 56.39°


def _quantity_rows(texts: str) -> list[str]:
    return re.findall(r"[ωε]\s*_?\{?(\d+)", texts)


def test_link_rows_follow_the_link_numbers():
    from plans.compare import compare
    from plans.graphical import construct
    from plans.report import sheet_table

    for example in ("quick-return", "six-bar", "linear-arm", "scotch-yoke"):
        scene = plans.load(plans.example_path(example))
        a, g = solve(scene), construct(scene)
        labels = [row[0] for row in sheet_table(compare(a, g), g, a)[1:]]
        links = [re.search(r"\\(omega|varepsilon)_\{(\w+)\}", t) for t in labels]
        numbers = [int(m.group(2)) for m in links if m and m.group(2).isdigit()]
        assert numbers == sorted(numbers), (example, numbers)
        if example == "quick-return":  # the block 3 (a [[slider]]) among the links, not after link 5
            assert numbers[:3] == [2, 3, 3], numbers
        # and ω before ε of each link
        kinds = [m.group(1) for m in links if m]
        for k in range(1, len(kinds)):
            if kinds[k] == "omega" and numbers[k] == numbers[k - 1]:
                pytest.fail((example, labels))


def _pdf_text(path) -> str:
    from pypdf import PdfReader

    return " ".join(" ".join(page.extract_text() for page in PdfReader(path).pages).split())


def test_the_sr_handout_results_table_lists_the_links_in_order(tmp_path):
    import unicodedata

    assert main(["handout", "--example", "quick-return", "--lang", "sr", "-o", str(tmp_path / "qr.pdf"), "--quiet"]) == 0
    text = unicodedata.normalize("NFKC", _pdf_text(tmp_path / "qr.pdf"))
    table = text[text.index("Графичке и аналитичке вредности"):]
    # the results table's rows: "ω2 [rad/s]", "ε3 [rad/s²]" …
    numbers = [int(n) for n in re.findall(r"[ωε](\d+) \[rad", table)]
    assert len(numbers) >= 5, table[:400]
    assert numbers == sorted(numbers), numbers


def test_bg_pages_write_negative_numbers_with_a_true_minus(tmp_path):
    assert main(["handout", "--example", "linear-arm", "--positions", "4", "--lang", "bg", "-o", str(tmp_path / "la.pdf"), "--quiet"]) == 0
    text = _pdf_text(tmp_path / "la.pdf")
    assert not re.search(r"(^|[\s(=:;,])-\d", text), re.findall(r".{20}(?:^|[\s(=:;,])-\d.{5}", text)
    assert "s₂ = −" in text  # the positions with a negative s₂ are there, with "−"


def _hatched(ax) -> list[tuple[float, float]]:
    """The x extents of the 'cannot assemble' bands (grey, hatched ///) inside the axes."""
    lo, hi = ax.get_xlim()
    out = []
    for p in ax.patches:
        if p.get_hatch() == "///":
            x0, x1 = sorted(p.get_path().transformed(p.get_patch_transform()).get_extents().intervalx)
            a, b = max(x0, lo), min(x1, hi)
            if b > a:
                out.append((a, b))
    return out


@pytest.fixture(scope="module")
def rocker_limit():
    # a turn of given angles through the interval without assembly (plans' own cycle swings this input: issue 19)
    scene = plans.load(plans.example_path("rocker-limit"))
    sweep = solve(scene, scene.driver.phi + 2 * np.pi * np.arange(361) / 360, allow_partial=True)
    marked = list(scene.driver.phi + 2 * np.pi * np.arange(12) / 12)
    return scene, sweep, marked


def test_rocker_limit_diagrams_show_where_it_assembles_with_a_margin(rocker_limit):
    scene, sweep, marked = rocker_limit
    first, last = -30.0 - LIMIT, LIMIT - 30.0  # −86.39°, +26.39°
    for name, fig in draw_cycle_diagrams(sweep, marked=marked):
        for ax in fig.axes:
            if not ax.lines:
                continue
            lo, hi = ax.get_xlim()
            assert first - 30.0 <= lo <= first - 1.0 and last + 1.0 <= hi <= last + 30.0, (name, lo, hi)
            hatched = sum(b - a for a, b in _hatched(ax))
            assert 0 < hatched <= 0.4 * (hi - lo), (name, hatched, hi - lo)
            # the curves run over the whole arc where it assembles
            xs = np.concatenate([np.asarray(line.get_xdata(), dtype=float)[np.isfinite(np.asarray(line.get_ydata(), dtype=float))]
                                 for line in ax.lines if not line.get_label().startswith("_") and len(line.get_xdata()) > 10])
            assert xs.min() <= first + 1.0 and xs.max() >= last - 1.0, (name, xs.min(), xs.max())
            # a marked position is drawn where the axis shows it (position 10 at −60°, 11 at −30°, 0 at 0°)
    texts = {t.get_text() for t in fig.axes[0].texts}
    assert {"0", "10", "11"} <= texts and "5" not in texts


def test_plot_cycle_shows_the_same_window(rocker_limit):
    scene, sweep, marked = rocker_limit
    ax = plot_cycle(sweep, "omega")[0].axes
    lo, hi = ax.get_xlim()
    assert lo < -30.0 - LIMIT < LIMIT - 30.0 < hi and hi - lo < 180.0


def test_a_whole_turn_is_drawn_to_360_with_its_tick(tmp_path):
    assert main(["sweep", "--example", "six-bar", "--plot", str(tmp_path), "-o", str(tmp_path / "s.csv")]) == 0
    scene = plans.load(plans.example_path("six-bar"))
    sweep = solve(scene, np.asarray(cycle_positions(scene, 360)), allow_partial=True)
    for name, fig in draw_cycle_diagrams(sweep):
        ax = [a for a in fig.axes if a.lines][-1]
        assert ax.get_xlim() == pytest.approx((0.0, 360.0)), name
        assert 360.0 in [round(t, 6) for t in ax.get_xticks()], name
        assert not _hatched(ax), name  # the six-bar assembles everywhere: nothing hatched at the turn's last step
