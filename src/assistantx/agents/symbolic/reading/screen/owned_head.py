"""The head noun of an item's name, said with whose it is, names the one item of that owner
whose name ends in it: "take my lamp to Rose" where the speaker owns an "inspection lamp",
"can I borrow Mark's gauge" where Mark owns a "tyre pressure gauge". English shortens a
compound to its head when whose it is already says which thing is meant ("my lamp" of the
one lamp I have), as it does after the thing was named (``head_noun_back``).

The head is read so only where it names nothing of the office on its own, begins no longer
name of the office said there ("Rose's *card reader*", the office's card machine, is no
"registration card"), and comes right after "my"/"our" (the speaker) or a colleague's
possessive; it is written as the name of the
one type of that person's things that ends in it, and the later stages read it as if said in
full. Where two of the owner's types end in it ("my lamp" with an inspection lamp and a desk
lamp), which is asked (``several_owned_heads``); where none does, it keeps its reading (a
thing the office does not know, asked about). The names and who owns what are the office's;
nothing here knows an office.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.head_noun_back import names_something
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language
from assistantx.core.task_schema import Evidence
from assistantx.core.wording import a_thing

_OWNED = re.compile(
    r"\b(?P<owner>my|our|[^\W\d_]+['’]s?)\s+(?P<head>[^\W\d_]+)\b(?!['’])", re.IGNORECASE
)
_SPEAKER = frozenset({"my", "our"})
_LONGEST = 4  # words of the longest name looked for at a head ("card reader", ...)
# how the question opens (``InstructionParser.parse_with_answers`` reads the answer to it)
ASKED = "Which item do you mean by "


def _heads(terms: Terms, type_id: str) -> frozenset[str]:
    """The head nouns of an item type's names of several words ("lamp" of "inspection
    lamp", "light" of "work light"), and their plurals."""
    t = terms.office.item_type(type_id)
    heads = {n.lower().split()[-1] for n in (t.name, *t.synonyms) if len(n.split()) > 1}
    return frozenset(heads | {language.plural(h) for h in heads})


def _opens_a_name(terms: Terms, text: str, at: int) -> bool:
    """Whether a name of the office of several words starts at character ``at``: "card" of
    "Rose's *card reader*" where the office's card machine is also called so. The longest
    name said wins over a shorter one's head ("registration *card*"), as the lexicon reads it."""
    said = language.words(text[at:])[:_LONGEST]
    lex = terms.lex
    return any(
        " ".join(said[:k]) in table
        for k in range(2, len(said) + 1)
        for table in (lex.items, lex.facilities, lex.places)
    )


def _owner(terms: Terms, said: str, requester: str) -> str | None:
    """Whose "my"/"Mark's" says: the speaker, or the one colleague the possessive names."""
    if said.lower() in _SPEAKER:
        return requester
    mentions = terms.lex.read(said).mentions
    if len(mentions) != 1 or mentions[0].kind != "person" or not mentions[0].possessive:
        return None
    return mentions[0].ids[0] if len(mentions[0].ids) == 1 else None


def _owned_heads(
    terms: Terms, text: str, requester: str
) -> Iterator[tuple[re.Match[str], str, list[str]]]:
    """Each "my/Mark's HEAD" of ``text`` whose head names nothing of the office alone and
    ends a name of the owner's things: the match, the owner, and those things' types."""
    for match in _OWNED.finditer(text):
        head = match.group("head").lower()
        if names_something(terms, head):
            continue  # "my ruler", "Mark's document": the office's own word, read as it is
        if _opens_a_name(terms, text, match.start("head")):
            continue  # "Rose's card reader": the longer name said in full wins
        owner = _owner(terms, match.group("owner"), requester)
        if owner is None:
            continue
        owned = dict.fromkeys(o.type for o in terms.office.person(owner).owns)
        types = [t for t in owned if head in _heads(terms, t)]
        if types:
            yield match, owner, types


def owned_head(terms: Terms, text: str, requester: str) -> tuple[str, list[Evidence]]:
    """``text`` with a head noun said with whose it is written as the name of the owner's
    one thing that ends in it."""
    found: list[Evidence] = []
    out: list[str] = []
    pos = 0
    for match, _, types in _owned_heads(terms, text, requester):
        if len(types) != 1:
            continue  # two of the owner's things end in it: asked (``several_owned_heads``)
        name = terms.office.item_type(types[0]).name
        out += [text[pos : match.start("head")], name]
        pos = match.end("head")
        found.append(Evidence(words=match.group(0), meaning=f"{match.group('owner')} {name}"))
    return "".join(out) + text[pos:], found


def several_owned_heads(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """ "my lamp" where two of the speaker's things are lamps: asked which, never guessed."""
    for match, owner, types in _owned_heads(terms, piece.text, requester):
        if len(types) < 2:
            continue
        whose = "your" if owner == requester else f"{terms.office.person(owner).name}'s"
        names = " or ".join(f"{whose} {terms.office.item_type(t).name}" for t in types)
        said = match.group(0)
        question = f"{ASKED}{said!r}: {names}?"
        head = a_thing(match.group("head"))
        meaning = f"{head} of several of {whose} things: asked"
        return Finding("which", piece, meaning, message=question)
    return None


# "not the blue folder, the red one": what follows "not", up to a pause, is ruled out
_RULED_OUT = re.compile(r"\b(?:not|no)\b[^,;.]*", re.IGNORECASE)


def with_owned_chosen(
    terms: Terms, text: str, requester: str, question: str, answer: str
) -> str | None:
    """The request with the head ``several_owned_heads`` asked about written as the owner's
    thing the answer chooses ("the red one", "not the blue folder, the red one": the words
    only that thing's name has, outside what the answer rules out); None where the question
    was another's or the answer chooses none or several (asked again)."""
    if not question.startswith(ASKED):
        return None
    kept = set(language.words(_RULED_OUT.sub(" ", answer).lower()))
    for match, _, types in _owned_heads(terms, text, requester):
        if len(types) < 2 or repr(match.group(0)) not in question:
            continue
        names = {t: set(language.words(terms.office.item_type(t).name.lower())) for t in types}
        shared = set.intersection(*names.values())
        chosen = [t for t, words in names.items() if (words - shared) & kept]
        if len(chosen) != 1:
            return None
        name = terms.office.item_type(chosen[0]).name
        return text[: match.start("head")] + name + text[match.end("head") :]
    return None
