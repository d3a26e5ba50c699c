"""Units as the Russian and Bulgarian courses write them, and nothing else turned Cyrillic: the image m′ of a point
M in a readings table stays a Latin letter (a fresh-eye review found "π м′" on a Russian sheet)."""

import pytest

from plans._text import course_units


@pytest.mark.parametrize("lang", ["ru", "bg"])
def test_units_turn_cyrillic(lang):
    assert course_units("OA = 0.15 m; k_l = 0.002 m/mm; 12.5 mm; v = 3 m/s; a = 2 m/s²; ω = 6 rad/s", lang) == (
        "OA = 0.15 м; k_l = 0.002 м/мм; 12.5 мм; v = 3 м/с; a = 2 м/с²; ω = 6 рад/с")


@pytest.mark.parametrize("cell", ["π m′", "m₁ m″", "πm′", "π m′ 12.5 mm"])
def test_an_image_named_m_stays_latin(cell):
    assert course_units(cell, "ru") == cell.replace("mm", "мм")


def test_other_languages_untouched():
    assert course_units("π m′ = 12.5 mm", "sr") == "π m′ = 12.5 mm"
