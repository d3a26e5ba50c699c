"""plans draw --positions on the command line: progress on a terminal, --quiet, Ctrl-C while the files are renamed."""

from __future__ import annotations

import io
import os
import pty
import select
import subprocess
import sys
from pathlib import Path

import pytest

from plans.cli import main

ROOT = Path(__file__).resolve().parent.parent


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_draw_positions_shows_sheet_progress_on_a_terminal_and_not_with_quiet(tmp_path, monkeypatch, capsys):
    terminal = _Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    assert main(["draw", "--example", "slider-crank", "--positions", "3", "-o", str(tmp_path / "a")]) == 0
    shown = terminal.getvalue()
    # three sheets and the plan of positions: four files, counted in place (carriage returns), the line cleared at the end
    for n in (1, 2, 3, 4):
        assert f"sheet {n}/4" in shown
    assert "sheet 5/4" not in shown and "\r" in shown
    assert shown.endswith("\r\033[K")
    quiet = _Terminal()
    monkeypatch.setattr("sys.stderr", quiet)
    assert main(["draw", "--example", "slider-crank", "--positions", "3", "-o", str(tmp_path / "b"), "--quiet"]) == 0
    assert quiet.getvalue() == ""


def test_draw_positions_is_silent_when_stderr_is_not_a_terminal(tmp_path, capsys):
    assert main(["draw", "--example", "slider-crank", "--positions", "3", "-o", str(tmp_path)]) == 0
    captured = capsys.readouterr()
    assert captured.err == ""
    assert [Path(p).name for p in captured.out.split()] == ["sheet-00.svg", "sheet-01.svg", "sheet-02.svg", "positions.svg"]


@pytest.mark.skipif(not hasattr(os, "openpty"), reason="needs a pseudo-terminal")
def test_draw_positions_progress_on_a_real_terminal(tmp_path):
    """The process's stderr is a pseudo-terminal (what a user's shell gives it): the progress shows there."""
    master, slave = pty.openpty()
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    process = subprocess.Popen(
        [sys.executable, "-m", "plans", "draw", "--example", "slider-crank", "--positions", "2", "-o", str(tmp_path)],
        stdout=subprocess.PIPE, stderr=slave, cwd=ROOT, env=env,
    )
    os.close(slave)
    seen = b""
    while True:
        ready, _, _ = select.select([master], [], [], 60)
        if not ready:
            break
        try:
            chunk = os.read(master, 4096)
        except OSError:  # the terminal closed: the process has ended
            break
        if not chunk:
            break
        seen += chunk
    out, _ = process.communicate(timeout=60)
    os.close(master)
    assert process.returncode == 0
    assert b"sheet 1/3" in seen and b"sheet 3/3" in seen
    assert out.decode().split()[-1].endswith("positions.svg")


def test_ctrl_c_while_renaming_leaves_the_earlier_files_and_no_partial_one(tmp_path, monkeypatch, capsys):
    """Interrupted between two renames of the final commit: every file is as before, no temporary file is left."""
    out = tmp_path / "sheets"
    assert main(["draw", "--example", "slider-crank", "--positions", "3", "-o", str(out)]) == 0
    capsys.readouterr()
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    assert sorted(before) == ["positions.svg", "sheet-00.svg", "sheet-01.svg", "sheet-02.svg"]

    real_replace = os.replace
    calls = []

    def interrupted_replace(src, dst, *args, **kwargs):
        calls.append(Path(dst).name)
        if len(calls) == 3:  # two files already have their new content
            raise KeyboardInterrupt
        return real_replace(src, dst, *args, **kwargs)

    monkeypatch.setattr(os, "replace", interrupted_replace)
    # another language: every file's new content differs from the old
    assert main(["draw", "--example", "slider-crank", "--positions", "3", "--lang", "sr", "-o", str(out)]) == 130
    err = capsys.readouterr().err
    assert err.strip() == "plans: interrupted; nothing written" and "Traceback" not in err
    assert len(calls) > 3  # the interruption came mid-way and the two renamed files were put back
    after = {p.name: p.read_bytes() for p in out.iterdir()}
    assert after == before  # the same names (no temporary or backup file) with the same bytes


def test_ctrl_c_while_renaming_into_a_new_directory_leaves_nothing(tmp_path, monkeypatch, capsys):
    real_replace = os.replace
    calls = []

    def interrupted_replace(src, dst, *args, **kwargs):
        calls.append(dst)
        if len(calls) == 2:
            raise KeyboardInterrupt
        return real_replace(src, dst, *args, **kwargs)

    monkeypatch.setattr(os, "replace", interrupted_replace)
    target = tmp_path / "new" / "sheets"
    assert main(["draw", "--example", "slider-crank", "--positions", "3", "-o", str(target)]) == 130
    assert "interrupted" in capsys.readouterr().err
    assert not (tmp_path / "new").exists()  # neither the files nor the directories made for them
