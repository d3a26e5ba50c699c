"""The conditions beside a vector equation are formulas, not the program's English: a slider on a guide that does
not turn reads "ω₂ = 0 ⇒ a^k = 0" (a Bulgarian wedge sheet printed "no Coriolis")."""

import re
import subprocess

from plans.cli import main


def test_a_guide_that_does_not_turn_says_so_in_a_formula(tmp_path):
    assert main(["draw", "--example", "wedge", "--lang", "bg", "-o", str(tmp_path / "w.pdf")]) == 0
    text = subprocess.run(["pdftotext", str(tmp_path / "w.pdf"), "-"], capture_output=True, check=True).stdout.decode()
    assert "Coriolis" not in text
    latin = set(re.findall(r"\b[A-Za-z]{3,}\b", text)) - {"rad", "max"}
    assert not latin, latin
    assert re.search(r"2 = 0 ⇒ \S+ = 0", text), text
