"""What someone wants to know ("a passenger wants to know high water at the pier", "my intern
asked about water damage") is a topic, never a thing asked for (``screen.need_to_know``): the
request is the rest of the message, a fetch for the speaker ("a calculator I could borrow").
Before, harbour declined "not offered here: coffee" and lost the borrow, and the default
office made a coffee for "a visitor wants to know the coffee prices"."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader, parser_for

_DEFAULT = frame_reader(default_office, "wang")
_HARBOUR = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        (
            "does anyone have a calculator I could borrow? a passenger wants to know high "
            "water at the pier",
            "calculator",
        ),
        (
            "anyone got a calculator I could borrow? a visitor wants to know the coffee prices",
            "calculator",
        ),
        ("can I borrow a ruler? my boss wants to know the tea schedule", "ruler"),
        ("could I borrow a highlighter? the courier is asking about coffee", "highlighter"),
    ],
)
def test_harbour_the_borrow_is_the_request(text: str, item: str) -> None:
    frame = _HARBOUR(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "may")]


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("does anyone have a book I could borrow? my intern asked about water damage", "book"),
        ("anyone got a stapler I could borrow? a client is asking about coffee beans", "stapler"),
        ("we need to know the water rota, can you bring me a pen", "pen"),
    ],
)
def test_default_the_borrow_is_the_request(text: str, item: str) -> None:
    frame = _DEFAULT(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "wang")]


@pytest.mark.parametrize(
    "text", ["a visitor wants to know the coffee prices", "I want to know the water rota"]
)
def test_alone_nothing_is_made(text: str) -> None:
    frame = _DEFAULT(text)
    assert not frame.tasks and frame.question is None, frame


def test_a_reported_request_is_still_read() -> None:
    """Neighbour: "wants to know if you can bring him a coffee" asks for the coffee."""
    frame = _DEFAULT("Zhang wants to know if you can bring him a coffee")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "coffee", "zhang")]


def test_a_want_of_the_thing_is_still_a_want() -> None:
    """Neighbour: "a visitor wants a coffee" wants the thing, not to know about it. Said of
    someone else, the want is restated and asked (``outsider_need``, test_outsider_wants):
    a yes makes the coffee, for the speaker to pass on."""
    frame = _DEFAULT("a visitor wants a coffee")
    assert frame.tasks == [] and frame.question == "Shall I get coffee for you?"
    yes = parser_for(default_office).parse_with_answers("a visitor wants a coffee", "wang", ["yes"])
    assert [(t.kind, t.item, t.recipient) for t in yes.tasks] == [("produce", "coffee", "wang")]
