"""A part of a request this office has no means to do is said before anything moves: "I need
my document scanned and stamped" where nobody in the office has a seal. Stamping needs the
tool its doer owns (``task_kinds.tool_type``); an office whose file lists no such tool can
never get it done, and asking everyone at the end, after the scan was run, only tells the
requester afterwards that a part they asked for was dropped. So such a part is told first:
alone, the request is declined with the reason; beside parts that can be done, the
requester is asked whether to do those without it ("Shall I still scan your document?"),
and only their yes (``confirmed``) runs the rest. Parts the office has the means for are
read as before, whoever turns out to be free to do them."""

from __future__ import annotations

from assistantx.agents.symbolic.planning import describe
from assistantx.core import english, language, task_kinds
from assistantx.core.office import Office
from assistantx.core.task_schema import Task, TaskFrame


def _toolless(office: Office, task: Task) -> bool:
    """Whether nobody in the office can do the task: its kind needs a tool the office has no
    item type for at all, no colleague is named to do it (a named doer stamps with their
    own), and no service of the office on that paper is asked by the kind's words (a front
    desk that stamps forms with the practice stamp)."""
    if not task_kinds.needs_tool(task.kind) or task.actor is not None:
        return False
    if task_kinds.tool_type(task.kind, office) is not None:
        return False
    words = english.words(f"kind_{task.kind}")
    return not any(
        language.verb_lemmas(v.split()[0]) & words or v.split()[0] in words
        for op in office.operations
        if op.input == task.item  # a service on this paper ("seal in plastic" is a badge's)
        for v in op.verbs
    )


def _why(office: Office, task: Task, requester: str) -> str:
    tool = task_kinds.kind(task.kind).parts[0]
    return f"I can't {describe(task, office, requester)} here: no one in this office has a {tool}"


def without_toolless(
    office: Office, frame: TaskFrame, requester: str, *, confirmed: bool
) -> TaskFrame:
    """``frame`` with the parts no one in the office has the tool for told first: declined
    when nothing else is asked, asked about beside other parts, and left out once the
    requester said yes to doing the rest (``confirmed``)."""
    if not frame.understood:
        return frame
    missing = [t for t in frame.tasks if _toolless(office, t)]
    if not missing:
        return frame
    rest = [t for t in frame.tasks if not _toolless(office, t)]
    why = "; ".join(dict.fromkeys(_why(office, t, requester) for t in missing))
    if not rest:
        return TaskFrame(requester=requester, decline=f"Sorry, {why}.")
    if confirmed:
        return frame.model_copy(update={"tasks": rest})
    still = " and ".join(describe(t, office, requester) for t in rest)
    return TaskFrame(requester=requester, question=f"Sorry, {why}. Shall I still {still}?")
