"""One of a colleague's things named by a word for a kind, not by the thing's name: "could you
bring me one of Sunny's tools?" where Sunny has a pump, a multitool and tyre levers. "One of"
says the colleague has several of what the word names, so the word is a kind ("tools"), and
the lexicon's reading of it as the one item whose name it heads ("bike tool": the multitool)
is a guess; which one is asked, and the answer names it ("the pump" → "Sunny's track pump").
A word that is the thing's own name ("one of Zhang's staplers"), or a colleague with only one
thing of that kind, reads as before."""

from __future__ import annotations

import re
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language
from assistantx.core.office import Office


@dataclass(frozen=True)
class OneOfSeveral:
    owner: str
    things: tuple[str, ...]  # the owner's item types of the kind the word could name
    start: int  # the span "one of Sunny's tools" in the text
    end: int


def one_of_several(terms: Terms, lexed: Lexed, text: str) -> OneOfSeveral | None:
    """ "one of P's <word>" in ``text``, the word a plural that is none of its item's own
    names, and P owning several things of that item's kind."""
    tokens, mentions = lexed.tokens, lexed.mentions
    for n, m in enumerate(mentions[:-1]):
        if m.kind != "person" or not m.possessive or len(m.ids) != 1 or m.start < 2:
            continue
        if [t.word for t in tokens[m.start - 2 : m.start]] != ["one", "of"]:
            continue
        thing = mentions[n + 1]
        if thing.kind != "item" or len(thing.ids) != 1 or thing.start != m.end:
            continue
        said = " ".join(t.word for t in tokens[thing.start : thing.end])
        if not language.is_plural_noun(said) or _own_name(terms.office, thing.id, said):
            continue
        things = _of_its_kind(terms.office, m.id, thing.id)
        if len(things) < 2:
            continue
        pattern = r"one\s+of\s+" + re.escape(m.text) + r"\s+" + re.escape(thing.text)
        found = re.search(pattern, text, flags=re.IGNORECASE)
        if found is None:
            continue
        return OneOfSeveral(m.id, things, found.start(), found.end())
    return None


def _own_name(office: Office, type_id: str, said: str) -> bool:
    """Whether ``said`` is the plural of one of the item type's own names ("staplers")."""
    t = office.item_type(type_id)
    names = {language.fold(n) for n in (t.name, *t.synonyms)}
    return said in names or said in {language.plural(n) for n in names}


def _of_its_kind(office: Office, owner: str, type_id: str) -> tuple[str, ...]:
    """The item types ``owner`` owns of the same kind as ``type_id`` (things, not files)."""
    kind = office.item_type(type_id).kind
    owned = (o.type for o in office.person(owner).owns)
    return tuple(dict.fromkeys(t for t in owned if office.item_type(t).kind == kind))


def several_of_theirs(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """ "one of Sunny's tools": which of the colleague's things is asked, nothing moves."""
    found = one_of_several(terms, piece.lexed, piece.text)
    if found is None:
        return None
    office = terms.office
    names = [f"the {office.item_type(t).name}" for t in found.things]
    which = f"{', '.join(names[:-1])} or {names[-1]}"
    whose = office.person(found.owner).name
    question = f"{whose} has several things: do you mean {which}?"
    return Finding("which", piece, "which of the colleague's things", message=question)


def chosen_of_several(terms: Terms, text: str, answer: str) -> str | None:
    """The request with the answer to "do you mean the multitool or the pump?" in place of
    the words that asked it ("one of Sunny's tools" → "Sunny's track pump"); None when the
    answer names none, or several, of the colleague's things."""
    found = one_of_several(terms, terms.lex.read(text), text)
    if found is None:
        return None
    said = {i for m in terms.lex.read(answer).mentions if m.kind == "item" for i in m.ids}
    chosen = [t for t in found.things if t in said]
    if len(chosen) != 1:
        return None
    whose = terms.office.person(found.owner).name
    name = terms.office.item_type(chosen[0]).name
    return f"{text[: found.start]}{whose}'s {name}{text[found.end :]}"
