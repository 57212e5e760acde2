"""Where a person is, said after their name ("Sue on reception needs a highlighter"), is no
part of the request (``screen.seated_where``); and "one" taken from a facility in the clause
after a thing was asked for is that thing, from there, never the facility's own product for
the requester (``reading.one_from_source``)."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    ("office", "requester", "text", "tasks"),
    [
        (
            "harbour",
            "rose",
            "Sue on reception needs a highlighter, can you take one down from the cupboard",
            [("transfer", "highlighter", None, "sue")],
        ),
        (
            "harbour",
            "rose",
            "Mark by the kitchen could use a ruler, bring him one",
            [("transfer", "ruler", None, "mark")],
        ),
        (
            "harbour",
            "will",
            "Joy in the lounge needs a calculator, grab one from the cupboard",
            [("transfer", "calculator", None, "joy")],
        ),
        (
            "default",
            "mao",
            "Wang at the print room needs paper, grab some from the printer",
            [("transfer", "paper", None, "wang")],
        ),
        (
            "default",
            "mao",
            "Hu by the water corner needs a pen, bring her one",
            [("transfer", "pen", None, "hu")],
        ),
    ],
)
def test_where_they_are_is_no_part_of_the_request(
    office: str, requester: str, text: str, tasks: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of(office, text, requester) == tasks


@pytest.mark.parametrize(
    ("office", "requester", "text", "tasks"),
    [
        # a recipient at a facility: the printout was the requester's and a coffee made for
        # Wang
        (
            "default",
            "lee",
            "print my file and give it to Wang at the coffee machine, he needs it at 3",
            [("print", "file", "lee", "wang")],
        ),
        (
            "default",
            "lee",
            "print my file. no wait, print it and give it to Wang at the vending machine",
            [("print", "file", "lee", "wang")],
        ),
        (
            "default",
            "lee",
            "take my stapler to Mao by the water dispenser",
            [("transfer", "stapler", "lee", "mao")],
        ),
        # must not change: the facility's own product named, and a room the thing goes to
        (
            "default",
            "lee",
            "bring a coffee to Wang at the coffee machine",
            [("produce", "coffee", None, "wang")],
        ),
        ("default", "lee", "take my lunch to the microwave", [("heat", "lunch", "lee", "lee")]),
    ],
)
def test_a_recipient_at_a_facility_is_where_they_are(
    office: str, requester: str, text: str, tasks: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of(office, text, requester) == tasks


@pytest.mark.parametrize(
    ("office", "requester", "text", "tasks"),
    [
        (
            "harbour",
            "rose",
            "Sue needs a highlighter, can you take one down from the cupboard",
            [("transfer", "highlighter", None, "sue")],
        ),
        (
            "harbour",
            "rose",
            "Sue needs a notepad, grab one from the cupboard",
            [("produce", "notepad", None, "sue")],
        ),
        (
            "harbour",
            "mark",
            "I need a highlighter, grab one from the cupboard",
            [("transfer", "highlighter", None, "mark")],
        ),
    ],
)
def test_one_from_a_facility_is_the_thing_asked_for(
    office: str, requester: str, text: str, tasks: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of(office, text, requester) == tasks


@pytest.mark.parametrize(
    ("office", "requester", "text", "tasks"),
    [
        # a possessive: Sue's own highlighter, for the requester
        (
            "harbour",
            "rose",
            "bring me Sue's highlighter from reception",
            [("transfer", "highlighter", "sue", "rose")],
        ),
        # the name does not open the sentence: as before
        ("default", "mao", "bring Wang at desk 6 a pen", [("transfer", "pen", None, "wang")]),
        # "one" with nothing asked before it: the cupboard's own product
        (
            "harbour",
            "rose",
            "grab me one from the cupboard",
            [("produce", "notepad", None, "rose")],
        ),
    ],
)
def test_must_not_change(
    office: str, requester: str, text: str, tasks: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of(office, text, requester) == tasks


def test_a_need_with_a_place_is_still_restated_first() -> None:
    # "Wang at the print room needs a pen" is a third person's need: asked, never Wang's pen
    # carried to the requester
    frame = parser("default").parse("Wang at the print room needs a pen", "mao")
    assert not frame.tasks
    assert frame.question is not None and "Wang Fang" in frame.question


async def test_the_highlighter_reaches_sue_in_the_simulated_office() -> None:
    # the consent guard reads Sue as the one it goes to (runtime.recipients), so it is done
    from symbolic_run import run_instruction

    from helpers.dataset_offices import harbour_office

    text = "Sue on reception needs a highlighter, can you take one down from the cupboard"
    run = await run_instruction(harbour_office(), "rose", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"holds": ["sue", "highlighter:*"]})
    assert not run.sim.world.check({"holds": ["rose", "highlighter:*"]})
