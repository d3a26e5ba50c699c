"""``plans bench``: error against run time, both methods side by side.

Runs a fixed suite (every bundled example, a four-bar near its toggle, the
offset slider-crank at micro and large scale), measures each method's
relative errors against a 50-digit reference and its time per position,
prints a Markdown table, and with ``-o DIR`` writes ``bench.csv``,
``bench.md`` and ``error_vs_time.svg``.  The committed results are made with::

    plans bench -o figures

This module only declares the command: numpy, mpmath (an optional
dependency, needed by the benchmark alone) and matplotlib are imported when
it runs, so that adding it to ``plans``' parser costs nothing at start-up.

* :mod:`plans.bench.reference` — the 50-digit reference (mpmath)
* :mod:`plans.bench.yardstick` — the offset slider-crank in closed numpy form
* :mod:`plans.bench.cases` — the suite
* :mod:`plans.bench.run` — timing, errors, Markdown and CSV
* :mod:`plans.bench.plot` — ``error_vs_time.svg``
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

__all__ = ["add_parser", "run_command", "EXIT_ERROR"]

#: The exit status for a benchmark that cannot run (the CLI's convention).
EXIT_ERROR = 2


def add_parser(subparsers) -> argparse.ArgumentParser:
    """Add ``bench`` to the ``plans`` command's subparsers; returns its parser."""
    parser = subparsers.add_parser(
        "bench",
        help="benchmark both methods: relative error against time per position, on a fixed suite",
        description="Measure the relative errors (against a 50-digit mpmath reference) and the run time per position "
        "of the analytic solver and the graphical construction on a fixed suite of scenes. Prints a Markdown table; "
        "with -o DIR also writes DIR/bench.csv, DIR/bench.md and DIR/error_vs_time.svg. Needs mpmath.",
    )
    parser.add_argument("--quick", action="store_true", help="a smoke run of a few seconds (fewer sizes, samples and repeats)")
    parser.add_argument("-o", "--output", metavar="DIR", help="write bench.csv, bench.md and error_vs_time.svg here")
    parser.add_argument("--case", action="append", metavar="NAME", help="run only this case (repeatable)")
    parser.add_argument("--no-processes", action="store_true", help="skip timing plans solve / plans draw as whole processes (the chains of RRR dyads too)")
    return parser


def run_command(args) -> int:
    """Run ``plans bench`` with parsed *args*; returns the exit status."""
    try:
        import mpmath  # noqa: F401
    except ImportError:
        print("plans bench: needs mpmath for its 50-digit reference: pip install mpmath", file=sys.stderr)
        return EXIT_ERROR
    from dataclasses import replace

    from .run import DEFAULT, QUICK, markdown, run_bench, to_csv

    settings = QUICK if args.quick else DEFAULT
    if args.case:
        settings = replace(settings, cases=tuple(args.case))
    if args.no_processes:
        settings = replace(settings, processes=False, chains=())
    try:
        result = run_bench(settings, progress=lambda line: print(line, file=sys.stderr, flush=True))
    except ValueError as exc:
        print(f"plans bench: {exc}", file=sys.stderr)
        return EXIT_ERROR
    text = markdown(result)
    if args.output:
        from .._files import replace_all
        from .plot import render_svg

        out = Path(args.output)
        replace_all({out / "bench.csv": to_csv(result), out / "bench.md": text, out / "error_vs_time.svg": render_svg(result)})
    sys.stdout.write(text)
    return 0
