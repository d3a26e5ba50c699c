"""Teacher's review (issue 20): a unary minus sits tight against its number in every language.

Typst keeps the spaces written around a string in math; a decimal-comma number (``25,64``) is set as a
string, so ``= −25,64`` came out as ``= − 25,64`` (a binary minus to the eye) where English printed
``= −25.64``.  Checked on the typeset text (``pdftotext``): the independent reference is the English
form of the same equation, whose numbers Typst sets as numbers.
"""

from __future__ import annotations

import subprocess

import pytest

from plans.pages.typesetting import compile_document, math

EQUATIONS = [
    (r"\omega_{3} = −25.64, \dot{s}_{B} = −14.7", "ω3 = −25.64, s\u0307B = −14.7"),
    (r"(−12.99 + 7.5 i) + i \omega_{3} \cdot 0.3", "(−12.99 + 7.5i) + iω3 ⋅ 0.3"),
    (r"2 i \cdot 1.946 \cdot (−0.01116)", "2i ⋅ 1.946 ⋅ (−0.01116)"),
    (r"(i(−0.06361) − 1.946)", "(i(−0.06361) − 1.946)"),
    (r"a − 2.5", "a − 2.5"),  # a binary minus keeps its spaces
]


def _typeset(bodies: list[str]) -> list[str]:
    import os
    import tempfile
    import unicodedata

    source = "\n\n".join(f"${math(b)}$" for b in bodies)
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "m.pdf")
        with open(path, "wb") as f:
            f.write(compile_document(source))
        out = subprocess.run(["pdftotext", "-raw", path, "-"], capture_output=True, text=True, check=True).stdout
    plain = "".join(unicodedata.normalize("NFKC", c) if 0x1D400 <= ord(c) <= 0x1D7FF else c for c in out)
    return [line.strip() for line in plain.splitlines() if line.strip()]


@pytest.mark.parametrize("comma", [False, True], ids=["point", "comma"])
def test_unary_minus_tight_in_every_language(comma):
    bodies = [b.replace(".", ",") if comma else b for b, _ in EQUATIONS]
    expected = [e.replace(".", ",") if comma else e for _, e in EQUATIONS]
    assert _typeset(bodies) == expected


def test_two_strings_stay_apart():
    """A unit string before a number is not glued to it (``m 0,5``)."""
    assert _typeset([r"\mathrm{m}\ 0,5"])[0].startswith("m")
    assert "m0,5" not in _typeset([r"\mathrm{m} 0,5"])[0]
