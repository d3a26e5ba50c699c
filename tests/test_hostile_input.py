"""Hostile scene input (issue 12): deep nesting, endless or huge files, huge scenes.

Each case ends with one line on stderr naming the file, exit status 2, and no
traceback, in bounded time and memory.  The coincident-points check is
compared with an all-pairs computation written here (the definition: two
points of one body equal, or closer than COINCIDENT × the largest distance
between two points of the scene).
"""

from __future__ import annotations

import itertools
import math
import os
import random

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from plans.cli import main
from plans.errors import SceneError
from plans.scene import MAX_LINKS, MAX_NESTING, MAX_POINTS, MAX_SCENE_BYTES, diameter, example_path, loads

FOUR_BAR = example_path("four-bar").read_text(encoding="utf-8")


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def one_line_error(status, out, err, *words):
    assert status == 2, err
    assert out == ""
    assert err.count("\n") == 1 and err.startswith("plans: error: "), err
    assert "Traceback" not in err
    for word in words:
        assert word in err, (word, err)


def chain(n: int) -> str:
    """A driver and n crank-rocker stages in a row: stage k is driven by the arm Q(k-1) of the rocker before it."""
    frame = ["O = [0, 0]"] + [f"D{k} = [{0.22 * k!r}, 0]" for k in range(1, n + 1)]
    lines = ['title = "chain"', "[frame]", "points = { " + ", ".join(frame) + " }", "[link.2]", "points = { O = [0, 0], Q0 = [0.08, 0] }"]
    for k in range(1, n + 1):
        lines += [
            f"[link.{2 * k + 1}]",
            f"points = {{ Q{k - 1} = [0, 0], B{k} = [0.25, 0] }}",
            f"[link.{2 * k + 2}]",
            f"points = {{ D{k} = [0, 0], B{k} = [0.2, 0], Q{k} = [0, 0.08] }}",
        ]
    lines += ["[driver]", 'crank = "2"', 'angle = "60 deg"', "omega = 10"]
    return "\n".join(lines) + "\n"


def with_frame_points(points: list[tuple[float, float]], text: str = FOUR_BAR) -> str:
    extra = ", ".join(f"F{k} = [{x!r}, {y!r}]" for k, (x, y) in enumerate(points))
    return text.replace("points = { O = [0, 0]", "points = { " + extra + ", O = [0, 0]", 1)


# --- deep nesting -------------------------------------------------------------------------


@pytest.mark.parametrize("depth", [MAX_NESTING + 1, 1000, 5000, 100_000])
@pytest.mark.parametrize("kind", ["array", "inline table"])
def test_deep_nesting_is_refused_naming_the_file(capsys, tmp_path, depth, kind):
    value = "[" * depth + "]" * depth if kind == "array" else "{a = " * depth + "1" + "}" * depth
    path = tmp_path / "deep.toml"
    path.write_text(FOUR_BAR.replace("[frame]", f"junk = {value}\n[frame]", 1))
    one_line_error(*run(capsys, "solve", str(path)), str(path), "nested more than 32 deep")


def test_nesting_a_real_scene_uses_is_accepted_and_a_little_more_is_not():
    assert loads(FOUR_BAR).title.startswith("Crank-rocker")
    with pytest.raises(SceneError, match="nested more than"):
        loads(FOUR_BAR + "\n[compute]\npoints = " + "[" * 40 + "]" * 40 + "\n")


# --- files that never end, or are huge ------------------------------------------------------


def test_dev_zero_is_refused_without_reading_it(capsys):
    one_line_error(*run(capsys, "solve", "/dev/zero"), "/dev/zero", "not a regular file")


def test_a_fifo_is_refused_without_waiting_for_a_writer(capsys, tmp_path):
    fifo = tmp_path / "scene.toml"
    os.mkfifo(fifo)  # opening it for reading would block until someone writes to it
    one_line_error(*run(capsys, "solve", str(fifo)), str(fifo), "not a regular file")


def test_a_directory_is_refused(capsys, tmp_path):
    one_line_error(*run(capsys, "solve", str(tmp_path)), str(tmp_path), "directory")


def test_a_file_over_one_megabyte_is_refused_and_one_under_is_read(capsys, tmp_path):
    assert MAX_SCENE_BYTES == 1_000_000  # the README says 1 MB
    under = tmp_path / "under.toml"
    padding = "#" * 100 + "\n"
    text = FOUR_BAR + padding * ((MAX_SCENE_BYTES - len(FOUR_BAR.encode())) // len(padding))
    under.write_text(text)
    assert MAX_SCENE_BYTES - 101 < under.stat().st_size <= MAX_SCENE_BYTES
    status, out, _ = run(capsys, "solve", "--analytic-only", str(under))
    assert status == 0 and "RRR(3,4)" in out
    over = tmp_path / "over.toml"
    over.write_text(text + "#" * (MAX_SCENE_BYTES + 1 - len(text.encode())))
    assert over.stat().st_size == MAX_SCENE_BYTES + 1
    one_line_error(*run(capsys, "solve", str(over)), str(over), "larger than 1 MB")


# --- the coincident-points check ------------------------------------------------------------


def brute_diameter(zs):
    return max((abs(a - b) for a, b in itertools.combinations(zs, 2)), default=0.0)


coordinate = st.one_of(
    st.integers(-4, 4).map(float),  # many exact ties and collinear triples
    st.floats(-1e3, 1e3, allow_nan=False, allow_infinity=False),
    st.sampled_from([1e-300, -1e-300, 5e-324, 1e300 / 3, 0.1, 0.2, 0.3]),
)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(coordinate, coordinate), max_size=30), st.floats(0, math.pi), st.booleans())
def test_the_diameter_is_the_largest_distance_of_all_pairs(points, angle, collinear):
    if collinear:  # nearly collinear after rounding: the case a floating-point hull gets wrong
        direction = complex(math.cos(angle), math.sin(angle))
        zs = [direction * x + complex(y, y) * 1e-3 for x, y in points]
    else:
        zs = [complex(x, y) for x, y in points]
    assert diameter(zs) == brute_diameter(zs)


@pytest.mark.parametrize("seed", range(3))
def test_coincident_frame_points_are_found_among_many(seed):
    """1500 random frame points, one pair made equal / 0.5e-12 of the size apart / 2e-12 apart."""
    rnd = random.Random(seed)
    points = [(rnd.uniform(-1, 1), rnd.uniform(-1, 1)) for _ in range(1500)]
    i, j = sorted(rnd.sample(range(len(points)), 2))
    exact = list(points)
    exact[j] = exact[i]
    with pytest.raises(SceneError, match=rf"points F{i} and F{j} of the frame coincide"):
        loads(with_frame_points(exact))
    size = brute_diameter([complex(*p) for p in points] + [0j, 0.22 + 0j])  # the scene's size, all pairs
    near, far = list(points), list(points)
    near[j] = (points[i][0] + 0.5e-12 * size, points[i][1])
    far[j] = (points[i][0] + 2e-12 * size, points[i][1])
    assert brute_diameter([complex(*p) for p in near] + [0j, 0.22 + 0j]) == pytest.approx(size, rel=1e-12)
    with pytest.raises(SceneError, match=rf"points F{i} and F{j} of the frame are .* apart"):
        loads(with_frame_points(near))
    loads(with_frame_points(far))  # 2e-12 of the size apart is two points


def test_the_check_compares_points_of_one_body_only():
    # a frame point where a link's point is (in its own coordinates) is no coincidence
    loads(with_frame_points([(0.08, 0.0), (0.25, 0.0)]))


# --- scenes beyond the documented size ---------------------------------------------------------


def test_ten_thousand_frame_points_are_refused_with_the_limit(capsys, tmp_path):
    rnd = random.Random(1)
    path = tmp_path / "many.toml"
    path.write_text(with_frame_points([(round(rnd.random(), 9), round(rnd.random(), 9)) for _ in range(10_000)]))
    one_line_error(*run(capsys, "solve", str(path)), str(path), f"at most {MAX_POINTS:,}", "10,009 points")


def test_a_scene_at_the_point_limit_is_accepted():
    rnd = random.Random(2)
    loads(with_frame_points([(rnd.random(), rnd.random()) for _ in range(MAX_POINTS - 9)]))


def test_a_chain_beyond_the_link_limit_is_refused_and_one_within_solves(capsys, tmp_path):
    assert MAX_LINKS == 200
    path = tmp_path / "long.toml"
    path.write_text(chain(100))  # 1 + 2 × 100 = 201 links
    one_line_error(*run(capsys, "solve", str(path)), str(path), "201 links", "at most 200")
    path.write_text(chain(99))  # 199 links
    status, out, _ = run(capsys, "solve", "--analytic-only", str(path))
    assert status == 0 and "RRR(197,198)" in out
