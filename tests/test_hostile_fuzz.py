"""Fuzzing the hostile classes of issue 12 through the command line, a time bound per example.

* hostile TOML: arrays and inline tables nested 0 … 20 000 deep, anywhere;
* huge files: sizes around the 1 MB limit;
* long chains: 1 … 110 crank-rocker stages in a row (the limit is 200 links);
* non-regular outputs: FIFOs, directories, links to them, paths through a file;
* a failure at any rename of a commit.

Each run must end with exit status 0, or 2 and one line on stderr; a refused
or failed run leaves the output location exactly as it was.
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from plans.cli import main
from plans.scene import MAX_LINKS, MAX_SCENE_BYTES, example_path
from test_hostile_input import chain
from test_hostile_outputs import snapshot

FOUR_BAR = example_path("four-bar").read_text(encoding="utf-8")
def fuzz(examples: int):
    """Settings of one fuzz test: a few examples, each within 20 s."""
    return settings(max_examples=examples, deadline=20_000, suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    assert status in (0, 2), err
    if status == 2:
        assert err.count("\n") == 1 and err.startswith("plans: error: "), err
    assert "Traceback" not in err
    return status, out, err


def fresh(tmp_path: Path, name: str) -> Path:
    path = tmp_path / name
    shutil.rmtree(path, ignore_errors=True)
    path.mkdir()
    return path


@st.composite
def nested(draw):
    depth = draw(st.sampled_from([0, 1, 5, 31, 32, 33, 200, 999, 1000, 1001, 5000, 20_000]))
    pattern = draw(st.lists(st.sampled_from(["[", "{a = "]), min_size=1, max_size=3))  # arrays, tables or a mix
    levels = (pattern * (depth // len(pattern) + 1))[:depth]
    value = "".join(levels) + "1" + "".join("]" if o == "[" else "}" for o in reversed(levels))
    where = draw(st.sampled_from(["junk = ", "[compute]\npoints = ", "[link.2]\nlines = ", "title = "]))
    return depth, where, value


@fuzz(25)
@given(nested())
def test_hostile_toml(capsys, tmp_path, case):
    depth, where, value = case
    text = FOUR_BAR.replace("[frame]", f"{where}{value}\n[frame]", 1) if where == "junk = " else FOUR_BAR + f"\n{where}{value}\n"
    path = tmp_path / "deep.toml"
    path.write_text(text)
    status, _, err = run(capsys, "solve", "--analytic-only", str(path))
    assert status == 2  # nothing here is a valid scene
    assert str(path) in err
    if depth > 32:
        assert "nested more than 32 deep" in err or "not valid TOML" in err, err


@fuzz(6)
@given(st.integers(-3000, 3000))
def test_files_around_the_size_limit(capsys, tmp_path, delta):
    size = MAX_SCENE_BYTES + delta
    path = tmp_path / "big.toml"
    padding = size - len(FOUR_BAR.encode())
    path.write_text(FOUR_BAR + "".join("#" * 99 + "\n" for _ in range(padding // 100)) + "#" * (padding % 100))
    assert path.stat().st_size == size
    status, _, err = run(capsys, "solve", "--analytic-only", str(path))
    assert status == (2 if size > MAX_SCENE_BYTES else 0)
    if status:
        assert "larger than 1 MB" in err


@fuzz(8)
@given(st.integers(1, 110))
def test_long_chains_solve_or_are_refused(capsys, tmp_path, n):
    path = tmp_path / "chain.toml"
    path.write_text(chain(n))
    status, out, err = run(capsys, "solve", "--analytic-only", str(path))
    if 1 + 2 * n > MAX_LINKS:
        assert status == 2 and "at most 200" in err
    else:
        assert status == 0, err
        assert f"RRR({2 * n + 1},{2 * n + 2})" in out


KINDS = ["absent", "regular", "fifo", "directory", "link to regular", "link to fifo", "link to directory", "dangling link", "under a file"]


def make(tmp_path: Path, kind: str) -> Path:
    target = tmp_path / "target"
    other = tmp_path / "other"
    if kind == "regular":
        target.write_text("old")
    elif kind == "fifo":
        os.mkfifo(target)
    elif kind == "directory":
        target.mkdir()
        (target / "inside").write_text("keep")
    elif kind.startswith("link"):
        if kind.endswith("regular"):
            other.write_text("old")
        elif kind.endswith("fifo"):
            os.mkfifo(other)
        else:
            other.mkdir()
        target.symlink_to(other)
    elif kind == "dangling link":
        target.symlink_to(other)
    elif kind == "under a file":
        other.write_text("a file")
        target = other / "target"
    return target


@fuzz(15)
@given(st.sampled_from(KINDS), st.sampled_from(["sweep", "draw"]))
def test_outputs_onto_anything(capsys, tmp_path, kind, command):
    where = fresh(tmp_path, "work")
    target = make(where, kind)
    before = snapshot(where)
    if command == "sweep":
        status, _, err = run(capsys, "sweep", "--example", "four-bar", "--steps", "4", "-o", str(target))
        writable = kind in ("absent", "regular", "link to regular", "dangling link")
    else:
        status, _, err = run(capsys, "draw", "--example", "slider-crank", "-o", str(target))
        writable = kind in ("absent", "directory", "link to directory", "dangling link")
    if writable:
        assert status == 0, err
    else:
        assert status == 2
        assert snapshot(where) == before


@fuzz(6)
@given(st.integers(1, 4), st.booleans())
def test_a_failure_at_any_rename_leaves_the_output_as_it_was(capsys, tmp_path, failing, earlier):
    where = fresh(tmp_path, "work")
    out = where / "out"
    if earlier:  # an earlier run's files and a file of the user's
        assert run(capsys, "draw", "--example", "four-bar", "-o", str(out))[0] == 0
        (out / "notes.txt").write_text("mine")
    before = snapshot(where)
    real = os.replace
    calls = []

    def replace(src, dst, *args, **kwargs):
        calls.append(dst)
        if len(calls) == failing:
            raise OSError(28, "No space left on device")
        return real(src, dst, *args, **kwargs)

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(os, "replace", replace)
        status, _, _ = run(capsys, "draw", "--example", "slider-crank", "-o", str(out))
    assert status == 2
    assert snapshot(where) == before
