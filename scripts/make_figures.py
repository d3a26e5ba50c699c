"""Regenerate figures/: the drawings of every bundled example.

    python scripts/make_figures.py

runs ``plans draw --example NAME -o figures/NAME`` for each bundled scene.
"""

import sys
from pathlib import Path

from plans.cli import main
from plans.scene import example_names

ROOT = Path(__file__).resolve().parent.parent


def make_figures() -> int:
    for name in example_names():
        status = main(["draw", "--example", name, "-o", str(ROOT / "figures" / name)])
        if status:
            return status
    return 0


if __name__ == "__main__":
    sys.exit(make_figures())
