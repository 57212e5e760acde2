"""Fact: "Wang is away", "Zhang is in the meeting room", "Zhang's stapler is broken", "I
can't find my stapler": a hint for the plan; the piece is dropped."""

from __future__ import annotations

from dataclasses import replace

from assistantx.agents.symbolic.reading.screen.elsewhere import (
    away_elsewhere,
    leaving_soon,
    state_said,
)
from assistantx.agents.symbolic.reading.screen.english import starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.left_behind import (
    left_behind,
    lend_offer,
    situation_said,
)
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english, wording
from assistantx.core.task_schema import Hint

_BACK = tuple(
    sorted((tuple(p.split()) for p in english.entries("back_openers")), key=lambda p: -len(p))
)
_BACK_TIMES = english.words("back_times")
_JOINS = frozenset({"and", "but", "so"})
_BACK_LEADS = english.words("back_leads")


def fact(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    if any(m.kind == "self" for m in mentions):  # "ugh laptop's dead and I forgot my cable"
        behind = own_item_fact(terms, msg, piece, requester)
        if behind is not None:
            return behind  # "calving at Pryce's tonight and my head torch is dead"
    k = 0
    while k < len(mentions) and mentions[k].kind == "word":
        if tokens[mentions[k].start].word not in terms.en.fact_openers:
            return None
        k += 1
    if k < len(mentions) and mentions[k].kind == "self":
        return own_item_fact(terms, msg, piece, requester)
    if k == 0 and mentions and mentions[0].kind == "item":  # "stapler's broken"
        return own_item_fact(terms, msg, piece, requester)
    if k >= len(mentions) or mentions[k].kind != "person" or len(mentions[k].ids) != 1:
        return None
    subject = mentions[k]
    person = subject.ids[0]
    rest = [t.word for t in tokens[subject.end :]]
    item: str | None = None
    if subject.possessive and k + 1 < len(mentions) and mentions[k + 1].kind == "item":
        item = mentions[k + 1].ids[0]
        rest = [t.word for t in tokens[mentions[k + 1].end :]]
    copula = next((c for c in terms.en.copulas if starts_with(rest, 0, c)), None)
    if copula is None and not (subject.possessive and item is None):
        return None  # "Wang's away" reads as a possessive: the copula is in the 's
    state = rest[len(copula) :] if copula else rest
    name = terms.office.person(person).name
    if item is not None:
        cond = next((c for c in terms.en.conditions if starts_with(state, 0, c)), None)
        if cond is None:
            return None
        said = " ".join(cond)
        hint = Hint(kind="condition", person=person, value=said, item_type=item, said=piece.text)
        thing = terms.office.item_type(item).name
        return Finding("fact", piece, f"a fact: {name}'s {thing} is {said}", hint)
    if leaving_soon(state):  # "Owen is heading to the match": still here, not away
        return None
    if _ran_out(state, terms.en.away):  # "Min is out of paper": her supply, not her
        return None
    if _says(state_said(state), terms.en.away, after=2):  # "Wang is away today"
        return _availability(piece, person, name, "away")
    if state and state[0] in terms.en.location_prepositions:
        place = terms.place(piece.lexed)
        if place is not None:
            hint = Hint(kind="location", person=person, value=place, said=piece.text)
            where = terms.office.location(place).name
            return Finding("fact", piece, f"a fact: {name} is at the {where}", hint)
    if away_elsewhere(state_said(state), piece.lexed, subject.end):  # "... at the dentist"
        return _availability(piece, person, name, "away")
    if _says(state, terms.en.here, after=1):  # "Zhang is back"
        return _availability(piece, person, name, "here")
    return None


def _ran_out(state: list[str], away: tuple[tuple[str, ...], ...]) -> bool:
    """ "Min is out of paper", "Gao's out of staples": "out of" a thing says a supply ran
    out, not that the person is away; only the away phrases that say "out of" themselves
    ("out of office", "out of the office") are an absence."""
    if state[:2] != ["out", "of"]:
        return False
    return not any(p[:2] == ("out", "of") and starts_with(state, 0, p) for p in away)


def _says(state: list[str], phrases: tuple[tuple[str, ...], ...], *, after: int) -> bool:
    """Whether the state opens with one of ``phrases`` and says at most ``after`` words more."""
    return any(starts_with(state, 0, p) and len(state) <= len(p) + after for p in phrases)


def _availability(piece: Piece, person: str, name: str, value: str) -> Finding:
    hint = Hint(kind="availability", person=person, value=value, said=piece.text)
    return Finding("fact", piece, f"a fact: {name} is {value}", hint)


def own_item_fact(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """ "I can't find my stapler", "my stapler is broken": the requester's own item is out
    of use (so they want someone else's), said as a fact, not a request. Chat drops the
    "my" ("stapler's broken", "controller is dead"): a bare item opening the piece with its
    condition is the requester's own where they have one, else told as context; either way
    it asks for nothing by itself."""
    tokens = piece.lexed.tokens
    words = [t.word for t in tokens]
    items = [m for m in piece.lexed.mentions if m.kind == "item"]
    if len(items) == 1 and items[0].start == 0:
        return _bare_item_fact(terms, piece, items[0].ids[0], words[items[0].end :], requester)
    if len(items) != 1 or items[0].start == 0 or words[items[0].start - 1] != "my":
        return None
    before, after = words[: items[0].start - 1], words[items[0].end :]
    lost = any(
        starts_with(before, n, p) for n in range(len(before)) for p in terms.en.own_item_lost
    )
    broken = _out_of_use(terms, after)
    behind = left_behind(before, after)  # "... and I left my cable at home"
    # "my stapler is broken", and after a clause of the speaker's situation ("calving at
    # Pryce's tonight and my head torch is dead")
    broken = broken and (not before or before[-1] in _JOINS)
    if not (lost and before[:1] == ["i"]) and not broken and not behind:
        return None
    found = _own_out_of_use(terms, piece, items[0].ids[0], requester)
    needed = behind and situation_said(before)
    offered = lend_offer(terms, items[0].ids[0], requester) if needed else None
    if offered is None:
        return found
    known, offer, shall = offered
    return replace(found, message=known, offer=offer, shall=shall)


def _out_of_use(terms: Terms, after: list[str]) -> bool:
    """Whether the words after an item say it is out of use: a copula and a condition."""
    copula = next((c for c in terms.en.copulas if starts_with(after, 0, c)), None)
    return copula is not None and any(
        starts_with(after, len(copula), c) for c in terms.en.conditions
    )


def _own_out_of_use(terms: Terms, piece: Piece, item: str, requester: str) -> Finding:
    """The requester's own item out of use: a hint that they want someone else's."""
    hint = Hint(
        kind="condition", person=requester, value="missing", item_type=item, said=piece.text
    )
    kind = terms.office.item_type(item)
    be = wording.is_are(kind.name, mass=kind.mass)
    return Finding("fact", piece, f"a fact: your {kind.name} {be} out of use", hint)


def _bare_item_fact(
    terms: Terms, piece: Piece, item: str, after: list[str], requester: str
) -> Finding | None:
    """ "stapler is broken" (a bare item, its copula and a condition, nothing more asked)."""
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.question is not None:
        return None
    if not _out_of_use(terms, after):
        return None
    if requester not in terms.office.owners_of(item):
        kind = terms.office.item_type(item)
        said = (
            f"a statement: the {kind.name} {wording.is_are(kind.name, mass=kind.mass)} out of use"
        )
        return Finding("statement", piece, said)
    return _own_out_of_use(terms, piece, item, requester)


def back_when(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """ "back in an hour", "should be back after lunch", "just back from site", "back off the
    hill": when someone said to be gone (or the speaker) will be or is back, said with no
    subject; a time, never a thing to fetch (not "an
    hour", nor the lunch of "back after lunch"). "bring it back", "back to my desk with it
    pls" have a verb or a place and are read as before."""
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.question is not None:
        return None
    words = content(piece.words)
    while words and words[0] in _BACK_LEADS:  # "just back from site", "finally back"
        words = words[1:]
    opener = next((p for p in _BACK if starts_with(words, 0, p)), None)
    if opener is None:
        return None
    rest = words[len(opener) :]
    if rest and rest[0] not in _BACK_TIMES:
        return None
    if any(m.kind == "cue" for m in piece.lexed.mentions):
        return None  # "back in an hour, print my rota": a task word of its own
    return Finding("statement", piece, "when someone will be back: context only")
