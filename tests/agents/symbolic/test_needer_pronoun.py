"""Whom "her" means where two colleagues are named and one of them is said as the owner of the
thing ("Nadia needs Miles's dev kit for the art build - could you ask him and take it to
her?"): the owner does not receive their own thing, so "her" is the other one named, the one
who needs it (blind round 39's class: "Who do you mean by 'her'?"). "Miles's" before an item
is Miles Okafor, whose given name it is, though Nadia's family name is Miles. Where no owner
is said, or two others are left, the reader still asks."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.parcel_desk import parcel_desk
from helpers.reading import frame_reader

_frame = frame_reader(parcel_desk, "petra")


@pytest.mark.parametrize(
    ("text", "item", "owner", "recipient"),
    [
        (
            "Nadia needs Miles's dev kit for the art build - could you ask him and take it to her?",
            "dev_kit",
            "miles",
            "nadia",
        ),
        (
            "Nadia needs Miles's dev kit - could you take it to her?",
            "dev_kit",
            "miles",
            "nadia",
        ),
        (
            "Olive needs Miles's dev kit for the art build, can you ask him for it and bring "
            "it to her",
            "dev_kit",
            "miles",
            "olive",
        ),
        (
            "Nadia needs Anne-Marie's dev kit - could you take it to her?",
            "dev_kit",
            "annemarie",
            "nadia",
        ),
        (
            "Anne-Marie needs Olive's calculator, please take it to her",
            "calculator",
            "olive",
            "annemarie",
        ),
    ],
)
def test_her_is_the_one_named_who_does_not_own_it(
    text: str, item: str, owner: str, recipient: str
) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, recipient)
    ]


@pytest.mark.parametrize(
    "text",
    [
        "Olive's busy and Nadia's out, take her a calculator",
        "Olive needs Miles's dev kit and Nadia wants one too, take it to her",
        "Olive and Nadia are in the hall, take her a calculator",
        "Olive's calculator broke and Nadia is here, lend her mine",
    ],
)
def test_still_unclear_is_still_asked(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None, frame


def test_a_named_recipient_is_kept() -> None:
    frame = _frame("Could you take Miles's dev kit to Nadia?")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("dev_kit", "miles", "nadia")]


async def test_end_to_end_the_needer_gets_it_from_its_owner() -> None:
    text = "Nadia needs Miles's dev kit for the art build - could you ask him and take it to her?"
    run = await run_instruction(parcel_desk(), "petra", text)
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    assert "Nadia Miles now has Miles Okafor's dev kit" in (trace.summary or ""), trace.summary
