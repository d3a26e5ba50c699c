"""Messages a new user meets (issue 21): output names, file names with newlines, help, huge sizes."""

import pytest

from plans.cli import main


@pytest.mark.parametrize("argv", [
    ["draw", "--example", "four-bar", "-o", "OUT/x.jpg"],
    ["draw", "--example", "four-bar", "--positions", "2", "-o", "OUT/x.png"],
    ["centres", "--example", "four-bar", "-o", "OUT/c.svg"],
    ["sweep", "--example", "four-bar", "--steps", "4", "--plot", "OUT/d.tiff"],
])
def test_output_named_as_a_format_plans_does_not_write_there_is_refused(tmp_path, capsys, argv):
    out = tmp_path / "o"
    out.mkdir()
    assert main([a.replace("OUT", str(out)) for a in argv]) == 2
    err = capsys.readouterr().err
    assert err.startswith("plans: error: ") and err.count("\n") == 1
    name = argv[-1].split("/")[-1]
    assert name in err and "directory" in err
    assert list(out.iterdir()) == []  # nothing created


def test_existing_directory_with_a_suffix_is_still_a_directory(tmp_path, capsys):
    out = tmp_path / "drawings.png"
    out.mkdir()
    assert main(["centres", "--example", "four-bar", "-o", str(out)]) == 0
    assert (out / "centres.svg").exists()


@pytest.mark.parametrize("command", [["solve"], ["sweep"], ["centres"], ["draw", "-o", "OUT/d"], ["handout", "-o", "OUT/h.pdf"]])
def test_a_file_name_with_a_newline_keeps_the_error_on_one_line(tmp_path, capsys, command):
    scene = tmp_path / "my\nscene.toml"
    scene.write_text('title = "x"\n[frame\n')
    argv = [a.replace("OUT", str(tmp_path)) for a in command[:1]] + [str(scene)] + [a.replace("OUT", str(tmp_path)) for a in command[1:]]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("plans: error: ")
    assert "my\\nscene.toml" in err


def test_centres_help_has_a_description_and_an_example(capsys):
    with pytest.raises(SystemExit):
        main(["centres", "--help"])
    out = capsys.readouterr().out
    assert "Kennedy's theorem" in out.split("positional arguments")[0]
    assert "example:\n  plans centres --example" in out


def test_a_scale_factor_too_small_to_compute_names_no_infinity(capsys):
    assert main(["solve", "--example", "four-bar", "--k-l", "5e-324"]) == 2
    err = capsys.readouterr().err
    assert "inf" not in err.replace("information", "")
    assert "larger than 1.8e+308 mm" in err
