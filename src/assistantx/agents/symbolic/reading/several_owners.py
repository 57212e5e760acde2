"""Whose "the X" is when several colleagues have one: "could you take the tray over to Amber",
said by someone with no tray of their own where three colleagues each have one. "The" points
at one particular tray, and nothing said tells whose: guessing would move a colleague's thing
nobody meant, so the requester is asked whose it is, and their answer ("Bruno's") is read as
the owner in the request's own words ("take Bruno Keel's tray over to Amber").

Only a verb that moves one particular thing ("take", "carry", "pop ... over") asks, or one
that borrows it for the requester ("can I borrow the book?", with no book named before): "bring
Amber the tray" provides her with one, and any one the planner finds will do. The question
names the colleagues who have one where they are few (four at most). Nothing is asked
where the requester has one (``definite_own``: their own), where one colleague
besides the recipient has one (the planner finds them), for a thing the office keeps for anyone
(a supply), for "a tray" (any one will do) or where whose it is was said ("Bruno's tray", "the
tray from Bruno")."""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading._parties import Clause, Roles
from assistantx.agents.symbolic.reading.lexicon import Lexicon, Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office
from assistantx.core.task_schema import Task
from assistantx.core.wording import a_thing

# How the question starts, so the answer to it is read as whose the thing is.
SEVERAL_HAVE = "Several colleagues have "
# Verbs that move a particular thing from where it is, rather than provide one.
_MOVING = frozenset({"take", "carry", "move", "shift", "ferry", "wheel", "cart", "lug", "pop"})
# Verbs that ask for one particular thing lent by its owner ("can I borrow the book?").
_BORROW = frozenset({"borrow"})
# An answer that any one will do ("Anyone's, any will do", "whichever").
_ANY = frozenset({"any", "anyones", "anybodys", "whichever", "whoevers"})
_ASKED = re.compile(rf"^{SEVERAL_HAVE}(?:an?|some|a pair of) (?P<name>.+?)(?: \([^)]*\))?: whose")
# The frames' own question whose a personal thing is ("Whose document do you mean?")
_WHOSE = re.compile(r"^Whose (?P<name>.+?) do you mean\?")
# An answer to "Whose X do you mean?" that any owner's will do: its words, or its phrases
_ANY_OWNER = english.words("any_owner_words")
_PHRASES = [re.escape(p) for p in sorted(english.words("any_owner_phrases"))]
# "doesn't matter", "don't mind": a negation that says any will do
_NO_MATTER = frozenset({"matter", "mind", "care", "fussed", "bothered"})
# An answer that takes back what it says ("not mine", "it isn't mine")
_NOT = frozenset({"not", "no", "nt", "isnt", "aint", "never"})


def whose_of_several(
    office: Office,
    tokens: Sequence[Token],
    clause: Clause,
    roles: Roles,
    task: Task,
    requester: str,
    earlier: Sequence[Mention] = (),
) -> str | None:
    """The question whose the thing is, when ``task`` takes "the X" (whose not said) to
    someone else, or borrows it for the requester ("can I borrow the book?") with nothing
    said of it before (``earlier``: the things earlier clauses named), the requester has no X
    and several colleagues besides the recipient do."""
    if task.kind != "transfer" or task.owner is not None or task.item is None:
        return None
    if task.recipient is None or roles.source or roles.returned_to:
        return None
    borrowed = task.recipient == requester
    if office.supplier(task.item) is not None:
        return None  # "take the box of staples to Amber": the supply room's, for anyone
    owners = [p for p in office.owners_of(task.item) if p != task.recipient]
    if requester in office.owners_of(task.item) or len(owners) < 2:
        return None
    said = [m for m in clause.objects() if m.id == task.item and m.start > 0]
    if len(said) != 1 or tokens[said[0].start - 1].word.lower() != "the":
        return None
    if borrowed:
        # "can I borrow the book?" with nothing said of it before; "bring me the tray": one
        # for the speaker, any will do
        if any(m.id == task.item for m in earlier) or not _borrowing(tokens, said[0].start):
            return None
    elif not _moved(tokens, clause, said[0].start):
        return None
    name = office.item_type(task.item).name
    return f"{SEVERAL_HAVE}{a_thing(name)}{_named(office, owners)}: whose {name} do you mean?"


# At most this many owners are named in the question; more would bury it.
_NAMED_OWNERS = 4


def _named(office: Office, owners: Sequence[str]) -> str:
    """ " (Bruno Keel, Tove Lind and Ines Varga)": the colleagues who have one, by name,
    where they are few."""
    if len(owners) > _NAMED_OWNERS:
        return ""
    names = [office.person(p).name for p in owners]
    return f" ({', '.join(names[:-1])} and {names[-1]})"


def _borrowing(tokens: Sequence[Token], item_at: int) -> bool:
    """Whether the verb just before the thing borrows it ("can I borrow the book?", "let me
    borrow the tray"): one particular thing, lent by whoever owns it."""
    return any(
        _BORROW & ({t.word.lower()} | language.verb_lemmas(t.word.lower()))
        for t in tokens[max(0, item_at - 3) : item_at]
    )


def _moved(tokens: Sequence[Token], clause: Clause, item_at: int) -> bool:
    """Whether the verb before the thing moves one particular thing where it is ("take the
    tray over to Amber", "carry the ruler to ..."), not provides someone with one ("bring
    Amber the tray", "bring him the kick stool": any one the planner finds will do)."""
    start = min((m.start for m in clause.mentions), default=item_at)
    for token in tokens[start:item_at]:
        verb = token.word.lower()
        if ({verb} | language.verb_lemmas(verb)) & _MOVING:
            return True
    return False


def with_owner(lex: Lexicon, text: str, question: str, answer: str) -> str | None:
    """``text`` with "the X" asked about replaced by the colleague the answer names ("Bruno's",
    "it's Bruno's tray"): "take Bruno Keel's tray over to Amber", or by "a tray" when any
    will do; to "Whose X do you mean?" also by the requester's own ("Mine.", "my own", "it's
    mine": "my X"); None when the answer says neither or the question is not this one."""
    asked = _ASKED.match(question)
    whose = _WHOSE.match(question)
    found = asked or whose
    if found is None:
        return None
    said = lex.read(answer)
    people = {p for m in said.mentions if m.kind == "person" for p in m.ids}
    name = found.group("name")
    article = r"the" if asked is not None else r"the|an?|this|that|these|those"
    # the question says the type's name ("document"), the request may have said another of
    # its names ("this permit")
    names = sorted(_names_of(lex, name) | _said_as(lex, text, name), key=len, reverse=True)
    said_as = "|".join(re.escape(n) for n in names)
    # "take lunch to Chen" → "Whose lunch do you mean?": the frames ask whatever the thing
    # was said with, so their answer fills a bare noun too; "the" alone for the several
    opener = rf"(?:(?:{article})\s+)?" if whose is not None else rf"(?:{article})\s+"
    pattern = re.compile(rf"\b{opener}(?:{said_as})\b", re.IGNORECASE)
    if pattern.search(text) is None:
        return None
    if len(people) == 1:
        owner = lex.office.person(next(iter(people))).name
        return pattern.sub(f"{owner}'s {name}", text, count=1)
    words = {t.word for t in said.tokens}
    own = any(m.kind == "self" for m in said.mentions)
    if whose is not None and own and not people and not words & _NOT:
        return pattern.sub(f"my {name}", text, count=1)  # "Mine.", "my own", "it's mine"
    if not people and words & _ANY:
        return pattern.sub(a_thing(name), text, count=1)  # "any will do": "take a tray ..."
    return None


def any_owner_meant(lex: Lexicon, question: str, answer: str) -> bool:
    """Whether ``answer`` to the frames' "Whose X do you mean?" says any owner's will do
    ("Anyone's, any will do.", "doesn't matter", "whoever's"), naming nobody (not even the
    requester: "mine")."""
    if _WHOSE.match(question) is None:
        return False
    said = lex.read(answer)
    if any(m.kind in ("person", "self") for m in said.mentions):
        return False
    folded = language.fold(answer).replace("'", "").replace("’", "")
    words = set(language.words(folded))
    if words & _NOT and not words & _NO_MATTER:
        return False  # "not anyone's": no answer of any owner
    return bool(words & _ANY_OWNER) or any(re.search(rf"\b{p}\b", folded) for p in _PHRASES)


def _said_as(lex: Lexicon, text: str, name: str) -> set[str]:
    """The words ``text`` said the item type called ``name`` with where the lexicon read them
    as it without the office listing them ("paperwork" read as the requester's paper)."""
    ids = {t.id for t in lex.office.item_types if t.name.lower() == name.lower()}
    return {m.text for m in lex.read(text).mentions if m.kind == "item" and set(m.ids) & ids}


def unowned_mine(lex: Lexicon, question: str, answer: str, requester: str) -> str | None:
    """ "Whose lunch do you mean?" "Mine." from someone with no lunch: the question again,
    saying so, never their own thing looked for where there is none; None where the answer
    is no "mine" or they have one."""
    whose = _WHOSE.match(question)
    if whose is None:
        return None
    said = lex.read(answer)
    words = {t.word for t in said.tokens}
    own = any(m.kind == "self" for m in said.mentions)
    if not own or words & _NOT or any(m.kind == "person" for m in said.mentions):
        return None
    name = whose.group("name")
    ids = {t.id for t in lex.office.item_types if t.name.lower() == name.lower()}
    if any(requester in lex.office.owners_of(i) for i in ids):
        return None
    return f"Whose {name} do you mean? As far as I know, you have no {name} of your own."


def _names_of(lex: Lexicon, name: str) -> set[str]:
    """Every name the office gives the item type called ``name`` (with ``name`` itself)."""
    names = {name}
    for t in lex.office.item_types:
        if t.name.lower() == name.lower():
            names |= {t.name, *t.synonyms, t.id.replace("_", " ")}
    return names
