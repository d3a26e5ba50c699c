"""``plans bench`` reports the targets of issue 14: one position against the yardstick, first calls in fresh processes."""

from __future__ import annotations

import math

from plans.bench.run import DEFAULT, Settings, markdown, run_bench, time_cold

ONE = Settings(ns=(1,), yardstick_ns=(1,), samples=2, arc_segments=(), precisions=(), budget=0.0, processes=False,
               cases=("slider-crank", "six-bar"))


def test_the_issue_14_targets_are_measured_and_judged():
    result = run_bench(ONE)
    targets = {t.name: t for t in result.targets}
    for name, goal in [
        ("analytic, offset slider-crank, one position", "< 30 µs"),
        ("one position: solve / yardstick", "≤ 1.5×"),
        ("analytic, six-bar, one position", "< 60 µs"),
        ("graphical, six-bar, one position, both plans (issue 14)", "< 250 µs"),
    ]:
        assert targets[name].goal == goal
        assert isinstance(targets[name].met, bool), name  # measured, and judged met or missed
    yard = next(r for r in result.rows if r.method == "yardstick")
    assert yard.n == 1 and yard.versus > 0 and yard.err_v < 1e-14  # the yardstick is exact too
    text = markdown(result)
    assert "| one position: solve / yardstick | ≤ 1.5× |" in text


def test_the_full_bench_times_first_calls_in_fresh_processes():
    assert DEFAULT.cold_ns == (3600, 100_000) and 1 in DEFAULT.yardstick_ns
    (general, yardstick), = time_cold((64,), 1).values()
    assert 0 < general < 5 and 0 < yardstick < 5 and math.isfinite(general / yardstick)
