"""The handout's speed: ``python -m plans.bench.pages`` (a benchmark, not a test).

Times the quick-return's handout at 12 positions with the instant-centre pages
(issue 20's yardstick: under 10 s), in its two phases — the document built
(positions solved, every drawing drawn as an SVG block by matplotlib, the
Typst source written) and the document typeset (Typst compiles the PDF) —
and the whole ``plans handout`` command as a process.  Prints a Markdown
table; each figure is the best of ``--repeats`` runs.

    python -m plans.bench.pages [--example quick-return] [--positions 12] [--lang sr] [--repeats 3]
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path

__all__ = ["time_handout", "main"]


def time_handout(example: str = "quick-return", positions: int = 12, lang: str = "sr", centres: bool = True, repeats: int = 3) -> dict[str, float]:
    """Best-of-*repeats* times [s]: ``build`` (solve and draw), ``typeset`` (Typst to PDF), ``process`` (the CLI), and
    the handout's page count (``pages``)."""
    import plans
    from plans.handout import handout

    scene = plans.load(plans.example_path(example))
    build = typeset = process = float("inf")
    pages = 0
    for _ in range(repeats):
        t0 = time.perf_counter()
        document = handout(scene, positions=positions, lang=lang, centres=centres)
        t1 = time.perf_counter()
        pdf = document.pdf()
        t2 = time.perf_counter()
        build, typeset = min(build, t1 - t0), min(typeset, t2 - t1)
        pages = pdf.count(b"/Type /Page\n") or pdf.count(b"/Type/Page")
        with tempfile.TemporaryDirectory() as tmp:
            command = [sys.executable, "-m", "plans", "handout", "--example", example, "--positions", str(positions),
                       "--lang", lang, "-o", str(Path(tmp) / "h.pdf"), "-q"] + (["--centres"] if centres else [])
            t3 = time.perf_counter()
            subprocess.run(command, check=True, capture_output=True)
            process = min(process, time.perf_counter() - t3)
    return {"build": build, "typeset": typeset, "process": process, "pages": pages}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m plans.bench.pages", description=__doc__.splitlines()[0])
    parser.add_argument("--example", default="quick-return")
    parser.add_argument("--positions", type=int, default=12)
    parser.add_argument("--lang", default="sr")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--no-centres", action="store_true")
    args = parser.parse_args(argv)
    t = time_handout(args.example, args.positions, args.lang, not args.no_centres, args.repeats)
    print(f"| handout | {args.example}, {args.positions} positions{'' if args.no_centres else ', centres'}, {args.lang} |")
    print("|---|---|")
    print(f"| solved and drawn (SVG blocks, Typst source) | {t['build']:.2f} s |")
    print(f"| typeset (Typst → PDF) | {t['typeset']:.2f} s |")
    print(f"| `plans handout` as a process | {t['process']:.2f} s |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
