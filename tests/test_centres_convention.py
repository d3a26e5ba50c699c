"""Issue 20 §4: centres pages a student can use.

* far centres are arrows at the edge with their distance (mm of the drawing beyond the tip), so
  the mechanism keeps its size: the Bulgarian linear-arm page drew it 45 mm across at k_l 0.03;
* no label over another, and a centre's label clear of the mechanism's names ("3 P₁₂" read as one);
* the centres page's k_l found from geometry, without drawing the page per candidate (114 drawings for six positions);
* angles 0…360° and four digits as on every other page; ``plans centres`` prints 0, not 1.38778e-17.

Expected values: the centres from :func:`plans.centres.instant_centres` called here, the renderer's
text extents (matplotlib), the CLI's own output.
"""

from __future__ import annotations

import re

import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg

import plans
from plans.centres import instant_centres
from plans.cli import main
from plans.drawing import mechanism
from plans.drawing.centres import CentresSizer, draw_centres_into
from plans.drawing.svg import new_figure
from plans.handout import handout

#: the plate's k_l for the linear-arm (the mechanism over 100 mm across, as the plate draws it)
LINEAR_ARM_K_L = 0.008


@pytest.fixture(scope="module")
def linear_arm_bg():
    """The Bulgarian linear-arm's centres drawing as the centres page places it: at physical size [mm]."""
    result = instant_centres(plans.load(plans.example_path("linear-arm")))
    fig = new_figure()
    ax = fig.add_axes([0, 0, 1, 1])
    width, height = draw_centres_into(ax, result, LINEAR_ARM_K_L, "bg", legend=False, diagram=False, room_min=12.0)
    fig.set_size_inches(width / 25.4, height / 25.4)
    return fig, ax


def _extents(fig, ax, prefix=""):
    FigureCanvasAgg(fig)
    renderer = fig.canvas.get_renderer()
    return [(t.get_gid(), t.get_text(), t.get_window_extent(renderer)) for t in ax.texts if t.get_text().strip() and (t.get_gid() or "").startswith(prefix)]


def test_linear_arm_drawn_100_mm_across_fits_a_page_width():
    """At the k_l that draws the linear-arm mechanism over 100 mm across (it was 45 mm on the Bulgarian page,
    its far centres fitted in), the centres drawing is at most 180 mm × 160 mm: far centres are edge arrows."""
    result = instant_centres(plans.load(plans.example_path("linear-arm")))
    k_l = 0.008
    ax = new_figure().add_axes([0, 0, 1, 1])
    width, height = draw_centres_into(ax, result, k_l, lang="bg", legend=False, diagram=False, room_min=12.0)
    xs, ys = [], []
    for line in ax.lines:
        if (line.get_gid() or "").startswith("mech-"):
            xs += list(line.get_xdata())
            ys += list(line.get_ydata())
    assert max(max(xs) - min(xs), max(ys) - min(ys)) >= 100.0
    assert width <= 180.0 and height <= 160.0, (width, height)
    arrows = {(a.get_gid() or "") for a in ax.lines if "-edge-" in (a.get_gid() or "")}
    assert {"centres-edge-P13", "centres-edge-P24"} <= arrows  # the far ones (1.3 m and 0.9 m from the frame's origin)


def test_no_label_overlaps_another_on_the_page_and_centre_labels_keep_clear_of_names(linear_arm_bg):
    fig, ax = linear_arm_bg
    boxes = _extents(fig, ax)
    mm = fig.dpi / 25.4  # display units per mm
    for k, (ga, ta, a) in enumerate(boxes):
        for gb, tb, b in boxes[k + 1:]:
            overlap = min(a.x1, b.x1) - max(a.x0, b.x0) > 0 and min(a.y1, b.y1) - max(a.y0, b.y0) > 0
            assert not overlap, (ta, tb)
            # a centre's label and a name or number of the mechanism are apart by at least 0.8 mm ("3 P₁₂" read as one)
            if ("centres-label-" in ga) != ("centres-label-" in gb) and ga.startswith(("centres-label-", "mech-")) and gb.startswith(("centres-label-", "mech-")):
                gap = max(b.x0 - a.x1, a.x0 - b.x1, b.y0 - a.y1, a.y0 - b.y1)
                assert gap >= 0.8 * mm, (ta, tb, gap / mm)


@pytest.mark.parametrize("name", ["six-bar", "quick-return", "linear-arm", "slider-crank"])
def test_every_far_centre_is_an_edge_arrow_reading_its_distance_in_mm(name):
    """Each centre not marked where it is has an arrow pointing at it whose label gives the distance
    beyond its tip in mm of the drawing (to the mm), or ∞."""
    result = instant_centres(plans.load(plans.example_path(name)))
    k_l = CentresSizer(result).result.size / 100.0  # the mechanism 100 mm across
    ax = new_figure().add_axes([0, 0, 1, 1])
    draw_centres_into(ax, result, k_l, legend=False, diagram=False)
    gids = {a.get_gid(): a for a in ax.get_children() if a.get_gid()}
    for c in result.centres:
        if f"centres-mark-{c.label}" in gids:
            continue
        head = gids[f"centres-edge-{c.label}-head"]
        tip = complex(*head.get_xy()[0])
        text = gids[f"centres-label-{c.label}"].get_text()
        if c.point is None:
            assert text.endswith("∞"), text
            continue
        far = c.point / k_l
        distance = float(re.search(r"(\d+) mm$", text).group(1))
        assert distance == pytest.approx(abs(far - tip), abs=0.5), (c.label, text)


@pytest.mark.parametrize("name", ["six-bar", "linear-arm", "quick-return", "wedge"])
def test_the_sizer_foresees_the_drawn_size_at_its_own_scales(name):
    """The size the page plans with is the size drawn (both scales the sizer measured the mechanism at)."""
    result = instant_centres(plans.load(plans.example_path(name)))
    sizer = CentresSizer(result, room_min=12.0)
    k0 = plans.graphical.scales.round_scale(result.size)
    for k in (k0, k0 / 2):
        ax = new_figure().add_axes([0, 0, 1, 1])
        w, h = draw_centres_into(ax, result, k, legend=False, diagram=False, room_min=12.0)
        assert sizer.size(k) == pytest.approx((w, h), abs=0.05)


def test_the_page_is_not_drawn_per_candidate_scale(monkeypatch):
    """A handout's centres page draws the mechanism a few times (twice to measure it, once or twice on the
    page), not once per candidate k_l: counted as the pages with centres less the pages without."""
    count = [0]
    original = mechanism.MechanismDrawing.draw

    def counting(self):
        count[0] += 1
        return original(self)

    monkeypatch.setattr(mechanism.MechanismDrawing, "draw", counting)
    scene = plans.load(plans.example_path("six-bar"))
    handout(scene, positions=1)
    without = count[0]
    handout(scene, positions=1, centres=True)
    assert count[0] - 2 * without <= 4, (without, count[0])


def test_page_angles_are_0_to_360():
    """v_H points down and right: 337.3°, not −22.7°, as the results tables of every other page."""
    from plans.compare import compare_centres
    from plans.drawing.centres_page import centres_page_table

    scene = plans.load(plans.example_path("linear-arm"))
    result = instant_centres(scene)
    rows = centres_page_table(result, compare_centres(plans.solve(scene), result), "bg")
    angles = [float(m.replace(",", ".").replace("−", "-")) for row in rows for cell in row for m in re.findall(r"∠ ([−\-]?[\d,\.]+)°", cell)]
    assert angles and all(0.0 <= a < 360.0 for a in angles), angles
    assert any(a == pytest.approx(337.3, abs=0.05) for a in angles)


def test_plans_centres_prints_zero_for_round_off(capsys, tmp_path):
    assert main(["centres", "--example", "four-bar", "-o", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "e-17" not in out and "e-16" not in out
    row = next(line for line in out.splitlines() if line.startswith("P24"))
    assert row.split()[3] == "0", row  # P24 lies on the x axis through O and D


def test_the_table_reads_p1j_m_in_mm_of_the_drawing():
    """With the drawing's k_l the table gives P_1jM [mm]; × k_l × |ω_j| it is |v_M| (to the 0.1 mm printed)."""
    from plans.compare import compare_centres
    from plans.drawing.centres_page import centres_page_table

    scene = plans.load(plans.example_path("linear-arm"))
    result = instant_centres(scene)
    analytic = plans.solve(scene)
    k_l = 0.008
    rows = centres_page_table(result, compare_centres(analytic, result), "en", k_l)
    assert rows[0][2] == "from the drawing (lengths in mm)"  # P_1jM for a point, the path's lengths for ω (fourth review)
    checked = 0
    for name in scene.report:
        row = next(r for r in rows if r[0].startswith(f"$v_{{{name}}}$"))
        centre = result.centre("frame", scene.home_of(name))
        if centre.point is None:
            assert row[2] == "—"
            continue
        # the segment it is, P_1jM, and its length (round 20: a bare "349,9" said nothing of what was measured)
        segment, _, length = row[2].partition(" = ")
        assert segment == "P" + centre.label[1:].translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")) + name, row[2]
        mm = float(length)
        assert mm == pytest.approx(abs(analytic.points[name].r[0] - centre.point) / k_l, abs=0.051)
        omega = abs(analytic.links[scene.home_of(name)].omega[0])
        assert mm * k_l * omega == pytest.approx(abs(analytic.points[name].v[0]), abs=0.051 * k_l * omega + 1e-9)  # to the 0.1 mm printed
        checked += 1
    assert checked >= 3
