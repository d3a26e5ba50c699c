"""centres.svg: no label touches another label or a centre's mark (review finding 22).

The six-bar's link number "2" touched the P₂₆ dot, and P₂₅, P₂₆, P₁₂ crowd
around O.  Measured with matplotlib's renderer: the rendered extents of every
text (the mechanism's names and numbers, the centres' labels) against each
other and against every centre's mark (ring or dot).
"""

from __future__ import annotations

import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg

import plans
from plans.centres import instant_centres
from plans.drawing.centres import draw_centres


def _overlap(a, b, shrink: float = 0.0) -> bool:
    return min(a.x1, b.x1) - max(a.x0, b.x0) > shrink and min(a.y1, b.y1) - max(a.y0, b.y0) > shrink


@pytest.fixture(scope="module", params=plans.example_names())
def drawn(request):
    result = instant_centres(plans.load(plans.example_path(request.param)))
    fig = draw_centres(result)
    FigureCanvasAgg(fig)
    return request.param, fig, fig.canvas.get_renderer()


def _texts(fig):
    return [t for t in fig.findobj(lambda a: hasattr(a, "get_text") and (a.get_gid() or "")) if t.get_text().strip()]


def test_no_text_on_the_mechanism_touches_a_centre_s_mark(drawn):
    name, fig, renderer = drawn
    marks = [(m.get_gid(), m.get_window_extent(renderer)) for m in fig.findobj(lambda a: (a.get_gid() or "").startswith("centres-mark-"))]
    assert marks, name
    for t in _texts(fig):
        gid = t.get_gid()
        if gid.startswith(("centres-legend", "centres-title", "centres-undetermined", "centres-diagram", "mech-heading", "mech-scale")):
            continue
        box = t.get_window_extent(renderer)
        for mark, extent in marks:
            assert not _overlap(box, extent), (name, gid, t.get_text(), mark)


def test_no_label_overlaps_another(drawn):
    name, fig, renderer = drawn
    boxes = [(t.get_gid(), t.get_text(), t.get_window_extent(renderer)) for t in _texts(fig)]
    for k, (ga, ta, a) in enumerate(boxes):
        for gb, tb, b in boxes[k + 1 :]:
            assert not _overlap(a, b), (name, ta, tb)


def test_the_six_bar_link_number_2_is_clear_of_p26():
    result = instant_centres(plans.load(plans.example_path("six-bar")))
    fig = draw_centres(result)
    FigureCanvasAgg(fig)
    renderer = fig.canvas.get_renderer()
    two = [t for t in _texts(fig) if t.get_gid().startswith("mech-number-2")]
    dot = [m for m in fig.findobj(lambda a: a.get_gid() == "centres-mark-P26")]
    assert two and dot
    a, b = two[0].get_window_extent(renderer), dot[0].get_window_extent(renderer)
    gap = max(b.x0 - a.x1, a.x0 - b.x1, b.y0 - a.y1, a.y0 - b.y1)  # [px = pt at 72 dpi]
    assert gap > 1.0, gap
