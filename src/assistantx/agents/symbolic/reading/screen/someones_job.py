"""Someone's job, said as a remark: "printer's out of toner, someone's gonna have to ring the
engineer", "somebody needs to sort it out", "someone should tell facilities". An obligation
put on nobody in particular names no one to do it and asks the assistant nothing: it is told
beside what is reported, answered in words, and nothing moves.

Read by its shape, whatever the office: an indefinite person ("someone", "somebody") as the
subject, then an obligation ("should", "needs to", "'s gonna have to", ``obligations`` in
``english.yaml``), then a verb whose words name no errand of the office and nothing for the
speaker or the assistant. "someone should bring me some paper" (an errand, for the speaker)
and "somebody needs to get Wang a pen" keep their request."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.obligation import obliged_verb
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content

_NOBODY_NAMED = frozenset({"someone", "somebody", "someones", "somebodys"})
# What may stand between the subject and its obligation ("someone's *really* gotta", "someone
# *is gonna* have to", "somebody *will* need to").
_BETWEEN = frozenset(
    {"s", "is", "ll", "will", "really", "probably", "definitely", "just", "gonna", "seriously"}
)
_GOING = ("going", "to")  # "someone is going to have to ...": the future, then the obligation
# Words that make it the speaker's or the assistant's own business: then read as ever.
_ADDRESSED = frozenset({"me", "us", "my", "our", "mine", "you", "your", "yours", "i"})


def someones_job(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    acts = piece.acts
    if piece.asks or acts.imperative or acts.question is not None:
        return None
    words = content(piece.words)
    if not words or words[0] not in _NOBODY_NAMED:
        return None
    at = 1
    while at < len(words) and words[at] in _BETWEEN:
        at += 1
    if tuple(words[at : at + 2]) == _GOING and words[at + 2 : at + 3] in (["have"], ["need"]):
        at += 2
    verb = obliged_verb(words, at)
    if verb is None:
        return None
    if set(words[verb:]) & _ADDRESSED:
        return None  # "someone should bring me some paper": for the speaker, asked
    # "needs" is also an errand's word ("give"): only the words from the verb on are read
    start = len(piece.words) - len(words) + verb
    if any(m.kind in ("cue", "person") and m.end > start for m in piece.lexed.mentions):
        return None  # an errand's word or a colleague named: read as a request as ever
    return Finding("statement", piece, "a remark of what someone ought to do, asking nothing")
