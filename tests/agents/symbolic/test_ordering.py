"""Ordering from outside is not offered (``screen.ordering``): a request whose verb buys
("order", "buy", "purchase", "book") a thing of the office that no machine makes and no
cupboard supplies is declined in words, never read as fetching a colleague's thing of that
type ("order us some sandwiches" on harbour asked "Whose lunch do you mean?")."""

from __future__ import annotations

import pytest
from _offices import parser

_NOT_OFFERED = "Sorry, I can't order things"


@pytest.mark.parametrize(
    ("name", "who", "text"),
    [
        # the class's analogue
        ("harbour", "will", "order us some sandwiches for the meeting"),
        # other verbs, other things, other offices
        ("harbour", "will", "order me a ruler"),
        ("harbour", "will", "could you buy a calculator for Rose"),
        ("harbour", "will", "please purchase some leftovers for the team"),
        ("default", "wu", "please purchase some scissors for the team"),
        ("default", "wu", "can you order me some paper"),
    ],
)
def test_ordering_from_outside_is_declined(name: str, who: str, text: str) -> None:
    frame = parser(name).parse(text, who)
    assert not frame.tasks and frame.question is None, frame
    assert frame.decline is not None and frame.decline.startswith(_NOT_OFFERED), frame


@pytest.mark.parametrize(
    ("name", "who", "text", "move"),
    [
        # must not change: a product the office makes is got here
        ("harbour", "will", "buy me a tea", ("produce", "tea", None, "will")),
        ("default", "wu", "buy me a coffee", ("produce", "coffee", None, "wu")),
        # must not change: the requester's own lunch, a colleague's lunch asked for
        ("harbour", "will", "bring me my lunch", ("transfer", "lunch", "will", "will")),
        ("harbour", "will", "can I have Rose's lunch", ("transfer", "lunch", "rose", "will")),
        # must not change: "book" the noun is no verb of buying
        ("default", "wu", "find me a book", ("transfer", "book", None, "wu")),
    ],
)
def test_the_offices_own_things_are_read_as_before(
    name: str, who: str, text: str, move: tuple[str, str, str | None, str]
) -> None:
    frame = parser(name).parse(text, who)
    assert frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [move], frame


def test_a_thing_the_office_has_no_word_for_is_declined_as_before() -> None:
    frame = parser("default").parse("order a pizza for the team", "wu")
    assert not frame.tasks and frame.decline is not None, frame
    assert not frame.decline.startswith(_NOT_OFFERED), frame


@pytest.mark.parametrize(
    "text",
    [
        # blind round 148's class: the cupboard keeps the thing, but the order names a seller
        # outside as its source; it fetched one from the cupboard (a wrong physical action)
        "order some notepads from the supplier, we are almost out",
        "order more notepads off the website pls",
        "can you order a box of notepads from the wholesaler",
    ],
)
def test_an_order_from_a_seller_outside_is_declined_whatever_the_cupboard_keeps(
    text: str,
) -> None:
    frame = parser("harbour").parse(text, "will")
    assert not frame.tasks and frame.question is None, frame
    assert frame.decline is not None and frame.decline.startswith(_NOT_OFFERED), frame


@pytest.mark.parametrize(
    "text", ["order me a notepad", "order a notepad from the supply room", "get me a notepad"]
)
def test_an_order_the_cupboard_fills_is_still_got_here(text: str) -> None:
    frame = parser("harbour").parse(text, "will")
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", "notepad")], frame
