"""Every CLI path end to end, every output kind byte-identical between runs, and
all-or-none writing with a failure injected after the first file (issue 9 §4)."""

import csv
import hashlib
import io
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pypdf
import pytest

from plans.cli import main

ROOT = Path(__file__).resolve().parent.parent

#: Every command path, run in one process: (argv, the files it must write (relative to OUT), stdout kind).
RUNS = [
    (["solve", "--example", "six-bar"], [], "table"),
    (["solve", "--example", "six-bar", "--json"], [], "json"),
    (["solve", "--example", "quick-return", "--json", "--analytic-only"], [], "json"),
    (["solve", "--example", "four-bar", "--at", "10,25 deg", "--json"], [], "json"),
    (["solve", "--example", "ladder", "--at", "50 mm"], [], "table"),
    (["sweep", "--example", "slider-crank", "--steps", "24", "-o", "OUT/sweep.csv"], ["sweep.csv"], None),
    (["sweep", "--example", "four-bar", "--steps", "24"], [], "csv"),
    (["sweep", "--example", "quick-return", "--steps", "24", "-o", "OUT/qr.csv", "--plot", "OUT/diagrams"],
     ["qr.csv", "diagrams/links.svg", "diagrams/points.svg", "diagrams/sliders.svg"], None),
    (["draw", "--example", "six-bar", "-o", "OUT/one"],
     ["one/mechanism.svg", "one/velocity.svg", "one/acceleration.svg", "one/sheet.svg"], None),
    (["draw", "--example", "four-bar", "-o", "OUT/png", "--format", "png"],
     ["png/mechanism.png", "png/velocity.png", "png/acceleration.png", "png/sheet.png"], None),
    (["draw", "--example", "four-bar", "-o", "OUT/page.pdf"], ["page.pdf"], None),
    (["draw", "--example", "slider-crank", "-o", "OUT/page.png"], ["page.png"], None),
    (["draw", "--example", "four-bar", "--positions", "2", "-o", "OUT/positions"],
     ["positions/sheet-00.svg", "positions/sheet-01.svg", "positions/positions.svg"], None),
    (["draw", "--example", "four-bar", "--at", "0,90 deg", "-o", "OUT/at"], ["at/sheet-00.svg", "at/sheet-01.svg", "at/positions.svg"], None),
    (["handout", "--example", "four-bar", "-o", "OUT/handout.pdf", "--lang", "sr"], ["handout.pdf"], None),
    (["examples"], [], "text"),
    (["examples", "wedge"], [], "toml"),
]

SCRIPT = """
import contextlib, io, json, sys
from plans.cli import main
out = sys.argv[1]
runs = json.loads(sys.argv[2])
results = []
for argv in runs:
    argv = [a.replace("OUT", out) for a in argv]
    stdout = io.StringIO()
    with contextlib.redirect_stdout(stdout):
        status = main(argv)
    results.append([status, stdout.getvalue().replace(out, "OUT")])
print(json.dumps(results))
"""


def _run_all(directory: Path):
    done = subprocess.run(
        [sys.executable, "-c", SCRIPT, str(directory), json.dumps([argv for argv, _, _ in RUNS])],
        capture_output=True, text=True, cwd=ROOT, env={**os.environ, "PYTHONHASHSEED": "random"},
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.splitlines()[-1])


@pytest.fixture(scope="module")
def two_runs(tmp_path_factory):
    first, second = tmp_path_factory.mktemp("first"), tmp_path_factory.mktemp("second")
    return (first, _run_all(first)), (second, _run_all(second))


def _valid(path: Path):
    data = path.read_bytes()
    assert data, path
    if path.suffix == ".svg":
        root = ET.fromstring(data)
        assert root.tag.endswith("svg") and root.get("width", "").endswith("mm"), path
    elif path.suffix == ".pdf":
        assert data.startswith(b"%PDF-") and len(pypdf.PdfReader(path).pages) >= 1, path
    elif path.suffix == ".png":
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and data[12:16] == b"IHDR", path
        width, height = int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")
        assert width > 100 and height > 100, path
    elif path.suffix == ".csv":
        rows = list(csv.reader(io.StringIO(data.decode())))
        assert len(rows) == 25 and len(set(map(len, rows))) == 1, path


def test_every_command_path_runs_and_writes_valid_files(two_runs):
    (directory, results), _ = two_runs
    for (argv, files, kind), (status, stdout) in zip(RUNS, results):
        assert status == 0, argv
        for name in files:
            _valid(directory / name)
            if not name.endswith(".csv"):
                assert f"OUT/{name}" in stdout, (argv, stdout)  # the CLI lists the drawings it wrote
        if kind == "json":
            doc = json.loads(stdout)
            assert (doc[0] if isinstance(doc, list) else doc)["schema"] == 1
        elif kind == "csv":
            assert len(list(csv.reader(io.StringIO(stdout)))) == 25
        elif kind == "table":
            assert "structure: I(1,2)" in stdout
        elif kind == "toml":
            assert 'title = { en = "Wedge cam", sr = ' in stdout
        elif kind == "text":
            assert stdout.count("\n") >= 9


def test_every_output_kind_is_byte_identical_between_runs(two_runs):
    (first, results_1), (second, results_2) = two_runs
    assert results_1 == results_2  # stdout: tables, JSON, CSV, listings
    files = sorted(p.relative_to(first) for p in first.rglob("*") if p.is_file())
    assert {p.suffix for p in files} >= {".svg", ".pdf", ".png", ".csv"}
    assert "diagrams/links.svg" in {str(p) for p in files}  # the cycle diagrams (the SVG hash salt)
    assert files == sorted(p.relative_to(second) for p in second.rglob("*") if p.is_file())
    for name in files:
        one, two = (first / name).read_bytes(), (second / name).read_bytes()
        assert hashlib.sha256(one).digest() == hashlib.sha256(two).digest(), name


def test_single_position_draw_writes_every_file(tmp_path, capsys):
    assert main(["draw", "--example", "wedge", "-o", str(tmp_path / "d")]) == 0
    listed = capsys.readouterr().out.split()
    names = sorted(p.name for p in (tmp_path / "d").iterdir())
    assert names == ["acceleration.svg", "mechanism.svg", "sheet.svg", "velocity.svg"]
    assert sorted(Path(p).name for p in listed) == names
    for name in names:
        _valid(tmp_path / "d" / name)


@pytest.mark.parametrize("argv, written", [
    (["draw", "--example", "four-bar", "-o", "OUT"], "mechanism.svg"),
    (["draw", "--example", "four-bar", "--positions", "3", "-o", "OUT"], "sheet-00.svg"),
    (["draw", "--example", "four-bar", "-o", "OUT", "--format", "png"], "mechanism.png"),
])
def test_all_or_none_with_a_failure_after_the_first_file(tmp_path, capsys, monkeypatch, argv, written):
    """The second file's write fails: the first (already written to its temporary file) must not appear."""
    out = tmp_path / "out"
    out.mkdir()
    (out / "keep.txt").write_text("the user's own")
    real_fsync = os.fsync
    calls = []

    def failing_fsync(fd):
        calls.append(fd)
        if len(calls) == 2:
            raise OSError(28, "No space left on device")
        return real_fsync(fd)

    monkeypatch.setattr(os, "fsync", failing_fsync)
    status = main([a.replace("OUT", str(out)) for a in argv])
    _, err = capsys.readouterr()
    assert status == 2 and "No space left on device" in err
    assert len(calls) == 2  # the failure came after the first file was written in full
    assert sorted(p.name for p in out.iterdir()) == ["keep.txt"]  # nothing, not even a temporary file
