"""Blind round 17's place classes, on a school arts block no sentence was written for
(``helpers.arts_block``; the round's office and sentences were never read).

1. "need X in P", P the room the requester works in, where no X is kept: one X brought to
   them there, from whoever has one (its owner asked); "the X in P" where one is kept still
   names that one.
2. A source said after the request ("..., the art room has some", "there are some in ...",
   "... should have some"): the one kept there, never anyone's elsewhere; a place said to
   have one that keeps none is asked about."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.task_schema import TaskFrame
from helpers.arts_block import arts_block
from helpers.reading import frame_reader

_frame = frame_reader(arts_block, "ola")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str]]:
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


# -- 1. "need X in P": P is where the requester works --------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "need a tape measure in the music room asap, marking out the stage",
        "I need a tape measure in the music room please",
        "could I get a tape measure in the music room for the set build",
    ],
)
def test_a_need_in_the_requesters_own_room_brings_one_there(text: str) -> None:
    # Ola sits in the music room, where no tape measure is kept: anyone's will do
    assert _tasks(_frame(text, "ola")) == [("transfer", "tape_measure", None, "ola")]


@pytest.mark.parametrize("who", ["priya", "ola"])
async def test_the_tape_measure_reaches_the_requester_with_its_owner_asked(who: str) -> None:
    where = {"priya": "dance studio", "ola": "music room"}[who]
    run = await run_instruction(
        arts_block(), who, f"need a tape measure in the {where} asap, marking out the floor"
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    held = [i for i, h in run.sim.world.holder.items() if h == who and i.startswith("tape")]
    assert len(held) == 1, run.sim.world.holder
    owner = held[0].split(":")[1]
    asked = [m.chat.id for m in run.sim.messenger.sent]
    keeper = {"ewan": "ewan", "prep_shelves": "colm"}[owner]
    assert keeper in asked


@pytest.mark.parametrize(
    ("who", "text"),
    [
        ("colm", "need the stapler in the staff room"),
        ("marta", "can I have the stapler in the staff room please"),
    ],
)
def test_the_one_kept_in_the_room_is_still_that_one(who: str, text: str) -> None:
    [(kind, item, owner, recipient)] = _tasks(_frame(text, who))
    assert (kind, item, recipient) == ("transfer", "stapler", who)
    assert owner in (None, "staff_shelf")  # None: the one the planner takes anyway


def test_a_named_one_not_kept_in_the_room_is_still_asked_about() -> None:
    asked = _frame("need the tape measure in the music room", "ola").question
    assert asked is not None and "music room" in asked


# -- 2. a source said after the request -----------------------------------------------------


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("need cable ties for the rig, the art room has some", "art_cupboard"),
        ("need some cable ties for the lights, there are some in the art room", "art_cupboard"),
        ("could you get me cable ties, art room should have some", "art_cupboard"),
        ("need cable ties for the rig, the art cupboard's got some", "art_cupboard"),
        ("need cable ties for the rig, there's some in the art room", "art_cupboard"),
        ("need cable ties for the rig. There should be some in the prep room.", "prep_shelves"),
        ("need cable ties for the rig, the prep room has some", "prep_shelves"),
        ("need a stopwatch, the music room has one", "finn"),
    ],
)
def test_the_source_said_after_the_request_is_where_it_comes_from(text: str, owner: str) -> None:
    [(kind, _item, got_owner, recipient)] = _tasks(_frame(text, "marta"))
    assert (kind, got_owner, recipient) == ("transfer", owner, "marta")


def test_with_no_source_said_any_one_will_do() -> None:
    assert _tasks(_frame("need cable ties for the rig", "marta")) == [
        ("transfer", "cable_ties", None, "marta")
    ]


def test_a_place_said_to_have_one_that_keeps_none_is_asked_about() -> None:
    frame = _frame("need a stopwatch, the kitchen has one", "marta")
    assert frame.tasks == [] and frame.question is not None
    assert "kitchen" in frame.question


@pytest.mark.parametrize(
    "text",
    ["the art room has some cable ties", "thanks, the art room has some"],
)
def test_a_statement_or_thanks_still_moves_nothing(text: str) -> None:
    frame = _frame(text, "marta")
    assert frame.tasks == [] and frame.question is None and frame.decline is not None


async def test_the_cable_ties_come_from_the_place_said() -> None:
    run = await run_instruction(
        arts_block(), "marta", "need cable ties for the rig, the art room has some"
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.holder["cable_ties:art_cupboard"] == "marta"
