"""The head noun of an item's name of several words, said after that item was named, refers
back to it: "anyone got sticky tape? bring me a dispenser pls" asks for the tape dispenser,
"does anyone have allen keys? bring me a set pls" for the hex key set. English shortens a
compound to its head once the whole is known ("the tape dispenser ... the dispenser"), as it
says "one" for it.

The head is read so only where it names nothing of the office on its own, comes after a
determiner ("a", "the", "that"), and only the item named before it has a name ending in it;
the head is then written as that item's name, and the later stages read it as if said in full.
Said with no such item before it ("bring me a dispenser"), it keeps its reading (a thing the
office does not have). The names are the office's; nothing here knows an office.
"""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language
from assistantx.core.task_schema import Evidence

# The determiners after which a noun refers back to a thing already named.
_BACK = ("a", "an", "the", "that", "this", "one", "another")
_AFTER_DETERMINER = re.compile(
    rf"\b(?P<det>{'|'.join(_BACK)})\s+(?P<head>[^\W\d_]+)\b(?!['’])", re.IGNORECASE
)


def _heads(terms: Terms, type_id: str) -> frozenset[str]:
    """The head nouns of an item type's names of several words ("dispenser" of "tape
    dispenser", "set" of "hex key set"), and their plurals."""
    t = terms.office.item_type(type_id)
    heads = {n.lower().split()[-1] for n in (t.name, *t.synonyms) if len(n.split()) > 1}
    return frozenset(heads | {language.plural(h) for h in heads})


def head_noun_back(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """``text`` with a head noun that refers back to the item named before it written as
    that item's name."""
    lexed = terms.lex.read(text)
    named = [m for m in lexed.mentions if m.kind == "item" and len(m.ids) == 1]
    if not named:
        return text, []
    found: list[Evidence] = []
    out: list[str] = []
    pos = 0
    for match in _AFTER_DETERMINER.finditer(text):
        head = match.group("head").lower()
        if names_something(terms, head):
            continue  # "a ruler", "the tape": the office's own word, read as it is
        if opens_a_long_name(terms, text[match.start("head") :]):
            continue  # "in the key press": the first word of a facility's own name
        before = _named_before(text, named, match.start())
        owners = {i for i in before if head in _heads(terms, i)}
        if len(owners) != 1:
            continue  # nothing named before ends in it, or two things do: read as before
        name = terms.office.item_type(next(iter(owners))).name
        out += [text[pos : match.start("head")], name]
        pos = match.end("head")
        found.append(Evidence(words=match.group(0), meaning=f"{match.group('det')} {name}"))
    return "".join(out) + text[pos:], found


def names_something(terms: Terms, word: str) -> bool:
    """Whether a word alone names something of the office (a thing, a person, a place, a
    facility) or asks for work."""
    lex = terms.lex
    return any(
        word in table
        for table in (lex.items, lex.people, lex.name_words, lex.facilities, lex.places)
    ) or (word in lex.cue_words)


def opens_a_long_name(terms: Terms, rest: str, kinds: frozenset[str] | None = None) -> bool:
    """Whether ``rest`` opens with a name of the office of two words or more ("key press" of
    the key cabinet, "test records" of the work pack), of one of ``kinds`` (any where None):
    its first word is that name's, never a word to read back or unclip on its own."""
    first = next(iter(terms.lex.read(rest).mentions), None)
    if first is None or first.start != 0 or first.end < 2 or first.kind == "word":
        return False
    return kinds is None or first.kind in kinds


def _named_before(text: str, named: list[Mention], at: int) -> set[str]:
    """The item types named before character ``at`` of ``text``."""
    out: set[str] = set()
    for m in named:
        where = text.lower().find(m.text.lower()) if m.text else -1
        if 0 <= where and where + len(m.text) <= at:
            out.add(m.ids[0])
    return out
