"""Where the requester says the thing can be had, after asking for it: "need cable ties for
the rig, the art room has some", "... there are some in the art room", "... art room should
have some" (the frames stage, once the tasks are read).

A statement that a colleague has one ("need scissors, Sun Li has a pair", "I think Zhang has
one", "Liu's got a spare stapler") names whom to borrow from, as "Sun Li's scissors" would;
where the office knows of none of theirs, the requester is asked.

A statement that a place or facility of the office has some (a modal may come before "have":
"should", "might", "will"), or that there are some in/at it, names the source of the item the
request leaves to anyone: the one kept there, as "cable ties from the art room" would. None
kept there, or several people's: the requester is asked, never a guess elsewhere.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

from assistantx.agents.symbolic.reading.kept_items import items_kept_at
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core.office import Office
from assistantx.core.task_schema import Task

# "has some", "should have a few": the words that say some are there (not which)
_SOME = frozenset(
    {"some", "them", "plenty", "loads", "lots", "spares", "spare", "few", "one", "pair"}
)
_HAVE = frozenset({"has", "have", "got", "keeps", "keep", "stocks"})
_MODALS = frozenset({"should", "might", "may", "will", "would", "must", "probably", "definitely"})
_BE = frozenset({"is", "are", "be", "were", "was"})
_AT = frozenset({"in", "at", "on", "inside"})
_FILLERS = frozenset({"the", "a", "an", "still", "also", "usually", "always", "spare", "of"})


@dataclass(frozen=True)
class StatedSource:
    """A place, facility or colleague said to have some."""

    place: str  # its name, as the office writes it
    kind: Literal["facility", "place", "person"]
    where: str  # the facility's, location's or person's id
    item: str | None = None  # the item type named after "has" ("has a spare stapler")


def stated_sources(
    office: Office, tokens: Sequence[Token], mentions: Sequence[Mention]
) -> list[StatedSource]:
    """The places the text says have some ("P has some", "there are some in P"), and the
    colleagues ("Sun Li has a pair", "Liu's got a spare stapler")."""
    found: list[StatedSource] = []
    for m in mentions:
        if m.kind == "person" and len(m.ids) == 1:
            if _has_some_after(tokens, m.end, tokens[m.end - 1].possessive):
                kept = _kept_in(tokens, mentions, m.end)
                if kept is not None:  # "Siobhán usually has them in the key press": there
                    found.append(_source(office, kept))
                    continue
                named = [
                    n.ids[0]
                    for n in mentions
                    if n.kind == "item" and m.end <= n.start < m.end + 5 and len(n.ids) == 1
                ]
                name = office.person(m.ids[0]).name
                found.append(StatedSource(name, "person", m.ids[0], named[0] if named else None))
            continue
        if m.kind not in ("facility", "place"):
            continue
        if _has_some_after(tokens, m.end, tokens[m.end - 1].possessive) or _there_some_before(
            tokens, m.start
        ):
            found.append(_source(office, m))
    return found


# how far after a colleague's "has some" the place they keep them may be said ("has them
# *in the key press*", "usually has a few spare ones *at the stores*")
_KEPT_NEAR = 8


def _kept_in(tokens: Sequence[Token], mentions: Sequence[Mention], at: int) -> Mention | None:
    """The facility or place of the office said after a colleague's "has some", with "in",
    "at" or "on" before it, in the same clause: where the things are, which the colleague
    only looks after or keeps there ("Siobhán usually has them in the key press")."""
    for m in mentions:
        if m.kind not in ("facility", "place") or not at <= m.start < at + _KEPT_NEAR:
            continue
        if any(t.opens or t.after_pause for t in tokens[at : m.start + 1]):
            return None
        n = m.start - 1
        while n >= at and tokens[n].word in _FILLERS:
            n -= 1
        return m if n >= at and tokens[n].word in _AT else None
    return None


def _has_some_after(tokens: Sequence[Token], at: int, contracted: bool) -> bool:
    """ "<P> has some", "<P> should have a few", "<P>'s got some"."""
    return says_has_some([t.word for t in tokens[at : at + 5]], contracted)


def says_has_some(words: Sequence[str], contracted: bool = False) -> bool:
    """Whether the words after a place say it has some ("has some", "should have a few",
    after "<P>'s": "got some"); the place is then where the thing is, not a service asked."""
    words = list(words[:5])
    n = 0
    while n < len(words) and words[n] in _MODALS:
        n += 1
    if n < len(words) and (words[n] in _HAVE or (contracted and words[n] == "got")):
        n += 1
        while n < len(words) and words[n] in ("a", "got"):
            n += 1
        return n < len(words) and words[n] in _SOME
    return False


def _there_some_before(tokens: Sequence[Token], start: int) -> bool:
    """ "there are some in <P>", "there should be some at the <P>", "there's one in <P>"."""
    n = start - 1
    while n >= 0 and tokens[n].word in _FILLERS:
        n -= 1
    if n < 0 or tokens[n].word not in _AT:
        return False
    n -= 1
    if n < 0 or tokens[n].word not in _SOME:
        return False
    n -= 1
    while n >= 0 and (tokens[n].word in _BE or tokens[n].word in _MODALS):
        n -= 1
    return n >= 0 and tokens[n].word == "there"


def _source(office: Office, m: Mention) -> StatedSource:
    if m.kind == "facility":
        return StatedSource(office.facility(m.ids[0]).name, "facility", m.ids[0])
    return StatedSource(office.location(m.ids[0]).name.lower(), "place", m.ids[0])


def from_stated_source(
    office: Office, tasks: Sequence[Task], sources: Sequence[StatedSource]
) -> tuple[list[Task], str | None]:
    """The tasks with the item left to anyone taken from the one place said to have some;
    the question to ask when that place keeps none of it, or several people's, or several
    places were said."""
    if not sources:
        return list(tasks), None
    out: list[Task] = []
    for task in tasks:
        if task.kind != "transfer" or task.item is None or task.owner or task.source:
            out.append(task)
            continue
        # a colleague said to have another thing, or the one it goes to: not the source
        fit = [
            s
            for s in sources
            if s.kind != "person" or (s.item in (None, task.item) and s.where != task.recipient)
        ]
        if not fit:
            out.append(task)
            continue
        sources = fit
        name = office.item_type(task.item).name
        person = sources[0]
        if all(s.kind == "person" and s.where == person.where for s in sources):
            if person.where not in office.owners_of(task.item):
                return [], (
                    f"I don't know of any {name} of {person.place}'s. Where should I get one from?"
                )
            out.append(task.model_copy(update={"owner": person.where}))
            continue
        if len({s.place for s in sources}) > 1:
            places = " or ".join(
                s.place if s.kind == "person" else f"the {s.place}" for s in sources
            )
            return [], f"Where should I get the {name} from: {places}?"
        source = sources[0]
        if source.kind == "person":  # a colleague said twice: the place's name is theirs
            return [], f"Where should I get the {name} from?"
        there = items_kept_at(office, source.kind, source.where)
        kept = tuple(
            dict.fromkeys(
                k.owner for k in there if k.type_id == task.item and k.owner != task.recipient
            )
        )
        if len(kept) != 1:
            return [], (
                f"I don't know of any {name} kept at the {source.place}. Where should I get "
                f"one from?"
                if not kept
                else f"Which {name} at the {source.place} should I get?"
            )
        out.append(task.model_copy(update={"owner": kept[0]}))
    return out, None
