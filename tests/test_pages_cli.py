"""plans handout on the command line: progress on a terminal, --quiet, Ctrl-C."""

from __future__ import annotations

import io


import plans.handout
from plans.cli import main


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_progress_shows_on_a_terminal_and_not_with_quiet(tmp_path, monkeypatch, capsys):
    terminal = _Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    assert main(["handout", "--example", "slider-crank", "-o", str(tmp_path / "h.pdf")]) == 0
    shown = terminal.getvalue()
    assert "Position 1/1" in shown and "\r" in shown
    quiet = _Terminal()
    monkeypatch.setattr("sys.stderr", quiet)
    assert main(["handout", "--example", "slider-crank", "-o", str(tmp_path / "q.pdf"), "--quiet"]) == 0
    assert quiet.getvalue() == ""


def test_no_progress_when_stderr_is_not_a_terminal(tmp_path, capsys):
    assert main(["handout", "--example", "slider-crank", "-o", str(tmp_path / "h.svg")]) == 0
    captured = capsys.readouterr()
    assert captured.err == ""
    assert captured.out.split() == [str(tmp_path / "h-01.svg"), str(tmp_path / "h-02.svg"), str(tmp_path / "h-03.svg")]


def test_ctrl_c_is_one_line_exit_130_and_no_file(tmp_path, monkeypatch, capsys):
    def interrupted(*args, **kwargs):
        kwargs["progress"] and None
        raise KeyboardInterrupt

    monkeypatch.setattr(plans.handout, "handout", interrupted)
    target = tmp_path / "out" / "h.pdf"
    assert main(["handout", "--example", "six-bar", "--positions", "12", "-o", str(target)]) == 130
    err = capsys.readouterr().err
    assert err.strip() == "plans: interrupted; nothing written"
    assert "Traceback" not in err
    assert not target.parent.exists()  # not even the directory
