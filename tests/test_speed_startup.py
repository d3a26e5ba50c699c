"""The plans command imports matplotlib without its generated property docstrings; a library user's is untouched.

Each case runs in a fresh interpreter (what matplotlib does at import cannot be undone in this one).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

_PROBE = """
import json, sys
{setup}
from matplotlib.lines import Line2D
from matplotlib.patches import Circle
from matplotlib.artist import Artist

class Mine(Circle):
    pass

line = Line2D([0, 1], [0, 1])
line.set(linewidth=2.5, color="red")  # set keeps working
mine = Mine((0, 0), 1.0)
mine.set(radius=2.0)
print(json.dumps({{
    "line_doc": Line2D.set.__doc__,
    "own_set": Mine.set is not Circle.set,
    "width": line.get_linewidth(),
    "radius": mine.get_radius(),
}}))
"""


def _probe(setup: str) -> dict:
    out = subprocess.run(
        [sys.executable, "-c", _PROBE.format(setup=setup)],
        capture_output=True, text=True, check=True, cwd=ROOT, env={**os.environ, "PYTHONPATH": str(ROOT)},
    ).stdout
    return json.loads(out)


def test_the_command_s_matplotlib_has_short_set_docstrings_and_the_same_behaviour():
    got = _probe("from plans._startup import lighter_matplotlib; lighter_matplotlib()")
    assert "linewidth" not in got["line_doc"] and "set_*" in got["line_doc"]
    assert got["own_set"] and got["width"] == 2.5 and got["radius"] == 2.0


def test_a_library_user_s_matplotlib_is_untouched():
    got = _probe("import plans, plans.drawing")
    assert "linewidth" in got["line_doc"]  # matplotlib's own property list
    assert got["own_set"] and got["width"] == 2.5 and got["radius"] == 2.0


def test_nothing_changes_when_matplotlib_is_already_imported():
    got = _probe("import matplotlib.artist\nfrom plans._startup import lighter_matplotlib; lighter_matplotlib()")
    assert "linewidth" in got["line_doc"]
