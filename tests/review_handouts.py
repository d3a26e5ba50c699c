"""Handouts built once per test process and shared by the test files that read them (a handout is not changed by
the tests that read it: they read its source, drawings, scales and PDF).

:func:`built` is the handout of an example as ``plans handout --example …`` builds it, :func:`built_pdf` its PDF
(compiled once); the three handouts the teachers' reviews of the plans saw (sr quick-return at 12 positions, bg
linear-arm at 8, en six-bar) are :func:`reviewed_handouts`.  Likewise :func:`drawn_sheet`: the files
``plans draw --example …`` writes, written once per process into a scratch directory of its own (read them, never
write beside them).
"""

from __future__ import annotations

import atexit
import inspect
import shutil
import tempfile
from functools import lru_cache
from pathlib import Path

import plans
from plans.handout import handout
from plans.scene import example_path

REVIEWED = [("quick-return", 12, "sr"), ("linear-arm", 8, "bg"), ("six-bar", None, "en")]

#: the options of :func:`plans.handout.handout` and their defaults (an option given at its default is the same handout)
_DEFAULTS = {name: p.default for name, p in inspect.signature(handout).parameters.items() if p.default is not inspect.Parameter.empty}


def _key(example: str, positions, lang: str, options: dict) -> tuple:
    unknown = set(options) - set(_DEFAULTS)
    assert not unknown, f"not an option of handout(): {sorted(unknown)}"
    return example, positions, lang, tuple(sorted((k, v) for k, v in options.items() if v != _DEFAULTS[k] or type(v) is not type(_DEFAULTS[k])))


@lru_cache(maxsize=None)
def _built(example: str, positions, lang: str, options: tuple):
    return handout(plans.load(example_path(example)), positions=positions, lang=lang, **dict(options))


@lru_cache(maxsize=None)
def _pdf(example: str, positions, lang: str, options: tuple) -> bytes:
    return _built(example, positions, lang, options).pdf()


def built(example: str, positions=None, lang: str = "en", **options):
    """``handout(plans.load(example_path(example)), positions=positions, lang=lang, **options)``, built once per
    process (the same Handout for the same arguments: read it, never change it)."""
    return _built(*_key(example, positions, lang, options))


def built_pdf(example: str, positions=None, lang: str = "en", **options) -> bytes:
    """The PDF of :func:`built` (``.pdf()``), compiled once per process."""
    return _pdf(*_key(example, positions, lang, options))


def reviewed_handouts() -> dict:
    """name -> (Handout, lang) of :data:`REVIEWED` (the handouts are not changed by the tests that read them)."""
    return {name: (built(name, n, lang), lang) for name, n, lang in REVIEWED}


@lru_cache(maxsize=1)
def _scratch() -> Path:
    directory = Path(tempfile.mkdtemp(prefix="plans-tests-drawn-"))
    atexit.register(shutil.rmtree, directory, True)
    return directory


@lru_cache(maxsize=None)
def drawn_sheet(example: str, lang: str = "en", output: str = "") -> Path:
    """What ``plans draw --example EXAMPLE --lang LANG -o OUT`` writes (status 0 asserted), once per process: OUT a
    directory of its own (*output* ""; its drawings and ``sheet.svg``), or the file *output* in it (``sheet.pdf``,
    ``sheet.svg``: the sheet alone); the path of OUT."""
    from plans.cli import main

    out = Path(tempfile.mkdtemp(dir=_scratch()))
    target = out / output if output else out / "drawn"
    assert main(["draw", "--example", example, "--lang", lang, "-o", str(target), "-q"]) == 0, (example, lang, output)
    return target
