"""Every scale a rendered page states is a standard one (issue 20, the teacher's review: "k_l = 0,006 m/mm (1:6) is
not a standard drawing scale").

A drawing's scale follows GOST 2.302 (reduction scales 1:2, 1:2.5, 1:4, 1:5, 1:10, 1:15, 1:20, 1:25, 1:40, 1:50,
1:75, 1:100 …; ISO 5455's 1:2, 1:5, 1:10 … among them): k_l [m/mm] = N/1000 for the scale 1:N, so a page's k_l,
and with it every other factor a page states (k_v, k_a, μ_F, the diagrams' μ_s, μ_v, μ_a), is m·10ⁿ with m one
of 1, 1.5, 2, 2.5, 4, 5, 7.5.  The values are read off the compiled PDFs' text (pdftotext), as a reader reads
them; μ_t = T/L is the course's quotient of the cycle's time and the abscissa, not a chosen factor (not read).
"""

from __future__ import annotations

import math
import re
import subprocess
import unicodedata

import pytest

from plans.scene import example_path, load
from review_handouts import built_pdf, drawn_sheet

#: GOST 2.302's reduction scales 1:N of one decade, N = 10 … 75, as mantissas (written out here from the standard)
STANDARD = (1.0, 1.5, 2.0, 2.5, 4.0, 5.0, 7.5)
SUPERSCRIPT = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")
#: a stated factor: its symbol (k_l, k_v, k_a, μ_F, μ_s, μ_v, μ_a, μ_M, μ_φ; plain "kl" in a drawing's own text),
#: an optional "= formula" (μ_v = μ_s/(μ_t·H₁) = 0,08), then "= number"
STATED = re.compile(r"(?<![^\s(:;,])(k[lva]|μ[FsvaMφ])\s*(?:=\s*[^\d\s−-][^=\n]*)?=\s*(\d[\d.,\u2009\u202f ]*\d|\d)(·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?")


def _texts(pdf: bytes, tmp_path, name: str) -> str:
    path = tmp_path / f"{name}.pdf"
    path.write_bytes(pdf)
    text = subprocess.run(["pdftotext", str(path), "-"], capture_output=True, check=True).stdout.decode()
    return unicodedata.normalize("NFKC", text)


def _stated(text: str) -> list[tuple[str, float]]:
    out = []
    for m in STATED.finditer(text):
        digits = re.sub(r"[\s\u2009\u202f]", "", m.group(2))
        digits = digits.replace(",", ".") if digits.count(",") == 1 else digits.replace(",", "")
        value = float(digits)
        if m.group(3):
            value *= 10.0 ** int(m.group(3)[3:].translate(SUPERSCRIPT))
        out.append((m.group(1), value))
    return out


def _standard(value: float) -> bool:
    n = math.floor(math.log10(value))
    return any(math.isclose(value, m * 10.0**e, rel_tol=1e-9) for m in STANDARD for e in (n - 1, n, n + 1))


def test_the_reader_reads_what_the_pages_state():
    """The reader of the pages' text finds formulas and plain drawing labels alike (a check of this file's regex)."""
    text = "Размере: kl = 0,006 m/mm; kv = 0,02 (m/s)/mm; ka = 1,5·10⁻² (m/s²)/mm\nμv = μs /(μt ·H1 ) = 0,08 (m/s)/mm, μF = 1 000 N/mm"
    assert _stated(text) == [("kl", 0.006), ("kv", 0.02), ("ka", 0.015), ("μv", 0.08), ("μF", 1000.0)]
    assert not _standard(0.006) and not _standard(0.012) and not _standard(0.3) and not _standard(8e-5)
    assert _standard(0.0075) and _standard(15.0) and _standard(0.0004) and _standard(2.5e-7)


#: The pages still state scales off the standard (quick-return and linear-arm k_l = 0,006 = 1:6, six-bar 0,008,
#: k_v 0,012 …): the standard series (commit 92712aa, set aside in this branch's last commit) breaks issue 11's least
#: sizes on A3 sheets and handouts (its step 2.5 → 4 is 1.6: wedge's mechanism 75 mm, plans 52–56 mm) until the
#: fitting of sheets and handouts takes the coarser steps into account.  strict: the day the pages pass, this fails.
OFF_STANDARD = pytest.mark.xfail(strict=True, reason="pages' scales not yet the standard's (issue 20; see OFF_STANDARD)")

RENDERS = {
    "qr-sr": lambda: built_pdf("quick-return", 12, "sr"),
    "la-bg": lambda: built_pdf("linear-arm", 8, "bg", centres=True),
    "sb-en": lambda: built_pdf("six-bar", None, "en", centres=True),
    "scl-ru": lambda: built_pdf("slider-crank-loads", None, "ru", forces=True),
}


@OFF_STANDARD
@pytest.mark.parametrize("name", sorted(RENDERS))
def test_every_factor_a_handout_states_is_standard(tmp_path, name):
    stated = _stated(_texts(RENDERS[name](), tmp_path, name))
    assert {"kl", "kv", "ka"} <= {key for key, _ in stated}, stated  # the reader found the plate's three
    assert len({v for key, v in stated if key == "kl"}) == 1  # one k_l over the plate
    off = sorted({(key, v) for key, v in stated if not _standard(v)})
    assert not off, off


@OFF_STANDARD
@pytest.mark.parametrize("example, lang", [("six-bar", "en"), ("quick-return", "sr"), ("linear-arm", "bg")])
def test_every_factor_an_a3_sheet_states_is_standard(tmp_path, example, lang):
    stated = _stated(_texts(drawn_sheet(example, lang, "sheet.pdf").read_bytes(), tmp_path, "sheet"))
    assert {"kl", "kv", "ka"} <= {key for key, _ in stated}, stated
    off = sorted({(key, v) for key, v in stated if not _standard(v)})
    assert not off, off


#: the line's words in each language, written out here (μ the diagrams' scales, not the plans' k)
NOT_K = {"en": "the scales of these diagrams, not the plans'", "sr": "размере ових дијаграма, а не размере планова",
         "ru": "масштабы этих диаграмм, а не масштабы планов", "bg": "мащабите на тези диаграми, а не мащабите на плановете",
         "sl": "merila teh diagramov, ne merila načrtov"}


@pytest.mark.parametrize("lang", sorted(NOT_K))
def test_the_diagrams_page_says_its_mu_are_not_the_plans_k(lang):
    """One plate holds the plans' k_v and the v–t diagram's μ_v, different values: the diagrams' page says in the
    reader's language that its μ are its own scales."""
    from plans.differentiation import kinematic_diagrams
    from plans.drawing import kinematic_diagrams as kd

    d = kinematic_diagrams(load(example_path("quick-return")), 12)
    lines = kd.header_lines(d, lang)
    (line,) = [x for x in lines if NOT_K[lang] in x]
    assert line.startswith("$\\mu_{t}$, $\\mu_{s}$, $\\mu_{v}$, $\\mu_{a}$: ") and line.endswith("$k_{l}$, $k_{v}$, $k_{a}$")
    assert lines.index(line) == [i for i, x in enumerate(lines) if "T/L" in x][0] + 1  # under the time scale
