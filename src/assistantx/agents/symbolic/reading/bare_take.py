"""A bare "take the X" says neither whose X nor where it goes: "take the stapler", said by
someone with no stapler of their own where colleagues each have one. "Take" moves a thing
away from where it is; with no "me", no "to ..." and no "for ...", nothing says it comes to
the speaker (that is "bring me" or "can I take"), so reading it as theirs would carry a
colleague's thing off that nobody asked to move. The requester is asked whose it is and who
should get it, and their answer ("It's Zhang Wei's stapler, for me.") is read into the
request's own words ("take Zhang Wei's stapler to me").

Only the whole message as that bare imperative asks: the verb, "the" (or "this", "that") and
the thing, with nothing else but courtesy ("please", "could you ... pls"). A thing the
office keeps for anyone (a supply) or one the requester owns (their own) is no question."""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading._parties import Clause, Roles
from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language
from assistantx.core.office import Office
from assistantx.core.task_schema import Task

# How the question starts, so the answer to it is read into the request.
WHOSE_TO_TAKE = "Whose "
_ASKED = re.compile(r"^Whose (?P<name>.+?) should I take, and who should get it\?$")
# The words that only make an imperative polite, and ask nothing of their own.
_COURTESY = frozenset(
    {"please", "pls", "plz", "can", "could", "would", "will", "you", "u", "thanks", "thx"}
)
_POINTING = frozenset({"the", "this", "that"})


def whose_and_whom(
    office: Office,
    tokens: Sequence[Token],
    clause: Clause,
    roles: Roles,
    task: Task,
    requester: str,
) -> str | None:
    """The question whose the thing is and who should get it, where the whole message is a
    bare "take the X" read as a fetch for the requester, who has no X of their own."""
    if task.kind != "transfer" or task.owner is not None or task.item is None:
        return None
    if task.recipient != requester or roles.recipient or roles.source or roles.returned_to:
        return None
    if roles.occasion or office.supplier(task.item) is not None:
        return None
    owners = office.owners_of(task.item)
    if not owners or requester in owners:
        return None
    said = [m for m in clause.objects() if m.id == task.item]
    if len(said) != 1 or not _bare_take(tokens, said[0].start):
        return None
    if said[0].end != len(tokens) and not all(t.word in _COURTESY for t in tokens[said[0].end :]):
        return None
    name = office.item_type(task.item).name
    return f"{WHOSE_TO_TAKE}{name} should I take, and who should get it?"


def _bare_take(tokens: Sequence[Token], item_at: int) -> bool:
    """Whether the words before the thing are only "take the" after courtesy ("could you
    take the", "pls take that")."""
    if item_at < 2 or tokens[item_at - 1].word not in _POINTING:
        return False
    verb = tokens[item_at - 2].word
    if "take" not in {verb} | language.verb_lemmas(verb):
        return False
    return all(t.word in _COURTESY for t in tokens[: item_at - 2])


def with_whose_and_whom(lex: Lexicon, text: str, question: str, answer: str) -> str | None:
    """``text`` with the answer to "Whose X should I take, and who should get it?" in its own
    words: "the X" becomes the owner's ("Zhang Wei's X") and the one who gets it is added
    ("to me", "to Wang Fang"); None where the question is not this one or the answer names
    neither."""
    asked = _ASKED.match(question)
    if asked is None:
        return None
    name = asked.group("name")
    said = lex.read(answer)
    owner = next((m for m in said.mentions if m.kind == "person" and m.possessive), None)
    gets = next((m for m in said.mentions if m.kind == "person" and not m.possessive), None)
    to_me = any(m.kind == "self" and not m.possessive for m in said.mentions)
    if owner is None and gets is None and not to_me:
        return None
    names = sorted(_names_of(lex.office, name), key=len, reverse=True)
    said_as = "|".join(re.escape(n) for n in names)
    pattern = re.compile(rf"\b(?:the|this|that)\s+(?:{said_as})\b", re.IGNORECASE)
    if owner is not None:
        owner_name = lex.office.person(owner.id).name
        text = pattern.sub(f"{owner_name}'s {name}", text, count=1)
    if gets is not None:
        return f"{text.rstrip(' .!?')} to {lex.office.person(gets.id).name}"
    return f"{text.rstrip(' .!?')} to me" if to_me else text


def _names_of(office: Office, name: str) -> set[str]:
    """Every name the office gives the item type called ``name``: the request may have said
    another ("the shears" for the scissors)."""
    names = {name}
    for t in office.item_types:
        if t.name.lower() == name.lower():
            names |= {t.name, *t.synonyms}
    return names
