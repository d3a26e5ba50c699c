"""The lever drawing read as a teacher reads it: every image label at the image it names, every arrow at its point.

The images are computed here independently of the lever, from the analytic
velocities: the image of X on the lever is v_X / k_v turned by 90°
counter-clockwise (the plan's own k_v, a chosen scale, not a result).
"""

from __future__ import annotations

import pytest

import plans
from plans.drawing.force_drawing import draw_lever
from plans.forces.lever import joukowski_lever
from plans.graphical import construct
from plans.scene import example_path, load


def _label_centres(artists) -> dict[str, complex]:
    """gid -> the centre of the text's box [mm, data units]."""
    fig = artists[0].figure
    ax = fig.axes[0]
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    renderer = FigureCanvasAgg(fig).get_renderer()
    inverse = ax.transData.inverted()
    out = {}
    for a in artists:
        gid = a.get_gid()
        if gid and hasattr(a, "get_text"):
            (x0, y0), (x1, y1) = inverse.transform(a.get_window_extent(renderer).get_points())
            out[gid] = complex((x0 + x1) / 2, (y0 + y1) / 2)
    return out


def _analytic_images(scene, k_v: float) -> dict[str, complex]:
    """Image label -> i·v_X/k_v [mm] for every named point of every moving link (analytic velocities)."""
    solution = plans.solve(scene)
    images = {}
    for body, link in scene.bodies.items():
        if body == "1":
            continue
        for name, local in link.points.items():
            v = complex(solution.motion_of(body, local).v[0])
            images.setdefault(name.lower(), 1j * v / k_v)
    return images


@pytest.mark.parametrize("name", ["six-bar-loads", "quick-return-loads", "slider-crank-loads"])
def test_every_image_label_stands_nearest_its_own_image(name):
    scene = load(example_path(name))
    lever = joukowski_lever(construct(scene, precision=None))
    truth = _analytic_images(scene, lever.k_v)
    artists = draw_lever(lever)
    centres = _label_centres(artists)
    dots = {label: complex(z) for label, z in lever.images.items()}
    checked = 0
    for label, z in dots.items():
        if label in truth:
            assert z == pytest.approx(truth[label], abs=1e-6), label  # the image is where the velocity says
        gid = f"lever-image-{label}"
        if gid not in centres:
            continue
        centre = centres[gid]
        nearest = min(dots.values(), key=lambda q: abs(q - centre))
        assert abs(nearest - z) < 1e-6, f"{label}: its label is nearer another image ({nearest}) than its own ({z})"
        checked += 1
    assert checked >= 3
