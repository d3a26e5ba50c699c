"""Which positions' acceleration plans a handout draws by default (issue 20, round 12's blocking finding).

The quick-return's lever stands upright in the middle of each stroke (positions 4 and 10 of 12): its plans there
collapse onto a line (π a₄′ along π d′, the Coriolis component 0.08 mm and under 0.01 mm at the plate's k_a) and
nothing on them can be measured.  The reviewer asked for a general position of each stroke, "2 and 9": one of the
working and one of the idle stroke, each with every component long enough to measure.
"""

import pytest

from plans.pages.handout import choose_accelerations, stroke_phases
from plans.positions import run_positions
from plans.scene import example_path, load
from review_handouts import built

#: the shortest component a student can measure on a plan [mm] (a ruler's millimetre)
MEASURABLE_MM = 1.0


def test_the_quick_return_draws_the_reviewers_positions():
    run = run_positions(load(example_path("quick-return")), 12)
    assert choose_accelerations(run, None) == [2, 9]
    phases = stroke_phases(run)
    assert [phases[k][0] for k in (2, 9)] == ["working", "idle"]
    # what a user asks for is drawn as asked, the collapsed positions too
    assert choose_accelerations(run, [4, 10]) == [4, 10]


@pytest.mark.parametrize("example, lang", [("quick-return", "sr"), ("six-bar", "en"), ("four-bar", "ru")])
def test_every_component_on_the_default_plans_can_be_measured(example, lang):
    doc = built(example, 12, lang)
    k_a = doc.scales["k_a"]
    assert len(doc.accelerations) == 2
    for r in doc.runs:
        if r.index not in doc.accelerations:
            continue
        plan = r.graphical.acceleration_plan
        components = [v for v in plan.vectors if v.kind != "absolute"]
        assert components
        for v in components:  # |component| [m/s²] / k_a [(m/s²)/mm]: its length on the page
            assert v.value / k_a >= MEASURABLE_MM, (example, r.index, v.label, v.value / k_a)
