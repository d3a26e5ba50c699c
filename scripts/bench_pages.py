"""Whole-process times of the commands that make pages (issue 11 §6 targets).

    python scripts/bench_pages.py            # each command 3 times, the run with the least CPU
    python scripts/bench_pages.py --runs 1
    python scripts/bench_pages.py --source   # from the source tree, its modules compiled at every run
    python scripts/bench_pages.py --only animate   # the cases whose name holds "animate"

Each command runs in a fresh process (imports included), as a user runs it:
by default from a copy of the package with its bytecode compiled, as ``pip
install`` leaves it (run from the source tree with PYTHONDONTWRITEBYTECODE set,
as in some sandboxes, every module of plans is compiled again at every start,
about 0.15 s).  The table gives the run with the least CPU time (user +
system), its wall time, and the target, then whether the target is met (by
CPU time: on a shared machine the wall time also counts the other work on
the same cores, so the load average is printed too).  Run it from the
repository root.
"""

from __future__ import annotations

import argparse
import compileall
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

CASES = [
    ("handout six-bar --positions 12 (PDF, the plate)", ["handout", "--example", "six-bar", "--positions", "12", "-o", "{out}/six-bar.pdf"], 5.0),
    ("draw six-bar --positions 12 (13 SVG)", ["draw", "--example", "six-bar", "--positions", "12", "-o", "{out}/sheets"], 3.0),
    ("draw six-bar (4 SVG)", ["draw", "--example", "six-bar", "-o", "{out}/one"], 1.0),
    # issue 23: the lecture page of the six-bar at 36 positions, under 5 MB and 10 s
    ("animate six-bar (HTML, 36 positions)", ["animate", "--example", "six-bar", "-o", "{out}/six-bar.html"], 10.0),
    ("animate six-bar (GIF, 36 positions)", ["animate", "--example", "six-bar", "-o", "{out}/six-bar.gif"], 10.0),
    ("animate six-bar (MP4, 36 positions)", ["animate", "--example", "six-bar", "-o", "{out}/six-bar.mp4"], 10.0),
]


def _installed(where: Path) -> Path:
    """A copy of the package under *where* with its bytecode compiled (what ``pip install`` leaves); the directory to put on the path."""
    site = where / "site"
    shutil.copytree(ROOT / "plans", site / "plans", ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    if not compileall.compile_dir(site / "plans", quiet=1):
        raise SystemExit("could not compile the copy of plans")
    return site


def _run(argv: list[str], path: Path) -> tuple[float, float]:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "plans", *argv], cwd=ROOT, check=True, stdout=subprocess.DEVNULL, env={**os.environ, "PYTHONPATH": str(path)})
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--source", action="store_true", help="run plans from the source tree instead of a compiled copy")
    parser.add_argument("--only", metavar="TEXT", help="only the cases whose name holds TEXT")
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as out:
        path = ROOT if args.source else _installed(Path(out))
        print(f"plans from {'the source tree' if args.source else 'a compiled copy (as installed)'}")
        print(f"load average before: {os.getloadavg()[0]:.2f} on {os.cpu_count()} CPUs")
        print(f"{'command':52} {'wall [s]':>9} {'CPU [s]':>8} {'target':>7}")
        for name, command, target in CASES:
            if args.only and args.only not in name:
                continue
            argv = [a.format(out=out) for a in command]
            best = min((_run(argv, path) for _ in range(args.runs)), key=lambda t: t[1])
            written = Path(argv[argv.index("-o") + 1])
            size = f"  {written.stat().st_size / 1e6:.2f} MB" if written.is_file() else ""
            print(f"{name:52} {best[0]:9.2f} {best[1]:8.2f} {target:7.1f}  {'met' if best[1] <= target else 'missed'}{size}")
    print(f"load average after: {os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
