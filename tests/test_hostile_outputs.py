"""Output paths under attack (issue 12, issue 9 §1): all-or-none, directories included.

Every case runs through the command line (``plans.cli.main``) and compares the
output location before and after: names, kinds and bytes of everything in it.
A failure is injected after the first file has really been written (the
second rename of the commit fails), so the old content must come back.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest

from plans.cli import main


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def snapshot(root: Path) -> dict:
    """Every entry under *root*: kind and, for files, bytes (symbolic links not followed)."""
    if not os.path.lexists(root):
        return {}
    out = {}
    for directory, dirs, files in os.walk(root):
        for name in dirs + files:
            path = Path(directory) / name
            mode = os.lstat(path).st_mode
            if stat.S_ISREG(mode):
                out[str(path.relative_to(root))] = path.read_bytes()
            elif stat.S_ISLNK(mode):
                out[str(path.relative_to(root))] = ("link", os.readlink(path))
            else:
                out[str(path.relative_to(root))] = stat.S_IFMT(mode)
    return out


@pytest.fixture
def fail_second_rename(monkeypatch):
    """os.replace fails on its second call: the first output is then already in place."""
    real = os.replace
    calls = []

    def replace(src, dst, *args, **kwargs):
        calls.append(dst)
        if len(calls) == 2:
            raise OSError(28, "No space left on device")
        return real(src, dst, *args, **kwargs)

    monkeypatch.setattr(os, "replace", replace)
    return calls


# --- all-or-none through the command line ----------------------------------------------------


def test_draw_failing_after_the_first_file_leaves_the_directory_as_it_was(capsys, tmp_path, fail_second_rename):
    out = tmp_path / "out"
    out.mkdir()
    (out / "mechanism.svg").write_text("the user's earlier drawing")
    (out / "notes.txt").write_text("keep me")
    before = snapshot(tmp_path)
    status, _, err = run(capsys, "draw", "--example", "four-bar", "-o", str(out))
    assert status == 2 and "No space left on device" in err
    assert len(fail_second_rename) >= 2  # the failure came after a file had been renamed into place
    assert snapshot(tmp_path) == before


def test_draw_into_a_new_directory_failing_midway_leaves_no_directory(capsys, tmp_path, fail_second_rename):
    status, _, _ = run(capsys, "draw", "--example", "four-bar", "-o", str(tmp_path / "new" / "deeper"))
    assert status == 2
    assert snapshot(tmp_path) == {}


def test_sweep_csv_and_diagrams_failing_midway_change_nothing(capsys, tmp_path, fail_second_rename):
    (tmp_path / "cycle.csv").write_text("old csv")
    before = snapshot(tmp_path)
    status, out, _ = run(
        capsys, "sweep", "--example", "quick-return", "--steps", "12", "-o", str(tmp_path / "cycle.csv"), "--plot", str(tmp_path / "plots")
    )
    assert status == 2 and out == ""
    assert snapshot(tmp_path) == before


def test_sweep_writes_no_csv_when_a_diagram_fails(capsys, tmp_path, monkeypatch):
    from plans.drawing import diagrams
    from plans.errors import PlansError

    def broken(*args, **kwargs):
        raise PlansError("injected: the diagrams cannot be drawn")

    monkeypatch.setattr(diagrams, "draw_cycle_diagrams", broken)
    status, _, err = run(capsys, "sweep", "--example", "four-bar", "--steps", "12", "-o", str(tmp_path / "x.csv"), "--plot", str(tmp_path / "d"))
    assert status == 2 and "injected" in err
    assert snapshot(tmp_path) == {}


def test_handout_that_fails_to_render_creates_no_directory(capsys, tmp_path, monkeypatch):
    from plans.pages import handout as pages

    def broken(*args, **kwargs):
        raise OSError(5, "Input/output error")

    monkeypatch.setattr(pages, "compile_document", broken)  # the typesetter
    status, _, _ = run(capsys, "handout", "--example", "four-bar", "-o", str(tmp_path / "a" / "b" / "h.pdf"))
    assert status == 2
    assert snapshot(tmp_path) == {}


def test_positions_run_failing_midway_keeps_the_earlier_run(capsys, tmp_path, monkeypatch):
    out = tmp_path / "sheets"
    assert run(capsys, "draw", "--example", "four-bar", "--positions", "3", "-o", str(out))[0] == 0
    before = snapshot(tmp_path)
    real = os.replace
    calls = []

    def replace(src, dst, *args, **kwargs):
        calls.append(dst)
        if len(calls) == 2:
            raise OSError(28, "No space left on device")
        return real(src, dst, *args, **kwargs)

    monkeypatch.setattr(os, "replace", replace)
    assert run(capsys, "draw", "--example", "four-bar", "--positions", "2", "-o", str(out))[0] == 2
    assert snapshot(tmp_path) == before


# --- what may be replaced ------------------------------------------------------------------------


@pytest.mark.parametrize("kind", ["fifo", "directory", "link to a fifo", "link to a directory"])
def test_only_regular_files_are_replaced(capsys, tmp_path, kind):
    target = tmp_path / "out.csv"
    other = tmp_path / "other"
    if kind.endswith("fifo"):
        os.mkfifo(other if kind.startswith("link") else target)
    else:
        (other if kind.startswith("link") else target).mkdir()
    if kind.startswith("link"):
        target.symlink_to(other)
    before = snapshot(tmp_path)
    status, out, err = run(capsys, "sweep", "--example", "four-bar", "--steps", "4", "-o", str(target))
    assert status == 2 and out == ""
    assert err.startswith(f"plans: error: cannot write {target}") and "regular files" in err, err
    assert snapshot(tmp_path) == before


def test_a_link_to_a_regular_file_writes_the_file_and_keeps_the_link(capsys, tmp_path):
    (tmp_path / "real.csv").write_text("old")
    (tmp_path / "link.csv").symlink_to(tmp_path / "real.csv")
    assert run(capsys, "sweep", "--example", "four-bar", "--steps", "4", "-o", str(tmp_path / "link.csv"))[0] == 0
    assert (tmp_path / "link.csv").is_symlink()
    assert (tmp_path / "real.csv").read_text().startswith("driver_phi_deg,")


def test_two_outputs_of_one_command_onto_one_file_are_refused(capsys, tmp_path):
    status, _, err = run(capsys, "sweep", "--example", "four-bar", "--steps", "4", "-o", str(tmp_path / "links.svg"), "--plot", str(tmp_path))
    assert status == 2 and "links.svg" in err
    assert snapshot(tmp_path) == {}


def test_an_output_name_of_250_bytes_is_written(capsys, tmp_path):
    name = "a" * 246 + ".csv"  # 250 bytes; the file system allows 255
    status, _, err = run(capsys, "sweep", "--example", "four-bar", "--steps", "4", "-o", str(tmp_path / name))
    assert status == 0, err
    assert sorted(os.listdir(tmp_path)) == [name]


# --- issue 9 §1: nothing lost, nothing of the user's removed ---------------------------------------


def test_sweep_plot_without_output_prints_the_csv(capsys, tmp_path):
    status, out, _ = run(capsys, "sweep", "--example", "four-bar", "--steps", "8", "--plot", str(tmp_path / "d"))
    assert status == 0
    rows = out.splitlines()
    assert rows[0].startswith("driver_phi_deg,") and len(rows) == 9
    assert sorted(os.listdir(tmp_path / "d")) == ["kinematic.svg", "links.svg", "points.svg"]  # and the output link's kinematic diagrams (cycle-diagrams)


def test_draw_positions_removes_only_sheets_plans_wrote(capsys, tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "sheet-99.svg").write_text("<svg>the user's own</svg>")
    assert run(capsys, "draw", "--example", "four-bar", "--positions", "6", "-o", str(out))[0] == 0
    (out / "sheet-04.svg").write_bytes((out / "sheet-04.svg").read_bytes() + b"<!-- edited by hand -->")
    assert run(capsys, "draw", "--example", "four-bar", "--positions", "2", "-o", str(out))[0] == 0
    names = sorted(os.listdir(out))
    # sheet-02, -03, -05 were plans' own and unchanged: gone; the user's and the edited one stay
    assert names == ["positions.svg", "sheet-00.svg", "sheet-01.svg", "sheet-04.svg", "sheet-99.svg"]
    assert (out / "sheet-99.svg").read_text() == "<svg>the user's own</svg>"


def test_draw_without_accelerations_keeps_a_users_acceleration_svg(capsys, tmp_path):
    from plans.scene import example_path

    scene = tmp_path / "v.toml"
    scene.write_text(example_path("four-bar").read_text() + "\n[compute]\naccelerations = false\n")
    out = tmp_path / "out"
    out.mkdir()
    (out / "acceleration.svg").write_text("mine")
    assert run(capsys, "draw", str(scene), "-o", str(out))[0] == 0
    assert (out / "acceleration.svg").read_text() == "mine"
    # one plans wrote goes when a later run has no acceleration plan
    assert run(capsys, "draw", "--example", "four-bar", "-o", str(out))[0] == 0
    assert run(capsys, "draw", str(scene), "-o", str(out))[0] == 0
    assert sorted(os.listdir(out)) == ["mechanism.svg", "sheet.svg", "velocity.svg"]
