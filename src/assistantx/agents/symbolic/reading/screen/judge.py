"""The last stage: what the reader answers. A message the screen answered itself (declined,
replied to in words, or met with "Shall I ...?") ends as such; otherwise the frames read from
the request are judged: a third person's need said as a fact is restated and asked before
anything moves ("Shall I bring Gao Min scissors?"), and every task is said in words as the
evidence of what was understood."""

from __future__ import annotations

from assistantx.agents.symbolic.planning import describe
from assistantx.agents.symbolic.reading.screen.been_through import present_hints, reworded_evidence
from assistantx.agents.symbolic.reading.screen.findings import Screened
from assistantx.core.office import Office
from assistantx.core.task_schema import Evidence, Task, TaskFrame


def answered_frame(screened: Screened, requester: str) -> TaskFrame:
    """The frame of a message with no request left to read (``Screened.answered``)."""
    if screened.decline is not None:
        return TaskFrame(
            requester=requester,
            decline=screened.decline,
            decline_outcome=screened.outcome,
            hints=screened.hints,
            evidence=screened.evidence,
        )
    return TaskFrame(
        requester=requester,
        question=screened.question,
        hints=screened.hints,
        evidence=screened.evidence,
    )


def judge(
    office: Office, screened: Screened, frame: TaskFrame, requester: str, *, confirmed: bool
) -> TaskFrame:
    """The frame read from what the screen left, with the screen's hints and evidence; a
    need to restate asked first unless ``confirmed`` (the requester already said yes)."""
    said = screened.text.strip()
    # "Zhang's been out in the rain, bring him a coffee": where the one delivered to has
    # been is no absence (``been_through``)
    hints = present_hints(screened.hints, frame.tasks)
    told = reworded_evidence(screened.evidence, screened.hints, hints)
    evidence = [*told, *(task_evidence(office, t, said) for t in frame.tasks)]
    if frame.understood and screened.confirm and not confirmed:
        what = " and ".join(describe(t, office, requester) for t in frame.tasks)
        frame = TaskFrame(requester=requester, question=f"Shall I {what}?")
    return frame.model_copy(update={"hints": hints, "evidence": evidence})


def task_evidence(office: Office, task: Task, said: str) -> Evidence:
    """A task in words: what it does, with whose item, for whom."""
    name = office.item_type(task.item).name if task.item else "item"
    kept = office.owner_name(task.owner) if task.owner else None
    whose = (
        f"{kept}'s {name}"
        if kept is not None
        else f"the {office.facility(task.owner).name}'s {name}"  # a supply, owned by nobody
        if task.owner
        else f"anyone's {name}"
        if task.kind == "transfer"
        else name
    )
    parts = [f"{task.kind.replace('_', ' ')}: {whose}"]
    if task.actor:
        parts.append(f"by {office.person(task.actor).name}")
    parts.append(f"for {office.person(task.recipient).name}")
    return Evidence(words=said[:300], meaning=" ".join(parts))
