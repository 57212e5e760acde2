"""A colleague asked to run a service is its doer only if they run it: "could Wang print my
file?", "can Yang heat my lunch?", "could Mark scan my document?".

The same rule as ``named_maker`` (a thing made from nothing), for every service that works on
the requester's thing (print, copy, scan, heat, laminate ...): a colleague named as the
subject right after a request's modal ("could Wang ...") with the service's own verb right
after the name (the lexicon's cue of the task's kind) is asked to do it. The office says who
can: the keepers (guards) of a facility that offers the task's operation. A keeper so named
does it (the robot asks them, not the first keeper on the list). Anyone else cannot do what
they were asked, and doing it with the keepers instead would be another errand than the one
asked: the reader says so and asks first ("Wang Fang doesn't look after the printer. Shall I
print your file for you?"); a yes does it with the keepers, as before.

A name after the verb ("print my file for Wang") or before a need ("Wang needs my file
printed") is whom it is for, never the doer: only the modal's subject is read here.
"""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.agents.symbolic.reading.named_maker import (
    asked_colleagues,
    done_by_keeper_or_asked,
)
from assistantx.agents.symbolic.reading.work_pro_verb import work_referred_to
from assistantx.core import english
from assistantx.core.office import Facility, Office
from assistantx.core.task_schema import Task, TaskFrame, operation_of

_REQUEST_MODALS = english.words("request_modals")


def _asked_to_do(whole: Lexed, requester: str, kind: str) -> set[str]:
    """The colleagues the message asks to do work of ``kind``: the work's own verb right
    after the name."""

    def doing(at: int) -> bool:
        # "could Mark scan it", and "could Mark run it / do it": the work named before
        # (``work_pro_verb``)
        if work_referred_to(whole.tokens, at):
            return True
        return any(c.kind == "cue" and c.start == at and kind in c.ids for c in whole.mentions)

    return asked_colleagues(whole, requester, doing)


def _services(office: Office, tasks: list[Task]) -> list[Task]:
    """The tasks done at a facility on a thing given (not made from nothing: ``named_maker``)."""
    return [t for t in tasks if t.kind != "produce" and operation_of(office, t) is not None]


def _offering(office: Office, task: Task) -> list[Facility]:
    op = operation_of(office, task)
    return office.offering(op) if op else []


def with_named_doer(
    office: Office, whole: Lexed, frame: TaskFrame, requester: str, *, confirmed: bool
) -> TaskFrame:
    """``frame`` with the colleague asked to do its one service as its doer where they keep a
    facility that offers it; where they keep none, the question that says so and offers to
    have it done anyway (unless ``confirmed``: the requester said yes, and the keepers do
    it). Unchanged where no colleague is asked, or several are, or the frame asks for several
    kinds of service."""
    if not frame.understood:
        return frame
    services = _services(office, frame.tasks)
    if not services or len({t.kind for t in services}) != 1:
        return frame
    asked = _asked_to_do(whole, requester, services[0].kind)
    if len(asked) != 1:
        return frame
    doer = next(iter(asked))
    facilities = _offering(office, services[0])
    if not facilities:
        return frame  # offered by no facility of the office: read (and declined) as it was
    return done_by_keeper_or_asked(
        frame, office, requester, doer, facilities, services, confirmed=confirmed
    )
