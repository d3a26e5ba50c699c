"""The README's figures are the program's (issue 21): the examples tables, the first-scene tutorial."""

import re
from pathlib import Path


from plans.cli import main
from plans.scene import example_names, example_path

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text(encoding="utf-8")


def _largest(capsys, argv) -> dict[str, str]:
    assert main(argv) == 0
    out = capsys.readouterr().out
    return dict(re.findall(r"^largest relative difference (graphical|centres) vs analytic: (\S+)", out, re.MULTILINE))


def test_the_bundled_examples_table_gives_what_plans_solve_prints(capsys):
    section = README.split("## Bundled examples", 1)[1].split("\n## ", 1)[0]
    rows = re.findall(r"^\| `([a-z-]+)` \| [^|]+ \| ([^|]+) \| (\S+) \|$", section, re.MULTILINE)
    assert sorted(name for name, _, _ in rows) == sorted(example_names())
    for name, structure, figure in rows:
        printed = _largest(capsys, ["solve", "--example", name])
        assert figure == printed["graphical"], name


def test_the_centres_table_gives_what_plans_solve_prints(capsys):
    section = README.split("## Instant centres", 1)[1].split("\n## ", 1)[0]
    rows = re.findall(r"^\| `([a-z-]+)` \| (\S+) \| (\S+) \|$", section, re.MULTILINE)
    assert sorted(name for name, _, _ in rows) == sorted(example_names())
    for name, centres, graphical in rows:
        printed = _largest(capsys, ["solve", "--example", name])
        assert (centres, graphical) == (printed["centres"], printed["graphical"]), name


def test_no_reference_to_a_document_that_does_not_ship():
    texts = {"README.md": README} | {f"{n}.toml": example_path(n).read_text(encoding="utf-8") for n in example_names()}
    for name, text in texts.items():
        assert "domain.md" not in text and "domain brief" not in text, name


def test_the_first_scene_tutorial_prints_what_it_shows(tmp_path, capsys):
    tutorial = README.split("## Your first scene", 1)[1].split("\n## ", 1)[0]
    assert "plans examples slider-crank > my.toml" in tutorial
    assert main(["examples", "slider-crank"]) == 0
    text = capsys.readouterr().out
    # the changes the tutorial makes, each to a line the bundled scene has
    for key, value in re.findall(r"^ {7}(angle|omega) = (\"[^\"]+\")$", tutorial, re.MULTILINE):
        text, count = re.subn(rf"^{key} = .*$", f"{key} = {value}", text, flags=re.MULTILINE)
        assert count == 1, key
    hint = re.search(r"^ {7}B = (\[.*\])$", tutorial, re.MULTILINE).group(1)
    text, count = re.subn(r"^B = \[.*\]$", f"B = {hint}", text, flags=re.MULTILINE)
    assert count == 1
    scene = tmp_path / "my.toml"
    scene.write_text(text)
    assert main(["solve", str(scene)]) == 0
    out = [" ".join(line.split()) for line in capsys.readouterr().out.splitlines()]
    excerpt = tutorial.split("prints one table (excerpt):", 1)[1].split("Reading it:", 1)[0]
    shown = [" ".join(line.split()) for line in excerpt.splitlines() if line.strip() and "…" not in line]
    assert len(shown) >= 6
    for line in shown:
        if "graphical" in line:  # its abs. and rel. error are round-off: the values before them must match
            assert any(line.split()[:-2] == o.split()[:-2] for o in out), line
        else:
            assert line in out, line
