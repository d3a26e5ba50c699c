"""The sheet's results table lists what the plans show, and nothing that is zero by structure."""

from plans.analytic import solve
from plans.compare import compare
from plans.graphical import construct
from plans.report import sheet_table
from plans.scene import example_path, load


def _labels(name: str) -> list[str]:
    scene = load(example_path(name))
    analytic, graphical = solve(scene), construct(scene)
    return [row[0] for row in sheet_table(compare(analytic, graphical), graphical, analytic)[1:]]


def test_no_coriolis_and_no_omega_rows_where_nothing_turns():
    labels = _labels("wedge")  # the incline translates: no link turns
    assert not [label for label in labels if label.startswith(("$a^{k}$", "$\\omega", "$\\varepsilon"))]
    assert "$v_{C}$ [m/s]" in labels and "$v_{CC2}$ [m/s]" in labels  # block 3 on the incline 2, as drawn


def test_coriolis_row_where_the_guide_turns():
    labels = _labels("quick-return")
    assert "$a^{k}_{A4A3}$ [m/s²]" in labels  # the lever relative to the block riding it, as the plan draws it
    assert not [label for label in labels if label.startswith(("$a^{k}_{EE1}", "$a^{k}_{EE0}"))]  # the ram's guide is the frame


def test_positions_are_not_tabulated_on_a_sheet():
    assert not [label for label in _labels("six-bar") if label.startswith(("r ", "s "))]


def test_numbers_have_true_minus_signs_and_no_e_notation():
    rows = sheet_table(compare(solve(load(example_path("six-bar"))), construct(load(example_path("six-bar")))))[1:]
    cells = [cell for row in rows for cell in row[1:]]
    assert not [cell for cell in cells if "-" in cell or "e+" in cell or "e-" in cell]
    assert any(cell.startswith("−") for cell in cells)  # ω of the six-bar's crank is −10 rad/s
    assert "−10" in [row[1] for row in rows if row[0].startswith("$\\omega_{2}$")]
