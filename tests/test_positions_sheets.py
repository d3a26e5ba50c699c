"""plans draw --positions: one sheet per position at one set of scale factors, and the plan of positions."""

from __future__ import annotations

import numpy as np
import pytest

import plans
from plans import write_position_sheets
from plans.drawing.positions_plan import draw_positions_plan, numbered_points
from plans.positions import run_positions
from test_positions import STUCK

SVG = "{http://www.w3.org/2000/svg}"


def _text(path, plain: bool = True) -> str:
    from sheet_pages import text

    return " ".join(text(path.read_bytes(), plain).split())


@pytest.fixture(scope="module")
def sheets(tmp_path_factory):
    directory = tmp_path_factory.mktemp("sheets")
    scene = plans.load(plans.example_path("four-bar"))
    write_position_sheets(run_positions(scene, 6), directory)  # an earlier run with more positions
    run = run_positions(scene, "0, 120 deg")
    pdfs = tmp_path_factory.mktemp("pdf")
    return run, directory, write_position_sheets(run, directory), write_position_sheets(run, pdfs, format="pdf")


def test_one_sheet_per_position_and_the_plan_of_positions(sheets):
    import unicodedata

    run, directory, paths, pdfs = sheets
    assert [p.name for p in paths] == ["sheet-00.svg", "sheet-01.svg", "positions.svg"]
    assert sorted(p.name for p in directory.iterdir()) == ["positions.svg", "sheet-00.svg", "sheet-01.svg"]
    for k, path in enumerate(pdfs[:2]):
        title = _text(path)
        assert f"Position {k}: {unicodedata.normalize('NFKC', run.runs[k].label)}" in title
        assert f"Sheet {k + 2} of 3" in title  # the plan of positions is sheet 1 (the textbook's order)


def test_the_same_scale_factors_on_every_sheet(sheets):
    from sheet_pages import scales

    run, _, _, pdfs = sheets
    stated = [scales(_text(path)) for path in pdfs]
    assert stated[0] == stated[1] and set(stated[0]) == {"k_l", "k_v", "k_a"}
    # the plan of positions at the sheets' k_l (issue 20: one k_l per kind across the plate), stated
    assert set(stated[2]) == {"k_l"} and stated[2]["k_l"] == stated[0]["k_l"]


def test_the_plan_of_positions_draws_each_position_and_closed_paths(sheets):
    run, _, _, pdfs = sheets
    texts = _text(pdfs[2], plain=False)
    words = texts.split()
    for point in numbered_points(run.scene):
        # a number is its letter and its index in digits at the small text size (A₁ reads "A1" out of the PDF);
        # position 0 is lettered as the others (A₀, issue 20's second review)
        assert f"{point}1" in words and f"{point}0" in words
    artists = draw_positions_plan(run)
    by_gid = {}
    for artist in artists:
        by_gid.setdefault(artist.get_gid(), []).append(artist)
    for point in run.scene.report:
        (path,) = by_gid[f"pos-path-{point}"]
        x, y = path.get_data()
        assert (x[0], y[0]) == pytest.approx((x[-1], y[-1]), abs=1e-9)  # a full crank turn closes the path
        z = np.asarray(run.cycle.points[point].r) / run.scales["k_l"]
        assert np.allclose(x, z.real) and np.allclose(y, z.imag)
    assert "pos-link-1-3" in by_gid  # position 1 in thin lines; position 0 as the full scheme
    assert "pos-link-3" in by_gid


def test_a_position_that_cannot_assemble_gets_no_sheet(tmp_path):
    run = run_positions(plans.loads(STUCK), "10, 180 deg")
    paths = write_position_sheets(run, tmp_path)
    assert [p.name for p in paths] == ["sheet-00.svg", "positions.svg"]
    artists = draw_positions_plan(run)
    # the crank cannot turn fully: over its cycle it swings between its limit positions and back (issue 19), B on
    # one branch there and on the other back: its path is one closed curve, no NaN drawn
    pieces = [a for a in artists if (a.get_gid() or "").startswith("pos-path-B")]
    assert len(pieces) == 1
    for piece in pieces:
        assert np.all(np.isfinite(piece.get_xydata()))
