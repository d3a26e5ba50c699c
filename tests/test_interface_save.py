"""PNG wherever SVG or PDF is accepted; one meaning of .save(path); .plot returns the Axes (issue 9 §3)."""

import pypdf
import pytest
from matplotlib.axes import Axes
from matplotlib.figure import Figure

import plans
from plans.cli import main
from plans.drawing.formats import PNG_DPI
from plans.positions import run_positions

PNG = b"\x89PNG\r\n\x1a\n"


def png_size(path):
    data = path.read_bytes()
    assert data[:8] == PNG
    return int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")


@pytest.fixture(scope="module")
def run():
    return run_positions(plans.load(plans.example_path("four-bar")), 2)


@pytest.fixture(scope="module")
def graphical():
    return plans.construct(plans.load(plans.example_path("slider-crank")))


@pytest.mark.parametrize("suffix, magic", [(".svg", b"<?xml"), (".pdf", b"%PDF-"), (".png", PNG)])
def test_every_result_saves_one_file_in_the_format_of_its_suffix(run, graphical, tmp_path, suffix, magic):
    for name, obj in [("position", run.runs[1]), ("positions", run), ("sheet", graphical),
                      ("velocity", graphical.velocity_plan), ("acceleration", graphical.acceleration_plan)]:
        path = tmp_path / f"{name}{suffix}"
        written = obj.save(path)
        assert written == path and path.is_file() and path.read_bytes().startswith(magic), name
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(f"{n}{suffix}" for n in ("position", "positions", "sheet", "velocity", "acceleration"))


def test_png_is_drawn_at_its_documented_resolution(graphical, tmp_path):
    from plans.drawing.svg import svg_size_mm

    graphical.velocity_plan.save(tmp_path / "v.png")
    graphical.velocity_plan.save(tmp_path / "v.svg")
    width_mm, height_mm = svg_size_mm((tmp_path / "v.svg").read_bytes())
    width, height = png_size(tmp_path / "v.png")
    assert width == pytest.approx(width_mm / 25.4 * PNG_DPI, abs=1)
    assert height == pytest.approx(height_mm / 25.4 * PNG_DPI, abs=1)


def test_cycle_diagrams_save_to_one_pdf_or_a_file_a_page(run, tmp_path):
    diagrams = run.diagrams()
    (path,) = diagrams.save(tmp_path / "diagrams.pdf")
    assert len(pypdf.PdfReader(path).pages) == 2  # links and points (no prismatic pair)
    paths = diagrams.save(tmp_path / "diagrams.png")
    assert [p.name for p in paths] == ["diagrams-links.png", "diagrams-points.png"]
    assert all(p.read_bytes().startswith(PNG) for p in paths)
    assert not (tmp_path / "diagrams.png").exists()  # not a directory named diagrams.png either


@pytest.mark.parametrize("bad", ["sheet", "sheet.jpg", "out/"])
def test_a_path_without_a_drawing_suffix_is_refused(run, tmp_path, bad):
    with pytest.raises(ValueError, match=r"write a drawing as \.svg, \.pdf or \.png"):
        run.runs[0].save(tmp_path / bad)
    with pytest.raises(ValueError, match=r"write a drawing as \.svg, \.pdf or \.png"):
        run.diagrams().save(tmp_path / bad)
    assert list(tmp_path.iterdir()) == []


def test_plot_returns_the_axes(run, graphical):
    for obj in (graphical, graphical.velocity_plan, run, run.runs[0]):
        ax = obj.plot()
        assert isinstance(ax, Axes) and (ax.lines or ax.patches or ax.collections or ax.texts)
        given = Figure().add_subplot()
        assert obj.plot(given) is given
    ax = run.diagrams().plot("omega")
    assert isinstance(ax, Axes) and ax.get_lines()
    given = Figure().add_subplot()
    assert run.diagrams().plot("v", given) is given


def test_draw_writes_png_through_the_cli(tmp_path, capsys):
    assert main(["draw", "--example", "ladder", "-o", str(tmp_path / "d"), "--format", "png"]) == 0
    names = sorted(p.name for p in (tmp_path / "d").iterdir())
    assert names == ["acceleration.png", "mechanism.png", "sheet.png", "velocity.png"]
    assert main(["draw", "--example", "ladder", "-o", str(tmp_path / "page.png")]) == 0
    assert png_size(tmp_path / "page.png")[0] > 500
    assert main(["draw", "--example", "ladder", "--positions", "2", "-o", str(tmp_path / "p.png")]) == 2
    assert "give a directory" in capsys.readouterr().err


def test_handout_pages_and_cycle_diagrams_as_png(tmp_path, capsys):
    assert main(["handout", "--example", "ladder", "-o", str(tmp_path / "h.png")]) == 0
    pages = sorted(p.name for p in tmp_path.glob("h*.png"))
    assert pages[:2] == ["h-01.png", "h-02.png"] and "h.png" not in pages  # one file a page, numbered as SVG pages are
    assert all((tmp_path / p).read_bytes().startswith(PNG) for p in pages)
    assert main(["sweep", "--example", "wedge", "--steps", "12", "-o", str(tmp_path / "w.csv"),
                 "--plot", str(tmp_path / "d"), "--format", "png"]) == 0
    assert sorted(p.name for p in (tmp_path / "d").iterdir()) == ["kinematic.png", "links.png", "points.png", "sliders.png"]  # and the output link's kinematic diagrams
    assert all(p.read_bytes().startswith(PNG) for p in (tmp_path / "d").iterdir())
