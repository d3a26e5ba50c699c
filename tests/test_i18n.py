"""The terms table: complete in every language, the textbooks' words where domain.md §8 gives them."""

from __future__ import annotations

import re

import pytest

from plans.i18n import LANGUAGES, TERMS, check_language, term

CYRILLIC = re.compile(r"[\u0400-\u04FF]")


@pytest.mark.parametrize("key", sorted(TERMS))
def test_every_term_is_given_in_every_language(key):
    assert set(TERMS[key]) == set(LANGUAGES)
    for lang, words in TERMS[key].items():
        assert words.strip(), f"{key} is empty in {lang}"


@pytest.mark.parametrize("key", sorted(TERMS))
def test_serbian_russian_bulgarian_are_cyrillic_and_slovenian_is_latin(key):
    for lang in ("sr", "ru", "bg"):
        assert CYRILLIC.search(TERMS[key][lang]), f"{key} in {lang} has no Cyrillic letter: {TERMS[key][lang]!r}"
    assert not CYRILLIC.search(TERMS[key]["sl"])
    assert not CYRILLIC.search(TERMS[key]["en"])


@pytest.mark.parametrize(
    "key, lang, words",
    [
        # domain.md §8, as the textbooks write them
        ("velocity_plan", "sr", "План брзина"),
        ("velocity_plan", "ru", "План скоростей"),
        ("velocity_plan", "bg", "План на скоростите"),
        ("velocity_plan", "sl", "Načrt hitrosti"),
        ("acceleration_plan", "sr", "План убрзања"),
        ("acceleration_plan", "ru", "План ускорений"),
        ("acceleration_plan", "bg", "План на ускоренията"),
        ("acceleration_plan", "sl", "Načrt pospeškov"),
        ("mechanism", "sr", "Кинематска шема"),
        ("mechanism", "ru", "План механизма"),
        ("mechanism", "sl", "Kinematska shema"),
        ("scale_factor", "sr", "размера"),
        ("scale_factor", "ru", "масштаб"),
        ("scale_factor", "sl", "merilo"),
        ("assur_group", "ru", "группа Ассура"),
        ("assur_group", "sl", "Assurjeva skupina"),
        ("coriolis_acceleration", "sr", "Кориолисово убрзање"),
        ("coriolis_acceleration", "ru", "ускорение Кориолиса"),
        ("coriolis_acceleration", "sl", "Coriolisov pospešek"),
    ],
)
def test_the_textbook_terms(key, lang, words):
    assert term(key, lang).lower() == words.lower()


def test_the_complex_number_method_is_named_in_the_loop_heading():
    assert "метода комплексних бројева" in term("loop_equations", "sr")
    assert "метод комплексных чисел" in term("loop_equations", "ru")
    assert "metoda kompleksnih števil" in term("loop_equations", "sl")


def test_an_unknown_language_is_refused_naming_the_choices():
    with pytest.raises(ValueError, match=r"no language 'de'; plans speaks en, sr, ru, bg, sl"):
        term("velocity_plan", "de")
    assert check_language("bg") == "bg"
