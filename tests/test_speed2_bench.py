"""``plans bench`` also times one position with plans' whole result read, since the result is made on first reading."""

from __future__ import annotations

from plans.analytic import solve
from plans.bench.run import READ_ALL, Settings, markdown, read_all, run_bench
from plans.scene import example_path, load

ONE = Settings(ns=(1,), yardstick_ns=(1,), samples=2, arc_segments=(), precisions=(), budget=0.0, processes=False,
               cases=("slider-crank",))


def test_one_position_is_also_timed_with_the_result_read_in_full():
    result = run_bench(ONE)
    read = [r for r in result.rows if r.setting == READ_ALL]
    assert len(read) == 1 and read[0].method == "yardstick" and read[0].versus > 0 and read[0].seconds > 0
    assert "with every attribute of plans' result read" in markdown(result)


def test_read_all_makes_every_attribute():
    solution = read_all(solve(load(example_path("slider-crank"))))
    assert {"links", "points", "sliders", "poses", "origins", "conditions", "sines", "valid"} <= set(vars(solution))
