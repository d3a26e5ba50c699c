"""Sweep CSV cells each to their own precision (issue 21): one huge row does not take the others' digits."""

from plans.sweep import format_column


def test_a_huge_row_keeps_the_other_rows_digits():
    # a PRP's travel near parallel guides: one row 1.5e11 m, the others of order 0.1 m
    cells = format_column([0.123456789012345678, 1.5e11 + 0.123456789, 0.25, -0.987654321098768])
    assert cells == ["0.12345678901235", "150000000000.12", "0.25", "-0.98765432109877"]


def test_each_large_value_has_its_own_fourteen_digits():
    cells = format_column([1.0, 2.0, 123456.78901234567, 9.87654321098767e20])
    assert cells == ["1", "2", "123456.78901235", "9.8765432109877e+20"]


def test_round_off_beside_a_huge_row_is_still_zero():
    # round-off is judged against the column's typical size (order 1 here), not against its largest row
    assert format_column([1.25, -3e-17, 0.5, 1e12]) == ["1.25", "0", "0.5", "1000000000000"]
