"""A scene whose linear driver is given a non-zero acceleration at its instant, written out here.

The bundled linear-arm example runs at constant speed (a = 0: the course project's driver, domain.md §10).  This is the
same mechanism with a = 2 m/s² at the scene's instant (the bundled file's numbers until the teachers' reviews of issue
20), for the tests of what the program does with a driver's given acceleration: its term in the loop equations, the
plans and the scheme, the one-position data printing it as given, and the note that a cycle at constant speed does not
use it (``DriverLaw.given_note``).  Written out, not read from the bundled file and patched, so that a change to the
example cannot change what these tests see.
"""

from __future__ import annotations

from pathlib import Path

from plans.scene import Scene, loads

#: linear-arm.toml as it was with ``acceleration = "2 m/s^2"``: v = 0.5 m/s, a = 2 m/s² at s = 0, stroke ±100 mm.
LINEAR_ARM_ACCELERATING = """\
# A linear driver 2 carries a rigid arm AF.  Rod 3, pinned at F, slides in a
# sleeve welded at 60 deg to rocker 4; the sleeve passes through K, off the
# rocker's pivot D.  Block 5 rides on the moving rod and is pinned at H to
# rocker 6: a slider on a turning guide, so Coriolis appears twice.
title = { en = "Linear driver with arm, welded offset sleeve and block on a moving rod", sr = "Шесточлани кулисни механизам са транслаторним погонским чланом", ru = "Шестизвенный кулисный механизм с поступательным ведущим звеном", bg = "Шестзвенен кулисен механизъм с постъпателно водещо звено", sl = "Šestčlenski kulisni mehanizem s translatornim pogonskim členom" }

[names]                    # the guides' names in words on a page, per language
floor = { en = "guide", sr = { name = "вођица", of = "вођице" }, ru = { name = "направляющая", parallel = "направляющей", of = "направляющей" }, bg = { name = "стойка", parallel = "стойката", of = "стойката" }, sl = { name = "vodilo", of = "vodila" } }
rod = { en = "rod", sr = { name = "шипка", of = "шипке" }, ru = { name = "стержень", parallel = "оси стержня", of = "стержня" }, bg = { name = "прът", parallel = "оста на пръта", of = "пръта" }, sl = { name = "palica", of = "palice" } }
sleeve = { en = "sleeve", sr = { name = "чаура", of = "чауре" }, ru = { name = "втулка", parallel = "оси втулки", of = "втулки" }, bg = { name = "втулка", parallel = "оста на втулката", of = "втулката" }, sl = { name = "puša", of = "puše" } }

[frame]
points = { O = [0, 0], D = ["350 mm", "300 mm"], Q = ["200 mm", "50 mm"] }
lines = { floor = { through = "O", angle = 0 } }

[link.2]                   # the driven slide with its arm
points = { A = [0, 0], F = ["100 mm", "150 mm"] }

[link.3]                   # the rod
points = { F = [0, 0], G = ["550 mm", 0] }
lines = { rod = { through = "F", angle = 0 } }

[link.4]                   # rocker with the sleeve welded at 60 deg, through K
points = { D = [0, 0], K = ["100 mm", 0] }
lines = { sleeve = { through = "K", angle = "60 deg" } }

[link.6]                   # rocker carrying the block's pin H
points = { Q = [0, 0], H = ["150 mm", 0] }

[[prismatic]]              # the rod slides in the sleeve
line = "3.rod"
on = "4.sleeve"
name = "sleeve"

[[slider]]                 # block 5 on the rod, pinned at H
pin = "H"
on = "3.rod"
name = "5"

[driver]
slider = "2"
on = "frame.floor"
point = "A"
position = 0
velocity = "0.5 m/s"
acceleration = "2 m/s^2"
stroke = ["-100 mm", "100 mm"]

[assembly]
G = [0.49, 0.25]           # the rod points from F towards the sleeve
H = [0.26, 0.19]
"""


def linear_arm_accelerating() -> Scene:
    """The linear-arm mechanism with the driver's a = 2 m/s² at its instant (:data:`LINEAR_ARM_ACCELERATING`)."""
    return loads(LINEAR_ARM_ACCELERATING, source="linear-arm-accelerating.toml")


def write_linear_arm_accelerating(directory) -> Path:
    """:data:`LINEAR_ARM_ACCELERATING` as a scene file in *directory*, for the CLI's tests."""
    path = Path(directory) / "linear-arm-accelerating.toml"
    path.write_text(LINEAR_ARM_ACCELERATING, encoding="utf-8")
    return path
