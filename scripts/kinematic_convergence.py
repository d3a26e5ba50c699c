"""How the error of graphical differentiation falls with the number of positions (issue 19 §4).

    python scripts/kinematic_convergence.py slider-crank four-bar quick-return rocker-limit

For each bundled example and 8, 12, 24, 36, 72 positions: the largest error [%
of the largest analytic value over the positions] of v and a read off the
diagrams (method of chords), by the method of tangents, and from the plans (read
to 0.1 mm); the observed order log(e₁/e₂)/log(n₂/n₁) of the chords; and the
chords' error at the interval middles alone (against the analytic v at the
middle in time, from a cycle of 2n positions), whose order tends to 2.
Run it from the repository root.
"""

from __future__ import annotations

import math
import sys

import numpy as np

import plans
from plans.differentiation import kinematic_diagrams
from plans.motion import driver_cycle, output_link

COUNTS = (8, 12, 24, 36, 72)


def main(examples) -> None:
    for name in examples:
        scene = plans.load(plans.example_path(name))
        out = output_link(scene)
        print(f"{name}:    n  v_chords% a_chords% v_tang%  a_tang%  v_plans% a_plans%  order(v, a)  middles v% (order)")
        previous = None
        for n in COUNTS:
            d = kinematic_diagrams(scene, n)
            e = {k: float(np.nanmax(np.abs(x))) for k, x in d.errors().items()}
            v_middle = np.asarray(out.rates(driver_cycle(scene, 2 * n).solve()))[1::2]
            middle = 100 * float(np.max(np.abs(d.velocity.rates[: len(v_middle)] - v_middle))) / float(np.max(np.abs(d.v_analytic)))
            order = middle_order = ""
            if previous is not None:
                step = math.log(n / previous[3])
                order = f"{math.log(previous[0] / e['v_diagram']) / step:.2f}, {math.log(previous[1] / e['a_diagram']) / step:.2f}"
                middle_order = f"({math.log(previous[2] / middle) / step:.2f})"
            print(f"  {n:12d} {e['v_diagram']:9.3f} {e['a_diagram']:9.3f} {e['v_tangents']:8.3f} {e['a_tangents']:8.3f} "
                  f"{e['v_plans']:8.3f} {e['a_plans']:8.3f}  {order:11s}  {middle:.4f} {middle_order}")
            previous = (e["v_diagram"], e["a_diagram"], middle, n)


if __name__ == "__main__":
    main(sys.argv[1:] or ["slider-crank", "four-bar", "quick-return", "rocker-limit"])
