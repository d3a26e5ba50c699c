"""A plan's detail "Detail I (n : 1)" shows everything inside its ring, labelled as on the plan.

Measured from the drawing: the ring on the plan (gid ``…-detail-ring``: its centre and
radius in plan millimetres) and the detail's circle (``…-detail``: its radius, so the
magnification n = R / r).  What *should* be inside is computed from the plan's data
(its images and vectors), independently of the drawing code: every image within r of
the ring's centre, the pole by its full name ("p, o, c"), and every vector that passes
through the ring and is at least 3 mm long at n : 1 (quick-return pos 2: v_ED, 2.58 mm
on the plan, about 10 mm at 4 : 1).
"""

from __future__ import annotations

import re

import math

import pytest
from matplotlib.patches import Circle

from plans.drawing import draw_plan
from plans.graphical import construct
from plans.handout import handout
from plans.scene import example_path, load

from plandraw_overlaps import arrowheads, label_boxes, SLIVER_MM2

_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def _text(name: str) -> str:
    """An image's name as printed: the link number a subscript (a4 → a₄)."""
    return name[0] + name[1:].translate(_SUB)


def _gid(label: str) -> str:
    """A vector's label as it appears in gids (``a^k_A4A3`` → ``a_k_A4A3``)."""
    return label.replace("^", "_")


def _artists(fig):
    for ax in fig.axes:
        yield from ax.get_children()


def _circle(fig, suffix: str) -> Circle:
    found = [a for a in _artists(fig) if isinstance(a, Circle) and (a.get_gid() or "").endswith(suffix)]
    assert len(found) == 1, (suffix, [a.get_gid() for a in found])
    return found[0]


def _detail_texts(fig) -> dict[str, object]:
    """gid → Text of every label in the detail (``…-detail-image-x``, ``…-detail-pole-label``, ``…-detail-end-…``)."""
    out = {}
    for ax in fig.axes:
        for t in ax.texts:
            gid = t.get_gid() or ""
            if "-detail-image-" in gid or gid.endswith("-detail-pole-label") or "-detail-end-" in gid:
                if t.get_text().strip():
                    out[gid] = t
    return out


def _crosses(tail: complex, tip: complex, centre: complex, r: float) -> float:
    """Length [plan mm] of the part of segment tail–tip within the circle (sampled, not the drawing's clip)."""
    n = 4000
    inside = sum(1 for k in range(n + 1) if abs(tail + (tip - tail) * k / n - centre) <= r)
    return abs(tip - tail) * max(0, inside - 1) / n


def check_detail(fig, plan) -> list[str]:
    """What the detail of *fig* (drawn from *plan*) leaves out or mislabels, as text (empty: complete)."""
    ring, detail = _circle(fig, "-detail-ring"), _circle(fig, "-detail")
    centre, r = complex(*ring.center), ring.radius
    ratio = detail.radius / r
    problems = []

    # the images: each within the ring is labelled, by its printed name, and nothing else is
    pole_group = [plan.pole] + [n for n, z in plan.images.items() if abs(z) < 1e-6]
    expected = {_text(n) for n, z in plan.images.items() if abs(z - centre) <= r}
    if abs(centre) <= r:
        expected |= {_text(n) for n in pole_group}
    texts = _detail_texts(fig)
    shown = {t.get_text() for gid, t in texts.items() if "-detail-end-" not in gid}
    if shown != expected:
        problems.append(f"images labelled in the detail {sorted(shown)} != images inside its ring {sorted(expected)}")

    # the pole: its full name, in one label (pieces on one line, in the plan's order)
    if abs(centre) <= r:
        pole = [t for gid, t in texts.items() if gid.endswith("-detail-pole-label")]
        if len(pole) != 1:
            problems.append("the pole has no label in the detail")
        else:
            y = pole[0].get_position()[1]
            line = sorted((t for t in texts.values() if abs(t.get_position()[1] - y) < 1e-6), key=lambda t: t.get_position()[0])
            words = [t.get_text() for t in line]
            full = [_text(n) for n in pole_group]
            if words[: len(full)] != full:
                problems.append(f"the pole is labelled {', '.join(words)!r} in the detail, not {', '.join(full)!r}")

    # the vectors through the ring, long enough to draw at n : 1
    gids = {a.get_gid() or "" for a in _artists(fig)}
    for v in plan.vectors:
        if abs(v.tip - v.tail) * ratio < 3.0:
            continue
        if _crosses(complex(v.tail), complex(v.tip), centre, r) * ratio > 1.5 and not any(g.endswith(f"-detail-{_gid(v.label)}") for g in gids):
            if not any(abs(w.tail - v.tail) < 1e-3 and abs(w.tip - v.tip) < 1e-3 and any(g.endswith(f"-detail-{_gid(w.label)}") for g in gids) for w in plan.vectors):
                problems.append(f"{v.label} passes through the ring but is not drawn in the detail")
    return problems


def detail_overlaps(fig) -> list[str]:
    """A detail's labels that overlap another label or an arrowhead (measured with the renderer)."""
    labels = label_boxes(fig)
    heads = arrowheads(fig)
    found = []
    for i, (a, ba) in enumerate(labels):
        if "-detail-" not in a.split(":")[0]:
            continue
        for j, (b, bb) in enumerate(labels):
            if j != i and ba.intersection(bb).area > SLIVER_MM2:
                found.append(f"{a!r} on {b!r}")
        for h, bh in heads:
            if ba.intersection(bh).area > SLIVER_MM2:
                found.append(f"{a!r} on {h!r}")
    return found


def _handout_runs():
    """The quick-return's positions as its handout draws them: every plan at the handout's one k_v and k_a."""
    doc = handout(load(example_path("quick-return")), positions=4, lang="sr", start="scene")
    return {r.index: r for r in doc.runs}


def _as_drawn(plan):
    """The plan drawn as the handout's plan blocks draw it (no legend, its detail), as a figure."""
    return draw_plan(plan, lang="sr", legend=False, detail=True)[0].figure


@pytest.fixture(scope="module")
def quick_return_handout():
    return _handout_runs()


@pytest.fixture(scope="module")
def quick_return_page(quick_return_handout):
    plan = quick_return_handout[2].graphical.velocity_plan
    return _as_drawn(plan), plan


@pytest.fixture(scope="module")
def quick_return_acceleration(quick_return_handout):
    # position 2's Coriolis and relative components 1.38 and 1.26 mm long, as a per-position k_a drew them (at the
    # handout's one k_a they are 0.5 mm: notes, no detail): the detail magnifies components that short
    run = quick_return_handout[2]
    plan = construct(run.scene, k_a=0.08, precision=run.graphical.precision).acceleration_plan
    return _as_drawn(plan), plan


@pytest.fixture(scope="module")
def six_bar():
    plan = construct(load(example_path("six-bar"))).velocity_plan
    return draw_plan(plan)[0].figure, plan


def test_quick_return_detail_shows_every_image_and_vector_inside_it(quick_return_page):
    fig, plan = quick_return_page
    assert check_detail(fig, plan) == []
    texts = {t.get_text() for t in _detail_texts(fig).values()}
    # hand-read from the page: a₄, d, e around the pole p, o, c; v_ED (2.58 mm on the plan) drawn at 4 : 1
    assert {"p", "o", "c", "a₄", "d", "e"} <= texts
    gids = {a.get_gid() or "" for a in _artists(fig)}
    ved = next(v for v in plan.vectors if v.label == "v_ED")
    assert abs(ved.tip - ved.tail) < 3.0  # too short for an arrow on the plan...
    assert any(g.endswith("-detail-v_ED") for g in gids)  # ...drawn in the detail
    assert any(g.endswith("-detail-v_ED-head") for g in gids)
    # and its note on the plan says where
    notes = [t.get_text() for ax in fig.axes for t in ax.texts if (t.get_gid() or "").endswith("short-v_ED")]
    # the segment, its length, where it is drawn and how long it is there (a Serbian page; round 20 measured the plan's
    # length in the detail): the detail's ratio as its title states it
    title = next(t.get_text() for ax in fig.axes for t in ax.texts if (t.get_gid() or "").endswith("-detail-name"))
    ratio = int(re.fullmatch(r"Детаљ I \(([0-9]+) : 1\)", title).group(1))
    there = f"{ratio * abs(ved.tip - ved.tail):.2f}".replace(".", ",")
    assert notes and notes[0] == f"de = 1,37 mm (детаљ I: {there} mm)", notes


def test_six_bar_detail_shows_every_image_inside_it(six_bar):
    fig, plan = six_bar
    assert check_detail(fig, plan) == []
    texts = {t.get_text() for t in _detail_texts(fig).values()}
    assert {"a", "b", "c"} <= texts


def test_quick_return_acceleration_short_components_are_magnified(quick_return_acceleration):
    """Review 3 item 8: the Coriolis component a′→k (1.38 mm) and aʳ k→a₄′ (1.26 mm) get a detail with their heads."""
    fig, plan = quick_return_acceleration
    assert check_detail(fig, plan) == []
    texts = {t.get_text() for t in _detail_texts(fig).values()}
    assert {"a′", "k", "a₄′"} <= texts
    gids = {a.get_gid() or "" for a in _artists(fig)}
    for label in ("a^k_A4A3", "a^r_A4A3"):
        v = next(v for v in plan.vectors if v.label == label)
        assert abs(v.tip - v.tail) < 3.0, label  # too short for an arrow on the plan
        assert any(g.endswith(f"-detail-{_gid(label)}-head") for g in gids), label


@pytest.mark.parametrize("which", ["quick_return_page", "six_bar", "quick_return_acceleration"])
def test_detail_labels_overlap_no_label_or_arrowhead(which, request):
    fig, _ = request.getfixturevalue(which)
    assert detail_overlaps(fig) == []


def test_a_planted_omission_fails():
    for name in ("quick-return", "six-bar"):
        scene = load(example_path(name))
        if name == "quick-return":
            plan = _handout_runs()[2].graphical.velocity_plan
            fig = _as_drawn(plan)
        else:
            plan = construct(scene).velocity_plan
            fig = draw_plan(plan)[0].figure
        texts = _detail_texts(fig)
        # an image's label left out
        victim = next(t for gid, t in texts.items() if "-detail-image-" in gid)
        old = victim.get_text()
        victim.set_text("")
        assert check_detail(fig, plan) != [], name
        victim.set_text(old)
        assert check_detail(fig, plan) == [], name
        # a vector left out: its detail artists renamed
        drawn = [a for a in _artists(fig) if "-detail-v" in (a.get_gid() or "")]
        saved = [(a, a.get_gid()) for a in drawn]
        for a in drawn:
            a.set_gid("gone")
        assert any("not drawn in the detail" in p for p in check_detail(fig, plan)), name
        for a, gid in saved:
            a.set_gid(gid)
    # the pole called by one name only (what the detail printed before: "c")
    plan = _handout_runs()[2].graphical.velocity_plan
    fig = _as_drawn(plan)
    for gid, t in _detail_texts(fig).items():
        if gid.endswith("-detail-pole-label") or gid.endswith("-detail-image-o"):
            t.set_text("")
    assert check_detail(fig, plan) != []
