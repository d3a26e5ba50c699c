"""Scale factors that cannot be drawn (issue 12, issue 9 §1): refused with the range that fits.

The expected ranges come from the four-bar example worked here by hand: the
positions by the law of cosines (circle intersection), the velocities from
the loop v_B = v_A + iω₃(B − A) = iω₄(B − D) solved as a 2×2 system.  A figure's
size is the larger side of its bounding box (the mechanism's points; the
velocity plan's pole and images); a factor fits when it draws that size
1 mm … 1165 mm large (A0's long side, 1189 mm, less two 12 mm margins).
"""

from __future__ import annotations

import cmath
import math
import re

import numpy as np
import pytest

from plans.cli import main
from plans.errors import SceneError
from plans.graphical.scales import check_scale
from plans.scene import example_path

SHEET = 1189.0 - 2 * 12.0  # mm, A0 less margins


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def four_bar_by_hand():
    """Points and velocities of the four-bar example at φ = 60°, ω = 10 rad/s."""
    O, D = 0j, 0.22 + 0j
    A = 0.08 * cmath.exp(1j * math.radians(60))
    ab, db = 0.25, 0.2
    d = abs(D - A)
    along = (ab**2 - db**2 + d**2) / (2 * d)
    h = math.sqrt(ab**2 - along**2)
    u = (D - A) / d
    candidates = [A + u * (along + s * 1j * h) for s in (1, -1)]
    B = min(candidates, key=lambda z: abs(z - (0.2 + 0.2j)))  # [assembly] B = [0.2, 0.2]
    M = A + (B - A) / abs(B - A) * (0.1 + 0.06j)
    w2 = 10.0
    vA = 1j * w2 * A
    # iω3(B − A) − iω4(B − D) = −vA, real 2×2 in (ω3, ω4)
    c3, c4 = 1j * (B - A), -1j * (B - D)
    w3, w4 = np.linalg.solve([[c3.real, c4.real], [c3.imag, c4.imag]], [-vA.real, -vA.imag])
    vB = 1j * w4 * (B - D)
    vM = vA + 1j * w3 * (M - A)
    return [O, D, A, B, M], [0j, vA, vB, vM]


def box(zs):
    return max(max(z.real for z in zs) - min(z.real for z in zs), max(z.imag for z in zs) - min(z.imag for z in zs))


def stated_range(err, key):
    match = re.search(rf"{key} from ([0-9.e+-]+) to ([0-9.e+-]+) ", err)
    assert match, err
    return float(match.group(1)), float(match.group(2))


def check_range(err, key, size):
    low, high = stated_range(err, key)
    assert size / SHEET <= low <= size / SHEET * 1.01  # 3 digits, rounded into the range
    assert size * 0.99 <= high <= size


@pytest.mark.parametrize("k", ["1e-300", "5e-324", "1e-30"])
def test_a_tiny_k_l_is_refused_not_reported_as_a_dead_centre(capsys, k):
    status, out, err = run(capsys, "solve", "--example", "four-bar", "--k-l", k)
    assert status == 2 and out == ""
    assert "larger than the largest sheet" in err and "dead" not in err and "nan" not in err, err
    assert err.count("\n") == 1 and "at φ = 60.0°" in err
    points, _ = four_bar_by_hand()
    check_range(err, "k_l", box(points))


def test_a_tiny_k_v_is_refused_with_the_range_of_the_velocity_plan(capsys):
    status, _, err = run(capsys, "solve", "--example", "four-bar", "--k-v", "1e-9")
    assert status == 2
    _, velocities = four_bar_by_hand()
    size = box(velocities)
    assert f"{size / 1e-9:.3g} mm large" in err, err
    check_range(err, "k_v", size)


def test_a_k_l_that_draws_less_than_a_millimetre_is_refused(capsys):
    status, _, err = run(capsys, "solve", "--example", "four-bar", "--k-l", "1000")
    assert status == 2 and "smaller than a millimetre" in err
    points, _ = four_bar_by_hand()
    check_range(err, "k_l", box(points))


def test_factors_just_inside_the_range_are_accepted(capsys):
    points, velocities = four_bar_by_hand()
    for key, option, size in (("k_l", "--k-l", box(points)), ("k_v", "--k-v", box(velocities))):
        for k in (size / SHEET * 1.001, size * 0.999):
            status, out, err = run(capsys, "solve", "--example", "four-bar", option, repr(k))
            assert status == 0, err
            assert f"{key} = {k:g}" in out


def test_draw_with_an_unfit_factor_writes_nothing(capsys, tmp_path):
    for option in (["--k-l", "1e-30"], ["--k-v", "1e-9"], ["--positions", "3", "--k-v", "1e-9"]):
        status, _, err = run(capsys, "draw", "--example", "four-bar", *option, "-o", str(tmp_path / "out"))
        assert status == 2 and "fits" in err
        assert not (tmp_path / "out").exists()


def test_a_scene_scales_factor_is_refused_naming_the_key(capsys, tmp_path):
    scene = tmp_path / "s.toml"
    scene.write_text(example_path("four-bar").read_text() + "\n[scales]\nk_l = 1e-30\n")
    status, _, err = run(capsys, "handout", str(scene), "-o", str(tmp_path / "h" / "h.pdf"))
    assert status == 2
    assert f"{scene}: scales.k_l" in err and "k_l = 1e-30 m/mm" in err
    assert not (tmp_path / "h").exists()


def test_the_limits_are_one_millimetre_and_the_a0_sheet():
    def refused(k, size):
        try:
            check_scale("k_v", k, size, what="the plan", where="here", source=None, field=None)
        except SceneError:
            return True
        return False

    assert not refused(1.0, SHEET) and refused(1.0, SHEET * (1 + 1e-9))
    assert not refused(2.0, 2.0) and refused(2.0, 2.0 * (1 - 1e-9))
    assert not refused(1e-300, 0.0)  # a plan of a mechanism at rest fits any factor
