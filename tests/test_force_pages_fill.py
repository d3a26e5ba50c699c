"""The force pages are filled, and Joukowski's lever is drawn at the k_v its page states (issue 20, branch forces3).

Read from the typeset PDF: a page's fill is the lowest inked pixel row above the title block as a share of the
frame's height above it (pdftoppm at 50 dpi), as a teacher sees a page half empty.  The lever's scale is checked
against the scene's own data: the crank pin's image lies ω·l_OA / k_v from the pole (k_v as the page prints it).
"""

from __future__ import annotations

import io
import re
import shutil
import subprocess
import tempfile
import unicodedata
from pathlib import Path

import numpy as np
import pypdf
import pytest

from plans.i18n import term
from plans.scene import example_path, load
from review_handouts import built, built_pdf

pytestmark = pytest.mark.skipif(shutil.which("pdftoppm") is None, reason="pdftoppm (poppler-utils) is not installed")

HANDOUTS = [("six-bar-loads", "en"), ("quick-return-loads", "bg"), ("scotch-yoke-loads", "ru"), ("slider-crank-loads", "ru")]


def _fills(pdf: bytes) -> list[float]:
    """Each page's fill: (the lowest inked row above the title block) / (the frame's height above the title block)."""
    from PIL import Image

    with tempfile.TemporaryDirectory() as d:
        (Path(d) / "h.pdf").write_bytes(pdf)
        subprocess.run(["pdftoppm", "-r", "50", "-gray", "-png", str(Path(d) / "h.pdf"), str(Path(d) / "p")], check=True)
        out = []
        for f in sorted(Path(d).glob("p-*.png"), key=lambda p: int(p.stem.rsplit("-", 1)[1])):
            a = np.asarray(Image.open(f).convert("L")) < 128
            h = a.shape[0]
            cols = np.where(a.mean(axis=0) > 0.6)[0]  # the frame's sides
            left, right = cols.min(), cols.max()
            rows = np.where(a[:, left:right].mean(axis=1) > 0.8)[0]  # the frame's top and the title block's lines
            top, block = rows.min(), rows[rows > h * 0.6].min()
            inked = np.where(a[top + 3:block - 2, left + 4:right - 3].any(axis=1))[0]
            out.append(((inked.max() if len(inked) else 0) + 3) / (block - top))
        return out


@pytest.fixture(scope="module", params=HANDOUTS, ids=[f"{e}-{lang}" for e, lang in HANDOUTS])
def typeset(request):
    example, lang = request.param
    doc = built(example, None, lang, forces=True)
    pdf = built_pdf(example, None, lang, forces=True)
    texts = [unicodedata.normalize("NFKC", p.extract_text() or "") for p in pypdf.PdfReader(io.BytesIO(pdf)).pages]
    return example, lang, doc, pdf, texts


def test_no_force_page_is_left_half_empty(typeset):
    example, lang, _, pdf, texts = typeset
    plate = term("kinetostatics", lang)
    force = [k for k, t in enumerate(texts) if plate in t]
    assert len(force) >= 2, example
    fills = _fills(pdf)
    low = {k + 1: round(fills[k], 2) for k in force if fills[k] < 0.5}
    assert not low, f"{example} ({lang}): force pages under half filled: {low}"
    # the three methods' table is never alone on a page: the lever's moments (or its drawing) share it
    methods = term("force_methods", lang).split(":")[0][:25]
    lever = term("lever_moments", lang)[:20]
    for k in force:
        if methods in re.sub(r"\s+", " ", texts[k]):
            assert lever in re.sub(r"\s+", " ", texts[k]), f"page {k + 1}: the methods' table without the lever's moments"


def _centre(svg: str, gid: str) -> complex:
    """The centre [pt of the drawing] of the circle drawn under *gid* (the mean of its path's extremes)."""
    body = svg[svg.index(f'id="{gid}"'):]
    path = re.search(r'\sd="([^"]+)"', body)[1]
    xy = np.array([float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", path)]).reshape(-1, 2)
    return complex((xy[:, 0].min() + xy[:, 0].max()) / 2, (xy[:, 1].min() + xy[:, 1].max()) / 2)


def test_the_lever_is_drawn_at_the_k_v_its_page_states(typeset):
    example, lang, doc, _, texts = typeset
    scene = doc.scene if hasattr(doc, "scene") else load(example_path(example))
    driver = scene.driver
    if not hasattr(driver, "omega"):
        pytest.skip("a linear driver")
    # the crank pin's speed from the scene's data: ω·l_OA
    pin = next(p for p in scene.bodies[driver.link].points if p != driver.pivot)
    own = scene.bodies[driver.link].points
    v_pin = abs(driver.omega) * abs(own[pin] - own[driver.pivot]) if driver.pivot in own else None
    assert v_pin
    heading = term("joukowski_lever", lang)
    page = next(t for t in texts if heading in t and term("lever_turned_ccw", lang)[:15] in t)
    stated = re.search(r"k\s*v\s*=\s*([0-9]+[.,][0-9]+)\s*\(", page[page.index(heading):])
    assert stated, page[:600]
    k_v = float(stated[1].replace(",", "."))
    svg = doc.images["forces-0-lever"]
    svg = svg.decode() if isinstance(svg, bytes) else svg
    width_mm = float(re.search(r'width="([0-9.]+)mm"', svg)[1])
    units = float(re.search(r'viewBox="0 0 ([0-9.]+) ', svg)[1]) / width_mm  # drawing units a millimetre
    label = pin.lower()
    drawn = abs(_centre(svg, f"lever-dot-{label}") - _centre(svg, "lever-pole")) / units
    assert drawn == pytest.approx(v_pin / k_v, rel=0.01, abs=0.3), (example, drawn, v_pin, k_v)
    # where the lever has a k_v of its own, the page says the plate's too
    plate_kv = doc.plate.get("k_v") if hasattr(doc, "plate") else None
    if plate_kv and abs(plate_kv - k_v) > 1e-9:
        assert term("lever_own_scale", lang).split("(")[0].strip()[:20] in re.sub(r"\s+", " ", page)
