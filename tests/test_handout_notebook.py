"""Notebook display: solutions, plans and runs show themselves (``_repr_svg_``), plot into an Axes, save."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np
import pypdf
import pytest
from matplotlib.figure import Figure

import plans
from plans.positions import Diagrams, run_positions

SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def graphical():
    return plans.construct(plans.load(plans.example_path("slider-crank")))


def _texts(svg: str) -> list[str]:
    return ["".join(t.itertext()) for t in ET.fromstring(svg.encode("utf-8")).iter(f"{SVG}text")]


def test_a_plan_displays_itself_and_plots_into_a_given_axes(graphical):
    texts = _texts(graphical.velocity_plan._repr_svg_())
    assert "Velocity plan" in texts and "p" in texts  # the heading and the pole
    ax = Figure().add_subplot()
    assert graphical.acceleration_plan.plot(ax, lang="bg") is ax  # .plot returns the Axes, as in matplotlib
    assert ax.lines or ax.patches or ax.collections
    assert "План на ускоренията" in [t.get_text() for t in ax.texts]


def test_a_graphical_solution_shows_its_sheet_and_saves_it_as_pdf(graphical, tmp_path):
    texts = _texts(graphical._repr_svg_())
    assert "Mechanism" in texts and "Velocity plan" in texts and "Acceleration plan" in texts
    path = graphical.save(tmp_path / "sheet.pdf", lang="sl")
    reader = pypdf.PdfReader(path)
    assert len(reader.pages) == 1 and "Načrt hitrosti" in reader.pages[0].extract_text()


def test_runs_and_their_diagrams_display_themselves():
    run = run_positions(plans.load(plans.example_path("four-bar")), 2)
    assert "Mechanism in its positions, with the paths of its points" in _texts(run._repr_svg_())
    assert "Position 1 (2/2)" in " ".join(_texts(run.runs[1]._repr_svg_()))
    diagrams = run.diagrams(lang="ru")
    assert isinstance(diagrams, Diagrams)
    assert diagrams._repr_html_().count("<svg") == 2  # links and points: no prismatic pair
    curves = [c for c in diagrams.plot("v").get_lines() if not c.get_label().startswith("_")]
    # typeset; |v_A| = ω·OA is constant for a crank turning at constant ω: a note, not a flat curve
    assert {c.get_label() for c in curves} == {r"$|v_{\mathrm{B}}|$", r"$|v_{\mathrm{M}}|$"}
    assert np.allclose(curves[0].get_ydata(), np.abs(run.cycle.points["B"].v))
    with pytest.raises(ValueError, match="no diagram of 'jerk'"):
        diagrams.plot("jerk")
