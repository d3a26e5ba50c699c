"""The plan of positions numbers what has room, with leader lines (issue 11 §4, review finding 21).

Before: position 0 was unnumbered wherever the scheme's pin, block or slot
sat on its mark (six-bar C₀ and B₀, quick-return A₀, D₀ and E₀, linear-arm
A₀, H₀, K₀): a leader could not leave the pin it starts in.  Measured with
matplotlib's renderer (text extents) on the drawn figure.
"""

from __future__ import annotations

import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.transforms import Bbox

import plans
from plans.drawing.positions_plan import draw_positions_plan
from plans.positions import run_positions


def _cases():
    for name in plans.example_names():
        scene = plans.load(plans.example_path(name))
        if isinstance(scene.driver, plans.scene.Crank) or scene.driver.stroke is not None:
            yield name


@pytest.fixture(scope="module")
def plans_of_positions():
    out = {}
    for name in _cases():
        run = run_positions(plans.load(plans.example_path(name)), 12)
        fig = draw_positions_plan(run)[0].figure
        FigureCanvasAgg(fig)
        out[name] = (run, fig, fig.canvas.get_renderer())
    return out


def _gids(fig, prefix: str):
    return [a for a in fig.findobj(lambda a: (a.get_gid() or "").startswith(prefix))]


def test_position_0_of_every_numbered_point_is_numbered(plans_of_positions):
    for name, (run, fig, _) in plans_of_positions.items():
        first = run.runs[0].index
        marks = {a.get_gid()[len("pos-mark-"):] for a in _gids(fig, f"pos-mark-{first}-")}
        numbers = {a.get_gid()[len("pos-position-"):] for a in _gids(fig, f"pos-position-{first}-") if not a.get_gid().endswith(("-leader", "-index", "-comma"))}
        # position 0 is the scheme drawn in full: a point its scheme labels (A) is not numbered again (A₀ at A)
        numbers |= _scheme_labelled(run)
        assert marks and marks <= numbers, (name, sorted(marks - numbers))


def _scheme_labelled(run) -> set[str]:
    """The marks of position 0 that the scheme drawn in full labels (``0-A``)."""
    from plans.drawing.mechanism import mechanism_labels

    first = run.runs[0]
    return {f"{first.index}-{p}" for p in mechanism_labels(first.graphical)}


def test_most_marks_are_numbered(plans_of_positions):
    counted, numbered = 0, 0
    for name, (run, fig, _) in plans_of_positions.items():
        marks = {a.get_gid()[len("pos-mark-"):] for a in _gids(fig, "pos-mark-")}
        numbers = {a.get_gid()[len("pos-position-"):] for a in _gids(fig, "pos-position-") if not a.get_gid().endswith(("-leader", "-index", "-comma"))}
        assert numbers <= marks
        numbers |= _scheme_labelled(run) & marks  # position 0's points labelled once, by the scheme
        # the linear arm's 12 positions crowd a 60 mm stroke: 28 of its 60 marks have room (18 before)
        # (issue 20, 2nd review: a number that would lie nearer another point is left out, and the plan says so)
        assert len(numbers) >= 0.4 * len(marks), (name, len(numbers), len(marks))
        if name == "rocker-limit":
            # its input swings over ±56° there and back (issue 19): the crank pin revisits its arc, positions pair up
            # (15 of 24 numbered); counted on its own so that the others' share stays what it was
            continue
        counted += len(marks)
        numbered += len(numbers)
    # 218 of 318 marks (69 %) were numbered before; then 260 (82 %); 248 of 312 (79 %) with every number nearer its
    # own mark than any other (issue 20, second review: the rest said under the plan)
    assert numbered >= 0.75 * counted, (numbered, counted)


def test_a_leader_line_crosses_no_label(plans_of_positions):
    for name, (run, fig, renderer) in plans_of_positions.items():
        texts = [t for t in fig.findobj(lambda a: hasattr(a, "get_text") and a.get_gid()) if t.get_text().strip()]
        boxes = [(t.get_gid(), t.get_window_extent(renderer)) for t in texts]
        for leader in _gids(fig, "pos-position-"):
            if not leader.get_gid().endswith("-leader"):
                continue
            own = leader.get_gid()[: -len("-leader")]
            path = leader.get_path().transformed(leader.get_transform())
            for gid, box in boxes:
                if gid == own:
                    continue
                inner = Bbox.from_extents(box.x0 + 0.5, box.y0 + 0.5, box.x1 - 0.5, box.y1 - 0.5)
                assert not path.intersects_bbox(inner, filled=False), (name, own, gid)
