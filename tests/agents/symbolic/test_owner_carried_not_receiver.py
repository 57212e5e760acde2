"""Issue #23, fixer fix143b class 1: "Pat's tape ran out. Can you take May's over to her?": the
owner of the thing carried ("May's", its noun left out or said) is never the "her" it is taken
over to; the colleague named before (Pat, whose own ran out) is. "back to her" takes it home
to its owner, as before (``core.handed_owner``). The reader named the pronoun only where "to"
came right after the possessive ("May's to her"), and the consent guard not at all."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic.reading.parser import shared_parser
from assistantx.core.handed_owner import carried_to
from assistantx.core.office import Office
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import default_office, harbour_office


def _office(name: str) -> Office:
    return harbour_office() if name == "harbour" else default_office()


@pytest.mark.parametrize(
    ("office", "who", "text", "item", "owner", "receiver"),
    [
        # the class's analogues
        ("harbour", "will", "Pat's tape ran out. Can you take May's over to her?", "tape",
         "may", "pat"),
        ("harbour", "will", "Rose's umbrella broke, could you get Ray's to her", "umbrella",
         "ray", "rose"),
        ("default", "mao", "Lin's scissors are blunt, can you bring Chen's over to him",
         "scissors", "chen", "lin"),
        # variants of our own: other particles of the way, the noun said again
        ("harbour", "will", "Ken's ruler snapped, could you take Art's round to him", "ruler",
         "art", "ken"),
        ("default", "mao", "Wang's stapler is jammed, could you take Hu's across to him",
         "stapler", "hu", "wang"),
        ("default", "mao", "Wang's stapler is jammed, could you bring Hu's stapler over to him",
         "stapler", "hu", "wang"),
    ],
)  # fmt: skip
def test_the_owner_of_the_thing_carried_is_not_whom_the_pronoun_means(
    office: str, who: str, text: str, item: str, owner: str, receiver: str
) -> None:
    here = _office(office)
    frame = shared_parser(here).parse_with_answers(text, who, [])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, receiver)
    ], frame
    # the consent guard reads the same receiver from the words
    assert named_recipients(here, memory(who, text)) == {receiver}


def test_back_to_her_is_the_owner() -> None:
    # neighbour: "back" takes the owner's thing home to them (the label maker is kept in the
    # supply room's cupboard)
    text = "can you get May's label maker back to her"
    frame = shared_parser(harbour_office()).parse_with_answers(text, "will", [])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "label_maker", "may", "may")
    ], frame


@pytest.mark.parametrize(
    ("words", "at", "to"),
    [
        (["may", "over", "to", "her"], 1, 2),
        (["may", "to", "her"], 1, 1),
        (["may", "label", "maker", "round", "to", "her"], 1, 4),
        (["may", "back", "to", "her"], 1, None),  # home to the owner
        (["may", "is", "broken"], 1, None),
    ],
)
def test_carried_to(words: list[str], at: int, to: int | None) -> None:
    assert carried_to(words, at, {"label", "maker"}) == to


async def test_end_to_end_mays_tape_goes_to_pat() -> None:
    text = "Pat's tape ran out. Can you take May's over to her?"
    run = await run_instruction(harbour_office(), "will", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    handed = [(e.detail["item"], e.detail["to"]) for e in run.sim.world.handovers()]
    assert ("tape:may", "pat") in handed, run.stm.trace.summary
