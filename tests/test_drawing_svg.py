"""The drawings as SVG files: labels, physical size, components present, determinism, atomic writing.

Everything is read back from the SVG's XML or from the artists' data; no pixels.
"""

from __future__ import annotations

import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

import drawing_fixtures as F
from plans.drawing import draw_mechanism, draw_plan
from plans.drawing import sheet as sheet_module
from plans.pages import sheet as pages_sheet
from plans.pages.sheet import sheet_at, write_drawings
from plans.drawing.mechanism import mechanism_labels
from plans.drawing.svg import render_svg, svg_size_mm

SVG = "{http://www.w3.org/2000/svg}"
MM_TOL = 1e-3  # mm, rounding of the width/height attributes


@pytest.fixture(scope="module")
def drawn(tmp_path_factory):
    """write_drawings for every fixture, once: name -> (solution, directory)."""
    out = {}
    for name in ("slider_crank", "quick_return", "ladder"):
        solution = getattr(F, name)()
        directory = tmp_path_factory.mktemp(name)
        write_drawings(solution, directory)
        out[name] = (solution, directory)
    return out


def texts(path: Path) -> list[str]:
    root = ET.parse(path).getroot()
    return ["".join(t.itertext()) for t in root.iter(f"{SVG}text")]


def ids(path: Path) -> list[str]:
    root = ET.parse(path).getroot()
    return [e.get("id") for e in root.iter() if e.get("id")]


# -- labels ----------------------------------------------------------------


@pytest.mark.parametrize("name", ["slider_crank", "quick_return", "ladder"])
def test_every_reported_point_and_frame_pivot_is_labelled_on_the_mechanism(drawn, name):
    solution, directory = drawn[name]
    found = texts(directory / "mechanism.svg")
    wanted = set(solution.scene.report) | {"O"} if name != "ladder" else set(solution.scene.report)
    assert wanted <= set(mechanism_labels(solution))
    for point in wanted:
        assert point in found, f"{point} not labelled on the mechanism of {name}"


def test_only_reported_points_and_pivots_are_labelled(drawn):
    solution, directory = drawn["ladder"]
    found = set(texts(directory / "mechanism.svg"))
    assert "W" not in found  # a frame point no link uses is not a pivot


@pytest.mark.parametrize("name", ["slider_crank", "quick_return", "ladder"])
@pytest.mark.parametrize("which", ["velocity", "acceleration"])
def test_every_image_and_the_pole_are_labelled_on_the_plan(drawn, name, which):
    solution, directory = drawn[name]
    plan = getattr(solution, f"{which}_plan")
    if plan is None:
        assert not (directory / f"{which}.svg").exists()
        return
    found = texts(directory / f"{which}.svg")
    assert plan.pole in found
    labelled = ids(directory / f"{which}.svg")
    for image in plan.images:
        tag = "vel" if which == "velocity" else "acc"
        assert f"{tag}-image-{image.rstrip('′')}" in labelled or image == plan.pole, f"image {image} missing on the {which} plan of {name}"


def test_scale_factors_are_stated(drawn):
    _, directory = drawn["slider_crank"]

    def squeezed(path):  # the symbol is typeset (k, then the subscript as a glyph of its own): compare without spaces
        return ["".join(t.split()) for t in texts(path)]

    assert "kl=0.002m/mm" in squeezed(directory / "mechanism.svg")
    assert "kv=0.5(m/s)/mm" in squeezed(directory / "velocity.svg")
    assert "ka=100(m/s²)/mm" in squeezed(directory / "acceleration.svg")


# -- true to scale -----------------------------------------------------------


def _axes_of(artists):
    return artists[0].axes


@pytest.mark.parametrize("name", ["slider_crank", "quick_return", "ladder"])
def test_mechanism_svg_is_sized_in_mm_from_the_data_extent_at_k_l(name):
    solution = getattr(F, name)()
    artists = draw_mechanism(solution)
    ax = _axes_of(artists)
    data = render_svg(ax.figure)
    width, height = svg_size_mm(data)
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    # the axes fills the page and one data unit is one millimetre
    assert width == pytest.approx(x1 - x0, abs=MM_TOL)
    assert height == pytest.approx(y1 - y0, abs=MM_TOL)
    # and the data are the positions divided by k_l
    k_l = solution.scales["k_l"]
    for z in solution.positions.values():
        assert x0 < z.real / k_l < x1 and y0 < z.imag / k_l < y1
    # a length L [m] measures L / k_l mm on paper: transform two points into points (1/72 in)
    first, last = list(solution.positions.values())[0], list(solution.positions.values())[-1]
    a, b = first / k_l, last / k_l
    pa, pb = ax.transData.transform([(a.real, a.imag), (b.real, b.imag)])
    drawn_mm = ((pa[0] - pb[0]) ** 2 + (pa[1] - pb[1]) ** 2) ** 0.5 * 25.4 / 72
    assert drawn_mm == pytest.approx(abs(first - last) / k_l, rel=1e-9)


def test_svg_root_declares_mm():
    data = render_svg(draw_plan(F.slider_crank().velocity_plan)[0].figure).decode()
    root = ET.fromstring(data)
    assert root.get("width").endswith("mm") and root.get("height").endswith("mm")
    vb = [float(v) for v in root.get("viewBox").split()]
    assert float(root.get("width")[:-2]) == pytest.approx(vb[2] * 25.4 / 72, abs=MM_TOL)


@pytest.mark.parametrize("point, which", [("A", "velocity"), ("B", "velocity"), ("A", "acceleration"), ("B", "acceleration")])
def test_tip_of_an_absolute_vector_lands_at_pole_plus_value_over_k(point, which):
    solution = F.slider_crank()
    plan = getattr(solution, f"{which}_plan")
    key = "v" if which == "velocity" else "a"
    prefix = "vel" if which == "velocity" else "acc"
    artists = draw_plan(plan)
    head = next(a for a in artists if a.get_gid() == f"{prefix}-absolute-{key}_{point}-head")
    tip = complex(*head.get_xy()[0])
    expected = 0j + complex(solution.points[point][key]) / plan.scale  # pole at 0
    assert abs(tip - expected) < 1e-9
    # and on paper: the pole-to-tip distance in points is |v| / k mm
    ax = head.axes
    p0, p1 = ax.transData.transform([(0, 0), (tip.real, tip.imag)])
    measured = ((p1[0] - p0[0]) ** 2 + (p1[1] - p0[1]) ** 2) ** 0.5 * 25.4 / 72
    assert measured == pytest.approx(abs(solution.points[point][key]) / plan.scale, rel=1e-9)


# -- what is shown only when present ----------------------------------------


def test_coriolis_only_when_the_plan_has_one(drawn):
    _, with_k = drawn["quick_return"]
    _, without_k = drawn["slider_crank"]
    assert any("coriolis" in i for i in ids(with_k / "acceleration.svg"))
    assert "Coriolis component aᵏ" in texts(with_k / "acceleration.svg")
    assert not any("coriolis" in i for i in ids(without_k / "acceleration.svg"))
    assert not any("Coriolis" in t for t in texts(without_k / "acceleration.svg"))


def test_no_tangential_on_a_velocity_plan_and_legend_lists_only_kinds_present(drawn):
    for name in ("slider_crank", "quick_return"):
        solution, directory = drawn[name]
        for which in ("velocity", "acceleration"):
            plan = getattr(solution, f"{which}_plan")
            present = {v.kind for v in plan.vectors if v.length > 0}
            found = ids(directory / f"{which}.svg")
            legend = {i.split("legend-text-")[1] for i in found if "legend-text-" in i}
            assert legend == present | {"construction"}
            for kind in ("normal", "tangential", "coriolis", "relative"):
                drawn_kind = any(i.startswith(f"{which[:3]}-{kind}-") for i in found)
                assert drawn_kind == (kind in present), (name, which, kind)


def test_zero_length_vector_is_not_drawn_nor_in_the_legend():
    import dataclasses

    from plans.graphical.plan import PlanVector

    solution = F.slider_crank()
    plan = solution.acceleration_plan
    zero = PlanVector(plan.images["b′"], plan.images["b′"], "coriolis", "a^k_B", 0.0)
    plan = dataclasses.replace(plan, vectors=plan.vectors + (zero,))
    artists = draw_plan(plan)
    gids = [a.get_gid() or "" for a in artists]
    assert not any("coriolis" in g for g in gids)
    assert "Coriolis component aᵏ" not in [a.get_text() for a in artists if hasattr(a, "get_text")]


def test_no_acceleration_svg_without_an_acceleration_plan(drawn, tmp_path):
    _, directory = drawn["ladder"]
    assert sorted(p.name for p in directory.iterdir()) == ["mechanism.svg", "sheet.svg", "velocity.svg"]
    # a stale one from an earlier run with accelerations goes (one plans wrote: a user's own file stays,
    # tests/test_hostile_outputs.py)
    write_drawings(F.quick_return(), tmp_path)
    assert (tmp_path / "acceleration.svg").exists()
    paths = write_drawings(F.ladder(), tmp_path)
    assert [p.name for p in paths] == ["mechanism.svg", "velocity.svg", "sheet.svg"]
    assert not (tmp_path / "acceleration.svg").exists()


def test_write_drawings_returns_the_four_paths(drawn):
    _, directory = drawn["quick_return"]
    assert sorted(p.name for p in directory.iterdir()) == ["acceleration.svg", "mechanism.svg", "sheet.svg", "velocity.svg"]


# -- the sheet ---------------------------------------------------------------


def _pdf_text(sheet) -> str:
    import io
    import unicodedata

    from pypdf import PdfReader

    return " ".join(unicodedata.normalize("NFKC", PdfReader(io.BytesIO(sheet.pdf())).pages[0].extract_text()).split())


def test_sheet_has_title_formula_equations_and_table(tmp_path):
    from plans.analytic import solve
    from plans.graphical import construct
    from plans.scene import example_path, load

    solution = construct(load(example_path("quick-return")))
    sheet = sheet_at(solution, solve(solution.scene))
    found = _pdf_text(sheet)
    assert "Crank and slotted lever quick-return" in found  # the example's title
    # the structural formula as the course writes it: RPR is a group of class II, kind 3; RRP kind 2
    assert "Structural formula: I(1,2) → II3(3,4) → II2(5,6)" in found
    assert "Vector equations: velocity plan" in found
    for cell in ("quantity", "graphical", "analytic", "rel. error"):
        assert cell in found
    write_drawings(F.quick_return(), tmp_path)
    width, height = svg_size_mm((tmp_path / "sheet.svg").read_bytes())
    assert (round(width), round(height)) == (420, 297)  # A3 landscape


def test_sheet_equations_default_to_the_plan_steps():
    lines = sheet_module.sheet_equations(F.slider_crank())
    assert lines[1] == "RRP(3,4):  v_B = v_A + v_BA;   v_B = v_B0 + v_BB0"
    assert len(lines) == 4


def test_cyrillic_title_is_written_as_text(tmp_path):
    import dataclasses

    solution = F.slider_crank()
    solution = dataclasses.replace(solution, scene=dataclasses.replace(solution.scene, title="План брзина — кривајни механизам", titles={}))  # a plain title, in every language
    assert "План брзина — кривајни механизам" in _pdf_text(sheet_at(solution))


# -- determinism and atomic writing ----------------------------------------


def test_two_runs_give_identical_bytes(tmp_path):
    a, b = tmp_path / "a", tmp_path / "b"
    write_drawings(F.quick_return(), a)
    write_drawings(F.quick_return(), b)
    for name in ("mechanism.svg", "velocity.svg", "acceleration.svg", "sheet.svg"):
        assert (a / name).read_bytes() == (b / name).read_bytes(), name


def test_identical_bytes_across_processes(tmp_path):
    code = (
        "import sys; sys.path.insert(0, 'tests'); import drawing_fixtures as F;"
        "from plans import write_drawings; write_drawings(F.slider_crank(), sys.argv[1])"
    )
    root = Path(__file__).resolve().parent.parent
    env = dict(os.environ, PYTHONPATH=str(root), PYTHONHASHSEED="123")
    subprocess.run([sys.executable, "-c", code, str(tmp_path / "sub")], cwd=root, env=env, check=True)
    write_drawings(F.slider_crank(), tmp_path / "here")
    for name in ("mechanism.svg", "velocity.svg", "acceleration.svg", "sheet.svg"):
        assert (tmp_path / "sub" / name).read_bytes() == (tmp_path / "here" / name).read_bytes(), name


def test_a_failing_sheet_leaves_existing_files_untouched_and_no_temporaries(tmp_path, monkeypatch):
    for name in ("mechanism.svg", "velocity.svg", "acceleration.svg", "sheet.svg"):
        (tmp_path / name).write_text(f"good {name}")

    def broken(*args, **kwargs):
        raise RuntimeError("sheet failed")

    monkeypatch.setattr(pages_sheet, "sheet_at", broken)
    with pytest.raises(RuntimeError, match="sheet failed"):
        write_drawings(F.slider_crank(), tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["acceleration.svg", "mechanism.svg", "sheet.svg", "velocity.svg"]
    for name in ("mechanism.svg", "velocity.svg", "acceleration.svg", "sheet.svg"):
        assert (tmp_path / name).read_text() == f"good {name}"


def test_a_failing_write_removes_its_temporaries(tmp_path, monkeypatch):
    from plans import _files as svg  # the atomic writer the drawings use

    (tmp_path / "mechanism.svg").write_text("good")
    real_replace = os.replace
    calls = []

    def failing_replace(src, dst):
        calls.append(dst)
        raise OSError("disk full")

    monkeypatch.setattr(svg.os, "replace", failing_replace)
    with pytest.raises(OSError, match="disk full"):
        write_drawings(F.slider_crank(), tmp_path)
    monkeypatch.setattr(svg.os, "replace", real_replace)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mechanism.svg"]
    assert (tmp_path / "mechanism.svg").read_text() == "good"


def test_written_files_are_readable_by_others(tmp_path):
    paths = write_drawings(F.ladder(), tmp_path)
    for path in paths:
        assert path.stat().st_mode & 0o044 == 0o044


def test_coincident_point_images_carry_the_link_as_a_subscript(tmp_path):
    from plans.graphical import construct
    from plans.scene import example_path, load

    solution = construct(load(example_path("six-bar")))
    write_drawings(solution, tmp_path)
    found = texts(tmp_path / "acceleration.svg")
    assert "e₅′" in found and "e5′" not in found  # the point of rod 5 at the sleeve's pin E
    assert "c′" in found
