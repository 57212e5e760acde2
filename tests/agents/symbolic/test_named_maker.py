"""A colleague asked to make a thing is its maker only where they look after a machine that
makes it (issue 23): "could Wang make one? I need a coffee" made the coffee with the coffee
machine's keepers and no word about Wang. The office's own data says who can make it: a keeper
named makes it (``named_maker``); anyone else is said not to, and the requester is asked before
the keepers make it instead. A name after the verb ("can you make Wang one") is whom it is for.
"""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import answered_reader, frame_reader

_DEFAULT = frame_reader(default_office, "mao")  # the coffee machine: Gao Min, Sun Li
_HARBOUR = frame_reader(harbour_office, "will")  # the kettle: Hope Mensah, Ken Abara
_DEFAULT_ANSWERED = answered_reader(default_office, "mao")
_HARBOUR_ANSWERED = answered_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("reader", "text", "said"),
    [
        # the class's analogue, and the same ask said after the need or in one clause
        (
            _DEFAULT,
            "could Wang make one? I need a coffee",
            "Wang Fang doesn't look after the coffee machine",
        ),
        (
            _DEFAULT,
            "I need a coffee, could Wang make one?",
            "Wang Fang doesn't look after the coffee machine",
        ),
        (
            _DEFAULT,
            "could Zhang make me a coffee?",
            "Zhang Wei doesn't look after the coffee machine",
        ),
        (
            _DEFAULT,
            "can Lee whip one up? I'm dying for a coffee",
            "Lee Ming doesn't look after the coffee machine",
        ),
        (
            _HARBOUR,
            "could Mark make one? I need a tea",
            "Mark Lindqvist doesn't look after the kettle",
        ),
        (_HARBOUR, "can Grace brew me a tea please", "Grace Huang doesn't look after the kettle"),
    ],
)
def test_a_colleague_who_keeps_no_maker_is_said_and_asked(
    reader: object, text: str, said: str
) -> None:
    frame = reader(text)  # type: ignore[operator]
    assert not frame.tasks, frame
    question = frame.question or ""
    assert question.startswith(said) and "Shall I" in question, question


@pytest.mark.parametrize(
    ("reader", "text", "item", "who"),
    [
        (_DEFAULT_ANSWERED, "could Wang make one? I need a coffee", "coffee", "mao"),
        (_HARBOUR_ANSWERED, "can Grace brew me a tea please", "tea", "will"),
    ],
)
def test_yes_makes_it_with_the_keepers(reader: object, text: str, item: str, who: str) -> None:
    frame = reader(text, ["yes please"])  # type: ignore[operator]
    got = [(t.kind, t.item, t.recipient, t.actor) for t in frame.tasks]
    assert got == [("produce", item, who, None)], frame


def test_no_does_nothing() -> None:
    frame = _DEFAULT_ANSWERED("could Wang make one? I need a coffee", ["no thanks"])
    assert not frame.tasks and frame.decline is not None, frame


@pytest.mark.parametrize(
    ("reader", "text", "item", "who", "maker"),
    [
        # the keeper asked makes it (the second keeper too, not the first on the list)
        (_DEFAULT, "could Sun make one? I need a coffee", "coffee", "mao", "sun"),
        (_DEFAULT, "I need a coffee. can Gao knock one up?", "coffee", "mao", "gao"),
        (_DEFAULT, "could Sun make me a coffee?", "coffee", "mao", "sun"),
        (_HARBOUR, "could Ken make one? I need a tea", "tea", "will", "ken"),
    ],
)
def test_must_not_change_the_keeper_asked_makes_it(
    reader: object, text: str, item: str, who: str, maker: str
) -> None:
    frame = reader(text)  # type: ignore[operator]
    got = [(t.kind, t.item, t.recipient, t.actor) for t in frame.tasks]
    assert got == [("produce", item, who, maker)], frame


@pytest.mark.parametrize(
    ("reader", "text", "item", "who"),
    [
        (_DEFAULT, "can you make Wang a coffee?", "coffee", "wang"),  # whom it is for
        (_HARBOUR, "could you make Mark a tea", "tea", "mark"),
        (_DEFAULT, "I need a coffee", "coffee", "mao"),
    ],
)
def test_must_not_change_a_name_after_the_verb_is_whom_it_is_for(
    reader: object, text: str, item: str, who: str
) -> None:
    frame = reader(text)  # type: ignore[operator]
    got = [(t.kind, t.item, t.recipient) for t in frame.tasks]
    assert got == [("produce", item, who)], frame


def test_must_not_change_a_colleague_asked_for_other_work() -> None:
    """Wang is asked to print, not to make the coffee: nothing is said about Wang and the
    coffee machine (the coffee is read as before). Wang keeps no printer either, which is
    said and asked (``named_doer``); a yes prints and makes the coffee with the keepers."""
    text = "could Wang print my file? I need a coffee too"
    frame = _DEFAULT(text)
    assert "coffee machine" not in (frame.question or ""), frame
    assert (frame.question or "").startswith("Wang Fang doesn't look after the printer."), frame
    yes = _DEFAULT_ANSWERED(text, ["yes"])
    assert ("produce", "coffee", None) in [(t.kind, t.item, t.actor) for t in yes.tasks], yes
