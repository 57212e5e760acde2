"""Two things offered as alternatives: "can you bring me the thing for cutting tape? or the
scissors, not sure which I need", "a ruler or maybe a calculator", "bring me the stapler or
the scissors", "bring me Zhang's or Wang's stapler". One of them is wanted, so both are never
fetched (fix180a class 5, fix60c class 1): one question names the options ("Which would you
like: the tape dispenser or the scissors?", "Whose stapler would you like: Zhang Wei's or
Wang Fang's?").

Two of the office's things joined by "or" (with "maybe", "perhaps", a determiner between:
``choice_between``) that differ in kind, or one kind of two owners ("Zhang's or Wang's
stapler", "Zhang's stapler or Wang's"); whatever their kinds, owners or keepers, the choice
is the speaker's. Said in the request's own piece ("I need a prism or a tripod"), the "or" is
enough; said in another piece of the message ("..., not sure which yet. can you bring me
one") a mark of doubt ties it to the request: "? or", "or maybe", or one of
``unsure_choice_marks`` ("not sure which", "whichever", "either"). A bare fragment that opens
with "either" and the two things is a request said short. "X and Y" asks for both; "X, or if
there isn't one, Y" is a fallback, never asked which: the surface keeps Y back (``fallback``)."""

from __future__ import annotations

import re
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.lexicon import Lexed, Mention
from assistantx.agents.symbolic.reading.screen.destructive import commanded
from assistantx.agents.symbolic.reading.screen.english import DETERMINERS, starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.rewrites import purposes
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_MARKS = tuple(tuple(e.split()) for e in english.entries("unsure_choice_marks"))
_BETWEEN = english.words("choice_between")
_EITHER = english.words("either_one")
_ASKED_OR = re.compile(r"\?\s*or\b", re.IGNORECASE)
_REACH = 2  # at most this many words between the first thing and "or" ("cutting *tape*? or")


@dataclass(frozen=True)
class _Option:
    """One of the two: the thing's kind (none yet: "Zhang's or ...") and whose."""

    ids: tuple[str, ...]
    owner: str | None


def alternatives(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if "or" not in (t.word for t in msg.lexed.tokens):
        return None
    if not (
        piece.acts.request or piece.acts.imperative or commanded(terms, piece) or _either(piece)
    ):
        return None
    # said in the request's own piece: the "or" is enough
    pair = _pair(terms, piece.lexed) if "or" in piece.words else None
    if pair is None:
        # "the thing for cutting tape? or ...": the thing a purpose describes, read as the
        # request reads it ("a scissors"); in another piece, only with a doubt said
        described, _ = purposes(terms, msg.text)
        lexed = msg.lexed if described == msg.text else terms.lex.read(described)
        pair = _pair(terms, lexed, doubted=bool(_ASKED_OR.search(described)))
    if pair is None:
        return None
    one, other = pair
    if set(one.ids) & set(other.ids):
        name = _name(terms, one.ids)
        first, second = (_owner(terms, o.owner) for o in pair)
        return Finding(
            "which",
            piece,
            f"one thing of two owners offered as alternatives: {first} or {second} {name}",
            message=f"Whose {name} would you like: {first}'s or {second}'s?",
        )
    first, second = (_said(terms, o) for o in pair)
    return Finding(
        "which",
        piece,
        f"two things offered as alternatives: {first} or {second}",
        message=f"Which would you like: {_the(terms, pair[0])} or {_the(terms, pair[1])}?",
    )


def _pair(
    terms: Terms, lexed: Lexed, *, doubted: bool | None = None
) -> tuple[_Option, _Option] | None:
    """The two things "or" offers in ``lexed``; ``doubted`` None: the "or" is enough, else
    a doubt must be said (``doubted`` True: "? or" was)."""
    tokens, mentions = lexed.tokens, lexed.mentions
    words = [t.word for t in tokens]
    items = [m for m in mentions if m.kind == "item" and len(m.ids) == 1]
    owners = {m.end: m for m in mentions if m.kind == "person" and m.possessive}
    for k, word in enumerate(words):
        if word != "or":
            continue
        one = _before(terms, words, items, owners, k)
        j = k + 1
        while j < len(words) and (words[j] in _BETWEEN or words[j] in DETERMINERS):
            j += 1
        hedged = any(w in _BETWEEN for w in words[k + 1 : j])
        whose = next((m for m in owners.values() if m.start == j), None)
        owner = whose.id if whose is not None else None
        at = whose.end if whose is not None else j
        second = next((m for m in items if m.start == at), None)
        if one is None or (second is None and whose is None):
            continue
        if one.ids:
            other = _Option(second.ids if second else one.ids, owner)
        elif second is not None:  # "Zhang's or Wang's stapler": the head said once, after
            one, other = _Option(second.ids, one.owner), _Option(second.ids, owner)
        else:
            continue
        if set(one.ids) & set(other.ids):
            if not (one.owner and other.owner) or one.owner == other.owner:
                continue  # one kind, one owner: the same thing named twice
        if doubted is None or doubted or hedged or _unsure(words):
            return one, other
    return None


def _before(
    terms: Terms, words: list[str], items: list[Mention], owners: dict[int, Mention], k: int
) -> _Option | None:
    """The first of the two, ending before the "or" at ``k``: a thing (and its owner), or an
    owner whose thing is said after the second ("Zhang's or Wang's stapler")."""
    if k in owners:
        return _Option((), owners[k].id)
    first = [m for m in items if m.end <= k and k - m.end <= _REACH]
    if first and not {"and", "or"} & set(words[first[-1].end : k]):
        owner = owners.get(first[-1].start)
        return _Option(first[-1].ids, owner.id if owner else None)
    # "a scissors tape? or ...": the thing's own word read as a modifier
    named = [n for n in range(max(0, k - _REACH), k) if words[n] in terms.lex.items]
    return _Option((terms.lex.items[words[named[-1]]],), None) if named else None


def _either(piece: Piece) -> bool:
    """ "either the projector or the spare laptop": a bare fragment offering the two."""
    return bool(piece.words) and piece.words[0] in _EITHER and not piece.acts.question


def _name(terms: Terms, ids: tuple[str, ...]) -> str:
    return terms.office.item_type(ids[0]).name


def _owner(terms: Terms, person_id: str | None) -> str:
    return terms.office.person(person_id).name if person_id else "anyone"


def _said(terms: Terms, option: _Option) -> str:
    name = _name(terms, option.ids)
    return f"{_owner(terms, option.owner)}'s {name}" if option.owner else name


def _the(terms: Terms, option: _Option) -> str:
    """ "the prism", "Ana Ruiz's prism": a thing named with its owner takes no article."""
    said = _said(terms, option)
    return said if option.owner else f"the {said}"


def _unsure(words: list[str]) -> bool:
    return any(starts_with(words, n, mark) for n in range(len(words)) for mark in _MARKS)
