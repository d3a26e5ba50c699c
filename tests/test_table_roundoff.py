"""Round-off of a zero quantity is printed 0 in the sheet's table, its relative error "—".

The quick-return's position 0 is a dead centre of the ram (the coulisse at
its extreme: the crank OA ⊥ the slot CA, checked here from the geometry),
so v_D = v_E = 0 and ω of the coulisse and the rod are 0 by hand; the
solver returns them as ~1e-15 round-off.
"""

import re

from plans.positions import run_positions
from plans.report import NO_ERROR, sheet_table
from plans.scene import example_path, load


def test_quick_return_dead_centre_prints_zeros():
    run = run_positions(load(example_path("quick-return")), 12)
    r = run.runs[0]
    pts = r.analytic.points
    o, a, c = (complex(pts[n].r[0]) for n in ("O", "A", "C"))
    assert abs(((a - o) / (a - c)).real) < 1e-9 * abs(a - o) / abs(a - c)  # OA ⊥ CA: the coulisse's extreme
    rows = {row[0]: row[1:] for row in sheet_table(r.comparisons, r.graphical, r.analytic)}
    for symbol in ("$v_{D}$ [m/s]", "$v_{E}$ [m/s]", r"$\omega_{3}$ [rad/s]", r"$\omega_{5}$ [rad/s]"):
        assert rows[symbol] == ["0", "0", NO_ERROR], symbol
    # a quantity that is not zero keeps its numbers and its error
    g, an, err = rows["$a_{D}$ [m/s²]"]
    assert an != "0" and err != NO_ERROR
    # no value cell prints round-off (a power of ten ≤ 10⁻⁹)
    tiny = re.compile("·10⁻(?:⁹|¹[0-9⁰¹²³⁴⁵⁶⁷⁸⁹])")
    for g, an, _ in rows.values():
        assert not tiny.search(g) and not tiny.search(an), (g, an)
