"""What the one a request gives to will do with it, said after it: "Please take my lab book
over to Renée. She needs to check my results before the write-up", "Bring my draft to Omar.
He has to look over my figures first", "Take my binder to Kai, he wants to compare my
readings". After a complete request that names one colleague to give to, a piece whose
subject is that colleague ("he", "she", "they", or the name) and which says their own plan
("needs to", "has to", "wants to" + a verb) says why: context only. Its doing is theirs, never
work asked of me, and what it works on ("my results", "my figures") is nothing to fetch nor
to ask about, even where its verb is one of the office's services ("check").

A need of a thing ("He also needs my stapler") is a second request, read as before, and so
is a person's work on the thing handed ("she needs to stamp it", "he has to sign it") and a
plan on a thing the office has ("she needs to sign my form": which form goes is asked as
before); a piece after a request that names nobody, or two colleagues, or no thing of its
own ("take it to Kai, he wants to compare my readings": "it" may be what he compares), is
read as before. The words are English's (``data/english.yaml``); nothing here knows an office."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.obligation import PERSON_WORK
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.own_doing import after_plan, infinitive
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.recipients_reason import party_ids
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content

# "needs to", "has to", "wants to", "has got to", "must": a colleague's plan or obligation
_PLAN = frozenset({"needs", "need", "has", "have", "wants", "want", "got", "must", "gotta"})
_BETWEEN = frozenset({"still", "just", "really", "first", "got", "probably"})
_THIRD = frozenset({"he", "she", "they"})
# what points back to the thing asked for ("she needs to stamp *it*")
_BACK = frozenset({"it", "them", "this", "that", "these", "those"})
# the finding's meaning: the parser reads no guess of the request's thing in such a piece
RECIPIENTS_DOING = "what the colleague the request names will do: context"


def recipients_doing(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    acts = piece.acts
    if piece.asks or acts.imperative or acts.question is not None:
        return None
    earlier = [
        p for p in msg.pieces if p.end <= piece.start and (p.acts.request or p.acts.imperative)
    ]
    if not any(m.kind == "item" and not m.guessed for p in earlier for m in p.lexed.mentions):
        return None  # "take it to Kai. He wants ...": the request's thing may be the one said
    parties = {i for p in earlier for i in party_ids(p)} - {requester}
    if len(parties) != 1:
        return None  # nobody to give to, or two: whom "she" means is read as before
    words = content(piece.words)
    mentions = piece.lexed.mentions
    people = [m for m in mentions if m.kind == "person"]
    if words[:1] and words[0] in _THIRD:
        if people:
            return None  # "she needs to check Wang's ...": another colleague, read as before
        rest = after_plan(words[1:], _PLAN, _BETWEEN)
    else:
        first = people[0] if people else None
        if first is None or first.start != 0 or first.possessive or set(first.ids) != parties:
            return None
        if len(people) > 1:
            return None
        rest = after_plan(
            content([t.word for t in piece.lexed.tokens[first.end :]]), _PLAN, _BETWEEN
        )
    if not rest or not infinitive(words, rest):
        return None  # "he also needs my stapler": a thing needed, a second request
    if rest[0] in PERSON_WORK or set(rest[1:4]) & _BACK:
        return None  # "she needs to stamp it": a person's work on the thing, read as before
    if any(m.kind == "item" and not m.guessed for m in mentions):
        return None  # "she needs to sign my form": a thing of the office, read as before
    return Finding("statement", piece, RECIPIENTS_DOING)
