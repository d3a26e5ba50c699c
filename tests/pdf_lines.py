"""The text lines of a typeset PDF as poppler's ``pdftotext -bbox-layout`` finds them (a reader's tool), for the
page tests: where a page's flow put its words."""

from __future__ import annotations

import re
import subprocess
import tempfile
import unicodedata
from pathlib import Path
from xml.etree import ElementTree

_XHTML = "{http://www.w3.org/1999/xhtml}"


def page_lines(pdf: bytes, normalise: bool = True) -> list[list[tuple[float, float, float, float, str]]]:
    """Every page's text lines as (x0, y0, x1, y1 [pt from the page's top left], words); *normalise*: the words
    in NFKC (a₂ reads a2, m/s² m/s2), else as written."""
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "h.pdf"
        path.write_bytes(pdf)
        out = subprocess.run(["pdftotext", "-bbox-layout", str(path), "-"], capture_output=True, text=True, check=True).stdout
    root = ElementTree.fromstring(re.sub(r"<!DOCTYPE[^>]*>", "", out))
    pages = []
    for page in root.iter(_XHTML + "page"):
        lines = []
        for line in page.iter(_XHTML + "line"):
            words = " ".join(w.text or "" for w in line.iter(_XHTML + "word"))
            lines.append((float(line.get("xMin")), float(line.get("yMin")), float(line.get("xMax")), float(line.get("yMax")),
                          unicodedata.normalize("NFKC", words) if normalise else words))
        pages.append(lines)
    return pages
