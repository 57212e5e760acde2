""" "can he have a coffee", "could she borrow my stapler": a thing asked for whom a modal's
"she"/"he" means. With nobody named before it the pronoun is asked about, never read as the
speaker (the coffee was made for the speaker); with one colleague named before, it is that
colleague; with several, which one is asked. Help ("can she have a look") and a thing said
before ("can he have it") are no such request."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.reading import answered_reader, frame_reader

_OFFICE = load_office()
_frame = frame_reader(load_office, "zhang")
_answered = answered_reader(load_office, "zhang")


@pytest.mark.parametrize(
    ("text", "pronoun"),
    [
        ("can he have a coffee", "he"),
        ("can she please have a coffee", "she"),
        ("could she borrow my stapler", "she"),
        ("could he use the scissors", "he"),
    ],
)
def test_nobody_named_is_asked(text: str, pronoun: str) -> None:
    frame = _frame(text)
    assert not frame.tasks, frame
    assert frame.question == f"Who do you mean by {pronoun!r}? Please tell me their name."


@pytest.mark.parametrize(
    ("answer", "recipient"), [("Mao", "mao"), ("Mao Jun", "mao"), ("me", "zhang")]
)
def test_the_answer_names_who_has_it(answer: str, recipient: str) -> None:
    frame = _answered("can he have a coffee", [answer])
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("produce", "coffee", recipient)
    ], frame


def test_borrowed_for_the_one_answered() -> None:
    frame = _answered("could she borrow my stapler", ["Sun"])
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "zhang", "sun")]


def test_one_colleague_named_before_has_it() -> None:
    frame = _frame("Mao is here, can he have a coffee")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "coffee", "mao")]
    stm = memory("zhang", "Mao is here, can he have a coffee")
    assert "mao" in named_recipients(_OFFICE, stm)


def test_two_colleagues_named_before_asks_which() -> None:
    frame = _frame("Mao and Sun are here, can he have a coffee")
    assert not frame.tasks, frame
    assert frame.question == "Who do you mean by 'he': Mao Jun or Sun Li?"


@pytest.mark.parametrize(
    "text",
    [
        "can she have a look at my report",  # help asked, no thing had
        "can he have it by friday",  # a thing said before: nothing to give yet
    ],
)
def test_no_thing_had_asks_no_pronoun(text: str) -> None:
    frame = _frame(text)
    assert "by 'she'" not in (frame.question or "") and "by 'he'" not in (frame.question or "")


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("can I have a coffee", "zhang"),  # the speaker's own
        ("can you get me a coffee", "zhang"),
        ("can Mao have a coffee", "mao"),
    ],
)
def test_must_not_change(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert [t.recipient for t in frame.tasks] == [recipient], frame
