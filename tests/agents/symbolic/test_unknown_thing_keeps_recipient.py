"""A second conjunct whose thing the office has none of ("... and bring for me a tea", "...
and for me a tea") is read as "bring for me a tea" alone is: declined as not offered (or
asked about), never lending its receiver to the thing before it. Before, the coffee asked
for Zhang went to the speaker and the tea was never mentioned. Whom a thing is for, said
with "for" between the verb and the thing, is read as "bring me a tea" reads it
(``screen.service``, ``unnamed_things``, ``verbless_conjunct``)."""

from __future__ import annotations

import pytest
from _offices import parser

_NOT_OFFERED = "not offered here: tea"


@pytest.mark.parametrize("text", ["bring for me a tea", "bring me a tea"])
def test_an_unoffered_thing_is_declined_not_lent_the_recipient(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.decline is not None and not frame.tasks, frame
    assert _NOT_OFFERED in frame.explain()


@pytest.mark.parametrize(
    ("text", "rest"),
    [
        ("bring a coffee to Zhang and bring for me a tea", "bring a coffee to Zhang"),
        ("bring a coffee to Zhang and for me a tea", "bring a coffee to Zhang"),
        ("bring a pen to Zhang and get for me a tea", "bring a pen to Zhang"),
        # said with "me"
        ("bring a coffee to Zhang and bring me a tea", "bring a coffee to Zhang"),
    ],
)
def test_an_unoffered_thing_beside_a_request_is_told_and_the_rest_offered(
    text: str, rest: str
) -> None:
    """The tea is said not to be here, the rest asked still for its own receiver (it had
    been declined whole: ``test_unoffered_part_beside_a_request``)."""
    frame = parser("default").parse(text, "lee")
    assert not frame.tasks and frame.decline is None, frame
    assert _NOT_OFFERED in frame.explain()
    assert (frame.question or "").endswith(f"Shall I still {rest}?"), frame


@pytest.mark.parametrize(
    "text",
    [
        "bring a coffee to Zhang and bring for me a tape measure",
        "bring a coffee to Zhang and for me a tape measure",
        # must not change: said with "me"
        "bring a coffee to Zhang and bring me a tape measure",
    ],
)
def test_an_unknown_thing_is_asked_about(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.question is not None and "tape measure" in frame.question, frame
    assert not frame.tasks


@pytest.mark.parametrize(
    "text",
    [
        # must not change: a known thing there is a task of its own
        "bring a coffee to Zhang and bring for me a water",
        "bring a coffee to Zhang and for me a water",
    ],
)
def test_a_known_thing_there_goes_to_its_own_receiver(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    done = [(t.kind, t.item, t.recipient) for t in frame.tasks]
    assert done == [("produce", "coffee", "zhang"), ("produce", "water", "lee")]
