"""Issue 20 §3, a teacher's review of the handout's plan pages: read as the teacher reads them.

Three handouts as the review rendered them (quick-return 12 positions in Serbian, linear-arm 8 positions in
Bulgarian, six-bar in English), each built once.  What is checked is read back from the SVG drawings the
handout places (text nodes and dots by their ids) and from the Typst source of its tables:

* every image label stands nearest its own image (the quick-return's position 4 had "a₄′" beside d′);
* the notes under a plan name the plan's segments ("a a₄ = 0,45 mm"), never a velocity in mm ("|v_A4A3| = …"),
  no program suffixes ("(k)", "(n₁)", "(I)"), each direction once;
* the Coriolis component's end letter is no image's letter (linear-arm's point K);
* the readings divide by l_AC, named by the scene's points, never a program token ("(A4C)");
* the comparison tables print no round-off ("1,5·10⁻¹⁶" errors of given values, "−1,998·10⁻¹⁵" for a zero) and a
  graphical value to the digits its 0.1 mm reading justifies ("0,08109 rad/s²" from a 0,2 mm segment).

Where a dot or a label should be comes from the plans' data at the handout's scale factors (mm on the paper);
where it is comes from the SVG (its viewBox and width give the units per mm).
"""

from __future__ import annotations

import re

import numpy as np
import xml.etree.ElementTree as ET

import pytest
from matplotlib.font_manager import FontProperties
from matplotlib.textpath import TextPath

import plans
from plans.scene import example_path
from review_handouts import built

pytestmark = pytest.mark.filterwarnings("ignore")

SVG = "{http://www.w3.org/2000/svg}"
#: the handouts of the review: example, positions, language
REVIEWED = [("quick-return", 12, "sr"), ("linear-arm", 8, "bg"), ("six-bar", None, "en")]


@pytest.fixture(scope="module")
def handouts():
    return {name: built(name, n, lang, centres=name == "quick-return")
            for name, n, lang in REVIEWED}


def _drawn_plans(doc):
    """(image key, Plan) of every plan the handout draws."""
    for r in doc.runs:
        yield f"v-{r.index}", r.graphical.velocity_plan
        if f"a-{r.index}" in doc.images:
            yield f"a-{r.index}", r.graphical.acceleration_plan


def _path_centre(group) -> complex:
    numbers = [float(x) for x in re.findall(r"-?[0-9]+(?:\.[0-9]+)?", next(group.iter(f"{SVG}path")).get("d"))]
    xs, ys = numbers[0::2], numbers[1::2]
    return complex((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2)


def _text_box(t) -> tuple[float, float, float]:
    """(left, right, baseline y) of a text node [SVG units], its width measured with its font."""
    size = float(re.search(r"font-size: ([0-9.]+)px", t.get("style")).group(1))
    width = TextPath((0, 0), t.text or "", size=size, prop=FontProperties(family="DejaVu Sans")).get_extents().width
    x, y = float(t.get("x")), float(t.get("y"))
    return x, x + width, y


def read_plan_svg(svg: bytes, tag: str):
    """The plan's dots and label lines as drawn: ``(per_mm, pole, dots, lines)``.

    *dots*: gid -> centre [SVG units]; *lines*: one per label as the eye reads it (the pieces a label is set in,
    one baseline, side by side: "π, o′, c′"), each ``(box [SVG units], [gids of its pieces], text)``; *rings*:
    (centre, radius) of the crowds ringed for a detail.
    """
    root = ET.fromstring(svg)
    per_mm = float(root.get("viewBox").split()[2]) / float(root.get("width").removesuffix("mm"))
    dots, pieces, rings = {}, [], []
    for g in root.iter(f"{SVG}g"):
        gid = g.get("id") or ""
        if re.fullmatch(rf"{tag}-(pole|dot-.+|end-dot-.+)", gid):
            dots[gid[len(tag) + 1:]] = _path_centre(g)
        if re.fullmatch(rf"{tag}-detail-ring(-[0-9]+)?", gid):
            numbers = [float(x) for x in re.findall(r"-?[0-9]+(?:\.[0-9]+)?", next(g.iter(f"{SVG}path")).get("d"))]
            rings.append((_path_centre(g), (max(numbers[0::2]) - min(numbers[0::2])) / 2))
        for t in g.findall(f"{SVG}text"):
            left, right, y = _text_box(t)
            pieces.append((round(y, 2), left, right, gid[len(tag) + 1:] if gid.startswith(tag + "-") else "", t.text or ""))
    pieces.sort()
    lines = []
    for y, left, right, gid, text in pieces:
        last = lines[-1] if lines else None
        if last and abs(last[0] - y) < 0.01 and -0.2 * per_mm < left - last[2] < (2.5 if last[4].endswith(", ") else 0.5) * per_mm:
            last[2] = right
            last[3].append(gid)
            last[4] += text
        else:
            lines.append([y, left, right, [gid], text])
    size = 10.0
    # each line's box: from the baseline to the cap height, about (0.75 of the size up, 0.2 down)
    out = [((left, y - 0.75 * size, right, y + 0.2 * size), gids, text) for y, left, right, gids, text in lines]
    return per_mm, dots["pole"], dots, out, rings


def _leaders(svg: bytes, tag: str) -> list[tuple[complex, complex]]:
    """The two ends [SVG units] of every leader line (gid ``<tag>-leader…``) drawn on a plan."""
    out = []
    for g in ET.fromstring(svg).iter(f"{SVG}g"):
        if re.fullmatch(rf"{tag}-leader(-[0-9]+)?", g.get("id") or ""):
            numbers = [float(x) for x in re.findall(r"-?[0-9]+(?:\.[0-9]+)?", next(g.iter(f"{SVG}path")).get("d"))]
            out.append((complex(numbers[0], numbers[1]), complex(numbers[-2], numbers[-1])))
    return out


def _to_box(z: complex, b: tuple[float, float, float, float]) -> float:
    dx = max(b[0] - z.real, 0.0, z.real - b[2])
    dy = max(b[1] - z.imag, 0.0, z.imag - b[3])
    return (dx * dx + dy * dy) ** 0.5


def _own(plan, gid: str) -> complex | None:
    """Where the labelled point is on the plan [mm], from the plan's data: an image, a component's end, the pole."""
    if gid == "pole-label":
        return 0j
    if gid.startswith("image-"):
        name = gid[len("image-"):]
        return complex(next(z for n, z in plan.images.items() if n.rstrip("′") == name))
    if gid.startswith("end-"):
        label = gid[len("end-"):]
        return next(complex(v.tip) for v in plan.vectors if v.label.replace("^", "_") == label)
    return None


@pytest.mark.parametrize("name", [n for n, _, _ in REVIEWED])
def test_every_image_label_stands_nearest_its_own_image(handouts, name):
    doc = handouts[name]
    checked = 0
    for key, plan in _drawn_plans(doc):
        tag = "vel" if plan.kind == "velocity" else "acc"
        per_mm, pole, dots, lines, rings = read_plan_svg(doc.images[key], tag)

        def mm(z: complex) -> complex:  # SVG units -> plan mm (y up), from the pole
            d = (z - pole) / per_mm
            return complex(d.real, -d.imag)

        for name_, z in plan.images.items():  # the dots are where the plan's data says
            if abs(z) > 1e-3:
                assert abs(mm(dots[f"dot-{name_.rstrip('′')}"]) - z) < 0.05, (key, name_)
        for box, gids, text in lines:
            owned = [(g, _own(plan, g)) for g in gids if _own(plan, g) is not None and not g.startswith("detail")]
            if not owned:
                continue
            # the dot nearest the label's box (as the eye joins a name to a point) is its own; a label that names
            # several points (one coincident image, or a lettered end within 1 mm: "a₄′, n₁") is nearest one of them
            if any(abs(dots[g] - c) < r for g in dots if any(abs(mm(dots[g]) - z) <= 0.05 for _, z in owned) for c, r in rings):
                continue  # a crowd ringed on the plan (six-bar a b c within 1 mm) is read in its enlarged detail
            own = [g for g in dots if any(abs(mm(dots[g]) - z) <= 0.05 for _, z in owned)]
            assert own, (key, text)
            distances = {g: _to_box(z, box) / per_mm for g, z in dots.items()}
            mine = min(distances[g] for g in own)
            other = min((d for g, d in distances.items() if g not in own), default=float("inf"))
            if mine > other + 0.05 and any(min(abs(a - dots[g]) for g in own) / per_mm < 0.8 and _to_box(b, box) / per_mm < 1.25
                                           for ends in _leaders(doc.images[key], tag) for a, b in (ends, ends[::-1])):
                continue  # a label kept off a neighbour's, joined to its own point by a leader line (which stops 0.6 mm
                # short of the label's box, where this box is the text's from baseline to cap height: up to 1.25 mm)
            assert mine <= other + 0.05, (f"{name} {key}: the label {text!r} stands nearer "
                                          f"{min((g for g in dots if g not in own), key=distances.get)} ({other:.2f} mm) than its own point ({mine:.2f} mm)")
            checked += len(owned)
    assert checked > 10


def _texts(svg: bytes) -> dict[str, str]:
    root = ET.fromstring(svg)
    return {g.get("id"): "".join(t.text or "" for t in g.findall(f"{SVG}text")) for g in root.iter(f"{SVG}g") if g.get("id")}


@pytest.mark.parametrize("name", [n for n, _, _ in REVIEWED])
def test_notes_under_the_plans_are_the_plans_segments(handouts, name):
    """"|v_A4A3| = 0,45 mm", "(k)", "(n₁)", "∠ pd" twice: a note gives a segment of the plan and its drawn length."""
    doc = handouts[name]
    seen = 0
    for key, plan in _drawn_plans(doc):
        tag = "vel" if plan.kind == "velocity" else "acc"
        texts = _texts(doc.images[key])
        notes = {gid: t for gid, t in texts.items() if gid.startswith((f"{tag}-short-", f"{tag}-along-"))}
        for gid, note in notes.items():
            assert "|" not in note and "_" not in note, note  # no vector's magnitude in mm
            assert not re.search(r"\((k|κ|n)[₀-₉]*\)|\((I+)\)", note), note  # no bare program marks
            if gid.startswith(f"{tag}-short-"):
                label = gid[len(f"{tag}-short-"):]
                v = next(v for v in plan.vectors if v.label.replace("^", "_") == label)
                m = re.fullmatch(r"(\S+(?: \S+)?) ([=<]) ([0-9]+[.,][0-9]{2}) (mm|мм)"
                                 r"(?: \((detail|детаљ|детайл) (I+): ([0-9]+[.,][0-9]{2}) (mm|мм)\))?", note)
                assert m, note
                if m.group(7):  # (its length in the detail, round 20: the plan's length × the ratio its title states)
                    title = next(t for gid, t in texts.items() if re.fullmatch(rf"{tag}(-detail)?-(detail-)?name", gid) and f" {m.group(6)} (" in t)
                    ratio = float(re.search(r"\(([0-9.,]+) : 1\)", title).group(1).replace(",", "."))
                    assert float(m.group(7).replace(",", ".")) == pytest.approx(ratio * v.length, abs=0.006 * ratio), (note, title)
                if m.group(2) == "=":
                    assert float(m.group(3).replace(",", ".")) == pytest.approx(v.length, abs=0.006)
                else:  # "< 0,01 mm", not "0,00 mm"
                    assert v.length < 0.01 and m.group(3) in ("0.01", "0,01")
                seen += 1
        directions = [t.split(" =")[0] for gid, t in notes.items() if gid.startswith(f"{tag}-along-")]
        assert len(directions) == len(set(directions)), directions  # each direction once
        for d in directions:
            assert re.fullmatch(r"∠\((p|π)\S+\)", d), d
    assert seen or name == "six-bar"


def test_the_quick_return_notes_read_as_the_review_asked():
    doc = built("quick-return", 12, "sr", accelerations=(4, 10))  # the positions the review saw (the lever upright)
    texts = _texts(doc.images["a-4"])
    notes = {t for gid, t in texts.items() if gid.startswith("acc-short-")}
    run = next(r for r in doc.runs if r.index == 4)
    k_a = doc.scales["k_a"]

    def mm(value: float) -> str:
        return f"{value / k_a:.2f}".replace(".", ",")

    a_e = abs(complex(np.ravel(run.analytic.points["E"].a)[0]))  # the analytic solution, not the plan
    # was "|a_E| = 2,44 mm" (at k_a 0.15); 9 mm long in the plan's enlarged detail (5 : 1) beside it, which the note
    # names (on a line of its own where the plan is narrow)
    title = next(t for gid, t in texts.items() if gid in ("acc-detail-name", "acc-detail-detail-name"))
    ratio = int(re.fullmatch(r"Детаљ I \(([0-9]+) : 1\)", title).group(1))
    there = f"{ratio * a_e / k_a:.2f}".replace(".", ",")  # (its length in the detail, round 20)
    assert (f"π e′ = {mm(a_e)} mm (детаљ I: {there} mm)" in notes
            or (f"π e′ = {mm(a_e)} mm" in notes and texts.get("acc-where-a_E") == f"(детаљ I: {there} mm)")), notes
    # the Coriolis component 2·ω₄·|v_A4A3| (domain.md §4): A4 the rocker's point under A, v_A4 = iω₄(r_A − r_C)
    first = lambda x: complex(np.ravel(x)[0])  # noqa: E731
    a = run.analytic
    omega4 = first(a.links["4"].omega).real
    v_a4 = 1j * omega4 * (first(a.points["A"].r) - first(a.points["C"].r))
    assert f"a′ k = {mm(2 * abs(omega4) * abs(first(a.points['A'].v) - v_a4))} mm" in notes, notes  # was "|a^k_A4A3| = 0,29 mm (k)"
    along = [t for gid, t in texts.items() if gid.startswith("acc-along-")]
    assert sorted(along) == sorted(["∠(πa₄′) = 271,4°", "∠(πa′) = 271,3°", "∠(πd′) = 271,4°"])  # ∠ πa′ once


def test_no_coriolis_end_shares_a_letter_with_an_image(handouts):
    """linear-arm: the images of its point K (k, k′) and the Coriolis ends, lettered k₁ and k₂ before."""
    doc = handouts["linear-arm"]
    for key, plan in _drawn_plans(doc):
        if plan.kind != "acceleration":
            continue
        texts = _texts(doc.images[key])
        images = {re.sub(r"[′₀-₉]", "", t) for gid, t in texts.items() if gid.startswith("acc-image-")}
        assert "k" in images
        ends = [t for gid, t in texts.items() if re.match(r"acc-end-a_k_", gid)]
        assert len(ends) == 2
        for t in ends:
            assert re.sub(r"[′₀-₉]", "", t) not in images, (t, images)
    # the readings name the same ends
    assert "aᵏ₁" in doc.source and "aᵏ₂" in doc.source and "κ" not in doc.source


@pytest.mark.parametrize("name", [n for n, _, _ in REVIEWED])
def test_readings_divide_by_the_link_length_named_by_the_scene_points(handouts, name):
    """"÷ 0,37 (A4C)" → "÷ 0,37 (l_AC)", in one unbreakable cell."""
    source = handouts[name].source
    assert not re.search(r"÷ [0-9,.]+ \(", source)
    cells = re.findall(r'\[#"(×[^\]]*÷[^\]]*)"\]', source)
    assert cells
    scene = plans.load(example_path(name))
    for cell in cells:
        assert " " not in re.sub(r"\$[^$]*\$", "", cell), cell  # no-break spaces only (math never breaks): the cell never wraps
        m = re.search(r"l_\(([A-Z][a-z0-9]*) ([A-Z][a-z0-9]*) \)", cell)
        assert m and all(e in scene.point_names for e in m.groups()), cell


def test_no_round_off_is_printed_in_the_tables(handouts):
    """Relative errors of 10⁻¹⁶ (given v_A, ω₂ of the driver) and values of 10⁻¹⁵ (a dead centre's ω₄, v_D, also on the
    centres pages): round-off is no reading."""
    for name, doc in handouts.items():
        assert not re.search(r"10⁻(⁹|¹[⁰¹²³⁴⁵⁶⁷⁸⁹])", doc.source), name


def _rows(source: str, heading: str) -> list[list[str]]:
    """The rows of the first table after *heading* in the Typst source: each cell's text (math as Typst writes it)."""
    start = re.search(re.escape(heading) + r'[^\n]*?\] \\\n#table\(', source).start()  # (a formula in it boxed: #box[…])
    table = source[source.index("#table(", start):]
    table = table[:table.index("table.hline(stroke: 0.7pt))")]
    cells = re.findall(r'text\(weight: "(?:bold|regular)"\)\[(.*?)\](?=, text\(|, table\.hline)', table)
    return [cells[k:k + 4] for k in range(0, len(cells) - 3, 4)]


def test_given_values_have_no_error_and_readings_their_digits(handouts):
    """Quick-return position 2 (sr, the working stroke's acceleration plan): v_A, a_A and ω₂ are given (error "—");
    ε₄ = ε₃ read off a segment at k_a ÷ l_AC printed to the decimals of one 0.1 mm step of it, l_AC from the analytic
    positions (|A − C|)."""
    import math

    doc = handouts["quick-return"]
    h = next(r for r in doc.runs if r.index == 2)
    rows = _rows(doc.source, "Положај 2:")
    by = {re.sub(r"\s+", "", r[0]): r for r in rows}
    for key in ('$v_(A)$#"[m/s]"', '$a_(A)$#"[m/s²]"', '$omega_(2)$#"[rad/s]"'):
        assert by[key][3] == '#"—"', by[key]
    assert by['$v_(D)$#"[m/s]"'][3] != '#"—"'  # a reading has its error
    eps = next(r for k, r in by.items() if "epsilon_(4" in k)
    l_ac = abs(h.analytic.points["A"].r[0] - h.analytic.points["C"].r[0])
    step = 0.1 * doc.scales["k_a"] / l_ac
    printed = eps[1].strip('#"')
    decimals = len(printed.split(",")[1]) if "," in printed else 0
    assert decimals == -math.floor(math.log10(step)), (printed, step)
    assert abs(float(printed.replace("−", "-").replace(",", ".")) - h.graphical.links["4"]["epsilon"]) <= step


def test_the_two_coriolis_components_of_one_rod_are_drawn_apart(handouts):
    """linear-arm: the sliders F and H on one rod have parallel Coriolis components that ran along one line (1.5 mm
    apart on the plan): drawn, their shafts stand at least 2 mm apart wherever they run alongside."""
    doc = handouts["linear-arm"]
    for key, plan in _drawn_plans(doc):
        if plan.kind != "acceleration":
            continue
        root = ET.fromstring(doc.images[key])
        per_mm = float(root.get("viewBox").split()[2]) / float(root.get("width").removesuffix("mm"))
        shafts = []
        for g in root.iter(f"{SVG}g"):
            if re.fullmatch(r"acc-coriolis-a_k_[A-Za-z0-9]+", g.get("id") or ""):
                numbers = [float(x) for x in re.findall(r"-?[0-9]+(?:\.[0-9]+)?", next(g.iter(f"{SVG}path")).get("d"))]
                shafts.append((complex(numbers[0], numbers[1]) / per_mm, complex(numbers[-2], numbers[-1]) / per_mm))
        assert len(shafts) == 2, key
        (a, b), (c, d) = shafts
        u = (b - a) / abs(b - a)
        offsets = [((z - a) * u.conjugate()) for z in (c, d)]
        lo, hi = sorted(o.real for o in offsets)
        if min(hi, abs(b - a)) - max(lo, 0.0) > 0 and abs(((d - c) / abs(d - c) * u.conjugate()).imag) < 0.05:
            assert min(abs(o.imag) for o in offsets) >= 2.0, (key, offsets)
