"""What ``assistantx report`` says in words and charts: real dates in the title, counts in
grammatical English, a survey chart that says when nobody has answered, and what counts as a
message task or a survey comment ("asdf qwerty" is neither)."""

from __future__ import annotations

from datetime import UTC, datetime
from pathlib import Path

from assistantx.core.actions import Inform, Stop
from assistantx.core.office import Office
from assistantx.feedback.impact import InstructionRecord
from assistantx.feedback.report import (
    NO_ANSWERS,
    Period,
    UsageReport,
    build_report,
    chart_figure,
    load_report,
    parse_time,
    render_markdown,
)
from assistantx.feedback.walking import WalkingEstimate

from .scripted import harness


def _at(text: str) -> float:
    return datetime.fromisoformat(text).replace(tzinfo=UTC).timestamp()


def _record(n: int, ended_at: float, group_requests: int = 0) -> InstructionRecord:
    return InstructionRecord(
        instruction_id=f"i{n}",
        requester="lee",
        text="bring me a stapler",
        kind="delivery",
        outcome="done",
        started_at=ended_at - 60,
        ended_at=ended_at,
        steps=3,
        actions=5,
        group_requests=group_requests,
        walking=WalkingEstimate(
            instruction_id=f"i{n}",
            requester="lee",
            route=[],
            walk_m=10.0,
            robot_m=20.0,
            saved_m=10.0,
            method="map",
        ),
    )


def _title(report: UsageReport) -> str:
    return render_markdown(report).splitlines()[0]


def test_the_title_names_real_dates() -> None:
    records = [_record(1, _at("2026-11-30T09:15")), _record(2, _at("2026-12-01T17:40"))]
    everything = build_report(records, [], Period(start=None, end=None))
    assert _title(everything) == "# Usage report (2026-11-30 to 2026-12-01)"
    # --from 2026-11-01 --to 2026-11-30: the end day is included, and shown as itself
    asked = Period(start=parse_time("2026-11-01"), end=parse_time("2026-11-30", end=True))
    assert (
        _title(build_report(records[:1], [], asked)) == "# Usage report (2026-11-01 to 2026-11-30)"
    )
    one_day = build_report(records[1:], [], Period(start=None, end=None))
    assert _title(one_day) == "# Usage report (2026-12-01)"
    to_the_minute = Period(start=_at("2026-12-01T08:30"), end=None)
    assert _title(build_report(records[1:], [], to_the_minute)) == (
        "# Usage report (2026-12-01 08:30 UTC to 2026-12-01)"
    )
    empty = build_report([], [], Period(start=None, end=None))
    assert _title(empty) == "# Usage report (no instructions yet)"
    assert "…" not in render_markdown(empty)


def test_counts_are_in_grammatical_english() -> None:
    one = render_markdown(
        build_report([_record(1, 1e9, group_requests=1)], [], Period(start=None, end=None))
    )
    assert "1 instruction ended." in one
    assert "1 help request to group chats, in 1 instruction." in one
    two = render_markdown(
        build_report(
            [_record(1, 1e9, group_requests=2), _record(2, 1e9, group_requests=1)],
            [],
            Period(start=None, end=None),
        )
    )
    assert "2 instructions ended." in two
    assert "3 help requests to group chats, in 2 instructions." in two
    none = render_markdown(build_report([], [], Period(start=None, end=None)))
    assert "0 instructions ended." in none and "0 help requests to group chats." in none


def test_the_survey_chart_says_no_answers_yet_when_nobody_answered() -> None:
    report = build_report([_record(1, 1e9)], [], Period(start=None, end=None))
    axes = chart_figure(report, "survey").axes[0]
    assert [t.get_text() for t in axes.texts] == [NO_ANSWERS]
    assert axes.get_legend() is None


async def test_asdf_qwerty_is_no_message_task_and_no_survey_comment(
    office: Office, tmp_path: Path
) -> None:
    async with harness(office, tmp_path / "journal.sqlite3") as h:
        # what the assistant does with nonsense: it answers the requester and stops
        await h.run(
            "lee",
            "asdf qwerty",
            [
                [Inform(contact="lee", content="Sorry, I did not understand that.")],
                [Stop(outcome="done", summary="nothing to do")],
            ],
        )
        await h.run(
            "wang",
            "tell Zhang the meeting moved",
            [
                [Inform(contact="zhang", content="The meeting moved.")],
                [Stop(outcome="done", summary="told")],
            ],
        )
        await h.say("wang", "all yes")
        await h.say("wang", "asdf qwerty")  # after complete answers: a comment, if anything
        sorry = [t for t in h.texts_to("wang") if t.startswith("Sorry, I could not read that")]
        await h.say("wang", "too slow")
        report = load_report(h.store)
    assert report.instructions.by_kind == {"message": {"done": 1}, "none": {"done": 1}}
    assert sorry == ["Sorry, I could not read that as a comment."]
    assert [c.text for c in report.surveys.comments] == ["too slow"]
    assert report.surveys.invalid == 1
