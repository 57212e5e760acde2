"""Why the speaker asks where a colleague is: "where's Mark? need a word about the franking",
"where is Lee? I need to ask him about the printer". After a question about where a person
is, the speaker's own need to speak with them ("need to ask / talk to / catch him", "need a
word", "want a quick chat") is the reason for the question, and the question is what is
answered (where they sit; the assistant does not track people). What the talk is about ("the
franking", "the van run") is its topic, never a service or a thing asked for: read as a
request, it left "which item do you mean for me to frank?" or "there is no word here".

A need that is no talk ("where's Mark? need my ruler back") and a talk with no question about
a person before it are read as before."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content

_WHERE = frozenset({"where", "wheres"})
_SPEAKER = frozenset({"i", "we", "id", "ive", "im"})
# The speaker's plan ("need to", "want to", "have to", "gotta", "hoping to").
_PLAN = frozenset({"need", "needed", "want", "wanted", "have", "got", "gotta", "must", "hoping"})
_BETWEEN = frozenset({"just", "really", "still", "quickly", "to", "a", "quick"})
# Verbs and nouns of speaking with someone.
_TALK_VERBS = frozenset(
    {"ask", "tell", "talk", "speak", "chat", "check", "catch", "see", "discuss", "remind"}
)
_TALK_NOUNS = frozenset({"word", "chat", "catchup", "natter", "talk"})


def whereabouts_reason(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if piece.acts.imperative or piece.acts.question is not None or piece.asks:
        return None
    before = [p for p in msg.pieces if p.end <= piece.start]
    if not before or not _asks_where_someone_is(before[-1], requester):
        return None
    words = content(piece.words)
    if words[:1] and words[0] in _SPEAKER:
        words = words[1:]
    if not words or words[0] not in _PLAN:
        return None
    rest = words[1:]
    while rest and rest[0] in _BETWEEN:
        rest = rest[1:]
    if not rest or not (rest[0] in _TALK_VERBS or rest[0] in _TALK_NOUNS):
        return None  # "need my ruler back": a thing, read as before
    return Finding("statement", piece, "why the speaker asks where a colleague is: context only")


def _asks_where_someone_is(piece: Piece, requester: str) -> bool:
    """ "where's Mark?", "where is Lee": a question opening with "where" about one colleague
    who is not the speaker."""
    if piece.acts.question is None or not piece.asks:
        return False
    words = content(piece.words)
    if not words or words[0] not in _WHERE:
        return False
    people = [m for m in piece.lexed.mentions if m.kind == "person" and not m.possessive]
    return len(people) == 1 and requester not in people[0].ids
