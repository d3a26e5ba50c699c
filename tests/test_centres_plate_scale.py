"""The centres pages draw the mechanism at the plate's k_l (issue 20 §4: one k_l over the plate): far centres
become arrows in the edge band of the page's box, and the room around the mechanism shrinks to what the page
leaves, instead of coarsening k_l (the teacher's second review: linear-arm's centres at 0.01 against the plate's
0.006, six-bar's at 0.01 against 0.008)."""

import re
import subprocess

import pytest

from review_handouts import built_pdf


def _pages(pdf: bytes, tmp_path) -> list[str]:
    path = tmp_path / "h.pdf"
    path.write_bytes(pdf)
    text = subprocess.run(["pdftotext", str(path), "-"], capture_output=True, check=True).stdout.decode()
    return text.split("\f")[:-1]


def _title_block(page: str) -> str | None:
    """The k_l the page's title block states (its last k_l in math italic)."""
    found = re.findall(r"𝑘𝑙 = ([0-9.,]+) ", page)
    return found[-1] if found else None


@pytest.mark.parametrize("name, positions, lang, plate, count", [
    ("quick-return", 12, "sr", "0,006", 12),  # the plan of positions: 0.55 m rocker on an A4 page
    ("linear-arm", 8, "bg", "0,006", 8),
    ("six-bar", None, "en", "0.008", 1),
])
def test_centres_at_the_plates_k_l(tmp_path, name, positions, lang, plate, count):
    pages = _pages(built_pdf(name, positions, lang, centres=True), tmp_path)
    assert _title_block(pages[0]) == plate, pages[0][:400]  # the plate's k_l, page 1
    centres = pages[-count:]  # the centres pages come last: a page for each position
    assert [_title_block(p) for p in centres] == [plate] * count
    # the drawing states its own k_l ("kl = 0,006 m/mm", plain text in the SVG): the plate's too
    drawn = [re.findall(r"(?<![𝑘\w])kl = ([0-9.,]+) ", p) for p in centres]
    assert drawn == [[plate]] * count, drawn
