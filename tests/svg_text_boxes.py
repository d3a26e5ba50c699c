"""The text boxes of a matplotlib SVG drawing, read from the SVG itself (for tests of labels that overlap).

Each text's box [SVG user units, y down]: its advance measured with matplotlib's own font metrics (the font the
SVG names, at the size it names), its height from the font's ascent and descent; a text with math is a group of
glyph tspans under one ``translate``, its box the union of theirs.  A text turned by a rotation is boxed by its
turned corners.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

from matplotlib.font_manager import FontProperties
from matplotlib.textpath import TextToPath

SVG = "{http://www.w3.org/2000/svg}"
_MEASURE = TextToPath()


def _style(style: str) -> dict:
    return dict(part.split(":", 1) for part in (p.strip() for p in style.split(";")) if ":" in part)


def _width(text: str, size: float, family: str) -> float:
    prop = FontProperties(family=family.strip(" '\""), size=size)
    w, _, _ = _MEASURE.get_text_width_height_descent(text, prop, ismath=False)
    return w


def _box(x: float, y: float, width: float, size: float, anchor: str, angle: float = 0.0):
    x0 = {"start": x, "middle": x - width / 2, "end": x - width}.get(anchor, x)
    corners = [(x0, y - 0.76 * size), (x0 + width, y - 0.76 * size), (x0, y + 0.24 * size), (x0 + width, y + 0.24 * size)]
    if angle:
        c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
        corners = [(x + (px - x) * c - (py - y) * s, y + (px - x) * s + (py - y) * c) for px, py in corners]
    xs, ys = [p[0] for p in corners], [p[1] for p in corners]
    return min(xs), min(ys), max(xs), max(ys)


def text_boxes(svg: bytes | str) -> list[tuple[str, str, tuple[float, float, float, float]]]:
    """``(group id, text, (x0, y0, x1, y1))`` of every text the drawing sets (whitespace-only texts left out)."""
    root = ET.fromstring(svg if isinstance(svg, bytes) else svg.encode("utf-8"))
    out = []

    def walk(node, gid: str, offset: tuple[float, float]):
        for child in node:
            tag = child.tag.replace(SVG, "")
            if tag == "g":
                dx, dy = offset
                m = re.match(r"translate\(([-0-9.e]+)[ ,]+([-0-9.e]+)\)", child.get("transform", ""))
                if m:
                    dx, dy = dx + float(m.group(1)), dy + float(m.group(2))
                walk(child, child.get("id", gid), (dx, dy))
            elif tag == "text":
                spans = list(child.iter(f"{SVG}tspan"))
                if spans:  # math: glyph by glyph
                    boxes, words = [], ""
                    for span in spans:
                        st = _style(span.get("style", ""))
                        size = float(st.get("font-size", "10px").rstrip("px"))
                        glyph = span.text or ""
                        words += glyph
                        if glyph.strip():
                            w = _width(glyph, size, st.get("font-family", "DejaVu Sans"))
                            boxes.append(_box(offset[0] + float(span.get("x", 0)), offset[1] + float(span.get("y", 0)), w, size, "start"))
                    if boxes:
                        out.append((gid, words, (min(b[0] for b in boxes), min(b[1] for b in boxes),
                                                 max(b[2] for b in boxes), max(b[3] for b in boxes))))
                elif (child.text or "").strip():
                    st = _style(child.get("style", ""))
                    size = float(st.get("font-size", "10px").rstrip("px"))
                    angle = 0.0
                    m = re.match(r"rotate\(([-0-9.e]+)", child.get("transform", ""))
                    if m:
                        angle = float(m.group(1))
                    w = _width(child.text, size, st.get("font-family", "DejaVu Sans"))
                    out.append((gid, child.text, _box(offset[0] + float(child.get("x", 0)), offset[1] + float(child.get("y", 0)), w, size,
                                                      st.get("text-anchor", "start").strip(), angle)))

    walk(root, "", (0.0, 0.0))
    return out


def overlaps(boxes, clear: float = 0.0) -> list[tuple[str, str]]:
    """Pairs of texts whose boxes (shrunk by *clear* each side) overlap."""
    found = []
    for i, (ga, ta, a) in enumerate(boxes):
        for gb, tb, b in boxes[i + 1:]:
            if min(a[2], b[2]) - max(a[0], b[0]) > 2 * clear and min(a[3], b[3]) - max(a[1], b[1]) > 2 * clear:
                found.append((f"{ga}:{ta}", f"{gb}:{tb}"))
    return found
