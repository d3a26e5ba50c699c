"""The single-position sheet fills its A3 landscape format (issue 10 §4, issue 11 §1).

Sizes are measured from the written SVG: scale factors as the title block prints them,
the mechanism's points from the analytic solution divided by that k_l, each plan's
arrows by gid (``tests/sheet_measure.py``), the ink of each drawing from its paths.
The blocks of text (equations, readings, results) are where the sheet's layout record
(``figure.plans_sheet``) says; the drawings' ink is checked to lie inside theirs.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

import plans
import plans.drawing
from plans.cli import main
from plans.positions import parse_positions
from sheet_measure import box_of, ink, mechanism_across, page_size, parse, plan_sizes, rect, scales

#: What a sheet must give its drawings [mm] (issue 11 §1), typed from the issue
MECHANISM_MM = 100.0
LARGEST_VECTOR_MM = 60.0
PLAN_ACROSS_MM = 40.0
A3_LANDSCAPE = (420.0, 297.0)
PREFIX = {"mechanism": "mech-", "velocity": "vel-", "acceleration": "acc-"}
#: SVG coordinates are written to 1e-6 pt: a length read back may fall short of its true value by this [mm]
READ = 1e-3


def _spy(monkeypatch):
    """Every sheet figure drawn by the command (the one written is the one whose factors the SVG prints)."""
    drawn = []
    real = plans.drawing.draw_sheet

    def spy(*args, **kwargs):
        fig = real(*args, **kwargs)
        drawn.append(fig)
        return fig

    monkeypatch.setattr(plans.drawing, "draw_sheet", spy)
    import plans.drawing.sheets as sheets_module

    monkeypatch.setattr(sheets_module, "draw_sheet", spy)
    return drawn


def _layout_of(drawn, root):
    printed = scales(root)
    for fig in reversed(drawn):
        layout = fig.plans_sheet
        if all(math.isclose(layout.scales[k], printed[k], rel_tol=1e-9) for k in layout.scales):
            return layout
    raise AssertionError(f"no drawn sheet has the printed factors {printed}")


@pytest.fixture(scope="module", params=plans.example_names())
def sheet(request, tmp_path_factory):
    mp = pytest.MonkeyPatch()
    drawn = _spy(mp)
    out = tmp_path_factory.mktemp(request.param)
    try:
        assert main(["draw", "--example", request.param, "-o", str(out)]) == 0
    finally:
        mp.undo()
    root = parse(out / "sheet.svg")
    return request.param, root, _layout_of(drawn, root), plans.solve(plans.load(plans.example_path(request.param)))


def _disjoint(a, b, tol=0.0) -> bool:
    return a[2] <= b[0] + tol or b[2] <= a[0] + tol or a[3] <= b[1] + tol or b[3] <= a[1] + tol


def _inside(inner, outer, tol=1e-6) -> bool:
    return inner[0] >= outer[0] - tol and inner[1] >= outer[1] - tol and inner[2] <= outer[2] + tol and inner[3] <= outer[3] + tol


def test_every_example_s_sheet_is_a3_landscape(sheet):
    name, root, layout, _ = sheet
    assert page_size(root) == A3_LANDSCAPE, name
    assert layout.format == "A3"


def test_the_mechanism_and_the_plans_reach_their_sizes(sheet):
    name, root, _, analytic = sheet
    k = scales(root)
    assert mechanism_across(analytic, k["k_l"]) >= MECHANISM_MM, name
    for prefix in ("vel-", "acc-"):
        largest, across = plan_sizes(root, prefix)
        assert largest >= LARGEST_VECTOR_MM - READ, (name, prefix, largest)
        assert across >= PLAN_ACROSS_MM - READ, (name, prefix, across)


def test_nothing_outside_the_frame_and_no_block_over_another_or_the_title_block(sheet):
    name, root, layout, _ = sheet
    frame = rect(root, "sheet-sheet-frame")
    title_block = rect(root, "sheet-title-block")
    drawings = {kind: ink(root, prefix) for kind, prefix in PREFIX.items()}
    assert all(drawings.values()), name
    for kind, box in drawings.items():
        assert _inside(box, frame), (name, kind, box, frame)
        assert _disjoint(box, title_block), (name, kind)
        # the layout's record of the block holds the ink drawn for it
        assert _inside(box, layout.blocks[kind][0], tol=0.5), (name, kind, box, layout.blocks[kind])
    texts = [(kind, b) for kind, boxes in layout.blocks.items() if kind not in PREFIX for b in boxes]
    assert {kind for kind, _ in texts} >= {"table", "readings"}, name
    everything = [(kind, b) for kind, b in drawings.items()] + texts
    for kind, b in texts:
        assert _inside(b, frame), (name, kind)
        assert _disjoint(b, title_block), (name, kind)
    for i, (ka, a) in enumerate(everything):
        for kb, b in everything[i + 1:]:
            assert _disjoint(a, b), (name, ka, a, kb, b)


def test_given_scale_factors_are_kept_exactly(tmp_path):
    assert main(["draw", "--example", "six-bar", "--k-l", "0.01", "--k-v", "0.05", "-o", str(tmp_path)]) == 0
    root = parse(tmp_path / "sheet.svg")
    k = scales(root)
    assert k["k_l"] == 0.01 and k["k_v"] == 0.05
    # v_A = ω·OA = 10 × 0.15 = 1.5 m/s (domain: six-bar crank) drawn 1.5 / 0.05 = 30 mm long
    largest, _ = plan_sizes(root, "vel-")
    assert largest == pytest.approx(1.5 / 0.05, abs=0.05) or largest > 30.0
    a = plans.solve(plans.load(plans.example_path("six-bar")))
    assert mechanism_across(a, 0.01) == pytest.approx(mechanism_across(a, k["k_l"]))


def test_the_rocker_limit_crank_is_larger_than_its_omega_arc_and_o_is_clear_of_the_epsilon_arrow(tmp_path):
    assert main(["draw", "--example", "rocker-limit", "-o", str(tmp_path)]) == 0
    root = parse(tmp_path / "sheet.svg")
    crank = ink(root, "mech-link-2")
    crank_mm = math.hypot(crank[2] - crank[0], crank[3] - crank[1])
    pin = ink(root, "mech-pin-O")
    centre = complex((pin[0] + pin[2]) / 2, (pin[1] + pin[3]) / 2)
    arc = ink(root, "mech-omega")
    radius = max(abs(complex(x, y) - centre) for x in (arc[0], arc[2]) for y in (arc[1], arc[3]))
    assert crank_mm >= 20.0 - 1e-6 and crank_mm >= 1.5 * radius, (crank_mm, radius)  # (at 20 mm exactly, read off the SVG)
    # the label O (10 pt text, its box from the anchor at the baseline) clear of the ε₂ arrowhead
    from sheet_measure import SVG, groups

    per_mm = float(root.get("viewBox").split()[2]) / 420.0
    text = next(groups(root)["mech-point-O"].iter(f"{SVG}text"))
    x, y = float(text.get("x")) / per_mm, 297.0 - float(text.get("y")) / per_mm
    size = 10.0 / per_mm
    label = (x, y - 0.25 * size, x + 0.8 * size, y + 0.8 * size)
    assert _disjoint(label, ink(root, "mech-epsilon-head")), (label, ink(root, "mech-epsilon-head"))


def _check_position_sheets(example, count, out):
    """Every sheet of ``draw --positions`` in *out*: A3, the sizes reached, ink inside the frame, drawings apart."""
    scene = plans.load(plans.example_path(example))
    from plans.motion import driver_cycle

    cycle = driver_cycle(scene, count)  # the positions of draw --positions, the driver's rates under its law
    analytic = cycle.solve()
    written = sorted(out.glob("sheet-*.svg"))
    assert written
    for path in written:
        index = int(path.stem.split("-")[1])
        root = parse(path)
        assert page_size(root) == A3_LANDSCAPE, path.name
        k = scales(root)
        x0, y0, x1, y1 = box_of([complex(m.r[index]) for m in analytic.points.values()])
        assert max(x1 - x0, y1 - y0) / k["k_l"] >= MECHANISM_MM, path.name
        for prefix in ("vel-", "acc-"):
            largest, across = plan_sizes(root, prefix)
            if prefix == "acc-" and all(abs(complex(m.a[index])) < 1e-12 for m in analytic.points.values()):
                # the wedge (PRP on fixed guides) at a constant driver velocity, the course's law: every
                # acceleration is 0 and the plan is its pole alone
                assert largest == 0.0, path.name
                continue
            assert largest >= LARGEST_VECTOR_MM - READ and across >= PLAN_ACROSS_MM - READ, (path.name, prefix, largest, across)
        frame = rect(root, "sheet-sheet-frame")
        boxes = {kind: ink(root, prefix) for kind, prefix in PREFIX.items()}
        for kind, box in boxes.items():
            assert _inside(box, frame) and _disjoint(box, rect(root, "sheet-title-block")), (path.name, kind)
        assert all(_disjoint(a, b) for i, a in enumerate(boxes.values()) for b in list(boxes.values())[i + 1:]), path.name
    return written


@pytest.mark.parametrize("example, count", [("six-bar", 4), ("rocker-limit", 4)])
def test_position_sheets_fill_a3_too(example, count, tmp_path):
    assert main(["draw", "--example", example, "--positions", str(count), "-o", str(tmp_path)]) == 0
    _check_position_sheets(example, count, tmp_path)


@pytest.fixture(scope="module", params=plans.example_names())
def twelve(request, tmp_path_factory):
    """``draw --example NAME --positions 12``, written once per example."""
    out = tmp_path_factory.mktemp(f"{request.param}-12")
    assert main(["draw", "--example", request.param, "--positions", "12", "-o", str(out)]) == 0
    return request.param, out


def test_every_example_s_twelve_position_sheets_fill_a3(twelve):
    """Issue 11 §1 on every sheet of every bundled example at 12 positions (rocker-limit: all 12 over its swing and back)."""
    example, out = twelve
    written = _check_position_sheets(example, 12, out)
    scene = plans.load(plans.example_path(example))
    analytic = plans.solve(scene, np.asarray(parse_positions(12, scene), dtype=float), allow_partial=True)  # (positions as drawn)
    solved = [i for i in range(12) if all(np.isfinite(complex(m.r[i])) for m in analytic.points.values())]
    # a sheet for every position the analytic solution reaches, and none other
    assert [int(p.stem.split("-")[1]) for p in written] == solved, example


def test_a_long_title_is_broken_into_lines_inside_the_title_block(tmp_path):
    """A position sheet's title (scene title, position, its value) is longer than the 180 mm title block."""
    assert main(["draw", "--example", "linear-arm", "--positions", "2", "-o", str(tmp_path)]) == 0
    from sheet_measure import SVG, groups

    root = parse(tmp_path / "sheet-00.svg")
    assert page_size(root) == A3_LANDSCAPE
    per_mm = float(root.get("viewBox").split()[2]) / page_size(root)[0]
    block = rect(root, "sheet-title-block")
    lines = [t for gid, g in groups(root).items() if gid.startswith("sheet-title-block-title") for t in g.iter(f"{SVG}text")]
    assert len(lines) >= 2
    assert "Position 0" in " ".join("".join(t.itertext()) for t in lines)
    for t in lines:
        size = float(re.search(r"font-size: ([\d.]+)px", t.get("style")).group(1)) / per_mm
        x = float(t.get("x") or t.get("transform").split("(")[1].split()[0]) / per_mm
        # DejaVu Sans Bold averages about 0.62 em a character
        assert x >= block[0] and x + 0.62 * size * len("".join(t.itertext())) <= block[2], "".join(t.itertext())
