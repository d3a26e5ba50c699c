"""What a page set by Typst holds, read back from its SVG and PDF: for the sheet tests.

Typst's SVG embeds each drawing as ``<image transform="translate(x y)" xlink:href="data:image/svg+xml;base64,…"
width=… height=…>`` (page units: pt).  :func:`drawings` returns them with their placement in millimetres (origin
the page's top left corner, y down) and the drawing's own SVG (matplotlib's, root size in mm, its groups named by
gid: ``mech-…``, ``vel-…``, ``acc-…``, ``legend…``, ``positions-…``).  :func:`words` reads the words of a PDF page
with their boxes [mm] (``pdftotext -bbox``); :func:`text` the page's text (pypdf, math letters as plain letters).
"""

from __future__ import annotations

import base64
import io
import re
import subprocess
import tempfile
import unicodedata
import xml.etree.ElementTree as ET
from dataclasses import dataclass

SVG = "{http://www.w3.org/2000/svg}"
XLINK = "{http://www.w3.org/1999/xlink}"
PT = 25.4 / 72  # mm per pt


@dataclass
class Drawing:
    """A drawing on a page: its box [mm] (x, y from the page's top left, y down), its SVG and what it is."""

    x: float
    y: float
    width: float
    height: float
    svg: bytes

    @property
    def root(self):
        return ET.fromstring(self.svg)

    @property
    def kind(self) -> str:
        """``mechanism``, ``velocity``, ``acceleration``, ``legend``, ``positions`` (from its groups' gids)."""
        ids = [g.get("id") or "" for g in self.root.iter(f"{SVG}g")]
        for prefix, kind in (("mech", "mechanism"), ("vel", "velocity"), ("acc", "acceleration"), ("positions", "positions"),
                             ("legend", "legend")):
            if any(i.startswith(prefix) for i in ids):
                return kind
        return "?"

    @property
    def declared(self) -> tuple[float, float]:
        """The drawing's own size [mm] as its SVG root declares it."""
        root = self.root
        return float(root.get("width").removesuffix("mm")), float(root.get("height").removesuffix("mm"))

    @property
    def box(self) -> tuple[float, float, float, float]:
        return self.x, self.y, self.x + self.width, self.y + self.height


def _matrix(transform: str | None) -> tuple[float, ...]:
    """An SVG transform (``translate(x y)``, ``matrix(a b c d e f)``, ``scale(s)``) as (a, b, c, d, e, f)."""
    out = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0)
    for name, args in re.findall(r"(\w+)\(([^)]*)\)", transform or ""):
        v = [float(x) for x in re.split(r"[ ,]+", args.strip())]
        m = {"translate": lambda: (1, 0, 0, 1, v[0], v[1] if len(v) > 1 else 0.0),
             "matrix": lambda: tuple(v),
             "scale": lambda: (v[0], 0, 0, v[1] if len(v) > 1 else v[0], 0, 0)}[name]()
        out = _compose(out, m)
    return out


def _compose(p, q):
    a, b, c, d, e, f = p
    A, B, C, D, E, F = q
    return (a * A + c * B, b * A + d * B, a * C + c * D, b * C + d * D, a * E + c * F + e, b * E + d * F + f)


def page_size(svg: bytes) -> tuple[float, float]:
    root = ET.fromstring(svg)
    return float(root.get("width").removesuffix("mm")), float(root.get("height").removesuffix("mm"))


def drawings(svg: bytes) -> list[Drawing]:
    """Every drawing embedded in a page's SVG, placed [mm]."""
    root = ET.fromstring(svg)
    per_pt = float(root.get("viewBox").split()[2]) / (float(root.get("width").removesuffix("mm")) / PT)  # viewBox units per pt
    out = []

    def walk(node, m):
        m = _compose(m, _matrix(node.get("transform")))
        if node.tag == f"{SVG}image":
            href = node.get(f"{XLINK}href") or node.get("href")
            assert href.startswith("data:image/svg+xml;base64,")
            assert m[:4] == (1.0, 0.0, 0.0, 1.0), f"a drawing scaled or turned on the page: {m}"
            data = base64.b64decode(href.split(",", 1)[1])
            w, h = float(node.get("width")), float(node.get("height"))
            out.append(Drawing(m[4] / per_pt * PT, m[5] / per_pt * PT, w / per_pt * PT, h / per_pt * PT, data))
        for child in node:
            walk(child, m)

    walk(root, (1.0, 0.0, 0.0, 1.0, 0.0, 0.0))
    return out


def by_kind(svg: bytes) -> dict[str, Drawing]:
    return {d.kind: d for d in drawings(svg)}


def text(pdf: bytes, plain: bool = True) -> str:
    """The text of a PDF's pages, math letters (𝑘𝑣) as plain letters when *plain*, whitespace as single spaces."""
    from pypdf import PdfReader

    pages = [page.extract_text() or "" for page in PdfReader(io.BytesIO(pdf)).pages]
    joined = "\n".join(unicodedata.normalize("NFKC", p) if plain else p for p in pages)
    return joined


def page_count(pdf: bytes) -> int:
    from pypdf import PdfReader

    return len(PdfReader(io.BytesIO(pdf)).pages)


def words(pdf: bytes) -> list[tuple[str, tuple[float, float, float, float]]]:
    """The words Typst set on the (first) page, each with its box [mm] from the page's top left (pdftotext -bbox)."""
    with tempfile.NamedTemporaryFile(suffix=".pdf") as f:
        f.write(pdf)
        f.flush()
        html = subprocess.run(["pdftotext", "-bbox", "-f", "1", "-l", "1", f.name, "-"], capture_output=True, text=True, check=True).stdout
    out = []
    for m in re.finditer(r'<word xMin="([-0-9.]+)" yMin="([-0-9.]+)" xMax="([-0-9.]+)" yMax="([-0-9.]+)">([^<]*)</word>', html):
        x0, y0, x1, y1 = (float(v) * PT for v in m.groups()[:4])
        out.append((m.group(5), (x0, y0, x1, y1)))
    return out


def overlap(a, b, tolerance: float = 0.0) -> bool:
    """Whether boxes (x0, y0, x1, y1) overlap by more than *tolerance* [mm] both ways."""
    return min(a[2], b[2]) - max(a[0], b[0]) > tolerance and min(a[3], b[3]) - max(a[1], b[1]) > tolerance


def scales(page_text: str) -> dict[str, float]:
    """``{"k_l": …, "k_v": …, "k_a": …}`` as the title block states them (``kl = 0,002 m/mm;`` …, either decimal mark)."""
    flat = "".join(page_text.split())
    out = {}
    for letter, value in re.findall(r"k([lva])=([0-9]+(?:[.,][0-9]+)?)", flat):
        out.setdefault(f"k_{letter}", float(value.replace(",", ".")))
    return out


def english(page_text: str, allowed=()) -> set[str]:
    """The Latin words of three letters or more on a page (none belongs on a page in another language)."""
    return {w for w in re.findall(r"[A-Za-z]{3,}", page_text) if w.lower() not in allowed}


def unpack(path, kind: str):
    """The drawing of *kind* embedded in the page *path*, written beside it (``sheet-00.mechanism.svg``): its path."""
    from pathlib import Path

    path = Path(path)
    out = path.with_name(f"{path.stem}.{kind}.svg")
    out.write_bytes(by_kind(path.read_bytes())[kind].svg)
    return out


def embedded_text(path) -> str:
    """The text of every drawing embedded in the page *path* (their SVG text nodes), joined by spaces."""
    from pathlib import Path

    out = []
    for d in drawings(Path(path).read_bytes()):
        out += ["".join(t.itertext()) for t in d.root.iter(f"{SVG}text")]
    return " ".join(out)
