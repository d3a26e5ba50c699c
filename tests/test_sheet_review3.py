"""Issue 20 (a teacher's review of the A3 sheets): what the printed sheet says must be checkable from the sheet.

Expected values come from the printed numbers themselves and from the scene file's numbers, never from the code
that printed them.
"""

from __future__ import annotations

import math
import re

import pytest

from plans.cli import main
from test_tables_readings import _number, results_table, sheet_lines


def _half_unit(text: str) -> float:
    """Half a unit of the last printed digit of a number as printed (``17680`` → 0.5 for 4+ digits shown)."""
    text = text.strip().replace("−", "-")
    if "·10" in text:
        mantissa, exponent = text.split("·10")
        from test_tables_readings import SUPERSCRIPT

        decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
        return 0.5 * 10 ** (int(exponent.translate(SUPERSCRIPT)) - decimals)
    decimals = len(text.split(".")[1]) if "." in text else 0
    return 0.5 * 10 ** -decimals


def _magnitude(cell: str) -> tuple[float, float]:
    """A cell's printed magnitude and half a unit of its last digit."""
    magnitude = cell.split("∠")[0]
    return _number(magnitude), _half_unit(magnitude)


@pytest.fixture(scope="module", params=[4, 3])
def slider_crank_sheets(request, tmp_path_factory):
    out = tmp_path_factory.mktemp("sc")
    assert main(["draw", "--example", "slider-crank", "--positions", str(request.param), "--format", "pdf", "-o", str(out), "-q"]) == 0
    return sorted(out.glob("sheet-*.pdf"))


def test_every_printed_error_is_the_error_of_the_two_printed_numbers(slider_crank_sheets):
    """|g − a|/|a| from the printed graphical and analytic values (each ± half its last digit) contains the printed
    relative error (± half its last digit): a reader can recompute the error from the row."""
    assert len(slider_crank_sheets) in (3, 4)
    checked = 0
    for path in slider_crank_sheets:
        for (name, unit), (g, a, e) in results_table(sheet_lines(path)).items():
            if e == "—" or "∠" in g and g.split("∠")[1] != a.split("∠")[1]:
                continue
            (gv, gh), (av, ah), (ev, eh) = _magnitude(g), _magnitude(a), (_number(e), _half_unit(e))
            if "∠" not in g:
                low = max(0.0, abs(gv - av) - gh - ah) / (abs(av) + ah)
                high = (abs(gv - av) + gh + ah) / max(abs(av) - ah, 1e-300)
            else:
                low = max(0.0, abs(gv - av) - gh - ah) / (abs(av) + ah)
                high = (abs(gv - av) + gh + ah) / max(abs(av) - ah, 1e-300)
            assert low <= ev + eh and ev - eh <= high, f"{path.name}: {name} [{unit}] {g} | {a} | {e}: the numbers give {low:.2e} … {high:.2e}"
            checked += 1
    assert checked >= 9


def test_the_slider_crank_data_lines_state_the_guide_s_offset_from_the_crank_pivot():
    """The offset e of the cylinder's line: the perpendicular distance from O (0, 0) to the line through (0, 50 mm)
    at 0° (plans/examples/slider-crank.toml), |(0 − 0)·sin 0 − (0 − 50)·cos 0| = 50 mm, in every language's words."""
    import plans
    from plans.pages.words import scene_data_lines

    scene = plans.load(plans.example_path("slider-crank"))
    origin, angle, pivot = complex(0, 50), 0.0, 0j  # the TOML's through, angle and O [mm, rad]
    e = abs((pivot.real - origin.real) * math.sin(angle) - (pivot.imag - origin.imag) * math.cos(angle))
    words = {"en": ("slider guide at", "from"), "sr": ("вођица клизача под углом", "од"), "ru": ("направляющая ползуна под углом", "от"),
             "bg": ("водач на плъзгача под ъгъл", "от"), "sl": ("vodilo drsnika pod kotom", "od")}
    for lang, (guide, from_word) in words.items():
        text = " ".join(scene_data_lines(scene, lang))
        assert f"{guide} 0°, e = {e:g} mm {from_word} O" in text, text


def test_a_guide_off_the_crank_pivot_states_its_distance_from_it():
    """The quick-return's ram line y = 520 mm at 0° and its crank's pivot O (0, 250 mm): e = 270 mm."""
    import plans
    from plans.pages.words import scene_data_lines

    text = " ".join(scene_data_lines(plans.load(plans.example_path("quick-return")), "en"))
    assert re.search(r" at 0°, e = 270 mm from O\b", text), text


def test_the_quick_return_sheet_names_the_ram_s_guide_not_the_ram(tmp_path):
    """sr: the condition of v_EE1 and the fixed line are the slider's guide (вођица клизача), not the slider (клизач)."""
    out = tmp_path / "qr.pdf"
    assert main(["draw", "--example", "quick-return", "--lang", "sr", "--format", "pdf", "-o", str(out), "-q"]) == 0
    text = "\n".join(sheet_lines(out))
    assert "вођица клизача под углом 0°" in text and "∥ вођица клизача" in text, text
    assert not re.search(r"(∥ клизач|клизач под)", text.replace("вођица клизача", "")), text


def test_a_guide_name_that_contains_its_key_is_named_once(tmp_path):
    """en: the guide ``ram`` is called "ram guide": the data line says "ram guide at 0°", never "ram guide guide"."""
    out = tmp_path / "qr.pdf"
    assert main(["draw", "--example", "quick-return", "--format", "pdf", "-o", str(out), "-q"]) == 0
    text = "\n".join(sheet_lines(out))
    assert "ram guide at 0°" in text and "∥ ram guide" in text and "guide guide" not in text, text


def _read_before(a, b) -> bool:
    """Whether drawing box *a* (x0, y0, x1, y1) [mm] is read before *b*: side by side (their heights overlap) the left
    one first, one over the other the upper one first."""
    if a[1] < b[3] and b[1] < a[3]:
        return a[0] < b[0]
    return a[1] < b[1]


@pytest.mark.parametrize("example, lang, positions", [("slider-crank", "sr", 4), ("four-bar", "ru", None)])
def test_the_velocity_plan_is_read_before_the_acceleration_plan(example, lang, positions, tmp_path):
    """The textbook's order, scheme → velocity plan → acceleration plan: the sheets the review found the acceleration
    plan left of / over the velocity plan keep the order, read from where their images are embedded."""
    from sheet_pages import by_kind

    args = ["draw", "--example", example, "--lang", lang, "-q", "-o", str(tmp_path if positions else tmp_path / "sheet.svg")]
    assert main(args + (["--positions", str(positions)] if positions else [])) == 0
    pages = sorted(tmp_path.glob("sheet*.svg"))
    assert len(pages) == (positions or 1)
    for page in pages:
        placed = by_kind(page.read_bytes())
        mechanism, velocity, acceleration = placed["mechanism"].box, placed["velocity"].box, placed["acceleration"].box
        assert _read_before(mechanism, velocity) and _read_before(velocity, acceleration), (page.name, mechanism, velocity, acceleration)
