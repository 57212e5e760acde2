"""``name_reading.slot_at``: the one place where the reader's lexicon and the consent guard
take a name word's neighbours, so both read "penny" in "give penny a pen" alike."""

from __future__ import annotations

from dataclasses import dataclass

from assistantx.core.name_reading import NameSlot, read_name, slot_at


@dataclass(frozen=True)
class _W:
    text: str
    word: str
    possessive: bool = False
    opens: bool = False
    after_pause: bool = False  # a comma before it


def _words(*spec: str) -> list[_W]:
    """Words as written; a leading "|" opens a sentence, a trailing "'s" is possessive."""
    out = []
    for n, raw in enumerate(spec):
        opens = n == 0 or raw.startswith("|")
        bare = raw.lstrip("|")
        possessive = bare.endswith("'s")
        bare = bare.removesuffix("'s")
        out.append(_W(bare, bare.lower(), possessive, opens))
    return out


def test_the_neighbours_and_what_the_office_says_of_the_next_word() -> None:
    words = _words("give", "penny", "a", "pen")
    assert slot_at(words, 1, items={"pen"}, name_words={"penny"}) == NameSlot(
        word="penny", written="penny", prev="give", next="a", after_next="pen", prev_opens=True
    )
    slot = slot_at(_words("give", "penny", "pens"), 1, items={"pens"}, name_words=set())
    assert slot.next_is_item and not slot.next_is_name
    slot = slot_at(_words("to", "penny", "Ivy's"), 1, items=set(), name_words={"ivy"})
    assert slot.next_is_name and slot.next_possessive


def test_the_next_word_stops_at_a_sentence_end_the_previous_one_does_not() -> None:
    slot = slot_at(_words("thanks", "Mark", "|Will", "you"), 1, items=set(), name_words=set())
    assert (slot.prev, slot.next) == ("thanks", "")
    slot = slot_at(_words("thanks", "|Mark", "is", "here"), 1, items=set(), name_words=set())
    assert slot.opens and slot.prev == "thanks"


def test_whether_the_word_before_opens_and_the_word_after_the_next_is_a_name() -> None:
    """ "is tam in?", "are tam and wren in?": the question's opening verb, the name joined."""
    slot = slot_at(_words("are", "tam", "and", "wren"), 1, items=set(), name_words={"wren"})
    assert slot.prev_opens and slot.after_next_is_name
    slot = slot_at(_words("so", "is", "tam", "in"), 2, items=set(), name_words=set())
    assert not slot.prev_opens and not slot.after_next_is_name


def test_a_title_declared_with_its_article() -> None:
    words = _words("ask", "the", "Provost")
    declared = slot_at(words, 2, items=set(), name_words=set(), with_article={("the", "provost")})
    plain = slot_at(words, 2, items=set(), name_words=set())
    assert declared.declared_with_prev and not plain.declared_with_prev
    assert read_name(declared) == "person"


def test_a_pause_before_the_next_word_is_taken() -> None:
    """ "to Mark, it's urgent": the comma keeps "it" from making "Mark" a verb."""
    words = [_W("to", "to"), _W("Mark", "mark"), _W("it", "it", after_pause=True)]
    assert slot_at(words, 1, items=set(), name_words=set()).next_after_pause
    words = [_W("to", "to"), _W("mark", "mark"), _W("it", "it")]
    assert not slot_at(words, 1, items=set(), name_words=set()).next_after_pause
