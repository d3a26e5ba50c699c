"""``plans forces -o DIR``, ``plans handout --forces`` and the kinetostatic pages (plans.drawing.forces_page).

The numbers a page states are checked against domain.md §11 (the worked
example), never against the code that drew them.
"""

from __future__ import annotations

import re

import pytest

from plans.cli import main
from plans.drawing.forces_page import draw_forces_pages
from plans.forces.force_plans import construct_force_plans
from plans.graphical import construct
from plans.handout import handout
from plans.i18n import term
from plans.scene import example_path, load

M_B = 620.218316  # domain.md §11
R_12 = 9646.41888


def test_forces_output_draws_every_drawing(tmp_path, capsys):
    assert main(["forces", "--example", "slider-crank-loads", "-o", str(tmp_path), "--format", "svg", "--precision", "0.1"]) == 0
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["force-plan-1.svg", "force-plan-driver.svg", "free-bodies.svg", "lever.svg"]
    plan = (tmp_path / "force-plan-driver.svg").read_text(encoding="utf-8")
    # the driver's plan states M_b read at 0.1 mm within drafting precision of §11's
    found = re.search(r"= ([0-9.]+) N·m", plan)
    assert found and abs(float(found[1]) - M_B) <= 0.01 * M_B
    lever = (tmp_path / "lever.svg").read_text(encoding="utf-8")
    assert "Joukowski" in lever
    out = capsys.readouterr().out
    assert "620.2" in out  # the table is still printed


def test_forces_output_per_position_for_an_at_list(tmp_path):
    assert main(["forces", "--example", "four-bar-loads", "--at", "30 deg, 120 deg", "-o", str(tmp_path)]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["position-0", "position-1"]
    assert (tmp_path / "position-1" / "force-plan-driver.svg").is_file()


def test_forces_output_refused_with_analytic_only(tmp_path, capsys):
    assert main(["forces", "--example", "slider-crank-loads", "--analytic-only", "-o", str(tmp_path / "out")]) == 2
    assert "--analytic-only" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()  # nothing written


def test_handout_forces_refused_without_loads(tmp_path, capsys):
    assert main(["handout", "--example", "slider-crank", "--forces", "-o", str(tmp_path / "h.pdf")]) == 2
    err = capsys.readouterr().err
    assert "no masses and no loads" in err
    assert not (tmp_path / "h.pdf").exists()


def _texts(fig) -> list[str]:
    out = []
    for ax in fig.axes:
        out += [t.get_text() for t in ax.texts]
        out += [a.get_text() for a in ax.get_children() if hasattr(a, "get_text") and a.get_text()]
    return out


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_the_page_states_the_worked_example(lang):
    g = construct(load(example_path("slider-crank-loads")), precision=0.1)
    pages = draw_forces_pages(g, lambda mu: construct_force_plans(g, mu_F=mu), lang=lang, header_lines=["φ = 60°"])
    assert len(pages) == 1  # one group: the free bodies and both plans fit one page
    texts = " ".join(_texts(pages[0]))
    assert term("free_bodies", lang) in texts
    assert f"{term('force_plan', lang)}: RRP(3,4)" in texts
    # the driver's plan names the driving link and what it is, in the reader's words (typed here)
    assert f"{term('force_plan', lang)}: " + {"en": "driving link 2 (crank)", "ru": "ведущее звено 2 (кривошип)"}[lang] in texts
    # R_12 read on the page at its own μ_F, within the page's drafting precision of §11's
    mu = pages[0].force_scales["driver"]
    found = re.search(r"R_\{\\mathrm\{12\}\}\$ = ([0-9.,]+) mm · [0-9.,]+ N/mm = ([0-9.,]+) N", texts)
    assert found, texts
    length, value = (float(x.replace(",", ".")) for x in found.groups())
    assert value == pytest.approx(length * mu, abs=mu * 0.05)  # what the page says is drawn length × μ_F
    assert abs(value - R_12) <= 2 * 0.1 * mu + 9 * 0.1 * g.scales["k_a"]
    # the plan is drawn at the scale the page states: its construction at that μ_F reads the same length
    plan = next(p for p in construct_force_plans(g, mu_F=pages[0].force_scales).plans if p.group == "driver")
    r = next(v for v in plan.vectors if v.label == "R_12")
    assert round(r.length, 1) == pytest.approx(length)


def test_a_crowded_mechanism_gets_a_second_page_for_its_plans():
    g = construct(load(example_path("six-bar-loads")), precision=0.1)
    pages = draw_forces_pages(g, lambda mu: construct_force_plans(g, mu_F=mu), header_lines=["φ"])
    assert len(pages) == 2
    assert pages[0].force_scales == {}
    assert set(pages[1].force_scales) == {"RPR(5,6)", "RRR(3,4)", "driver"}


def test_handout_with_forces_has_the_kinetostatic_pages():
    import xml.etree.ElementTree as ET

    doc = handout(load(example_path("slider-crank-loads")), forces=True)
    assert doc.order[-1] == "forces"
    names = [name for name in doc.images if name.startswith("forces-")]
    assert names == ["forces-0-0", "forces-0-1"]  # the plans' page, then the lever's, placed whole on the plate
    root = ET.fromstring(doc.images["forces-0-1"])
    assert "Joukowski's lever" in " ".join("".join(t.itertext()) for t in root.iter("{http://www.w3.org/2000/svg}text"))


def test_forces_drawings_read_to_a_tenth_of_a_millimetre_unless_told(tmp_path, capsys):
    """As plans draw's sheets: without --precision the table is exact, the drawings read lengths to 0.1 mm."""
    assert main(["forces", "--example", "slider-crank-loads", "-o", str(tmp_path / "a")]) == 0
    assert main(["forces", "--example", "slider-crank-loads", "-o", str(tmp_path / "b"), "--precision", "0"]) == 0
    capsys.readouterr()
    read = (tmp_path / "a" / "force-plan-driver.svg").read_text(encoding="utf-8")
    exact = (tmp_path / "b" / "force-plan-driver.svg").read_text(encoding="utf-8")
    assert re.search(r"= 96\.4 mm · 100 N/mm = 9640 N", read)  # R_12 = 9646.4 N of §11 read to 0.1 mm at 100 N/mm
    assert re.search(r"= 96\.46 mm · 100 N/mm = 9646 N", exact)
