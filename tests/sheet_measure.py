"""Sizes on a sheet, measured from its SVG (geometry by gid) and the analytic solution: for the sheet tests.

Everything is in millimetres on the page (origin lower left).  Scale factors are read
from the title block's text as printed; the mechanism's size is the analytic positions
of its points divided by that k_l; a plan's vectors are the drawn arrows (a line and its
``-head``, as ``tests/test_tables_readings.py`` reads them), the enlarged detail and
the legend left out.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"
_NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e-?\d+)?")


def _per_mm(root) -> float:
    return float(root.get("viewBox").split()[2]) / float(root.get("width").removesuffix("mm"))


def page_size(root) -> tuple[float, float]:
    return float(root.get("width").removesuffix("mm")), float(root.get("height").removesuffix("mm"))


def _points(group, per_mm: float, height: float) -> list[complex]:
    """Every coordinate of every path under *group* [mm, y up]."""
    out = []
    for path in group.iter(f"{SVG}path"):
        values = [float(v) for v in _NUMBER.findall(path.get("d") or "")]
        out += [complex(x / per_mm, height - y / per_mm) for x, y in zip(values[::2], values[1::2])]
    return out


def groups(root) -> dict:
    return {g.get("id"): g for g in root.iter(f"{SVG}g") if g.get("id")}


def box_of(points) -> tuple[float, float, float, float]:
    xs = [z.real for z in points]
    ys = [z.imag for z in points]
    return min(xs), min(ys), max(xs), max(ys)


def ink(root, prefix: str) -> tuple[float, float, float, float] | None:
    """The box (x0, y0, x1, y1) [mm] of every path drawn under gids starting with *prefix*."""
    per_mm, (_, height) = _per_mm(root), page_size(root)
    points = []
    for gid, group in groups(root).items():
        if gid.startswith(prefix):
            points += _points(group, per_mm, height)
    return box_of(points) if points else None


def rect(root, gid: str) -> tuple[float, float, float, float]:
    per_mm, (_, height) = _per_mm(root), page_size(root)
    return box_of(_points(groups(root)[gid], per_mm, height))


def scales(root) -> dict[str, float]:
    """``{"k_l", "k_v", "k_a"}`` as the title block prints them (typeset: k and its subscript are separate glyphs)."""
    text = ""
    for gid, group in groups(root).items():
        if gid.startswith("sheet-title-block-row"):
            text += "".join("".join(t.itertext()) for t in group.iter(f"{SVG}text")) + "\n"
    text = "".join(text.split()).replace("−", "-")
    out = {}
    for letter, value in re.findall(r"k([lva])=([0-9]+(?:[.,][0-9]+)?)", text):
        out[f"k_{letter}"] = float(value.replace(",", "."))
    return out


def vectors(root, prefix: str) -> list[tuple[complex, complex]]:
    """(tail, tip) [mm] of every arrow of a plan (*prefix* ``"vel-"`` or ``"acc-"``), legend and detail left out."""
    per_mm, (_, height) = _per_mm(root), page_size(root)
    found = groups(root)
    out = []
    for gid, group in found.items():
        if not gid.startswith(prefix) or gid.endswith("-head"):
            continue
        rest = gid[len(prefix):]
        if rest.startswith(("legend", "detail")):
            continue
        head = found.get(f"{gid}-head")
        if head is None:
            continue
        tail = _points(group, per_mm, height)[0]
        tip = _points(head, per_mm, height)[0]
        out.append((tail, tip))
    return out


def plan_sizes(root, prefix: str) -> tuple[float, float]:
    """(largest vector, larger side of the box of all vector ends) [mm] of a plan on the sheet."""
    arrows = vectors(root, prefix)
    if not arrows:
        return 0.0, 0.0
    largest = max(abs(b - a) for a, b in arrows)
    x0, y0, x1, y1 = box_of([z for pair in arrows for z in pair])
    return largest, max(x1 - x0, y1 - y0)


def mechanism_across(analytic, k_l: float) -> float:
    """The larger side of the bounding box of the mechanism's points [mm] at *k_l*, from the analytic positions."""
    zs = [complex(m.r[0]) for m in analytic.points.values()]
    x0, y0, x1, y1 = box_of(zs)
    return max(x1 - x0, y1 - y0) / k_l


def parse(path):
    return ET.parse(path).getroot()
