"""Notebook display: solutions, plans and runs show themselves (``_repr_svg_``), plot into an Axes, save."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np
import pypdf
import pytest
from matplotlib.figure import Figure

import plans
from plans import notebook
from plans.positions import Diagrams, run_positions

SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def graphical():
    return plans.construct(plans.load(plans.example_path("slider-crank")))


def _texts(svg: str) -> list[str]:
    return ["".join(t.itertext()) for t in ET.fromstring(svg.encode("utf-8")).iter(f"{SVG}text")]


def test_a_plan_displays_as_svg_and_plots_into_a_given_axes(graphical):
    texts = _texts(notebook.svg(graphical.velocity_plan))
    assert "Velocity plan" in texts and "p" in texts  # the heading and the pole
    ax = Figure().add_subplot()
    assert notebook.plot(graphical.acceleration_plan, ax, lang="bg") is ax  # returns the Axes, as in matplotlib
    assert graphical.acceleration_plan.plot(Figure().add_subplot(), lang="bg").texts  # the method is the same function
    assert ax.lines or ax.patches or ax.collections
    assert "План на ускоренията" in [t.get_text() for t in ax.texts]


def test_a_graphical_solution_shows_its_sheet_and_saves_it_as_pdf(graphical, tmp_path):
    from sheet_pages import by_kind, text

    page = notebook.svg(graphical).encode("utf-8")  # a Typst page: the drawings embedded, the words as glyphs
    assert {"mechanism", "velocity", "acceleration"} <= set(by_kind(page))
    words = " ".join(text(notebook.sheet(graphical).pdf()).split())
    assert "Mechanism" in words and "Velocity plan" in words and "Acceleration plan" in words
    path = notebook.save(graphical, tmp_path / "sheet.pdf", lang="sl")
    reader = pypdf.PdfReader(path)
    assert len(reader.pages) == 1 and "Načrt hitrosti" in reader.pages[0].extract_text()


def test_runs_and_their_diagrams_display_themselves():
    run = run_positions(plans.load(plans.example_path("four-bar")), 2)
    assert "Mechanism in its positions, with the paths of its points" in _texts(run._repr_svg_())
    from sheet_pages import by_kind, text

    assert "mechanism" in by_kind(run.runs[1]._repr_svg_().encode("utf-8"))
    assert "Position 1: φ2 =" in " ".join(text(run.runs[1].sheet().pdf()).split())
    diagrams = run.diagrams(lang="ru")
    assert isinstance(diagrams, Diagrams)
    assert diagrams._repr_html_().count("<svg") == 2  # links and points: no prismatic pair
    curves = [c for c in diagrams.plot("v").get_lines() if not c.get_label().startswith("_")]
    # typeset; |v_A| = ω·OA is constant for a crank turning at constant ω: a note, not a flat curve
    assert {c.get_label() for c in curves} == {r"$|v_{\mathrm{B}}|$", r"$|v_{\mathrm{M}}|$"}
    assert np.allclose(curves[0].get_ydata(), np.abs(run.cycle.points["B"].v))
    with pytest.raises(ValueError, match="no diagram of 'jerk'"):
        diagrams.plot("jerk")


class _Formatter:
    def __init__(self):
        self.named = []

    def for_type_by_name(self, module, name, function):
        self.named.append((module, name, function))


def test_ipython_is_told_to_show_solutions_and_plans_as_svg(graphical):
    formatter = _Formatter()
    shell = type("Shell", (), {})()
    shell.display_formatter = type("DisplayFormatter", (), {"formatters": {"image/svg+xml": formatter}})()
    assert notebook.register(shell)
    named = {(module, name): function for module, name, function in formatter.named}
    # the names registered are where the classes really live
    assert set(named) == {(type(graphical).__module__, "GraphicalSolution"), (type(graphical.velocity_plan).__module__, "Plan")}
    assert "Velocity plan" in _texts(named[(type(graphical).__module__, "Plan")](graphical.velocity_plan))
    assert notebook.register() is False or "IPython" in __import__("sys").modules  # no shell outside IPython
