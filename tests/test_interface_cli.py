"""A command line people find their way around (issue 9 §3)."""

import subprocess
import sys
import tomllib

import pytest

import plans
from plans.cli import main

COMMANDS = ["solve", "sweep", "draw", "handout", "bench", "examples"]


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_version(capsys):
    with pytest.raises(SystemExit) as done:
        main(["--version"])
    assert done.value.code == 0
    assert capsys.readouterr().out.strip() == f"plans {plans.__version__}"
    assert plans.__version__ == tomllib.loads(open("pyproject.toml").read())["project"]["version"]


@pytest.mark.parametrize("name", plans.example_names())
def test_examples_name_prints_the_scene_as_it_is_bundled(capsys, name):
    status, out, _ = run(capsys, "examples", name)
    assert status == 0
    assert out == plans.example_path(name).read_text()
    assert plans.loads(out).title == plans.load(plans.example_path(name)).title


def test_examples_unknown_name_is_refused_with_a_suggestion(capsys):
    status, out, err = run(capsys, "examples", "sixbar")
    assert status == 2 and out == "" and "did you mean 'six-bar'?" in err


def test_examples_list_says_what_each_shows_without_jargon(capsys):
    status, out, _ = run(capsys, "examples")
    assert status == 0
    lines = out.splitlines()
    assert [line.split()[0] for line in lines] == plans.example_names()
    for line in lines:
        words = line.split(maxsplit=1)[1]
        assert len(words) > 30
        for jargon in ("E1", "E2", "(RPP)", "(PRP)", "Grashof", "domain.md"):
            assert jargon not in words, line


@pytest.mark.parametrize("command", COMMANDS)
def test_every_help_ends_with_an_example_and_says_where_the_scene_format_is(capsys, command):
    with pytest.raises(SystemExit) as done:
        main([command, "--help"])
    assert done.value.code == 0
    out = capsys.readouterr().out
    example = out[out.rindex("example:"):]
    assert f"plans {command}" in example
    if command != "bench":  # bench reads no scene
        assert 'README, section "Scene files"' in out and "plans examples NAME" in out


@pytest.mark.parametrize("command", [c for c in COMMANDS if c != "bench"])
def test_the_help_examples_run(capsys, tmp_path, monkeypatch, command):
    """Every example line of the help runs as printed (in a scratch directory)."""
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit):
        main([command, "--help"])
    out = capsys.readouterr().out
    lines = [line.strip() for line in out[out.rindex("example:"):].splitlines()[1:] if line.strip().startswith("plans ")]
    assert lines
    for line in lines:
        argv = line.split()[1:]
        argv = [a.strip('"') for a in _join_quoted(argv)]
        target = None
        if ">" in argv:
            argv, target = argv[: argv.index(">")], argv[argv.index(">") + 1]
        status, out, err = run(capsys, *argv)
        assert status == 0, (line, err)
        if target:
            (tmp_path / target).write_text(out)


def _join_quoted(parts):
    out, buffer = [], None
    for part in parts:
        if buffer is not None:
            buffer += " " + part
            if part.endswith('"'):
                out.append(buffer)
                buffer = None
        elif part.startswith('"') and not part.endswith('"'):
            buffer = part
        else:
            out.append(part)
    return out


def test_dir_lists_the_public_api():
    names = dir(plans)
    for name in ("solve", "construct", "compare", "write_drawings", "write_position_sheets", "run_positions",
                 "write_handout", "load", "loads", "find_structure", "PlansError", "__version__"):
        assert name in names
        assert getattr(plans, name) is not None
    assert all(hasattr(plans, name) for name in plans.__all__)


def test_plans_module_runs_as_a_program():
    done = subprocess.run([sys.executable, "-m", "plans", "--version"], capture_output=True, text=True)
    assert done.returncode == 0 and done.stdout.startswith("plans ")
