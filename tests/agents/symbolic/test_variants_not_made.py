"""A made thing asked for in a variant the office does not make is not made plain (blind round
14's class 1; the round's office and sentences were never read). "make a master key card"
where the encoder makes ordinary door cards is declined (more authority than the product);
"an iced tea" where the urn makes tea is asked about ("Shall I get you some ordinary tea
instead?"); "a strong tea", "a tea, quick", "a new door card" are made as before."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.actions import Inquire, SendQR
from helpers import office_builder as ob
from helpers.guesthouse import guesthouse
from helpers.playschool import raw_playschool
from helpers.reading import answered_reader

_frame = answered_reader(guesthouse, "wren")


@pytest.mark.parametrize(
    ("text", "asked"),
    [
        ("make a master key card for room 12", "master door card"),
        ("encode me a master door card please", "master door card"),
        ("an all-access room card please", "all access door card"),
        ("Could you cut me a skeleton key card?", "skeleton door card"),
    ],
)
def test_a_variant_with_more_authority_is_declined(text: str, asked: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.decline is not None and asked in frame.decline
    assert frame.question is None


@pytest.mark.parametrize(
    ("text", "asked"),
    [
        ("an iced tea please", "iced tea"),
        ("brew me a decaf tea", "decaf tea"),
        ("could you get me some iced tea from the urn?", "iced tea"),
        ("get me a guest door card", "guest door card"),
    ],
)
def test_a_variant_not_made_here_is_asked_about(text: str, asked: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.question is not None
    assert asked in frame.question and "ordinary" in frame.question


@pytest.mark.parametrize("text", ["an iced tea please", "get me a guest door card"])
def test_a_yes_makes_the_ordinary_one_and_a_no_nothing(text: str) -> None:
    yes = _frame(text, ("yes",))
    assert len(yes.tasks) == 1 and yes.tasks[0].kind == "produce"
    assert yes.tasks[0].recipient == "wren"
    no = _frame(text, ("no thanks",))
    assert no.tasks == [] and no.decline is not None


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        ("a strong tea please", "tea", "wren"),
        ("some tea, quick", "tea", "wren"),
        ("a quick tea please", "tea", "wren"),
        ("could you brew me a nice hot tea", "tea", "wren"),
        ("a cup of tea please", "tea", "wren"),
        ("can I have a new door card, mine stopped working", "door_card", "wren"),
        ("encode a door card for Basil", "door_card", "basil"),
        ("2 door cards please", "door_card", "wren"),
        ("brew a tea for Ottilie", "tea", "ottilie"),
    ],
)
def test_qualities_and_plain_requests_are_made_as_before(
    text: str, item: str, recipient: str
) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", item, recipient)]


@pytest.mark.parametrize("text", ["does the urn make iced tea?", "thanks for the iced tea"])
def test_no_request_about_a_variant_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []


async def test_a_run_for_a_master_card_asks_nobody_and_makes_nothing() -> None:
    run = await run_instruction(guesthouse(), "wren", "make a master key card for room 12")
    acted = [r.action for r in run.stm.trace.actions()]
    assert not [a for a in acted if isinstance(a, Inquire | SendQR)]
    assert run.stm.trace.outcome == "unachievable"
    assert not run.sim.world.made


def _school_with_practicals() -> InstructionParser:
    """The school office whose practical kits also go by "practical" (as teachers call the
    lesson they are for)."""
    raw = raw_playschool()
    for kind in raw["item_types"]:
        if kind["id"] == "practical_kit":
            kind["synonyms"] = ["kit", "practical"]
    return InstructionParser(ob.parsed(lambda: raw)())


@pytest.mark.parametrize(
    "text",
    [
        "could Luke make up a kit for my 10Y2 electrolysis practical?",
        "prep room is miles away and I've got no free, could Luke make up a kit for my "
        "year 9 titration practical?",
        "make up a kit for my chromatography practical please",
    ],
)
def test_a_product_named_again_after_for_is_what_it_is_for_not_a_variant(text: str) -> None:
    frame = _school_with_practicals().parse(text, "ada")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("produce", "practical_kit", "ada")
    ]


def test_a_variant_of_the_product_named_once_is_still_asked_about() -> None:
    frame = _school_with_practicals().parse("could Luke make up an electrolysis kit for me", "ada")
    assert frame.tasks == []
    assert frame.question is not None and "electrolysis practical kit" in frame.question
