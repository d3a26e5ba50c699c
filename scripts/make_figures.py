"""Regenerate figures/: the drawings of every bundled example.

    python scripts/make_figures.py

runs ``plans draw --example NAME -o figures/NAME`` for each bundled scene.
"""

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # draw with this checkout's code

from plans.cli import main  # noqa: E402
from plans.scene import example_names  # noqa: E402


def make_figures() -> int:
    for name in example_names():
        status = main(["draw", "--example", name, "-o", str(ROOT / "figures" / name)])
        if status:
            return status
    return 0


if __name__ == "__main__":
    sys.exit(make_figures())
