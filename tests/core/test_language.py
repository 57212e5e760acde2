"""The reader's language libraries: morphology, word knowledge, typo distance, Unicode keys."""

from __future__ import annotations

import unicodedata

import pytest

from assistantx.core import language


@pytest.mark.parametrize(
    ("verb", "form"),
    [
        ("bind", "bound"),
        ("bring", "brought"),
        ("get", "got"),
        ("scan", "scanned"),
        ("copy", "copied"),
        ("shred", "shredded"),
        ("fax", "faxed"),
        ("print", "printing"),
    ],
)
def test_verb_forms_include_the_irregular_ones(verb: str, form: str) -> None:
    assert form in language.verb_forms(verb)


def test_a_phrase_inflects_its_first_word() -> None:
    assert "sealed in plastic" in language.verb_forms("seal in plastic")


@pytest.mark.parametrize(
    ("noun", "plural"),
    [
        ("scissors", "scissors"),
        ("box", "boxes"),
        ("battery", "batteries"),
        ("tape dispenser", "tape dispensers"),
        ("knife", "knives"),
    ],
)
def test_plurals(noun: str, plural: str) -> None:
    assert language.plural(noun) == plural


@pytest.mark.parametrize(
    "word",
    [
        "grace",
        "mark",
        "will",
        "sun",
        "summer",
        "frank",
        "sandy",
        "penny",
        "chase",
        "skip",
        "honest",
        "joy",
        "hope",
    ],
)
def test_names_that_are_also_english_words(word: str) -> None:
    assert language.is_english_word(word)


@pytest.mark.parametrize("word", ["zhang", "okafor", "obi", "mueller", "jie", "lindqvist"])
def test_names_that_are_no_english_words(word: str) -> None:
    assert not language.is_english_word(word)


@pytest.mark.parametrize(
    ("typed", "vocabulary", "meant"),
    [
        ("pnes", ["pens", "pen", "paper"], ["pens"]),  # four letters, one swap
        ("cpoy", ["copy", "cup"], ["copy"]),
        ("staplr", ["stapler", "staple"], ["stapler"]),  # tie broken by indels
        ("calcualtor", ["calculator"], ["calculator"]),
        ("highlgihter", ["highlighter"], ["highlighter"]),  # two edits in a long word
    ],
)
def test_typos_within_a_length_aware_limit(
    typed: str, vocabulary: list[str], meant: list[str]
) -> None:
    assert language.closest(typed, vocabulary) == meant


@pytest.mark.parametrize(
    ("typed", "vocabulary"), [("pen", ["pan"]), ("mugs", ["rugby"]), ("stpl", ["stapler"])]
)
def test_short_or_distant_words_are_not_corrected(typed: str, vocabulary: list[str]) -> None:
    assert language.closest(typed, vocabulary) == []


def test_folding_is_case_and_diacritics_blind() -> None:
    assert language.fold("José Müller") == language.fold("JOSE MULLER") == "jose muller"
    assert language.words("José Müller's ﬁle") == ["jose", "mullers", "file"]


@pytest.mark.parametrize(
    ("written", "typed"), [("Bjørn Søndergaard", "bjorn sondergaard"), ("Łukasz", "lukasz")]
)
def test_a_letter_with_a_stroke_folds_to_the_plain_letter(written: str, typed: str) -> None:
    assert language.fold(written) == language.fold(typed) == typed


def test_finite_verbs() -> None:
    assert language.is_finite_verb("hurt") and language.is_finite_verb("needs")
    assert not language.is_finite_verb("deck") and not language.is_finite_verb("period")


def test_spellings_said_alike_and_spelled_nearly_are_found() -> None:
    """The pronouncing dictionary says "li" and "lee", "jon" and "john", "ann" and "anne"
    alike; "lei" and "lin" are said differently; a word it lacks has no match."""
    alike = language.sound_alike_spellings(
        ["li", "lee", "lei", "lin", "jon", "john", "ann", "anne"]
    )
    assert alike["li"] == {"lee"} and alike["lee"] == {"li"}
    assert alike["jon"] == {"john"} and alike["ann"] == {"anne"}
    assert "lei" not in alike and "lin" not in alike
    assert language.sound_alike_spellings(["zxqv", "li"]) == {}


def test_pronunciations_asked_again_are_the_same_and_each_callers_own() -> None:
    """The answer for a set of words is kept (readers of one office ask the same words over
    and over); a caller that changes what it got does not change what the next one gets."""
    first = language.pronunciations(["Li", "lee", "zxqv"])
    assert first == {"li": frozenset({"L IY"}), "lee": frozenset({"L IY"})}
    first["li"] = frozenset({"changed"})
    del first["lee"]
    again = language.pronunciations(["lee", "li", "zxqv", "LI"])
    assert again == {"li": frozenset({"L IY"}), "lee": frozenset({"L IY"})}
    assert language.pronunciations(["zxqv", "1234"]) == {}


def test_plural_and_mass_nouns_come_from_the_dictionary() -> None:
    assert language.is_plural_noun("handling gloves") and language.is_plural_noun("scissors")
    assert not language.is_plural_noun("glass") and not language.is_plural_noun("gaffer tape")
    assert language.is_mass_noun("glue") and language.is_mass_noun("stationery")
    assert not language.is_mass_noun("battery") and not language.is_mass_noun("gloves")


@pytest.mark.parametrize("word", ["rebinding", "reprint", "binder", "rebacking", "unbinding"])
def test_word_forms(word: str) -> None:
    """The dictionary's forms, words in use, and a verb prefix on a word form."""
    assert language.is_word_form(word)


@pytest.mark.parametrize("word", ["pirnt", "rebnid", "stapeler", "cpoy", "printe"])
def test_typos_are_no_word_forms(word: str) -> None:
    assert not language.is_word_form(word)


@pytest.mark.parametrize("text", ["Siân's stool", "Trần Bảo Châu", "Zoë’s"])
def test_a_decomposed_accent_stays_in_its_word(text: str) -> None:
    """Text pasted in the decomposed form (a letter, then its combining accent) splits into
    the same words as the composed form, and they fold alike."""
    decomposed = unicodedata.normalize("NFD", text)
    assert decomposed != text
    found = [language.fold(m.group(0)) for m in language.WORD.finditer(decomposed)]
    assert found == [language.fold(m.group(0)) for m in language.WORD.finditer(text)]


def test_a_soft_c_typed_as_said_finds_its_word() -> None:
    """ "servisd" is two edits from "serviced" as spelled, one as said ("servised"); the
    soft "c" is only a second look, when nothing is near as spelled."""
    assert language.closest("servisd", ["service", "serviced", "servers"]) == ["serviced"]
    assert language.closest("servisd", ["scarves"]) == []  # a hard "c" is no "s"
