"""The sheet's vector equations name every component with its subscripts (review finding 20).

(The sheet's own subscript and table-cell measurements went with the hand typesetter of the old sheet: Typst
sets the sheet's equations and tables now, as the handout's: tests/test_plate_handout.py, tests/test_sheet_typst.py.)
"""

from __future__ import annotations

import re


def test_the_components_named_in_the_brackets_carry_their_subscripts():
    import plans
    from plans.drawing.sheet import sheet_equations
    from plans.graphical import construct

    lines = sheet_equations(construct(plans.load(plans.example_path("six-bar"))))
    text = " ".join(lines)
    assert "a^n_E5B ∥ EB" in text and "a^t_E5B ⊥ BE" in text
    assert not re.search(r"a\^[nt] [∥⊥]", text), text
