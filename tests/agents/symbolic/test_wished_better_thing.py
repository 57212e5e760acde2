"""A wish for a better thing is a grumble (fixer 59g class 1): "wish i had a stapler that
actually worked", "if only I had a pen that didn't leak lol", "if only my pen didn't leak": the
speaker's thing described by what it would do or not do (a relative clause after it, or a state
after "my" thing) is venting, answered in words; nothing is fetched (``reading.grumble.
wished_better``). Read as said, the bare thing was taken for one asked ("wish I had a bodycam
that didn't die" borrowed a colleague's). A wish beside a request, a plain wish for a thing,
a thing wanted for a use and a want keep their readings."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "wish i had a stapler that actually worked",
        "if only I had a pen that didn't leak lol",
        "wish i had a stapler that didnt die after 3 hours lol",
        "if only my pen didn't leak",
        "wish my laptop cable wasnt so short",
        "i wish my laptop cable wasnt so short",
        "wish we had a decent coffee machine",
    ],
)
def test_a_wish_for_a_better_thing_fetches_nothing(text: str) -> None:
    frame = _default(text)
    # noted in words, never declined as work ("I can't wish") nor asked about
    assert not frame.tasks and frame.question is None, frame
    assert frame.decline is not None and frame.decline.startswith("Noted"), frame


def test_a_wish_beside_a_request_still_asks() -> None:  # must not change
    frame = _default("I wish I had a stapler right now, could you bring me one")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "stapler", "lee")]


def test_a_plain_wish_for_a_thing_keeps_its_reading() -> None:  # must not change: words
    frame = _default("i wish i had a pen")
    assert not frame.tasks and frame.question is None and frame.decline, frame


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("wish i had a pen", "pen"),  # no clause: read as before, asked
        # a use of the thing for the speaker, not its quality
        ("i wish i had a stapler that i could use now", "stapler"),
    ],
)
def test_a_wish_with_no_quality_said_is_still_asked(text: str, item: str) -> None:
    frame = _default(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", item)], frame


def test_a_want_is_still_made() -> None:  # must not change
    frame = _default("I'd love a coffee")
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", "coffee")]
