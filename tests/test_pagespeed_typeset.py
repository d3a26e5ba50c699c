"""Typeset lines drawn fast (issue 11 §6): one artist per line, its runs written by the renderer (the A3
sheets' text; the handout is set by Typst, plans.pages).

The PDF fast path (plans.drawing.typeset._draw_pdf_line) must put the same glyphs at the same places
as matplotlib's own ``RendererPdf.draw_text``: the reference is a page rendered with the fast path
switched off, read back by pypdf (an independent PDF reader), text and positions.
"""

from __future__ import annotations

import io

import pytest

from plans.drawing import typeset
from plans.drawing.formats import render_pdf
from plans.drawing.layout import new_page
from plans.drawing.svg import drawing_rc
from plans.drawing.typeset import TypesetText, draw_text, measure

pypdf = pytest.importorskip("pypdf")

LINES = [
    (r"$a_{B} = a_{A} + (i\varepsilon_{3} - \omega_{3}^2)\,l_{AB}\,e^{i\varphi_{3}} = (-1.561 - 8.65i)\ \mathrm{m/s^2}$", 8.0, "normal"),
    ("Кривајни механизам: план брзина, φ₂ = 30,0°", 11.0, "bold"),
    (r"Costs \$5 and \$6, $v_{A}$ = 0.72 ∠ 120.0°", 9.0, "normal"),
    (r"$\dot{s}_{A}\,e^{i\,71.47^\circ} + i\omega_{4}\,l_{CD}$", 7.0, "normal"),
]


def _page():
    with drawing_rc():
        fig, sketch = new_page()
        for k, (text, size, weight) in enumerate(LINES):
            draw_text(sketch, complex(20.0, 250.0 - 12.0 * k), text, size=size, weight=weight, gid="line")
    return fig


def _glyphs(data: bytes) -> list[tuple[str, float, float]]:
    """(text, x, y) of every piece pypdf reads, in page points, rounded to 0.01 pt."""
    found = []

    def visit(text, cm, tm, font, size):
        if text.strip():
            x = tm[4] * cm[0] + tm[5] * cm[2] + cm[4]
            y = tm[4] * cm[1] + tm[5] * cm[3] + cm[5]
            found.append((text, round(x, 2), round(y, 2)))

    pypdf.PdfReader(io.BytesIO(data)).pages[0].extract_text(visitor_text=visit)
    return found


def test_a_pdf_line_puts_the_glyphs_where_matplotlib_s_draw_text_puts_them(monkeypatch):
    fast = render_pdf([_page()])
    monkeypatch.setattr(typeset, "_pdf_renderer", lambda renderer: None)  # every run through RendererPdf.draw_text
    reference = render_pdf([_page()])
    assert fast != reference  # two ways of writing the page
    got, expected = _glyphs(fast), _glyphs(reference)
    assert expected and "".join(t for t, _, _ in got) == "".join(t for t, _, _ in expected)
    # the same pieces start at the same places
    assert sorted((x, y) for _, x, y in got) == sorted((x, y) for _, x, y in expected)


def test_the_fast_pdf_is_the_same_bytes_on_a_rerun_and_embeds_truetype():
    first, second = render_pdf([_page()]), render_pdf([_page()])
    assert first == second
    fonts = {str(f["/DescendantFonts"][0].get_object()["/Subtype"]) for f in _fonts(first)}
    assert fonts == {"/CIDFontType2"}  # TrueType outlines (Type 42), Cyrillic included


def _fonts(data: bytes):
    page = pypdf.PdfReader(io.BytesIO(data)).pages[0]
    return [f.get_object() for f in page["/Resources"]["/Font"].values()]


def test_a_typeset_line_is_one_artist_and_matplotlib_measures_it_as_typeset():
    fig = _page()
    lines = fig.findobj(TypesetText)
    assert len(lines) == len(LINES)
    assert lines[1].get_text() == LINES[1][0] and lines[1].get_fontsize() == 11.0
    assert "$5 and $6" in lines[2].get_text()  # dollars are shown, never math
    with drawing_rc():
        fig.draw_without_rendering()
        for line, (text, size, weight) in zip(lines, LINES):
            box = line.get_window_extent()
            width_mm = box.width / fig.dpi * 25.4
            # the renderer's measurement (FreeType, per run) against the typesetter's advance widths
            assert width_mm == pytest.approx(measure(text, size, weight)[0], rel=0.03, abs=0.3), text
