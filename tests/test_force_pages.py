"""``plans forces -o DIR``, ``plans handout --forces`` and the kinetostatic pages set by Typst (plans.pages.forces).

The numbers a page states are read off the compiled PDF (as a reader reads them) and checked against
domain.md §11 (the worked example), never against the code that set them.
"""

from __future__ import annotations

import base64
import io
import re
import unicodedata

import pypdf
import pytest

from plans.cli import main
from plans.forces.force_plans import construct_force_plans
from plans.graphical import construct
from plans.i18n import term
from plans.pages.document import Document
from plans.pages.forces import force_pages
from plans.pages.typesetting import compile_document
from plans.scene import example_path, load
from review_handouts import built, built_pdf

M_B = 620.218316  # domain.md §11
R_12 = 9646.41888
TOKENS = ("RRR(", "RPR(", "RRP(", "PRP(", "RPP(", "PRR(", "PPR(")


def _pdf_texts(pdf: bytes) -> list[str]:
    """Each page's text as a reader reads it (math italics as plain letters)."""
    return [re.sub(r"[ \t]+", " ", unicodedata.normalize("NFKC", page.extract_text() or "")) for page in pypdf.PdfReader(io.BytesIO(pdf)).pages]


def _number(text: str) -> float:
    return float(text.replace(",", ".").replace("−", "-"))


@pytest.fixture(scope="module")
def worked():
    """The worked example's pages, in English and Russian: (lang -> (Document, ForcePages, page texts))."""
    out = {}
    g = construct(load(example_path("slider-crank-loads")), precision=0.1)
    from plans.forces.analytic import forces_from
    from plans.analytic import solve
    from plans.forces.lever import joukowski_lever

    analytic = forces_from(solve(g.scene))
    for lang in ("en", "ru"):
        doc = Document(g.scene, lang)
        doc.plate = dict(g.scales)
        pages = force_pages(doc, g, lever=joukowski_lever(g), analytic=analytic)
        out[lang] = (doc, pages, _pdf_texts(compile_document(doc.source(), doc.images, "pdf")), g)
    return out


def test_forces_output_draws_every_drawing_and_the_pages(tmp_path, capsys):
    assert main(["forces", "--example", "slider-crank-loads", "-o", str(tmp_path), "--format", "svg", "--precision", "0.1"]) == 0
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["force-plan-1.svg", "force-plan-driver.svg", "free-bodies.svg", "lever.svg", "page-1.svg", "page-2.svg", "page-3.svg"]
    plan = (tmp_path / "force-plan-driver.svg").read_text(encoding="utf-8")
    # the driver's plan states M_b read at 0.1 mm within drafting precision of §11's
    found = re.search(r"= ([0-9.]+) N·m", plan)
    assert found and abs(float(found[1]) - M_B) <= 0.01 * M_B
    lever = (tmp_path / "lever.svg").read_text(encoding="utf-8")
    assert "Joukowski" in lever
    # the group in words in the drawings' headings, never the program's token
    assert "group 3–4" in (tmp_path / "force-plan-1.svg").read_text(encoding="utf-8")
    for name in names:
        assert not any(t in (tmp_path / name).read_text(encoding="utf-8") for t in TOKENS), name
    out = capsys.readouterr().out
    assert "620.2" in out  # the table is still printed


def test_forces_output_pages_in_pdf_deterministic(tmp_path, capsys):
    for d in ("a", "b"):
        assert main(["forces", "--example", "slider-crank-loads", "-o", str(tmp_path / d), "--format", "pdf"]) == 0
    capsys.readouterr()
    assert (tmp_path / "a" / "pages.pdf").read_bytes() == (tmp_path / "b" / "pages.pdf").read_bytes()
    texts = _pdf_texts((tmp_path / "a" / "pages.pdf").read_bytes())
    assert len(texts) == 3  # free bodies, force plans, the lever with the three methods
    assert "Joukowski's lever" in texts[2]


def test_forces_output_per_position_for_an_at_list(tmp_path):
    assert main(["forces", "--example", "four-bar-loads", "--at", "30 deg, 120 deg", "-o", str(tmp_path)]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["position-0", "position-1"]
    assert (tmp_path / "position-1" / "force-plan-driver.svg").is_file()
    assert (tmp_path / "position-1" / "page-2.svg").is_file()


def test_forces_output_refused_with_analytic_only(tmp_path, capsys):
    assert main(["forces", "--example", "slider-crank-loads", "--analytic-only", "-o", str(tmp_path / "out")]) == 2
    assert "--analytic-only" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()  # nothing written


def test_handout_forces_refused_without_loads(tmp_path, capsys):
    assert main(["handout", "--example", "slider-crank", "--forces", "-o", str(tmp_path / "h.pdf")]) == 2
    err = capsys.readouterr().err
    assert "no masses and no loads" in err
    assert not (tmp_path / "h.pdf").exists()


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_the_pages_state_the_worked_example(worked, lang):
    doc, pages, texts, g = worked[lang]
    assert len(texts) == 3
    everything = "\n".join(texts)
    assert term("free_bodies", lang).lower() in everything.lower()
    # the group named in words, the driver's plan by the driving link and what it is (typed here)
    assert {"en": "Force plan: group 3–4 (II2)", "ru": "План сил: группа 3–4 (II2)"}[lang] in everything
    assert f"{term('force_plan', lang)}: " + {"en": "driving link 2 (crank)", "ru": "ведущее звено 2 (кривошип)"}[lang] in everything
    # R_12 read on the plans' page: drawn mm × the page's μ_F, within drafting precision of §11's
    mu = pages.mu_F
    found = re.search(r"R12 = ([0-9.,]+) (?:mm|мм) · ([0-9.,]+) (?:N|Н)/(?:mm|мм) = ([0-9.,]+) (?:N|Н)", texts[1])
    assert found, texts[1]
    length, stated_mu, value = (_number(x) for x in found.groups())
    assert stated_mu == mu
    assert value == pytest.approx(length * mu, abs=mu * 0.05)  # what the page says is drawn length × μ_F
    assert abs(value - R_12) <= 2 * 0.1 * mu + 9 * 0.1 * g.scales["k_a"]
    # the plan is drawn at the scale the page states: its construction at that μ_F reads the same length
    plan = next(p for p in construct_force_plans(g, mu_F=mu).plans if p.group == "driver")
    r = next(v for v in plan.vectors if v.label == "R_12")
    assert round(r.length, 1) == pytest.approx(length)
    # M_b with its sense (counter-clockwise on the crank, §11) by the force plans and by the lever
    for page in texts[1:]:
        m = re.search(r"M(?:b|ур) = [^\n]*?([0-9.,]+) (?:N|Н)·(?:m|м) ([↺↻])", page)
        assert m, page
        assert m[2] == "↺"
        assert abs(_number(m[1]) - M_B) <= 0.01 * M_B


def test_the_three_methods_side_by_side(worked):
    doc, pages, texts, g = worked["en"]
    row = re.search(r"Mb \[N·m\] ([0-9.]+) ([0-9.]+) ([0-9.]+) ([0-9.]+) ([0-9.]+)", texts[2])
    assert row, texts[2]
    analytic, plans_value, plans_delta, lever_value, lever_delta = (float(x) for x in row.groups())
    # the three values of the row to the same decimals (the readings'), the analytic one M_B rounded to them
    places = {len(row[k].partition(".")[2]) for k in (1, 2, 4)}
    assert len(places) == 1, row.group(0)
    assert abs(analytic - M_B) <= 0.5 * 10 ** -places.pop() + 1e-9
    for value, delta in ((plans_value, plans_delta), (lever_value, lever_delta)):
        assert abs(value - M_B) <= 0.01 * M_B
        # the difference the page states is that of the printed numbers (teacher's review: a reader recomputes it)
        assert delta == pytest.approx(100 * abs(value - analytic) / analytic, abs=0.0051)
    r12 = re.search(r"R12 \[N\] ([0-9.]+) ∠ ([0-9.]+)°", texts[2])
    assert float(r12[1]) == pytest.approx(R_12, abs=0.5) and float(r12[2]) == pytest.approx(199.942051, abs=0.05)


def test_the_title_block_states_the_force_scale(worked):
    for lang, (doc, pages, texts, g) in worked.items():
        unit = "N/mm" if lang == "en" else "Н/мм"
        stated = f"μF = {pages.mu_F:g} {unit}"
        # the free bodies' page (the loads in mm at μ_F), the plans' page and the lever's (its three methods' table reads
        # the force plans at μ_F; a teacher's review, issue 20, found it missing there) carry μ_F in the title block's scales
        for page in texts[:3]:
            block = page[page.rindex(term("scale_factors", lang)):]
            assert stated in block, block


def _embedded(svg: bytes) -> list[tuple[bytes, float, float]]:
    """(SVG bytes, width, height [mm]) of every drawing a Typst SVG page embeds."""
    out = []
    for m in re.finditer(rb'<image[^>]*?xlink:href="data:image/svg\+xml;base64,([^"]+)"[^>]*?>', svg):
        tag = m.group(0)
        w = float(re.search(rb'width="([0-9.]+)"', tag)[1])
        h = float(re.search(rb'height="([0-9.]+)"', tag)[1])
        out.append((base64.b64decode(m[1]), w * 25.4 / 72, h * 25.4 / 72))
    return out


def test_the_drawings_are_placed_at_100_percent(worked):
    doc, pages, _, _ = worked["en"]
    placed = [e for page in compile_document(doc.source(), doc.images, "svg") for e in _embedded(page)]
    found = 0
    for key, kind in pages.images.items():
        svg = doc.images[key]
        width = float(re.search(rb'<svg[^>]*?width="([0-9.]+)mm"', svg)[1])  # the drawing's own physical size
        matches = [(w, h) for data, w, h in placed if data == svg]
        assert matches, key
        for w, _ in matches:
            assert w == pytest.approx(width, abs=0.05), (key, w, width)
        found += 1
    assert set(pages.images.values()) == {"free-bodies", "plan:RRP(3,4)", "plan:driver", "lever"}
    assert found == 4


def test_a_plan_fits_its_cell_and_mu_is_round(worked):
    doc, pages, _, _ = worked["en"]
    assert re.fullmatch(r"(1|1\.2|1\.5|2|2\.5|3|4|5|6|8)", f"{pages.mu_F / 10 ** int(__import__('math').floor(__import__('math').log10(pages.mu_F))):g}")
    for key in pages.images:
        assert doc.sizes[key][0] <= doc.page.text_width + 0.5


@pytest.fixture(scope="module")
def six_bar_en():
    return built("six-bar-loads", forces=True), _pdf_texts(built_pdf("six-bar-loads", forces=True))


@pytest.fixture(scope="module")
def quick_return_sr():
    return built("quick-return-loads", None, "sr", forces=True), _pdf_texts(built_pdf("quick-return-loads", None, "sr", forces=True))


def _force_pages(texts, lang):
    return [t for t in texts if term("kinetostatics", lang) in t]


def test_no_program_token_on_any_force_page(six_bar_en, quick_return_sr):
    for (doc, texts), lang in ((six_bar_en, "en"), (quick_return_sr, "sr")):
        force = _force_pages(texts, lang)
        # free bodies, force plans (their equations under them, or on a page after them when the plans would lose
        # too much for them), the lever (and the three methods under it, or on a page after it: the lever is the
        # velocity plan at the plate's k_v, which a one-position plate draws large)
        assert len(force) in (3, 4, 5), len(force)
        for page in force:
            assert not any(t in page for t in TOKENS), page
        for key, svg in doc.images.items():
            if key.startswith("forces-"):
                assert not any(t.encode() in svg for t in TOKENS), key
    assert "group 5–6" in "".join(_force_pages(six_bar_en[1], "en"))


def test_no_english_word_on_the_serbian_force_pages(quick_return_sr):
    doc, texts = quick_return_sr
    for page in _force_pages(texts, "sr"):
        # symbols (k_l, μ_F, R12, Mb, lOA, II) and units (mm, N) are the course's; no Latin word of three letters or more
        words = {w for w in re.findall(r"[A-Za-z]{3,}", page) if not re.fullmatch(r"l[A-Z]{2}", w)}
        assert not words, words
    assert "План сила: група 3–4" in "".join(_force_pages(texts, "sr"))


def test_six_bar_plans_at_one_mu_stated_on_its_page(six_bar_en):
    doc, texts = six_bar_en
    plans_page = next(t for t in _force_pages(texts, "en") if "force plans; μF =" in t)
    mu = re.search(r"force plans; μF = ([0-9.]+) N/mm", plans_page)[1]
    used = set(re.findall(r"mm · ([0-9.]+) N/mm", plans_page))
    assert used == {mu}
    assert f"μF = {mu} N/mm" in plans_page[plans_page.rindex("Scale factors"):]


def test_the_forces_table_names_the_groups_as_the_course_does(capsys):
    assert main(["forces", "--example", "six-bar-loads"]) == 0
    heading = capsys.readouterr().out.splitlines()[1]
    # six-bar: the four-bar's RRR group (class II, kind 1), then the sleeve's RPR group (kind 3)
    assert heading == "Kinetostatic analysis: I(1,2) → II₁(3,4) → II₃(5,6)"
    assert not any(t in heading for t in TOKENS)
