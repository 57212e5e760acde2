"""A colleague's name that is also a describing word, said lower-case right before a thing
that colleague owns: "bring me the amber accord from the cold room" where Amber owns an
accord. The words say two different things to fetch, Amber's accord or an amber one (the
speaker's own, or anyone's), and the reader had taken the word and fetched the speaker's. So
one short question names both ("Do you mean Amber Shaw's accord, or your own amber accord?"),
and the answer rewrites the request: the colleague named (or "hers", "his") makes the word
their possessive, "mine", "my own" or "the <word> one" makes it the speaker's own (where they
have one; else the word is dropped as a name).

Only where the colleague owns a thing of that type: "the amber mug" where Amber has no mug is
the word, as before; a capital ("the Amber accord"), a possessive, or the word read as the
person already decides it. The names and what each colleague owns are the office's own."""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Lexed, Lexicon
from assistantx.core import english, language
from assistantx.core.name_reading import is_word_name
from assistantx.core.office import Office

_ASKED = re.compile(
    r"^Do you mean (?P<name>.+?)'s (?P<item>.+?), or (?:your own|some other) (?P<word>\S+) "
    r"(?P=item)\?$"
)
# words before the thing that say whose it is already
_OWNED = frozenset({"my", "our", "your", "his", "her", "their", "its"})
_GRAMMAR = english.words("determiners") | english.words("object_starts")
_THEIRS = frozenset({"his", "hers", "theirs", "their", "him", "her", "them"})
_MINE = frozenset({"mine", "my", "own", "me", "myself", "other", "any", "anyones"})


def attributive_name(office: Office, lex: Lexicon, lexed: Lexed, requester: str) -> str | None:
    """The question which thing is meant, where a lower-case word that names one colleague
    (never the requester) stands right before a thing of a type that colleague owns, read as
    no person; else None."""
    tokens = lexed.tokens
    as_person = {n for m in lexed.mentions if m.kind == "person" for n in range(m.start, m.end)}
    items = {m.start: m for m in lexed.mentions if m.kind == "item" and len(m.ids) == 1}
    for n, token in enumerate(tokens[:-1]):
        if n in as_person or token.possessive or not token.text[:1].islower():
            continue
        if n and (tokens[n - 1].possessive or tokens[n - 1].word in _OWNED):
            continue  # "my amber accord", "Lin's amber accord": whose is said
        ids = {*lex.people.get(token.word, ()), *lex.name_words.get(token.word, ())}
        thing = items.get(n + 1)
        if len(ids) != 1 or thing is None or not _describing(token.word):
            continue
        (person,) = ids
        if person == requester or person not in office.owners_of(thing.id):
            continue
        name = office.item_type(thing.id).name
        other = "your own" if requester in office.owners_of(thing.id) else "some other"
        return f"Do you mean {office.person(person).name}'s {name}, or {other} {token.word} {name}?"
    return None


def with_attribute_chosen(lex: Lexicon, text: str, question: str, answer: str) -> str | None:
    """``text`` with the word asked about made the colleague's possessive ("amber" →
    "Amber's") or dropped, as the ``answer`` chose; None where ``question`` is no such
    question or the answer chose neither."""
    asked = _ASKED.match(question)
    if asked is None:
        return None
    word, name = asked.group("word"), asked.group("name")
    said = lex.read(answer)
    named = {p for m in said.mentions if m.kind == "person" for p in m.ids}
    whose = {p for w in name.lower().split() for p in lex.people.get(w, ())}
    words = set(_plain(answer))
    theirs = bool(named & whose) or bool(words & _THEIRS)
    mine = bool(words & _MINE) or (word in words and not theirs and "one" in words)
    if theirs == mine:
        return None  # neither, or both: asked again
    pattern = re.compile(rf"\b(?:(?:the|this|that|a|an)\s+)?{re.escape(word)}\s+", re.IGNORECASE)
    if theirs:  # "the amber accord" → "Amber's accord"
        return pattern.sub(f"{word.capitalize()}'s ", text, count=1)
    if ", or your own " in question:  # "the amber accord" → "my accord"
        return pattern.sub("my ", text, count=1)
    return re.sub(rf"\b{re.escape(word)}\s+", "", text, count=1, flags=re.IGNORECASE)


def _describing(word: str) -> bool:
    """Whether a name word may describe a thing as an English word: a noun or an adjective
    ("amber", "rose"), never a word of grammar ("an" of Văn An, "may", "will")."""
    if not is_word_name(word) or word in _GRAMMAR:
        return False
    found = language.lemmas(word)
    return ("NOUN" in found or "ADJ" in found) and "AUX" not in found


def _plain(text: str) -> Sequence[str]:
    return [
        language.fold(w).replace("'", "").replace("’", "") for w in re.findall(r"[\w'’]+", text)
    ]
