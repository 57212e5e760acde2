"""Who receives a thing taken to a room, when the request names nobody to give it to: the one
colleague the message says needs it (or wants to borrow, use or have it) or is there. "Zhang
needs my stapler for the review. Can you take it over to the meeting room?", "Zhang needs my
stapler. take it to the meeting room please", "Zhang's in the meeting room, take my stapler
there ... to the meeting room", "Zhang wants to borrow my stapler, take it to the meeting
room" (``core.wanted_to_have``).

The robot hands things to people (the hand-over code goes to whoever receives it), never to
rooms, so a room alone leaves the receiver to be asked (``parts``). But a message that says,
anywhere, that one colleague needs a thing ("X needs", "X is after", "X could do with") or is in
the room the thing goes to ("X is in the meeting room", "he's in the meeting room" of the one
colleague named) has said who it is for: that colleague receives it. Several such colleagues,
or none, decide nothing, and the room's question is asked as before. The requester is never
this colleague ("I need it in the meeting room" is the requester's own errand).
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Lexed, Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english
from assistantx.core.office import Office
from assistantx.core.task_schema import TaskFrame
from assistantx.core.wanted_to_have import REACH, wants_to_have

# Where a thing goes: "to the meeting room", "into the boardroom".
_TO = frozenset({"to", "into"})
_ARTICLES = frozenset({"the", "a", "an", "our", "their", "this", "that"})
# The verbs of a need said right after a name ("Zhang needs ..."); a plain "wants" may be a
# wish about the thing ("Zhang wants it up on the board"), as the consent guard reads it
# (``runtime.recipients``), so it names no receiver.
_NEEDS = frozenset({"needs", "need"})
# The longer ways to say so ("is after", "could do with", "'s looking for"), as word tuples;
# a possessive's "'s" is the "is" of the phrase, so "s ..." phrases are read after one.
_NEED_PHRASES = tuple(tuple(p.split()) for p in english.entries("need_phrases"))
# Being in a room: "is in the meeting room", "'s at the lounge".
_BE = frozenset({"is", "was"})
_IN = frozenset({"in", "at", "inside"})
# Pronouns that may stand for the one colleague named ("he's in the meeting room").
_SUBJECTS = frozenset({"he", "she", "they"})


def rooms_taken_to(tokens: Sequence[Token], mentions: Sequence[Mention]) -> set[str]:
    """The places and facilities a thing is taken to: named after "to"/"into"."""
    found: set[str] = set()
    for m in mentions:
        if m.kind not in ("place", "facility"):
            continue
        k = m.start
        while k > 0 and tokens[k - 1].word in _ARTICLES:
            k -= 1
        if k > 0 and tokens[k - 1].word in _TO:
            found.add(m.id)
    return found


def _room_at(tokens: Sequence[Token], mentions: Sequence[Mention], at: int) -> str | None:
    """The place or facility named from token ``at`` on, articles skipped."""
    while at < len(tokens) and tokens[at].word in _ARTICLES:
        at += 1
    m = next((x for x in mentions if x.start == at and x.kind in ("place", "facility")), None)
    return m.id if m is not None else None


def _needs(tokens: Sequence[Token], m: Mention) -> bool:
    """Whether the name ``m`` is the subject of a need ("Zhang needs", "Zhang's after")."""
    after = tuple(t.word for t in tokens[m.end : m.end + 4])
    if not m.possessive and after[:1] and after[0] in _NEEDS:
        return True
    if not m.possessive and wants_to_have([t.word for t in tokens[m.end : m.end + REACH]]):
        return True  # "Zhang wants to borrow my stapler": a want of having it, no mere wish
    for phrase in _NEED_PHRASES:
        said = phrase[1:] if m.possessive and phrase[0] in ("s", "is") else phrase
        if m.possessive and said == phrase:
            continue  # "Zhang's needs": no "is" in this "'s"
        if said and after[: len(said)] == said:
            return True
    return False


def _is_in(
    tokens: Sequence[Token],
    mentions: Sequence[Mention],
    end: int,
    possessive: bool,
    rooms: set[str],
) -> bool:
    """Whether the subject ending at ``end`` is said to be in one of ``rooms``: "is in the
    meeting room", or "'s in ..." after a possessive."""
    at = end
    if not possessive:
        if at >= len(tokens) or tokens[at].word not in _BE:
            return False
        at += 1
    if at >= len(tokens) or tokens[at].word not in _IN:
        return False
    return _room_at(tokens, mentions, at + 1) in rooms


def room_receiver(whole: Lexed, requester: str) -> str | None:
    """The one colleague (not the requester) the message says needs a thing or is in the
    room it is taken to, where a thing is taken to a room; None otherwise."""
    tokens, mentions = whole.tokens, whole.mentions
    rooms = rooms_taken_to(tokens, mentions)
    if not rooms:
        return None
    people = {m.id for m in mentions if m.kind == "person" and len(m.ids) == 1} - {requester}
    found: set[str] = set()
    for m in mentions:
        if m.kind != "person" or len(m.ids) != 1 or m.id == requester:
            continue
        if _needs(tokens, m) or _is_in(tokens, mentions, m.end, m.possessive, rooms):
            found.add(m.id)
    if len(people) == 1:
        # "bring it to the meeting room, he's there ... he's in the meeting room": the one
        # colleague named is whom the pronoun means
        for k, t in enumerate(tokens):
            if t.word in _SUBJECTS and _is_in(tokens, mentions, k + 1, t.possessive, rooms):
                found |= people
    return next(iter(found)) if len(found) == 1 else None


def own_thing_unplaced(office: Office, frame: TaskFrame, requester: str) -> str | None:
    """ "Who should get your stapler?", where the words take the requester's own thing to a
    room and nothing found who there receives it (no need said, no room's question asked):
    the frames stage left that question to the room (``frames._check``), so it is asked here
    rather than the thing carried back to the requester."""
    for t in frame.tasks:
        if t.kind != "transfer" or t.item is None or t.source is not None:
            continue
        if t.owner != requester or t.recipient != requester:
            continue
        if office.keeper(requester, t.item) is not None:
            continue  # kept in a locker or store for them: fetched from there, as before
        return f"Who should get your {office.item_type(t.item).name}?"
    return None
