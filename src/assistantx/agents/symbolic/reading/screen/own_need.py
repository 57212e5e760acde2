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
_AUXILIARIES = frozenset(
    {"is", "was", "will", "ll", "s", "still", "really", "also", "does", "has", "have", "to", "got"}
)
_OWN_USE = frozenset({"need", "want", "use", "keep"})


def own_need(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if not any(p.acts.request for p in msg.pieces if p is not piece):
        return None  # alone it may be a request for that person: read on
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    k = 0
    while k < len(mentions) and mentions[k].kind == "word":
        if tokens[mentions[k].start].word not in terms.en.fact_openers:
            return None  # only "as", "since", "because", "so" ... before the subject
        k += 1
    if k >= len(mentions) or mentions[k].kind != "person":
        return None  # whoever it is (also a name asked about): the reason's person is context
    subject = mentions[k]
    if requester in subject.ids:
        return None
    rest = [t.word for t in tokens[subject.end :]]
    at = next((n for n, w in enumerate(rest[:6]) if _own_at(rest, n)), None)
    if at is None or not at:
        return None
    verbs = [w for w in rest[:at] if language.verb_lemmas(w) & _OWN_USE]
    if not verbs or not all(w in _AUXILIARIES or w in verbs for w in rest[:at]):
        return None  # "Ann needs hers", "Ann's using hers", "Ann has to keep hers"
    if subject.possessive and rest[0] not in verbs:
        return None  # "Ann's torch ...": whose item, not "Ann is"
    if any(m.kind == "item" for m in mentions[k + 1 :]):
        return None  # "Ann needs his torch": whose item is meant is read on
    return Finding("statement", piece, "a reason: a colleague needs their own")


def _own_at(words: list[str], n: int) -> bool:
    """ "hers", "his", "theirs", "her own" at ``n`` with no noun after it."""
    if words[n] in _OWN_BEFORE and words[n + 1 : n + 2] == ["own"]:
        return True
    return words[n] in _OWN and (n + 1 >= len(words) or words[n + 1] != "own")
