"""Blind rounds 20-22's class (analogues, not the measured sentences): a place outside the
office said past a comma or with a preposition. An address continuation after a comma (the
capitalised words of a street, a building, a town, that make no clause of their own) stays in
the destination when what stands before the comma is a place's proper name; "the lab, the
Bristol one" names the Bristol lab; a description followed by more than which one is asked
about. A clause after the comma, a colleague, a day or a courtesy word ends the destination,
and a question, a thanks or a negation still moves nothing."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.parser import InstructionParser
from assistantx.core.task_schema import Part
from assistantx.evaluation import metrics
from helpers.one_episode import ppdr_episode
from helpers.outside_broadcast import outside_broadcast

WHERE = "Where should I courier it to? Please give me the name and address of the place."


def _sends(instruction: str) -> list[str | None]:
    reading = InstructionParser(outside_broadcast()).parse(instruction, "quill")
    return [t.destination for t in reading.tasks if t.operation == "courier"]


@pytest.mark.parametrize(
    ("instruction", "destination"),
    [
        ("courier my master tape to Broadcast Centre, Wood Lane", "Broadcast Centre, Wood Lane"),
        ("courier my tape to Ofcom, Riverside House", "Ofcom, Riverside House"),
        (
            "dispatch my tape to the BBC, Media City, Salford please",
            "the BBC, Media City, Salford",
        ),
        ("please courier my tape to Arqiva in Winchester", "Arqiva in Winchester"),
        # who it is for there (round 21: "to Dublin, attention Customer Relations")
        (
            "courier my tape to Dublin, attention Customer Relations",
            "Dublin, attention Customer Relations",
        ),
        ("courier my tape to Ofcom, FAO Licensing please", "Ofcom, FAO Licensing"),
        ("can you send my tape off to the lab, the Bristol one", "the Bristol lab"),
        ("courier my tape to the lab, the one in Bristol please", "the lab in Bristol"),
        # the clause after the address is the next part, the address stays whole
        (
            "courier my tape to Ofcom, Riverside House, then bring me a headset",
            "Ofcom, Riverside House",
        ),
    ],
)
def test_the_whole_place_is_the_destination(instruction: str, destination: str) -> None:
    assert _sends(instruction) == [destination]


@pytest.mark.parametrize(
    ("instruction", "destination"),
    [
        # a clause of its own, a day, a courtesy word, a colleague after the comma
        ("courier my tape to Ofcom, Dov needs it back", "Ofcom"),
        ("courier my tape to Ofcom, Monday latest", "Ofcom"),
        ("courier my tape to Broadcast Centre, thanks", "Broadcast Centre"),
        # a description is no proper name: a town after it is not its address
        ("courier my tape to the Bristol lab, it has to go today", "the Bristol lab"),
    ],
)
def test_what_follows_a_comma_and_is_no_address_stays_out(
    instruction: str, destination: str
) -> None:
    assert _sends(instruction) == [destination]


def test_more_than_which_one_after_the_comma_is_asked_about() -> None:
    reading = InstructionParser(outside_broadcast()).parse(
        "courier my tape to the lab, the Bristol one or the Bath one", "quill"
    )
    assert reading.tasks == []
    assert reading.question == WHERE


@pytest.mark.parametrize(
    "instruction",
    [
        "did you courier my tape to Ofcom, Riverside House?",
        "don't courier my tape to Ofcom, Riverside House",
        "thanks for couriering my tape to Broadcast Centre, Wood Lane",
    ],
)
def test_a_question_a_negation_or_thanks_moves_nothing(instruction: str) -> None:
    assert InstructionParser(outside_broadcast()).parse(instruction, "quill").tasks == []


@pytest.mark.parametrize(
    ("instruction", "destination"),
    [
        ("courier my master tape to Broadcast Centre, Wood Lane", "Broadcast Centre, Wood Lane"),
        ("can you send my tape off to the lab, the Bristol one", "Bristol lab"),
        ("courier my tape to the lab, the Bristol one or the Bath one", "the Bristol lab"),
    ],
)
async def test_the_tape_is_sent_where_the_requester_said(
    instruction: str, destination: str
) -> None:
    office = outside_broadcast()
    episode = await ppdr_episode(
        office,
        "quill",
        instruction,
        [{"heated": "tape:quill"}, {"informed": "quill"}],
        [Part(kind="heat", item="tape", operation="courier", destination=destination)],
    )
    assert metrics.success(episode), episode.trace.summary
    assert metrics.wrong_sends(episode) == []
