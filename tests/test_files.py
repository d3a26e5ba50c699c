"""Atomic output: all files or none, nothing half-written, modes kept."""

import os
import stat

import pytest

from plans._files import replace_all, write_atomic


def test_write_atomic_creates_a_readable_file(tmp_path):
    target = write_atomic(tmp_path / "sub" / "out.csv", "a,b\n")
    assert target.read_text() == "a,b\n"
    assert stat.S_IMODE(target.stat().st_mode) == 0o644


def test_existing_mode_is_kept(tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("old")
    os.chmod(target, 0o600)
    write_atomic(target, "new")
    assert target.read_text() == "new" and stat.S_IMODE(target.stat().st_mode) == 0o600


def test_a_failure_before_the_renames_leaves_everything_untouched(tmp_path):
    good = tmp_path / "good.svg"
    good.write_text("precious")

    with pytest.raises(TypeError):  # the second file cannot be written
        replace_all({good: "new", tmp_path / "second.svg": object()})
    assert good.read_text() == "precious"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["good.svg"]
