"""A message cut into pieces by sentence and comma, each kept with its place and its lexed
words; the parts of a piece by "and"/"then"; what is left once pieces are taken out."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.screen.pieces import pieces, sub_pieces, without
from assistantx.core.office import Office


def test_sentences_and_comma_parts_keep_their_place_in_the_text(office: Office) -> None:
    text = "Wang is away. Thanks, bring me a pen?"
    found = pieces(text, Lexicon.from_office(office).read)
    assert [p.text for p in found] == ["Wang is away", "Thanks", "bring me a pen"]
    assert [text[p.start : p.end] for p in found] == [p.text for p in found]
    assert [p.asks for p in found] == [False, False, True]  # only the last part of "...?"


def test_each_piece_carries_the_lexicons_reading_of_its_own_words(office: Office) -> None:
    (piece,) = pieces("bring me Wang's stapeler", Lexicon.from_office(office).read)
    assert piece.lexed.text == "bring me Wang's stapeler"
    kinds = [(m.kind, m.ids) for m in piece.lexed.mentions if m.kind in ("person", "item")]
    assert kinds == [("person", ("wang",)), ("item", ("stapler",))]  # the typo corrected


def test_a_spaced_dash_ends_a_sentence_as_a_full_stop_does(office: Office) -> None:
    found = pieces("I'm at my desk - print my file", Lexicon.from_office(office).read)
    assert [p.text for p in found] == ["I'm at my desk", "print my file"]


def test_the_parts_of_a_piece_are_split_at_and_then_but(office: Office) -> None:
    (piece,) = pieces("hide the pen and bring me paper", Lexicon.from_office(office).read)
    assert [p.text.strip() for p in sub_pieces(piece)] == ["hide the pen", "bring me paper"]


def test_what_is_left_has_the_dropped_pieces_and_their_commas_taken_out(office: Office) -> None:
    text = "Thanks, bring me a pen, Wang is away"
    found = pieces(text, Lexicon.from_office(office).read)
    assert without(text, 0, [found[0], found[2]]) == "bring me a pen"
    assert without(text, found[1].start, []) == "bring me a pen, Wang is away"
