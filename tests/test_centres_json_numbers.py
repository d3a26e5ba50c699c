"""The instant centres in the JSON follow the table's number rules: a centre at a pin given in
the scene as "-450 mm", "350 mm" comes back as -0.45, 0.35 (not 0.35000000000000003)."""

import json

from plans.cli import main


def test_centres_at_pins_come_back_as_the_scene_gives_them(capsys):
    assert main(["solve", "--example", "six-bar", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    where = {c["label"]: c["point"] for c in doc["centres"]["list"]}
    assert where["P14"] == [-0.45, 0.35]  # D = ["-450 mm", "350 mm"] in six-bar.toml
    assert where["P16"] == [-0.2, -0.15]  # E = ["-200 mm", "-150 mm"]
    assert where["P12"] == [0.0, 0.0]
