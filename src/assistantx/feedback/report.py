"""The usage report: what the assistant did over a period and what people said about it.

``build_report`` aggregates the stored instruction records and surveys of the instructions
that *ended* in ``[start, end)``: instructions by kind and outcome, time to completion,
questions put to group chats, survey answer counts and shares, and walking saved (total and
per person). The same report renders as JSON (the model), as a Markdown summary and as PNG
charts (matplotlib's object API on the Agg canvas: no pyplot state, safe in worker threads).

Shares are of the surveys that answered the question (unanswered ones are counted apart as
``no_answer``), rounded to four places.
"""

from __future__ import annotations

import io
import math
import statistics
from collections import Counter, defaultdict
from collections.abc import Mapping
from datetime import UTC, date, datetime, time, timedelta
from pathlib import Path
from typing import TYPE_CHECKING, Literal

from pydantic import BaseModel, Field

from assistantx.core.task_schema import RECORD_KINDS
from assistantx.feedback.answers import CHOICES, Choice
from assistantx.feedback.impact import OUTCOMES, InstructionRecord
from assistantx.feedback.store import FeedbackStore
from assistantx.feedback.survey import QUESTIONS, Survey, SurveyState

if TYPE_CHECKING:  # matplotlib is imported when a chart is drawn: half a CPU-second at start
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

ChartName = Literal["outcomes", "survey", "walking"]
CHARTS: tuple[ChartName, ...] = ("outcomes", "survey", "walking")
NO_ANSWERS = "no answers yet"


class Period(BaseModel):
    start: float | None = Field(description="seconds since the epoch, inclusive")
    end: float | None = Field(description="seconds since the epoch, exclusive")
    requester: str | None = Field(default=None, description="only this person's instructions")


class Durations(BaseModel):
    count: int = 0
    mean_s: float | None = None
    median_s: float | None = None
    p90_s: float | None = None
    max_s: float | None = None


class InstructionSummary(BaseModel):
    total: int
    by_outcome: dict[str, int]
    by_kind: dict[str, dict[str, int]] = Field(description="kind → outcome → count")
    time_to_completion: Durations = Field(description="of the instructions that ended done")
    time_to_end: Durations = Field(description="of every instruction, whatever the outcome")
    first_ended_at: float | None = Field(default=None, description="the earliest end counted")
    last_ended_at: float | None = Field(default=None, description="the latest end counted")


class GroupRequests(BaseModel):
    total: int = Field(description="questions put to group chats")
    instructions: int = Field(description="instructions that asked a group chat")


class AnswerShare(BaseModel):
    count: int
    share: float | None = Field(description="count / answered; None when nobody answered")


class QuestionSummary(BaseModel):
    id: str
    text: str
    answered: int
    no_answer: int
    answers: dict[Choice, AnswerShare]


class SurveyComment(BaseModel):
    instruction_id: str
    person: str
    text: str
    name: str = Field(default="", description="the person's display name (the id when unknown)")


class SurveySummary(BaseModel):
    sent: int
    answered: int = Field(description="surveys with at least one answer or a comment")
    complete: int
    partial: int = Field(description="some but not all four questions answered")
    no_answer: int = Field(description="sent and never answered")
    declined: int
    opted_out: int = Field(description="surveys ended by an opt-out")
    invalid: int = Field(description="surveys that got an unreadable reply (each counted once)")
    reminded: int
    response_rate: float | None
    questions: list[QuestionSummary]
    comments: list[SurveyComment]


class PersonWalking(BaseModel):
    instructions: int
    saved_m: float
    name: str = Field(default="", description="the person's display name (the id when unknown)")


class WalkingSummary(BaseModel):
    saved_m: float = Field(description="walking saved by instructions that ended done")
    walk_m: float = Field(description="the requesters' walks for every instruction")
    robot_m: float
    by_person: dict[str, PersonWalking]
    method: dict[str, int] = Field(description="how the walks were measured: map/straight-line")


class UsageReport(BaseModel):
    period: Period
    generated_at: float
    instructions: InstructionSummary
    group_requests: GroupRequests
    surveys: SurveySummary
    walking: WalkingSummary


# -- periods -----------------------------------------------------------------------------------
LAST_EPOCH_S = datetime(9999, 12, 31, 23, 59, 59, tzinfo=UTC).timestamp()


def parse_time(text: str, *, end: bool = False) -> float:
    """An ISO date or date-time (UTC when no zone is given), or seconds since the epoch.

    A bare date as the end of a period means the end of that day, so ``--to 2025-03-31``
    includes the 31st. Raises ValueError naming the accepted forms.
    """
    value = text.strip()
    try:
        seconds = float(value)
    except ValueError:
        pass
    else:
        # float() also takes "nan", "inf" and 1e20: none is a moment a report can cover.
        if not (math.isfinite(seconds) and 0 <= seconds <= LAST_EPOCH_S):
            raise ValueError(
                f"{text!r} is not a time: epoch seconds must lie between 0 and "
                f"{LAST_EPOCH_S:.0f} (the end of year 9999)"
            )
        return seconds
    try:
        if len(value) == 10:
            day = date.fromisoformat(value)
            moment = datetime.combine(day, time(), tzinfo=UTC)
            return (moment + timedelta(days=1 if end else 0)).timestamp()
        moment = datetime.fromisoformat(value)
    except ValueError as exc:
        raise ValueError(
            f"{text!r} is not a time: use YYYY-MM-DD, an ISO date-time or epoch seconds"
        ) from exc
    if moment.tzinfo is None:
        moment = moment.replace(tzinfo=UTC)
    return moment.timestamp()


# -- aggregation -------------------------------------------------------------------------------
def load_report(
    store: FeedbackStore,
    start: float | None = None,
    end: float | None = None,
    now: float = 0.0,
    *,
    requester: str | None = None,
    names: Mapping[str, str] | None = None,
) -> UsageReport:
    """The report of the instructions that ended in [start, end) (of one requester if given);
    ``names`` (person id → display name) names people in the text and charts."""
    if start is not None and end is not None and end <= start:
        raise ValueError("the end of the period must come after its start")
    records = store.instructions(start, end)
    if requester is not None:
        records = [r for r in records if r.requester == requester]
    surveys = store.surveys([r.instruction_id for r in records])
    period = Period(start=start, end=end, requester=requester)
    return build_report(records, surveys, period, now, names=names)


def build_report(
    records: list[InstructionRecord],
    surveys: list[Survey],
    period: Period,
    now: float = 0.0,
    *,
    names: Mapping[str, str] | None = None,
) -> UsageReport:
    names = names or {}
    return UsageReport(
        period=period,
        generated_at=now,
        instructions=_instructions(records),
        group_requests=GroupRequests(
            total=sum(r.group_requests for r in records),
            instructions=sum(1 for r in records if r.group_requests),
        ),
        surveys=_surveys(surveys, names),
        walking=_walking(records, names),
    )


def _instructions(records: list[InstructionRecord]) -> InstructionSummary:
    by_outcome = Counter(r.outcome for r in records)
    by_kind: dict[str, dict[str, int]] = {}
    for kind in RECORD_KINDS:
        counts = Counter(r.outcome for r in records if r.kind == kind)
        if counts:
            by_kind[kind] = {o: counts[o] for o in OUTCOMES if counts[o]}
    return InstructionSummary(
        total=len(records),
        by_outcome={o: by_outcome[o] for o in OUTCOMES},
        by_kind=by_kind,
        time_to_completion=_durations([r.duration_s for r in records if r.outcome == "done"]),
        time_to_end=_durations([r.duration_s for r in records]),
        first_ended_at=min((r.ended_at for r in records), default=None),
        last_ended_at=max((r.ended_at for r in records), default=None),
    )


def _durations(values: list[float]) -> Durations:
    if not values:
        return Durations()
    ordered = sorted(values)
    p90 = ordered[max(0, math.ceil(0.9 * len(ordered)) - 1)]  # nearest-rank percentile
    return Durations(
        count=len(values),
        mean_s=round(statistics.fmean(values), 3),
        median_s=round(statistics.median(values), 3),
        p90_s=round(p90, 3),
        max_s=round(ordered[-1], 3),
    )


def _surveys(surveys: list[Survey], names: Mapping[str, str]) -> SurveySummary:
    questions = []
    for question in QUESTIONS:
        counts = Counter(s.answers[question.id] for s in surveys if question.id in s.answers)
        answered = sum(counts.values())
        questions.append(
            QuestionSummary(
                id=question.id,
                text=question.text,
                answered=answered,
                no_answer=len(surveys) - answered,
                answers={
                    c: AnswerShare(
                        count=counts[c], share=round(counts[c] / answered, 4) if answered else None
                    )
                    for c in CHOICES
                },
            )
        )
    responded = [s for s in surveys if s.answers or s.comment]
    complete = sum(1 for s in surveys if len(s.answers) == len(QUESTIONS))
    return SurveySummary(
        sent=len(surveys),
        answered=len(responded),
        complete=complete,
        partial=sum(1 for s in surveys if 0 < len(s.answers) < len(QUESTIONS)),
        no_answer=len(surveys) - len(responded),
        declined=sum(1 for s in surveys if s.state is SurveyState.DECLINED),
        opted_out=sum(1 for s in surveys if s.state is SurveyState.OPTED_OUT),
        invalid=sum(1 for s in surveys if s.invalid_replies),
        reminded=sum(1 for s in surveys if s.reminded_at is not None),
        response_rate=round(len(responded) / len(surveys), 4) if surveys else None,
        questions=questions,
        comments=[
            SurveyComment(
                instruction_id=s.instruction_id,
                person=s.person,
                text=s.comment,
                name=names.get(s.person, s.person),
            )
            for s in surveys
            if s.comment
        ],
    )


def _walking(records: list[InstructionRecord], names: Mapping[str, str]) -> WalkingSummary:
    per_person: dict[str, list[float]] = defaultdict(list)
    for r in records:
        per_person[r.requester].append(r.walking.saved_m)
    return WalkingSummary(
        saved_m=round(sum(r.walking.saved_m for r in records), 3),
        walk_m=round(sum(r.walking.walk_m for r in records), 3),
        robot_m=round(sum(r.walking.robot_m for r in records), 3),
        by_person={
            p: PersonWalking(instructions=len(v), saved_m=round(sum(v), 3), name=names.get(p, p))
            for p, v in sorted(per_person.items())
        },
        method=dict(Counter(r.walking.method for r in records)),
    )


# -- Markdown ----------------------------------------------------------------------------------
def render_markdown(report: UsageReport) -> str:
    ins, srv, walk = report.instructions, report.surveys, report.walking
    lines = [f"# Usage report ({_period_text(report)})", ""]
    lines += ["## Instructions", "", f"{_count(ins.total, 'instruction')} ended.", ""]
    lines += ["| kind | " + " | ".join(OUTCOMES) + " |", "|---" * (len(OUTCOMES) + 1) + "|"]
    for kind, counts in ins.by_kind.items():
        lines.append(f"| {kind} | " + " | ".join(str(counts.get(o, 0)) for o in OUTCOMES) + " |")
    lines.append("| **all** | " + " | ".join(str(ins.by_outcome[o]) for o in OUTCOMES) + " |")
    done = ins.time_to_completion
    lines += [
        "",
        f"Time to completion (done, n={done.count}): median {_seconds(done.median_s)}, "
        f"p90 {_seconds(done.p90_s)}, mean {_seconds(done.mean_s)}.",
        _group_requests_text(report.group_requests),
        "",
        "## Survey",
        "",
        f"{srv.sent} sent, {srv.answered} answered ({_percent(srv.response_rate)}), "
        f"{srv.complete} complete, {srv.partial} partial, {srv.no_answer} without answer, "
        f"{srv.declined} declined, {srv.opted_out} opted out; {srv.reminded} reminded, "
        f"{srv.invalid} with an unreadable reply.",
        "",
        "| question | yes | no | unsure | no answer |",
        "|---|---|---|---|---|",
    ]
    for q in srv.questions:
        cells = [f"{q.answers[c].count} ({_percent(q.answers[c].share)})" for c in CHOICES]
        lines.append(f"| {q.text} | " + " | ".join(cells) + f" | {q.no_answer} |")
    if srv.comments:
        lines += ["", "Comments:", ""]
        lines += [f"- {c.name or c.person}: {_one_line(c.text)}" for c in srv.comments]
    lines += [
        "",
        "## Walking saved",
        "",
        f"{walk.saved_m:.1f} m saved in all; the robot drove {walk.robot_m:.1f} m.",
        "",
        "| person | instructions | saved (m) |",
        "|---|---|---|",
    ]
    lines += [
        f"| {w.name or p} | {w.instructions} | {w.saved_m:.1f} |" for p, w in walk.by_person.items()
    ]
    return "\n".join(lines) + "\n"


def _period_text(report: UsageReport) -> str:
    """The period as dates: the bounds asked for, else the days of the first and last end
    counted. A bound at midnight is a whole day (an exclusive end shows as the day before);
    a bound at another time shows to the minute."""
    period, ins = report.period, report.instructions
    if period.start is not None:
        first = _bound(period.start, exclusive=False)
    elif ins.first_ended_at is not None:
        first = _day(ins.first_ended_at)
    else:
        first = "the beginning"
    if period.end is not None:
        last = _bound(period.end, exclusive=True)
    elif ins.last_ended_at is not None:
        last = _day(ins.last_ended_at)
    else:
        last = "now"
    if period.start is None and period.end is None and ins.first_ended_at is None:
        return "no instructions yet"
    return first if first == last else f"{first} to {last}"


def _day(t: float) -> str:
    return datetime.fromtimestamp(t, UTC).date().isoformat()


def _bound(t: float, *, exclusive: bool) -> str:
    moment = datetime.fromtimestamp(t, UTC)
    if moment.time() != time():
        return moment.strftime("%Y-%m-%d %H:%M UTC")
    return _day(t - 1) if exclusive else _day(t)


def _count(n: int, noun: str) -> str:
    return f"{n} {noun}" if n == 1 else f"{n} {noun}s"


def _group_requests_text(requests: GroupRequests) -> str:
    asked = f"{_count(requests.total, 'help request')} to group chats"
    if not requests.total:
        return f"{asked}."
    return f"{asked}, in {_count(requests.instructions, 'instruction')}."


def _percent(share: float | None) -> str:
    return "–" if share is None else f"{100 * share:.0f}%"


def _seconds(value: float | None) -> str:
    return "–" if value is None else f"{value:.0f} s"


def _one_line(text: str) -> str:
    return " ".join(text.split()).replace("|", "/")


# -- charts ------------------------------------------------------------------------------------
_COLOURS = {"yes": "#2e7d32", "no": "#c62828", "unsure": "#9e9e9e"}
_OUTCOME_COLOURS = {
    "done": "#2e7d32",
    "failed": "#c62828",
    "unachievable": "#ef6c00",
    "cancelled": "#9e9e9e",
}


def chart_figure(report: UsageReport, name: ChartName) -> Figure:
    """One chart as a matplotlib Figure (drawn on the Agg canvas)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    figure = Figure(figsize=(6.4, 3.6), dpi=100, layout="constrained")
    FigureCanvasAgg(figure)  # attaches the Agg canvas to the figure
    axes = figure.add_subplot()
    if name == "outcomes":
        _outcomes_chart(report, axes)
    elif name == "survey":
        _survey_chart(report, axes)
    elif name == "walking":
        _walking_chart(report, axes)
    else:
        raise ValueError(f"unknown chart {name!r}; charts: {', '.join(CHARTS)}")
    return figure


def render_chart(report: UsageReport, name: ChartName) -> bytes:
    """One chart as PNG bytes."""
    buffer = io.BytesIO()
    chart_figure(report, name).savefig(buffer, format="png")
    return buffer.getvalue()


def _outcomes_chart(report: UsageReport, axes: Axes) -> None:
    kinds = list(report.instructions.by_kind) or ["(none)"]
    bottom = [0] * len(kinds)
    for outcome in OUTCOMES:
        counts = [report.instructions.by_kind.get(k, {}).get(outcome, 0) for k in kinds]
        axes.bar(kinds, counts, bottom=bottom, label=outcome, color=_OUTCOME_COLOURS[outcome])
        bottom = [b + c for b, c in zip(bottom, counts, strict=True)]
    axes.set_ylabel("instructions")
    from matplotlib.ticker import MaxNLocator

    axes.yaxis.set_major_locator(MaxNLocator(integer=True))  # whole instructions only
    axes.set_title("Instructions by kind and outcome")
    _legend_outside(axes)


def _survey_chart(report: UsageReport, axes: Axes) -> None:
    questions = list(reversed(report.surveys.questions))
    labels = [f"{q.text} (n={q.answered})" for q in questions]
    left = [0.0] * len(questions)
    for choice in CHOICES:
        shares = [100 * (q.answers[choice].share or 0.0) for q in questions]
        axes.barh(labels, shares, left=left, label=choice, color=_COLOURS[choice])
        left = [a + b for a, b in zip(left, shares, strict=True)]
    axes.set_xlim(0, 100)
    axes.set_xlabel("% of answers")
    axes.set_title("Survey answers")
    if not any(q.answered for q in questions):  # an empty frame would read as a broken chart
        axes.text(0.5, 0.5, NO_ANSWERS, transform=axes.transAxes, ha="center", va="center")
        return
    _legend_outside(axes)


def _legend_outside(axes: Axes) -> None:
    """The legend right of the plot, never over a bar."""
    axes.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)


def chart_people(report: UsageReport) -> list[str]:
    """The walking chart's bar labels: people by name, in the report's order."""
    return [w.name or p for p, w in report.walking.by_person.items()]


def _walking_chart(report: UsageReport, axes: Axes) -> None:
    people = chart_people(report) or ["(none)"]
    saved = [w.saved_m for w in report.walking.by_person.values()] or [0.0]
    axes.bar(people, saved, color="#1565c0")
    axes.set_ylabel("metres")
    axes.set_title(f"Walking saved per person ({report.walking.saved_m:.0f} m in all)")
    axes.tick_params(axis="x", labelrotation=45)


# -- files -------------------------------------------------------------------------------------
def write_report(report: UsageReport, out_dir: Path) -> list[Path]:
    """usage.json, usage.md and one PNG per chart in ``out_dir``; returns the paths."""
    out_dir.mkdir(parents=True, exist_ok=True)
    written = [out_dir / "usage.json", out_dir / "usage.md"]
    written[0].write_text(report.model_dump_json(indent=2) + "\n", encoding="utf-8")
    written[1].write_text(render_markdown(report), encoding="utf-8")
    for name in CHARTS:
        path = out_dir / f"usage-{name}.png"
        path.write_bytes(render_chart(report, name))
        written.append(path)
    return written
