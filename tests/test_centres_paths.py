"""The centres page's readings take a path of centres a student can read (teacher's review, issue 20 §4), and say
so when no path can be read; the method's legend and rules are said once, the circle diagram's caption set by the
page.  Expected values from plans.analytic (not the centres method) and hand-written words."""

import io
import re

import pytest
from pypdf import PdfReader

import plans.centres
from plans.analytic import solve
from plans.centres import CentreError, instant_centres
from plans.handout import handout
from plans.positions import cycle_positions
from plans.scene import example_path, load
from review_handouts import built, built_pdf


@pytest.fixture(scope="module")
def quick_return_8():
    """The quick-return at its 12-position handout's position 8 (φ₂ = 211.3°), and its analytic solution."""
    scene = load(example_path("quick-return"))
    scene = scene.at(cycle_positions(scene, 12)[8])
    return scene, solve(scene)


def _error(read, analytic, link: str) -> float:
    want = float(analytic.links[link].omega[0])
    return abs(read.links[link] - want) / abs(want)


def test_quick_return_position_8_reads_omega_on_a_readable_path(quick_return_8):
    # at the plate's k_l 0.006 m/mm the crank's path to link 4 runs through P12P24, 1.06 mm long, read 1.1 mm: 4 %
    # off; a path whose lengths are all long reads ω3 = ω4 (one slider on one rocker) and ω5 to well under 1 %
    scene, analytic = quick_return_8
    read = instant_centres(scene, k_l=0.006, precision=0.1)
    assert _error(read, analytic, "3") < 0.005 and _error(read, analytic, "4") < 0.005 and _error(read, analytic, "5") < 0.005
    assert read.links["3"] == read.links["4"]


def test_a_length_read_as_zero_takes_another_path(quick_return_8):
    # at k_l 0.15 m/mm P12P24 is 0.04 mm on the drawing, read 0: through it ω4 would read 0 (or nothing); the other
    # paths (through link 5) are long enough
    scene, analytic = quick_return_8
    read = instant_centres(scene, k_l=0.15, precision=0.1)
    assert _error(read, analytic, "4") < 0.02 and _error(read, analytic, "5") < 0.02


def _texts(doc) -> list[str]:
    """The text of every page of *doc* (a Handout, or its PDF)."""
    pdf = doc if isinstance(doc, bytes) else doc.pdf()
    return [" ".join(page.extract_text().split()) for page in PdfReader(io.BytesIO(pdf)).pages]


WORDS = {  # hand-written: the page's note where no path of centres reads
    "en": "not read off the drawing",
    "sr": "не очитани са цртежа",
    "bg": "не са измерени от чертежа",
}


@pytest.mark.parametrize("lang", ["en", "sr", "bg"])
def test_no_readable_path_is_said_on_the_page(monkeypatch, lang):
    exact = plans.centres.instant_centres

    def unreadable(scene, structure=None, *, k_l=None, precision=None, room=None):
        if k_l is not None:  # every path of centres has two on one spot of the drawing
            raise CentreError("the velocity of link 3 is not determined by the instant centres at this position")
        return exact(scene, structure)

    monkeypatch.setattr(plans.centres, "instant_centres", unreadable)
    texts = _texts(handout(load(example_path("four-bar")), centres=True, lang=lang))
    pages = [t for t in texts if WORDS[lang] in t]
    assert len(pages) == 1 and "P" in pages[0]  # on the position's centres page


def test_a_readable_page_has_no_note():
    texts = _texts(built_pdf("four-bar", None, "en", centres=True))
    assert not any(WORDS["en"] in t for t in texts)


def test_six_bar_legend_and_rules_said_once_and_circle_caption_typeset():
    doc = built("six-bar", None, "en", centres=True)
    text = " ".join(_texts(built_pdf("six-bar", None, "en", centres=True)))
    # the legend of marks, the edge arrows' legend and the two rules: on the method's page only
    # (the rules in the textbook's words, the circle legend's 'solid lines': issue 20's centres review)
    for words in ("circles: centres at the kinematic pairs", "an arrow at the edge points to a centre off the drawing",
                  "Velocity of a point from the centre its link turns about",
                  "Angular velocities from the instant centres, link by link from the driver"):
        assert len(re.findall(re.escape(words), text, re.IGNORECASE)) == 1, words
    # the circle diagram's caption is the page's text (its typeface), not the drawing's
    assert len(re.findall("circle diagram: solid lines: centres at the kinematic pairs", text)) == 1
    svgs = [svg for key, svg in doc.images.items() if key.startswith("circle")]
    assert svgs and all(b'id="centres-diagram-circle"' in svg and b"centres-diagram-heading" not in svg for svg in svgs)
