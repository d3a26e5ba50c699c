"""The three handouts the teachers' reviews of the plans saw (sr quick-return at 12 positions, bg linear-arm at 8,
en six-bar), built once per test process and shared by the plan-label tests."""

from __future__ import annotations

from functools import lru_cache

import plans
from plans.handout import handout
from plans.scene import example_path

REVIEWED = [("quick-return", 12, "sr"), ("linear-arm", 8, "bg"), ("six-bar", None, "en")]


@lru_cache(maxsize=1)
def reviewed_handouts() -> dict:
    """name -> (Handout, lang) of :data:`REVIEWED` (the handouts are not changed by the tests that read them)."""
    return {name: (handout(plans.load(example_path(name)), positions=n, lang=lang), lang) for name, n, lang in REVIEWED}
