"""A short code in capitals is no colleague (blind rounds 20-22's class, on an airline catering
unit no sentence was written for, ``helpers.galley``): "bag for LIS" names an airport, "stand
B4" a stand, "BA117" a flight; the request around it is done, nobody is asked who "LIS" is. A
colleague's initials the office declares ("DK") are still the colleague, and a code where it
would say who gets the thing ("to LIS", "LIS's stapler", "a rush tag for LIS") is still
asked about."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic.reading.codes import looks_like_code
from helpers.galley import galley
from helpers.reading import frame_reader

_frame = frame_reader(galley, "nia")


@pytest.mark.parametrize(
    "text",
    [
        "rush tag pls, bag for LIS missed its connection",
        "rush tag please, the bag for OPO missed its connection",
        "can you make me a rush tag? the case from AMS is going on BA117",
        "rush tag pls, that suitcase for MAD is stuck on stand B4",
        "need a rush tag, trolley for GVA has a late bag",
    ],
)
def test_a_rush_tag_is_made_for_the_requester(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "rush_tag", "nia")]


@pytest.mark.parametrize(
    ("text", "owner"),
    [("bring me DK's stapler", "deepa"), ("could you bring DK's stapler to me", "deepa")],
)
def test_declared_initials_are_the_colleague(text: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", owner, "nia")]


@pytest.mark.parametrize(
    "text",
    [
        "bring my stapler to LIS",
        "bring me LIS's stapler",
        "make a rush tag for LIS",
        "ask LIS to sign my release form",
        "take my stapler to the desk for JT",
    ],
)
def test_a_code_where_a_person_would_stand_is_asked_about(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None, frame


@pytest.mark.parametrize(
    ("written", "code"),
    [
        ("LIS", True),
        ("BA117", True),
        ("B4", True),
        ("LIS's", True),
        ("Lis", False),
        ("GATES", False),
        ("117", False),
        ("I", False),
        ("lis", False),
    ],
)
def test_what_looks_like_a_code(written: str, code: bool) -> None:
    assert looks_like_code(written) is code


async def test_the_tag_is_made_and_handed_to_the_requester() -> None:
    run = await run_instruction(galley(), "nia", "rush tag pls, bag for LIS missed its connection")
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    assert "rush tag was handed to you" in (trace.summary or "")
    asked = [r.action for r in trace.actions() if r.action.type == "inquire"]
    assert all("LIS" not in getattr(a, "question", "") for a in asked)
