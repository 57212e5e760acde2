"""The survey store on both backends: impact records, surveys, replies and opt-outs."""

from __future__ import annotations

from pathlib import Path

from assistantx.core.ports.messenger import ChatRef
from assistantx.feedback.impact import InstructionRecord
from assistantx.feedback.store import FeedbackStore
from assistantx.feedback.survey import Survey, SurveyState
from assistantx.feedback.walking import WalkingEstimate


def _record(iid: str, ended_at: float) -> InstructionRecord:
    walking = WalkingEstimate(
        instruction_id=iid,
        requester="lee",
        route=["desk-lee"],
        walk_m=10.0,
        robot_m=12.0,
        saved_m=10.0,
        method="straight-line",
    )
    return InstructionRecord(
        instruction_id=iid,
        requester="lee",
        text="t",
        kind="delivery",
        outcome="done",
        started_at=ended_at - 1,
        ended_at=ended_at,
        steps=2,
        actions=3,
        group_requests=0,
        walking=walking,
    )


def test_surveys_replies_and_opt_outs_survive_reopening(
    tmp_path: Path, database_url: str | None
) -> None:
    path = tmp_path / "journal.sqlite3"
    store = FeedbackStore.open(path, database_url=database_url)
    survey = Survey(instruction_id="ins-1", person="lee", chat=ChatRef(kind="dm", id="lee"),
                    sent_at=5.0)  # fmt: skip
    store.put_survey(survey)
    store.put_survey(survey.model_copy(update={"state": SurveyState.COMPLETE}))  # replaced
    answered = survey.model_copy(update={"state": SurveyState.DECLINED, "comment": "fine"})
    store.record_reply(answered, 6.0, "all good", "comment")
    store.opt_out("zhang", 7.0)
    store.opt_out("zhang", 8.0)  # already out: kept as it was
    for n, ended in enumerate((3.0, 1.0, 2.0)):
        store.put_instruction(_record(f"ins-{n}", ended))
    store.close()

    store = FeedbackStore.open(path, database_url=database_url)
    stored = store.survey("ins-1")
    assert stored is not None and (stored.state, stored.comment) == (SurveyState.DECLINED, "fine")
    assert store.replies("ins-1") == [(6.0, "all good", "comment")]
    assert store.active_surveys("lee") == []
    assert store.opted_out("zhang") and store.opted_out_people() == ["zhang"]
    store.opt_in("zhang")
    assert not store.opted_out("zhang")
    assert [r.instruction_id for r in store.instructions()] == ["ins-1", "ins-2", "ins-0"]
    assert [r.instruction_id for r in store.instructions(1.5, 3.0)] == ["ins-2"]
    store.close()
