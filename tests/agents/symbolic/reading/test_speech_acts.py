"""The speech-act stage: each piece's acts read once from its words, with the message's
deferral read once for all its pieces."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.screen.english import split_words
from assistantx.agents.symbolic.reading.speech import SpeechActs
from assistantx.agents.symbolic.reading.speech_acts import Acts, acts_reader, without_fillers
from assistantx.core.office import Office

_SPEAKER = frozenset({"i", "me", "my", "we"})


@pytest.fixture(scope="module")
def speech(office: Office) -> SpeechActs:
    return SpeechActs(Lexicon.from_office(office))


@pytest.fixture(scope="module")
def read(speech: SpeechActs) -> Callable[[str, bool], Acts]:
    """One piece read alone, as the whole of its message."""

    def acts(text: str, asks: bool = False) -> Acts:
        words = split_words(text)
        return acts_reader(speech, _SPEAKER, words)(words, asks)

    return acts


def test_a_command_is_a_request_and_nothing_else(read: Callable[..., Acts]) -> None:
    acts = read("bring me a stapler")
    assert acts.request and acts.imperative
    assert acts.question is None and acts.thanks is None and not acts.statement
    assert not acts.withdrawal and not acts.wish and acts.note is None


def test_a_question_is_told_polite_or_asking_for_information(read: Callable[..., Acts]) -> None:
    assert read("could you bring me a pen", True).question == "polite"
    asked = read("who has a stapler", True)
    assert asked.question == "info" and not asked.request
    assert read("can you even carry a stapler", True).doubts_ability


def test_thanks_and_thanks_to_pass_on(read: Callable[..., Acts]) -> None:
    own = read("thanks for the stapler")
    assert own.thanks is not None and not own.thanks.relay
    relayed = read("say thanks to Wang for the stapler")
    assert relayed.thanks is not None and relayed.thanks.relay


def test_a_withdrawal_is_read_through_its_fillers(read: Callable[..., Acts]) -> None:
    assert read("oh actually forget about the scissors").withdrawal
    assert without_fillers(["oh", "ok", "never", "mind"]) == ["never", "mind"]
    assert not read("bring me the scissors").withdrawal


def test_a_third_persons_need_is_not_the_speakers(read: Callable[..., Acts]) -> None:
    assert read("Min needs scissors").need
    assert not read("I need scissors").need


def test_a_note_keeps_its_words_and_says_whether_they_ask(read: Callable[..., Acts]) -> None:
    kept = read("for the record the tape ran out")
    assert kept.note == ("the", "tape", "ran", "out") and not kept.note_asks
    assert read("please note I need a ruler").note_asks


def test_a_message_that_puts_its_asking_off_makes_a_later_want_one_for_later(
    speech: SpeechActs,
) -> None:
    piece = split_words("could I borrow the ruler later")
    put_off = acts_reader(
        speech, _SPEAKER, split_words("could I borrow the ruler later? I'll let you know")
    )
    asked_now = acts_reader(speech, _SPEAKER, piece)
    assert put_off(piece, True).future_need and put_off(piece, True).later
    assert not asked_now(piece, True).future_need
    assert put_off(split_words("I'll let you know"), False).defers
