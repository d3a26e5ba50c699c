"""Handouts built once per test process and shared by the test files that read them (a handout is not changed by
the tests that read it: they read its source, drawings, scales and PDF).

:func:`built` is the handout of an example as ``plans handout --example …`` builds it, :func:`built_pdf` its PDF
(compiled once); the three handouts the teachers' reviews of the plans saw (sr quick-return at 12 positions, bg
linear-arm at 8, en six-bar) are :func:`reviewed_handouts`.  Likewise :func:`drawn_sheet`: the files
``plans draw --example …`` writes, written once per process into a scratch directory of its own (read them, never
write beside them).  Under pytest-xdist the workers of one run share these builds (:func:`share_in`, from
``tests/conftest.py``): the first to need one builds it, the others read it.
"""

from __future__ import annotations

import atexit
import fcntl
import hashlib
import inspect
import pickle
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


#: where the test processes of one run (pytest-xdist's workers) share what they build (:func:`share_in`); None: each
#: process builds its own
_SHARED: Path | None = None


def share_in(directory: Path) -> None:
    """Share the handouts and sheets built from here on with the other processes of this test run, in *directory*
    (the run's own: ``tests/conftest.py`` gives the workers their run's temporary directory)."""
    global _SHARED
    directory.mkdir(exist_ok=True)
    _SHARED = directory


def _once(tag: str, key: tuple, make, keep=None):
    """``make()`` once per test run where it can be: the first process to ask builds it and leaves it pickled for the
    rest (*keep* given: ``keep(directory)`` writes it there and its path is returned).  A process that asks while
    another is still building it builds its own rather than wait idle (the workers ask for the same builds at about
    the same time: a lock waited on costs more than the build it saves)."""
    if _SHARED is None:
        return make() if keep is None else keep(Path(tempfile.mkdtemp(dir=_scratch())))
    name = hashlib.sha256(repr((tag, key)).encode()).hexdigest()[:24]
    path = _SHARED / (name if keep is not None else f"{name}.pickle")
    done = _SHARED / f"{name}.done"
    if done.exists():
        return Path(done.read_text()) if keep is not None else pickle.loads(path.read_bytes())
    with open(_SHARED / f"{name}.lock", "a") as lock:
        try:
            fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:  # (being built by another process: built here too)
            return make() if keep is None else keep(Path(tempfile.mkdtemp(dir=_scratch())))
        try:
            if done.exists():
                return Path(done.read_text()) if keep is not None else pickle.loads(path.read_bytes())
            if keep is not None:
                shutil.rmtree(path, ignore_errors=True)
                path.mkdir()
                target = keep(path)
                done.write_text(str(target))
                return target
            value = make()
            path.write_bytes(pickle.dumps(value))
            done.write_text(str(path))
            return value
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


@lru_cache(maxsize=None)
def _built(example: str, positions, lang: str, options: tuple):
    return _once("handout", (example, positions, lang, options),
                 lambda: handout(plans.load(example_path(example)), positions=positions, lang=lang, **dict(options)))


@lru_cache(maxsize=None)
def _pdf(example: str, positions, lang: str, options: tuple) -> bytes:
    return _once("pdf", (example, positions, lang, options), lambda: _built(example, positions, lang, options).pdf())


def built(example: str, positions=None, lang: str = "en", **options):
    """``handout(plans.load(example_path(example)), positions=positions, lang=lang, **options)``, built once per
    process, or once per test run where its processes share their builds (:func:`share_in`): the same Handout for
    the same arguments, read it, never change it."""
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

    def keep(out: Path) -> Path:
        target = out / output if output else out / "drawn"
        assert main(["draw", "--example", example, "--lang", lang, "-o", str(target), "-q"]) == 0, (example, lang, output)
        return target

    return _once("sheet", (example, lang, output), None, keep)
