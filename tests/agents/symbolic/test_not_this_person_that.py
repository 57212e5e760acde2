"""A person refused after a request, then another said in their place ("Send Lee my document.
sorry, not Lee - Lin Tao", "... Not Lee, Lin Tao", "..., not Lee but Lin Tao", "... Lee, no,
Lin Tao") replaces the refused person in whichever role they had, recipient or owner; "mine"
or "me" said in their place is the speaker. Blind rounds 59-64's class: the dash after "not
Lee" and the forms without "sorry" aimed at the first person and then refused. Nothing but a
person is replaced ("not today - tomorrow"), and a person the correction does not name keeps
their role."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "chen")


def _tasks(text: str) -> list[tuple[str | None, str | None, str | None]]:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    return [(t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "Send Lee my document. sorry, not Lee - Lin Tao.",
        "Send Lee my document. Sorry - not Lee, Lin Tao",
        "Send Lee my document. Not Lee, Lin Tao.",
        "Send Lee my document, not Lee but Lin Tao.",
        "Send Lee my document. not Lee but rather Lin Tao",
        "Send Lee my document. Lee, no, Lin Tao.",
        "Send Lee my document. I mean Lin Tao not Lee.",
        "Send Lee my document. make that Lin Tao.",
        "take my document to Lee - oops, not Lee – Lin",
        "take my document to Ming. Not Ming — Tao!",
    ],
)
def test_the_recipient_refused_is_replaced(text: str) -> None:
    assert _tasks(text) == [("document", "chen", "lin")]


@pytest.mark.parametrize(
    "text",
    [
        "Bring me Lee's stapler. sorry, not Lee - Lin Tao.",
        "Bring me Lee's stapler. Not Lee's, Lin's.",
        "Bring me Lee's stapler, not Lee's but Lin Tao's",
        "Bring me Lee's stapler. Lee, no, Lin Tao.",
    ],
)
def test_the_owner_refused_is_replaced(text: str) -> None:
    assert _tasks(text) == [("stapler", "lin", "chen")]


@pytest.mark.parametrize(
    "text",
    [
        "Take Wang's stapler to Lee. not Wang's - mine",
        "Take Wang's stapler to Lee. sorry, not Wang's, my own",
    ],
)
def test_mine_said_in_the_owners_place_is_the_speaker(text: str) -> None:
    assert _tasks(text) == [("stapler", "chen", "lee")]


@pytest.mark.parametrize(
    ("text", "task"),
    [
        # only the person refused changes: Lee still carries, the owner becomes Lin
        ("Ask Lee to bring Wang's stapler to me. not Wang - Lin Tao", ("stapler", "lin", "chen")),
        ("Take Wang's stapler to Lee. Not Lee, Lin Tao", ("stapler", "wang", "lin")),
        # no person refused: nothing replaced
        ("Bring my stapler to Lee tomorrow. not today - tomorrow", ("stapler", "chen", "lee")),
        # the person refused was never named: the request stands as said
        ("Send Lee my document, not Wang, Lin", ("document", "chen", "lee")),
        # plain requests
        ("Send Lee my document.", ("document", "chen", "lee")),
        ("Bring me Lee's stapler.", ("stapler", "lee", "chen")),
        ("Send my document to Lin Tao, not Lee.", ("document", "chen", "lin")),
    ],
)
def test_near_misses_keep_their_reading(text: str, task: tuple[str, str, str]) -> None:
    assert _tasks(text) == [task]
