"""A message cut into pieces by sentence and comma, each kept with its place and its lexed
words; the parts of a piece by "and"/"then"; what is left once pieces are taken out."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.screen.english import split_words
from assistantx.agents.symbolic.reading.screen.pieces import Piece, pieces, sub_pieces, without
from assistantx.agents.symbolic.reading.speech import SpeechActs
from assistantx.agents.symbolic.reading.speech_acts import acts_reader
from assistantx.core.office import Office


def _cut(office: Office, text: str) -> list[Piece]:
    lex = Lexicon.from_office(office)
    acts = acts_reader(SpeechActs(lex), frozenset({"i", "me"}), split_words(text))
    return pieces(text, lex.read, acts)


def test_sentences_and_comma_parts_keep_their_place_in_the_text(office: Office) -> None:
    text = "Wang is away. Thanks, bring me a pen?"
    found = _cut(office, text)
    assert [p.text for p in found] == ["Wang is away", "Thanks", "bring me a pen"]
    assert [text[p.start : p.end] for p in found] == [p.text for p in found]
    assert [p.asks for p in found] == [False, False, True]  # only the last part of "...?"


def test_each_piece_carries_the_lexicons_reading_of_its_own_words(office: Office) -> None:
    (piece,) = _cut(office, "bring me Wang's stapeler")
    assert piece.lexed.text == "bring me Wang's stapeler"
    kinds = [(m.kind, m.ids) for m in piece.lexed.mentions if m.kind in ("person", "item")]
    assert kinds == [("person", ("wang",)), ("item", ("stapler",))]  # the typo corrected


def test_each_piece_carries_what_it_does_read_by_the_speech_acts(office: Office) -> None:
    thanks, request = _cut(office, "Thanks, could you bring me a pen?")
    assert thanks.acts.thanks is not None and not thanks.acts.request
    assert request.acts.request and request.acts.question == "polite" and request.asks
    assert request.acts.thanks is None


def test_a_spaced_dash_ends_a_sentence_as_a_full_stop_does(office: Office) -> None:
    found = _cut(office, "I'm at my desk - print my file")
    assert [p.text for p in found] == ["I'm at my desk", "print my file"]


def test_the_parts_of_a_piece_are_split_at_and_then_but(office: Office) -> None:
    (piece,) = _cut(office, "hide the pen and bring me paper")
    assert [p.text.strip() for p in sub_pieces(piece)] == ["hide the pen", "bring me paper"]


def test_what_is_left_has_the_dropped_pieces_and_their_commas_taken_out(office: Office) -> None:
    text = "Thanks, bring me a pen, Wang is away"
    found = _cut(office, text)
    assert without(text, 0, [found[0], found[2]]) == "bring me a pen"
    assert without(text, found[1].start, []) == "bring me a pen, Wang is away"
