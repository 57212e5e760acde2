"""Own use: "grab my lunch from the fridge would you, need to eat it before 2": after a
request, a need or plan of the speaker's to do something with "it"/"them" (the thing the
request brings) is what the speaker will do with it once it comes, the reason for the request,
context only. Its verb is the speaker's, never asked of the robot, so a verb the robot refuses
("eat", "bin") is no refusal here: the request before it is done.

Read as before: a verb of the office's own services or errands ("..., need to heat it": the
heating asked), a piece that names its own thing ("eat my lunch", no pronoun: declined as
ever), a piece with no request before it, and a verb the robot refuses said of a thing the
request takes from a colleague ("grab Wang's lunch, need to eat it": the taking is refused).
"""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.own_doing import after_plan
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content

_SPEAKER = frozenset({"i", "we", "id", "ive", "im", "ill"})
# "need to", "have to", "got to", "gotta", "want to", "must": the speaker's own plan
_PLAN = frozenset({"need", "have", "got", "want", "must", "gotta", "going"})
_BETWEEN = frozenset({"still", "just", "really", "also", "first", "ve", "got", "then"})
# the thing already named by the request: "it", "them" ("em" as chat writes it)
_THE_THING = frozenset({"it", "them", "em"})


def own_use(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if piece.acts.imperative or piece.acts.question is not None or piece.asks:
        return None
    before = [p for p in msg.pieces if p.end <= piece.start]
    if not any(p.acts.request or p.acts.imperative for p in before):
        return None  # alone (or first) it may be the request itself: read on
    verb = _own_verb(content(piece.words))
    if verb is None:
        return None
    if terms.request_verb([verb], 0) or verb in terms.service_verbs:
        return None  # "..., need to heat it": the office's own work, asked
    if verb in terms.lex.items or verb in terms.office_words:
        return None
    if _refused(terms, verb) and any(_colleagues_thing(p, requester) for p in before):
        return None  # "grab Wang's lunch, need to eat it": taking theirs, refused as ever
    return Finding("statement", piece, "what the speaker will do with the thing, context only")


def _own_verb(words: list[str]) -> str | None:
    """The verb of "[I] need to <verb> it/them ...", else None."""
    if words[:1] and words[0] in _SPEAKER:
        words = words[1:]
    rest = after_plan(words, _PLAN, _BETWEEN)
    if rest is None or len(rest) < 2 or rest[1] not in _THE_THING:
        return None  # "need to eat my lunch": the thing named anew, read on
    return rest[0]


def _refused(terms: Terms, verb: str) -> bool:
    """Whether ``verb`` opens one of the doings the robot refuses ("eat", "bin", "rip up")."""
    return any(
        phrase[:1] == (verb,) for phrase in (*terms.en.destructive, *terms.en.destructive_of_others)
    )


def _colleagues_thing(piece: Piece, requester: str) -> bool:
    """Whether the piece names a colleague's thing ("Wang's lunch")."""
    return any(
        m.kind == "person" and m.possessive and len(m.ids) == 1 and m.ids[0] != requester
        for m in piece.lexed.mentions
    )
