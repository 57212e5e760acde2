"""A person's thing the office has no word for, at a place that keeps their items: "can you
bring me Jürgen's leftover curry from the staff fridge?". The facility (or the place) and
the owner say which of the office's items it is: their one item kept there (the rewrite in
``rewrites.kept_things`` names it), or, with several kept there, the rule here asks which.
Nothing is guessed: none kept there leaves the words as they were."""

from __future__ import annotations

import re
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.kept_items import PlaceKind, items_kept_at
from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms

_FROM = frozenset({"from", "out"})
_MOST_UNKNOWN_WORDS = 3


@dataclass(frozen=True)
class KeptThing:
    owner: str
    where: str  # the facility or place as written
    kept: tuple[str, ...]  # the item types of the owner's kept there
    start: int  # the unknown words' span in the text
    end: int


def kept_thing(terms: Terms, lexed: Lexed, text: str) -> KeptThing | None:
    """ "P's <words the office does not know> from <a facility or place>" in ``text``, where
    P keeps at least one item there."""
    tokens, mentions = lexed.tokens, lexed.mentions
    for n, m in enumerate(mentions):
        if m.kind != "person" or not m.possessive or len(m.ids) != 1:
            continue
        k = n + 1
        while k < len(mentions) and mentions[k].kind == "word":
            k += 1
        unknown = mentions[n + 1 : k]
        if not 0 < len(unknown) <= _MOST_UNKNOWN_WORDS or unknown[-1].text.lower() not in _FROM:
            continue
        unknown = unknown[:-1]  # the words before "from"
        if not unknown or k >= len(mentions) or mentions[k].kind not in ("facility", "place"):
            continue
        if any(tokens[u.start].word in terms.lex.cue_words for u in unknown):
            continue
        where = mentions[k]
        kept = _kept_at(terms, m.ids[0], where.kind, where.ids[0])
        said = r"\s+".join(re.escape(u.text) for u in unknown)
        found = re.search(rf"{re.escape(m.text)}\s+({said})\b", text)
        if not kept or found is None:
            continue
        return KeptThing(m.ids[0], where.text, tuple(kept), found.start(1), found.end(1))
    return None


def _kept_at(terms: Terms, owner: str, kind: str, where: str) -> list[str]:
    """The item types of ``owner``'s kept by the facility ``where`` (or at the place)."""
    place_kind: PlaceKind = "facility" if kind == "facility" else "place"
    there = items_kept_at(terms.office, place_kind, where)
    return [k.type_id for k in there if k.owner == owner and k.how == "keeper"]


def several_kept(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """Several of the owner's items kept there: which one is asked, nothing moves."""
    found = kept_thing(terms, msg.lexed, piece.text)
    if found is None or len(found.kept) < 2:
        return None
    office = terms.office
    names = [f"the {office.item_type(t).name}" for t in found.kept]
    which = f"{', '.join(names[:-1])} or {names[-1]}"
    whose = office.person(found.owner).name
    where = found.where.removeprefix("the ")
    question = f"{whose} keeps several things at the {where}: do you mean {which}?"
    return Finding("which", piece, "which of the owner's kept things", message=question)


def chosen_kept(terms: Terms, text: str, answer: str) -> str | None:
    """The request with the answer to "do you mean the lunch box or the worn book?" in place
    of the words that asked it ("Jürgen's curry" → "Jürgen's lunch box"); None when the
    answer names none, or several, of the things kept there."""
    found = kept_thing(terms, terms.lex.read(text), text)
    if found is None or len(found.kept) < 2:
        return None
    said = {i for m in terms.lex.read(answer).mentions if m.kind == "item" for i in m.ids}
    chosen = [t for t in found.kept if t in said]
    if len(chosen) != 1:
        return None
    name = terms.office.item_type(chosen[0]).name
    return text[: found.start] + name + text[found.end :]
