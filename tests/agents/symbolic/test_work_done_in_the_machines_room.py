"""Work already spoken of asked to be done in the room of the machine that does it: "my sample
still hasn't been spun down, could you get that done in the centrifuge room". The room is the
one working machine in it, and the service is run on the speaker's own thing, handed back to
the speaker (round 59, class 2); never who in the room should get it asked. The first clause
alone stays a statement, "get it done" with nothing before it asks, and carrying reads as
before."""

from __future__ import annotations

from typing import Any

import pytest

from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader
from helpers.spectro_lab import spectro_lab

_lab = frame_reader(spectro_lab, "lee")
_bill = frame_reader(harbour_office, "bill")


@pytest.mark.parametrize(
    ("read", "text", "item", "owner"),
    [
        (
            _lab,
            "my sample still hasnt been spun down, could you get that done in the centrifuge room",
            "sample",
            "lee",
        ),
        (
            _bill,
            "my badge still hasnt been laminated, could you get that done in the badge office",
            "badge",
            "bill",
        ),
        (
            _bill,
            "my badge isnt laminated yet, can you sort it in the badge office",
            "badge",
            "bill",
        ),
        # at the machine itself, as before
        (
            _lab,
            "the banner for the foyer hasn't been laminated yet, can you get it done at the "
            "laminator",
            "banner",
            "lee",
        ),
        (
            _lab,
            "the curtain for scene 3 isnt heat sealed yet, can you sort it in the sealing bay",
            "curtain",
            "lee",
        ),
        (
            _bill,
            "my badge hasn't been laminated yet, can you take it to the badge office",
            "badge",
            "bill",
        ),
    ],
)
def test_the_rooms_machine_works_on_the_speakers_thing(
    read: Any, text: str, item: str, owner: str
) -> None:
    frame = read(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("heat", item, owner, owner)
    ], frame


def test_the_first_clause_alone_is_a_statement() -> None:
    frame = _bill("my badge still hasnt been laminated")
    assert not frame.tasks and frame.question is None, frame


def test_nothing_before_it_is_asked() -> None:
    frame = _lab("can you get it done in the centrifuge room")
    assert not frame.tasks and frame.question is not None, frame


@pytest.mark.parametrize(
    ("text", "item", "operation"),
    [
        # the machine named by the last word of its name ("the booth" of the "spray booth",
        # round 221's class)
        (
            "the curtain for scene 3 isnt heat sealed yet, can you sort it in the bay",
            "curtain",
            "seal",
        ),
        ("the curtain isnt heat sealed yet, can you get it done at the bay", "curtain", "seal"),
    ],
)
def test_the_machine_named_by_its_head_word_works_on_it(
    text: str, item: str, operation: str
) -> None:
    frame = _lab(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.operation) for t in frame.tasks] == [
        ("heat", item, "lee", operation)
    ], frame


def test_a_head_word_of_a_machine_that_works_on_nothing_is_no_machine() -> None:
    # the coffee machine makes coffee from nothing: "the machine" names no work on the sample
    frame = _lab("my sample hasnt been spun down yet, can you get it done at the machine")
    assert not any(t.operation == "coffee" for t in frame.tasks), frame
