"""An indefinite request for a kind the requester owns and has with them, said with a place
where theirs is the only one ("need a tape measure in the lab asap", Kofi's own lying in the
lab where he works): "a" one from someone who has theirs means another one, anyone's (its
owner asked), as for a requester with none (blind round 55's class; its office and sentences
were never read). It was bound to the requester's own and asked "Who should get your tape
measure?". "the"/"my" keep that reading, and so does an own one kept by a facility there
("a thermometer from the lab cabinet", where Sami's is kept)."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.reading import frame_reader
from helpers.sample_lab import sample_lab

_frame = frame_reader(sample_lab, "kofi")


@pytest.mark.parametrize(
    "text",
    [
        "need a tape measure in the lab asap",
        "need another tape measure in the lab",
        "can someone find me a tape measure in the lab",
        "could I get a tape measure in the lab please",
    ],
)
def test_a_one_is_another_than_the_requesters_own(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "tape_measure", None, "kofi")
    ], frame


@pytest.mark.parametrize(
    "text", ["need the tape measure in the lab", "need my tape measure in the lab"]
)
def test_the_or_my_keep_the_requesters_own(text: str) -> None:
    frame = _frame(text)
    assert frame.question == "Who should get your tape measure?", frame


def test_an_own_one_kept_by_a_facility_is_still_theirs() -> None:
    frame = _frame("need a thermometer from the lab cabinet", "sami")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("thermometer", "sami", "sami")
    ], frame


async def test_end_to_end_a_colleagues_one_is_lent() -> None:
    run = await run_instruction(sample_lab(), "kofi", "need a tape measure in the lab asap")
    summary = run.stm.trace.summary
    assert summary.startswith("Done: you now have") and "Kofi" not in summary, summary
