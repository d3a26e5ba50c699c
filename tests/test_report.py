"""The sheet's results table lists what the plans show, and nothing that is zero by structure."""

from plans.analytic import solve
from plans.compare import compare
from plans.graphical import construct
from plans.report import sheet_table
from plans.scene import example_path, load


def _labels(name: str) -> list[str]:
    scene = load(example_path(name))
    return [row[0] for row in sheet_table(compare(solve(scene), construct(scene)))[1:]]


def test_no_coriolis_and_no_omega_rows_where_nothing_turns():
    labels = _labels("wedge")  # the incline translates: no link turns
    assert not [label for label in labels if label.startswith(("$a^{k}$", "$\\omega", "$\\varepsilon"))]
    assert "$v_{C}$ [m/s]" in labels and "$v^{r}$ slider C3 [m/s]" in labels


def test_coriolis_row_where_the_guide_turns():
    labels = _labels("quick-return")
    assert "$a^{k}$ slider A [m/s²]" in labels  # the block rides the swinging lever (aᵏ, typeset)
    assert "$a^{k}$ slider E [m/s²]" not in labels  # the ram's guide is the frame


def test_positions_are_not_tabulated_on_a_sheet():
    assert not [label for label in _labels("six-bar") if label.startswith(("r ", "s "))]


def test_numbers_have_true_minus_signs_and_no_e_notation():
    rows = sheet_table(compare(solve(load(example_path("six-bar"))), construct(load(example_path("six-bar")))))[1:]
    cells = [cell for row in rows for cell in row[1:]]
    assert not [cell for cell in cells if "-" in cell or "e+" in cell or "e-" in cell]
    assert any(cell.startswith("−") for cell in cells)  # ω of the six-bar's crank is −10 rad/s
    assert "−10" in [row[1] for row in rows if row[0].startswith("$\\omega_{2}$")]
