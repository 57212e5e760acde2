"""A need said, then the work that meets it: one errand, not two ("Priya asked for the
agenda, print it for her"; "Priya needs a printout of my agenda, print one for her").

The screen restates a third person's need as "Priya needs the agenda", which the frames read
as its own task (the file sent to her); the request after it that works on the same item for
the same person ("print it for her") is how the need is met, so the need's task gives way to
it. The work a need names, asked for again for the same person ("needs a printout ...,
print one for her"), is one print. An errand said as two requests ("send Priya my agenda and
print it for her") keeps both: only a need gives way.

An unnamed person's need ("an intern needs a stapler", "one of the beginners needs a marking
pen"), then a hand-over of that thing to a colleague ("could you bring one to Wang?"): the
colleague is how it reaches them; the need read as the speaker's own made a second one for the
speaker (``unnamed_need_met``). So is a person described by a noun that names nothing of the
office ("the carver needs a set square, could you take him mine", once "him" is named).
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading._parties import Clause
from assistantx.agents.symbolic.reading.outsider_need import (
    DESCRIBING_ARTICLES,
    LACKED_OPENERS,
    outsider_wants,
)
from assistantx.agents.symbolic.reading.speech import content
from assistantx.agents.symbolic.reading.tokens import Token, clause_start
from assistantx.core import english, language, task_kinds
from assistantx.core.task_schema import Task

_NEEDS = english.words("need_verbs")
_HANDING = frozenset({"transfer", "send_file"})


def says_a_need(clause: Clause, tokens: Sequence[Token]) -> bool:
    """Whether a clause says someone needs something ("Priya needs the agenda")."""
    return any(tokens[m.start].word in _NEEDS for m in clause.mentions)


def met_by(need: Task, made: Sequence[Task]) -> bool:
    """Whether the one task ``made`` works on the needed item for the one who needs it, so
    the need's own hand-over is only the reason for it."""
    if len(made) != 1 or need.kind not in _HANDING:
        return False
    work = made[0]
    return (
        work.kind != need.kind
        and work.item == need.item
        and work.recipient == need.recipient
        and (_makes_from(work.kind) or task_kinds.works_on_item(work.kind))
    )


def _makes_from(kind_id: str) -> bool:
    """Whether a kind makes a product from the item (a printout of the file, a copy or a
    scan of the paper): the product is what the one who needs the item gets, so "Zhang needs
    my report, make him a copy of it" is one copy, not the report handed over as well."""
    return task_kinds.kind(kind_id).shape in ("render", "transform")


def same_work(earlier: Task, task: Task) -> bool:
    """Whether ``task`` is ``earlier``'s work said again (not a hand-over: two pens are two)."""
    return (
        task.kind not in _HANDING
        and task.item is not None
        and (earlier.kind, earlier.item, earlier.owner, earlier.recipient, earlier.operation)
        == (task.kind, task.item, task.owner, task.recipient, task.operation)
        and earlier.actor == task.actor
    )


def needs_said_again(tasks: Sequence[Task], from_need: Sequence[Task]) -> list[Task]:
    """``tasks`` without a later task that is the same work as one a need said ("Wang needs a
    printout for the meeting. Can you print my file and take it to him?": the request's print
    is for Wang only once "take it to him" is read, after the need was compared with it). Two
    hand-overs stay two (``same_work``)."""
    out: list[Task] = []
    for t in tasks:
        said = [n for n in out if any(n is m for m in from_need)]
        if not any(same_work(n, t) for n in said):
            out.append(t)
    return out


# "*one of the* beginners needs ...": one of a group named by what they are
_ONE_OF = ("one", "of")


def says_an_unnamed_need(clause: Clause, tokens: Sequence[Token]) -> bool:
    """Whether a clause says a person named by what they are needs something ("an intern
    needs a stapler", "one of the beginners needs a pen"), nobody of the office."""
    if not clause.mentions:
        return False
    # the article before the first mention is no mention: from the clause's first word
    start, end = clause_start(tokens, clause.mentions[0].start), clause.mentions[-1].end
    words = content([t.word for t in tokens[start:end]])
    if tuple(words[:2]) == _ONE_OF:
        words = words[2:]
    return outsider_wants(words) or _described_party_needs(clause, tokens, start)


def _described_party_needs(clause: Clause, tokens: Sequence[Token], start: int) -> bool:
    """ "the carver needs a set square": an article, at most one describing word and a noun,
    none of them a name of the office (no mention of a thing, place or colleague covers
    them), then a need verb: someone described, whose need a later hand-over meets."""
    need = next((m.start for m in clause.mentions if tokens[m.start].word in _NEEDS), None)
    if need is None or not 2 <= need - start <= 3 or tokens[start].word not in DESCRIBING_ARTICLES:
        return False
    if any(m.kind != "word" and m.start < need for m in clause.mentions):
        return False
    # "needs *a* set square": a thing they lack, not work on a thing ("needs stamping")
    if need + 1 >= len(tokens) or tokens[need + 1].word not in LACKED_OPENERS:
        return False
    return language.is_noun(tokens[need - 1].word)


def unnamed_need_met(need: Task, made: Sequence[Task], requester: str) -> bool:
    """Whether ``made`` hands the thing an unnamed person needs (read as the speaker's) to
    a colleague: that hand-over meets the need, which is no errand of its own."""
    return (
        need.kind in _HANDING
        and need.recipient == requester
        and any(
            t.kind == need.kind and t.item == need.item and t.recipient != requester for t in made
        )
    )
