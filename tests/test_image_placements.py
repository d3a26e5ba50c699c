"""Every image a plan draws has a row of the vector equations saying how it is placed (issue 20, the teacher's review
of the Bulgarian linear-arm handout: the images g and h₃ of rod 3 were drawn and no row placed them).

The rows are read off the typeset pages (poppler's ``pdftotext``), the images from the plans' data: a row places the
point on the left of its equation (``v_F4 = v_D + v_F4D`` places f₄, ``v_D = v_Q = 0`` places d and q) or the last
letter of a proportion's first segment (``f h₃ / fg = FH / FG`` places h₃).  The linear-arm's numbers are worked by
hand from its scene (F = A + (100, 150) mm with A at O at s = 0, D = (350, 300) mm: DF = √(250² + 150²) = 291.5 mm;
G 550 mm along the rod from F) and its ω₄, ε₄ from the analytic solution (the other method).
"""

from __future__ import annotations

import math
import re
import shutil
import subprocess
import tempfile
import unicodedata
from pathlib import Path

import pytest

import plans

pytestmark = [pytest.mark.filterwarnings("ignore"),
              pytest.mark.skipif(shutil.which("pdftotext") is None, reason="poppler's pdftotext reads the pages")]

EXAMPLES = sorted(p.stem for p in Path(plans.example_path("four-bar")).parent.glob("*.toml"))


def _text(pdf: bytes) -> str:
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "p.pdf"
        path.write_bytes(pdf)
        out = subprocess.run(["pdftotext", str(path), "-"], capture_output=True, text=True, check=True).stdout
    return unicodedata.normalize("NFKC", out).replace("\u20d7", "")  # (the vectors' arrows)


def placed(text: str) -> set[str]:
    """The points the rows of *text* place, as the equations name them (``F4``, ``G``, ``H3``; a proportion's image
    letter in capitals with its link's number, ``h₃`` → ``H3``)."""
    out = set()
    for line in text.splitlines():
        start = re.search(r"(?:^|\s)[va][A-Z]", line)  # (after the row's words: "fixed points v_D = …")
        flat = line[start.start():].replace(" ", "") if start else ""
        equation = re.match(r"([va])([A-Z][A-Za-z0-9]*)=", flat)
        if equation:
            out.add(equation.group(2))
            chain = re.fullmatch(r"((?:[va][A-Z][A-Za-z0-9]*=)+)0", flat)  # v_D = v_Q = 0
            if chain:
                out.update(re.findall(r"[va]([A-Z][A-Za-z0-9]*)=", chain.group(1)))
        for first in re.findall(r"(?:^|\s)((?:[a-zπ][0-9]*′?\s?){1,2}) / [^=]+ = [A-Z]", line):
            letters = re.findall(r"[a-zπ][0-9]*", first.replace("′", ""))
            if letters and letters[-1] not in ("p", "π"):
                out.add(letters[-1][0].upper() + letters[-1][1:])
    return out


def unplaced(graphical, text: str, kinds=("velocity", "acceleration")) -> list[str]:
    """The images of *graphical*'s plans of *kinds* that no row of *text* places."""
    names = placed(text)
    missing = []
    for kind in kinds:
        plan = graphical.velocity_plan if kind == "velocity" else graphical.acceleration_plan
        for label, z in plan.images.items():
            point, body = plan.points[label]
            # a point at rest may be named by the link pivoted there (six-bar: e at the pole, v_E6 = 0)
            if point + body not in names and not (z == 0 and any(re.fullmatch(re.escape(point) + r"[0-9]+", n) for n in names)):
                missing.append(f"{kind} {label}")
    return missing


def _sheet_text(example: str, lang: str):
    from plans.graphical import construct
    from plans.pages.sheet import sheet_at

    g = construct(plans.load(plans.example_path(example)))
    return g, _text(sheet_at(g, lang=lang).pdf())


@pytest.mark.parametrize("example, lang", [(e, "en") for e in EXAMPLES] + [("linear-arm", "bg"), ("scotch-yoke", "sr")])
def test_every_image_on_a_sheets_plans_has_a_row(example, lang):
    g, text = _sheet_text(example, lang)
    assert g.velocity_plan.images and g.acceleration_plan.images
    assert not unplaced(g, text), (example, lang, unplaced(g, text), sorted(placed(text)))


def test_the_row_reader_is_not_satisfied_by_the_steps_alone():
    # the check itself can fail: the linear-arm's step rows alone place a, f₄, h (and the driver's a), not g or h₃
    text = "vA = v\nvF4 = vD + vF4D\nvF4 = vF3 + vF4F3\nvH = vQ + vHQ\nvD = vQ = 0\nby similarity pk / p f4 = DK / DF; f4 k / f4 p = FK / FD"
    assert placed(text) == {"A", "F4", "H", "D", "Q", "K"}


@pytest.fixture(scope="module")
def linear_arm_bg():
    return _sheet_text("linear-arm", "bg")


def _rows(text: str) -> str:
    return "\n".join(line.replace(" ", "") for line in text.splitlines())


def test_the_linear_arms_rod_images_are_placed_with_omega_4(linear_arm_bg):
    """g from f with the sleeve's ω₄, ε₄ (rod 3 slides in the sleeve welded to 4: ω₃ = ω₄), h₃ on fg by similarity,
    in the velocity and the acceleration equations, the row under "звено 3" (bg: link 3)."""
    _, text = linear_arm_bg
    rows = _rows(text)
    assert "vG=vF+vGF" in rows and "vGF⟂FG;ω3=ω4" in rows, rows
    assert "aG=aF+anGF+atGF" in rows and "ω3=ω4,ε3=ε4" in rows, rows
    assert "звено 3" in text and "звено 2" in text  # link 3's row; link 2 translates (f at a)
    assert "vF=vA" in rows and "ω2=0" in rows
    assert "fh3/fg=FH/FG" in rows and "f′h3′/f′g′=FH/FG" in rows


def test_the_linear_arms_rod_proportion_has_the_scenes_numbers(linear_arm_bg):
    """fg / p f₄ = FG / DF with FG = 550 mm and DF = 291.5 mm (the scene at s = 0, by hand); the plan's segments
    |p f₄| = ω₄·DF / k_v and fg = ω₃·FG / k_v with ω₃ = ω₄ of the analytic solution (bg: decimal commas)."""
    g, text = linear_arm_bg
    flat = " ".join(text.split()).replace(",", ".")
    analytic = plans.solve(g.scene)
    omega = abs(float(analytic.links["4"].omega[0]))
    epsilon = float(analytic.links["4"].epsilon[0])
    df = math.hypot(250.0, 150.0)
    k_v, k_a = g.scales["k_v"], g.scales["k_a"]
    for seg, base, rate, k in (("fg / p f4", "fg", omega, k_v), ("f′ g′ / π f4′", "f′ g′", math.hypot(epsilon, omega ** 2), k_a)):
        m = re.search(re.escape(seg) + r" = FG / DF: " + re.escape(base) + r" = ([0-9.]+) · ([0-9.]+) / ([0-9.]+) = ([0-9.]+) мм "
                      r"(?:\(на плана ([0-9.]+) мм\) )?\((.*?)\)", flat)
        assert m, (seg, flat)
        on_plan, fg, df_printed, result = map(float, m.groups()[:4])
        assert (fg, df_printed) == (550.0, round(df, 1))
        assert abs(on_plan - rate * df / 1e3 / k) <= 0.06, (on_plan, rate * df / 1e3 / k)
        assert abs(result - rate * 0.55 / k) <= 0.1, (result, rate * 0.55 / k)
        if m.group(5):  # the plan's own segment where the rounded inputs give another last digit
            assert abs(float(m.group(5)) - rate * 0.55 / k) <= 0.051 and m.group(5) != m.group(4), m.groups()
        assert m.group(6).replace(" ", "") == ("ω3=ω4" if k == k_v else "ω3=ω4.ε3=ε4")  # (NFKC: ₃ → 3; the comma read as a point)


def test_the_handout_places_every_image_it_draws():
    """The Bulgarian linear-arm handout (2 positions, both with acceleration plans: the reviewed one has 8, the rows
    are the same): every image of every velocity plan and of the acceleration plans it draws has its row, g's with
    ω₃ = ω₄."""
    from plans.handout import handout

    h = handout(plans.load(plans.example_path("linear-arm")), positions=2, lang="bg")
    assert h.accelerations == [0, 1]
    text = _text(h.pdf())
    rows = _rows(text)
    assert "vG=vF+vGF" in rows and "aG=aF+anGF+atGF" in rows
    for r in h.runs:
        if r.graphical is None:
            continue
        kinds = ("velocity", "acceleration") if r.index in h.accelerations else ("velocity",)
        assert not unplaced(r.graphical, text, kinds), (r.index, unplaced(r.graphical, text, kinds))



def test_a_rows_images_wait_for_their_steps_at_every_position():
    """Over the quick-return's 12 positions (position 0 at the extreme: ω₄ = 0 and a₄, d, e at the pole) no row places
    a step's image, every row starts from images drawn before it (at rest, a step's so far, or an earlier row's), every
    image of each plan is placed by a step or a row, and rocker 4 is never taken for a link that translates (it turns;
    its ω is zero for the instant only)."""
    from plans.drawing.readings import image_placements
    from plans.positions import run_positions

    run = run_positions(plans.load(plans.example_path("quick-return")), 12)
    for r in run.runs:
        for kind in ("velocity", "acceleration"):
            plan = r.graphical.velocity_plan if kind == "velocity" else r.graphical.acceleration_plan
            steps = [s.image for s in plan.steps]
            placements = image_placements(r.graphical, kind)
            drawn = set()
            for p in placements:
                assert not set(p.images) & set(steps), (r.index, kind, p)
                before = set(steps[:p.after + 1]) | drawn
                assert set(p.start) <= before, (r.index, kind, p, before)
                assert not (p.how == "translates" and p.link == "4"), (r.index, kind, p)
                drawn.update(p.images)
            assert set(plan.images) == drawn | set(steps), (r.index, kind, set(plan.images) - drawn - set(steps))
