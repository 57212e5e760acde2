"""Own need: "Wang needs hers today", "Jon is using his tonight", "as Ann needs her own": a
colleague who needs their own item, said beside a request, is the reason another one is asked
for (often right after a correction: "bring me Ann's torch... sorry, I meant Oona's, Ann needs
hers"). The person is context, never someone to hand the item to nor to take it from."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language

# The possessive pronouns that stand for the subject's own item with no noun after them.
_OWN = frozenset({"hers", "his", "theirs"})
_OWN_BEFORE = frozenset({"her", "his", "their"})  # "her own"
_AUXILIARIES = frozenset({"is", "was", "will", "ll", "s", "still", "really", "also", "does"})
_OWN_USE = frozenset({"need", "want", "use", "keep"})


def own_need(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if not any(terms.acts.request(p.words) for p in msg.pieces if p is not piece):
        return None  # alone it may be a request for that person: read on
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    k = 0
    while k < len(mentions) and mentions[k].kind == "word":
        if tokens[mentions[k].start].word not in terms.en.fact_openers:
            return None  # only "as", "since", "because", "so" ... before the subject
        k += 1
    if k >= len(mentions) or mentions[k].kind != "person" or len(mentions[k].ids) != 1:
        return None
    subject = mentions[k]
    if subject.possessive or subject.ids[0] == requester:
        return None
    rest = [t.word for t in tokens[subject.end :]]
    n = 0
    while n < len(rest) and rest[n] in _AUXILIARIES:
        n += 1
    if n >= len(rest) or not language.verb_lemmas(rest[n]) & _OWN_USE:
        return None
    own = rest[n + 1 : n + 3]
    if not own or not (own[0] in _OWN or (own[0] in _OWN_BEFORE and own[1:] == ["own"])):
        return None
    if any(m.kind == "item" for m in mentions[k + 1 :]):
        return None  # "Ann needs his torch": whose item is meant is read on
    name = terms.office.person(subject.ids[0]).name
    return Finding("statement", piece, f"a reason: {name} needs their own")
