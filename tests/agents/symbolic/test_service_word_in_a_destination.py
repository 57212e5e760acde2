"""A send-out service whose place outside holds another service's word (blind rounds 61-62's
class: "... couriered to the print works at Felling" was read as printing, and the courier
desk's guards, asked "could you send ... in the courier desk to the print works ...?",
answered that they could not print): the reader takes the service from the verb said, never
from the words of the place; the robot asks by the service's own verb, the place outside
last and the facility after the question; the simulated colleague reads which service is
asked from the verb, never from the place's words (``helpers.courier_room``)."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.sim.people import direct_reply
from assistantx.sim.understanding import mentioned_requests
from assistantx.sim.world import World
from helpers.courier_room import courier_room
from helpers.reading import frame_reader

_frame = frame_reader(courier_room, "bjorn")


@pytest.mark.parametrize(
    ("text", "place"),
    [
        (
            "Could you have my page proof couriered to the print works at Felling?",
            "the print works at Felling",
        ),
        ("get my contract couriered to the Print House in Leeds", "the Print House in Leeds"),
        ("courier my contract to the print works at Felling", "the print works at Felling"),
        ("send my contract by courier to the print works", "the print works"),
        ("dispatch my statement to Printworks Ltd", "Printworks Ltd"),
        ("courier my form to the copy centre on Hill St", "the copy centre on Hill St"),
    ],
)
def test_the_service_is_the_verb_said_not_a_word_of_the_place(text: str, place: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.operation, t.destination) for t in frame.tasks] == [
        ("heat", "courier", place)
    ], frame


@pytest.mark.parametrize(
    ("text", "operations"),
    [
        ("print my contract", [None]),  # the office's one copy service, as before
        ("print my contract and courier it to Acme Ltd", ["print", "courier"]),
    ],
)
def test_the_other_service_said_as_a_verb_is_still_asked_for(
    text: str, operations: list[str | None]
) -> None:
    frame = _frame(text)
    assert [t.operation for t in frame.tasks] == operations, frame


_ASKED = (
    "Hi Kit, could you courier Björn Åkesson's document to the print works at Felling? "
    "The robot will bring it to you at the courier desk."
)


@pytest.mark.parametrize(
    "text",
    [
        _ASKED,
        "Hi Kit, could you send by courier Björn Åkesson's document in the courier desk to the "
        "print works at Felling?",
        "Hi Kit, could you dispatch Björn Åkesson's document to Print House, Leeds?",
    ],
)
def test_the_colleague_reads_the_service_from_its_verb(text: str) -> None:
    assert [r for r in mentioned_requests(courier_room(), text) if r != "send_file"] == ["courier"]
    reply = direct_reply(World.from_office(courier_room()), "kit", text)
    assert reply is not None and reply.text.startswith("Yes, I can do that (courier)"), reply


def test_a_print_asked_is_still_a_print() -> None:
    text = "Hi Dev, could you print Björn Åkesson's document at the print room?"
    assert mentioned_requests(courier_room(), text) == ["print"]


async def test_the_courier_desk_is_asked_in_words_and_the_send_happens() -> None:
    run = await run_instruction(
        courier_room(),
        "bjorn",
        "Could you have my page proof couriered to the print works at Felling?",
        unavailable=("dev",),
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    asked = [m.text for m in run.sim.messenger.sent if m.chat.id == "kit"]
    assert asked and asked[0] == _ASKED, asked
    [sent] = run.sim.world.sent_out()
    assert sent.detail["item"] == "document:bjorn" and sent.detail["by"] == "kit"
