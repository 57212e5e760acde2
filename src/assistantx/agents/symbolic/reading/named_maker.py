"""A colleague asked to make a thing is its maker only if they look after a machine that makes
it: "could Wang make one? I need a coffee", "I need a coffee, could Wang make one?", "could
Zhang make me a coffee?".

A colleague named as the subject right after a request's modal ("could Wang ...", "can Gao
...") with a verb of making after the name ("make", "knock up", "whip up", "brew") is asked to
make the thing the message asks for (a thing made from nothing: a coffee, a tea). The office
says who can: the keepers (guards) of a facility whose operation makes it. A keeper so named
makes it (the robot asks them, not the first keeper on the list). Anyone else cannot do what
they were asked, and making it with the keepers instead would be a different errand from the
one asked: the reader says so and asks first ("Wang Fang doesn't look after the coffee
machine. Shall I make a coffee for you?"); a yes makes it with the keepers, as before.

Whom it is for is left as read ("could Zhang make *me* a coffee": the requester); a name after
the verb ("can you make Gao one") is whom it is for, never the maker.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from assistantx.agents.symbolic.planning import describe
from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.core import english
from assistantx.core.office import Facility, Office
from assistantx.core.task_schema import Task, TaskFrame

_MAKING = english.words("making_verbs")
_REQUEST_MODALS = english.words("request_modals")
# Whom a made thing is for, said before it ("make *me* a coffee"): skipped to its object.
_FOR_WHOM = frozenset({"me", "us", "you", "him", "her", "them"})
_ONE = frozenset({"one", "some"})
_ARTICLES = frozenset({"a", "an", "some", "another"})


def _makes_it(whole: Lexed, at: int, item: str) -> bool:
    """Whether the verb of making at token ``at`` takes the thing as its object: "one"
    ("make one", "knock one up"), or the thing's own word ("make me a coffee", "brew a
    tea"), after whom it is for; "make a copy of my file" names another thing."""
    tokens, k = whole.tokens, at + 1
    while k < len(tokens) and tokens[k].word in _FOR_WHOM:
        k += 1
    if k < len(tokens) and tokens[k].word in _ONE:
        return True
    while k < len(tokens) and tokens[k].word in _ARTICLES:
        k += 1
    return any(m.start == k and m.kind == "item" and m.ids == (item,) for m in whole.mentions)


def asked_colleagues(whole: Lexed, requester: str, work_at: Callable[[int], bool]) -> set[str]:
    """The colleagues the message asks to do some work: a person (not the requester) named
    right after a request's modal ("could Wang ..."), ``work_at`` true of the word right
    after the name (the work's verb)."""
    tokens = whole.tokens
    found: set[str] = set()
    for m in whole.mentions:
        if m.kind != "person" or len(m.ids) != 1 or m.possessive or m.id == requester:
            continue
        if m.start == 0 or tokens[m.start - 1].word not in _REQUEST_MODALS:
            continue
        if work_at(m.end):
            found.add(m.id)
    return found


def _asked_to_make(whole: Lexed, requester: str, item: str) -> set[str]:
    """The colleagues the message asks to make ``item``: a verb of making right after the
    name, the thing its object."""
    tokens = whole.tokens

    def making(at: int) -> bool:
        return at < len(tokens) and tokens[at].word in _MAKING and _makes_it(whole, at, item)

    return asked_colleagues(whole, requester, making)


def _makers_of(office: Office, item: str) -> list[Facility]:
    """The facilities one of whose operations makes ``item`` from nothing."""
    ops = {op.id for op in office.operations if op.product == item and op.input is None}
    return [f for f in office.facilities if ops & set(f.operations)]


def _made(tasks: Sequence[Task]) -> list[Task]:
    return [t for t in tasks if t.kind == "produce" and t.item is not None]


def with_named_maker(
    office: Office, whole: Lexed, frame: TaskFrame, requester: str, *, confirmed: bool
) -> TaskFrame:
    """``frame`` with the colleague asked to make its one kind of thing made from nothing as
    that thing's maker where they keep a facility that makes it; where they keep none, the
    question that says so and offers to make it anyway (unless ``confirmed``: the requester
    said yes, and the keepers make it). Unchanged where no colleague is asked to make one, or
    several are, or the frame makes several kinds of thing."""
    if not frame.understood:
        return frame
    made = _made(frame.tasks)
    if not made or len({t.item for t in made}) != 1:
        return frame
    item = made[0].item or ""
    asked = _asked_to_make(whole, requester, item)
    if len(asked) != 1:
        return frame
    maker = next(iter(asked))
    facilities = _makers_of(office, item)
    if not facilities:
        return frame  # made by no machine of the office: read as it was
    return done_by_keeper_or_asked(
        frame, office, requester, maker, facilities, made, confirmed=confirmed
    )


def done_by_keeper_or_asked(
    frame: TaskFrame,
    office: Office,
    requester: str,
    colleague: str,
    facilities: Sequence[Facility],
    asked_of: Sequence[Task],
    *,
    confirmed: bool,
) -> TaskFrame:
    """The tasks ``asked_of`` the colleague done by them where they keep one of
    ``facilities``; where they keep none, the question that says so and offers to do it
    anyway (unless ``confirmed``: the requester said yes, and the keepers do it). Shared by
    the maker asked to make a thing and the colleague asked to run a service."""
    if any(colleague in f.guards for f in facilities):
        tasks = [
            t.model_copy(update={"actor": colleague}) if t in asked_of else t for t in frame.tasks
        ]
        return frame.model_copy(update={"tasks": tasks})
    if confirmed:
        return frame  # "Shall I make it for you?" "Yes": done by the keepers
    who = office.person(colleague).name
    where = " or the ".join(dict.fromkeys(f.name for f in facilities))
    what = " and ".join(describe(t, office, requester) for t in frame.tasks)
    return TaskFrame(
        requester=requester,
        question=f"{who} doesn't look after the {where}. Shall I {what}?",
    )
