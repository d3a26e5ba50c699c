"""The centres pages draw the mechanism at the plate's k_l when it fits (issue 20 §4: one k_l over the plate):
far centres become arrows at the edge instead of shrinking the mechanism."""

import re
import subprocess

from plans.handout import handout
from plans.scene import example_path, load


def _scales(pdf: bytes, tmp_path) -> list[str]:
    """The k_l each page's title block states, page by page."""
    path = tmp_path / "h.pdf"
    path.write_bytes(pdf)
    text = subprocess.run(["pdftotext", str(path), "-"], capture_output=True, check=True).stdout.decode()
    out = []
    for page in text.split("\f")[:-1]:
        found = re.findall(r"𝑘𝑙 = ([0-9.,]+) m/mm", page)
        out.append(found[-1] if found else None)
    return out


def test_quick_return_centres_at_the_plates_k_l(tmp_path):
    doc = handout(load(example_path("quick-return")), positions=12, centres=True, lang="sr")
    scales = _scales(doc.pdf(), tmp_path)
    assert scales[0] == "0,006", scales[0]  # the plan of positions: 0.55 m rocker on an A4 page
    centres = scales[-12:]  # the centres pages come last: a page for each of the 12 positions
    assert set(centres) == {"0,006"}, scales
