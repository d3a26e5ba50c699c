"""A fixed support is drawn the same way on every centres page of the plate (teacher's second review: the pivot
symbol at O of the quick-return had its hatching above, tilted, below from one position's page to the next)."""

import cmath
import math
import re

from review_handouts import built


def _support_direction(svg: bytes, name: str) -> float:
    """The direction [deg, SVG's y down] from pivot *name* to its support's base: the triangle's apex is the pin."""
    text = svg.decode()
    group = re.search(rf'<g id="mech-ground-{name}">\s*<path d="([^"]+)"', text)
    assert group, f"no support drawn at {name}"
    xy = [complex(float(x), float(y)) for x, y in re.findall(r"([-0-9.]+) ([-0-9.]+)", group.group(1))]
    apex, left, right = xy[:3]
    return math.degrees(cmath.phase((left + right) / 2 - apex))


def test_quick_return_support_at_O_one_way_on_every_centres_page():
    doc = built("quick-return", 12, "sr", centres=True)
    blocks = [doc.images[f"centres-{n}"] for n in range(12)]
    for pivot in ("O", "C"):
        directions = [_support_direction(svg, pivot) for svg in blocks]
        assert max(directions) - min(directions) < 0.5, (pivot, [round(d) for d in directions])
