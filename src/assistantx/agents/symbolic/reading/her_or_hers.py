""" "bring her lunch": "her" right after a giving verb is either whom the thing goes to ("bring
lunch to her") or whose it is ("bring her lunch", to me). English leaves it to the context:
when the sentences before are about her ("Ngozi's stuck with a client", "Zhang can't get
away", "Wang's in a meeting"), the thing goes to her; when nothing decides, the reader asks
("Should Ngozi Eze's lunch go to Ngozi Eze, or to you?"), never handing a colleague's own
thing to the speaker on a guess (fix154a class 3: "Ngozi's stuck with a client, could you
bring her lunch up from the fridge?" handed Ngozi's lunch to the speaker). A recipient said
after the thing ("bring her lunch to me", "... to Wang") or before it ("bring me her lunch")
decides it the other way: "her" is then only whose it is. Only a thing the office keeps away
from her own place (her lunch in the fridge) can be brought to her; one at her desk she has,
and "her" says whose it is."""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office
from assistantx.core.task_schema import Task

_DATIVE_VERBS = english.words("dative_verbs")
# the words after "to"/"for" that open a place or an occasion, no one the thing is handed to
# ("to the meeting room", "up to her desk", "for the afternoon")
_NO_RECIPIENT = frozenset(
    {"the", "a", "an", "her", "hers", "his", "their", "this", "that", "these", "those"}
)
_CLAUSE_ENDS = frozenset({"and", "then", "but", "or", "so", "because", "while", "if"})
HER_OR_YOU = ", or to you?"


def giving_her(before: Sequence[str], after: Sequence[str]) -> bool:
    """Whether a "her" with the words ``before`` and ``after`` it (folded, its clause's and
    beyond) stands right after a giving verb, with no recipient said after it in its
    clause: her thing, or the thing to her."""
    if not before or before[-1] not in _DATIVE_VERBS:
        return False
    for k, word in enumerate(after):
        if word in _CLAUSE_ENDS:
            return True
        if word in ("to", "for") and k + 1 < len(after) and after[k + 1] not in _NO_RECIPIENT:
            return False  # "bring her lunch to me", "... for Wang": whose, not whom
    return True


def kept_from_her(office: Office, person: str, item_type: str) -> bool:
    """Whether ``person``'s own ``item_type`` is kept away from their own place (their lunch
    in the fridge): only then can "bring her <thing>" take it to her. A thing at her own desk
    she has already, so there "her" says whose it is, as before ("Zhang is off sick, grab her
    stapler": hers, lent to the speaker with her yes)."""
    home = office.person(person).location
    return any(
        o.type == item_type and o.at is not None and o.at != home
        for o in office.person(person).owns
    )


def giving_her_in(text: str, at: int) -> bool:
    """``giving_her`` for the "her" that starts at character ``at`` of ``text``."""
    end = at + len("her")
    return giving_her(language.words(text[:at]), language.words(text[end:]))


def her_or_you(owner_name: str, thing: str) -> str:
    """The question that settles "bring her <thing>" where nothing else does."""
    return f"Should {owner_name}'s {thing} go to {owner_name}{HER_OR_YOU}"


_VERBS = "|".join(sorted(_DATIVE_VERBS, key=len, reverse=True))
_GIVING_HER = re.compile(rf"\b(?P<verb>{_VERBS})(?P<gap>\s+)her\b", re.IGNORECASE)
_ASKED_NAME = re.compile(r" go to (?P<name>.+)" + re.escape(HER_OR_YOU) + "$")


def with_her_or_you(text: str, question: str, answer: str) -> str | None:
    """The request with the answer to ``her_or_you`` said in it: "to her" (or her name) makes
    "bring <her name> her lunch", "to me" makes "bring me her lunch"; None for any other
    question or an answer that says neither."""
    asked = _ASKED_NAME.search(question)
    if asked is None:
        return None
    her_name = asked.group("name")
    said = set(language.words(answer))
    names = set(language.words(her_name))
    if said & {"me", "mine", "myself", "i"} and not said & ({"her", "she"} | names):
        whom = "me"
    elif said & ({"her", "she", "hers"} | names):
        whom = her_name
    else:
        return None
    match = next(
        (m for m in _GIVING_HER.finditer(text) if giving_her_in(text, m.end() - 3)),
        None,
    )
    if match is None:
        return None
    return f"{text[: match.end('gap')]}{whom} {text[match.end('gap') :]}"


def her_thing_asked(
    office: Office,
    tokens: Sequence[Token],
    mentions: Sequence[Mention],
    made: Sequence[Task],
    requester: str,
    said_to: Sequence[str],
) -> str | None:
    """The question to ask where a clause's "<giving verb> her <thing>" was read as her
    thing handed to the speaker with no one said to receive it (``said_to``: the clause's
    recipients as said): which reading is meant is not the reader's to guess."""
    if requester in said_to:
        return None  # "bring her lunch to me": mine to have, as said
    words = [t.word for t in tokens]
    for n, m in enumerate(mentions[:-1]):
        thing = mentions[n + 1]
        if m.kind != "pronoun" or words[m.start] != "her" or thing.kind != "item":
            continue
        if thing.start != m.end or not giving_her(words[: m.start], words[m.end :]):
            continue
        for task in made:
            others = task.owner is not None and task.owner != requester
            others = others and kept_from_her(office, str(task.owner), thing.id)
            if task.item == thing.id and task.recipient == requester and others:
                name = office.person(str(task.owner)).name
                return her_or_you(name, office.item_type(thing.id).name)
    return None
