"""The requester's own doubt between two people: "bring my pen to Wei... or was it Wang?",
"give this to Zhang, or maybe Chen, not sure". The first name is no more meant than the
second, so whom the item goes to is asked, naming both; nothing is handed to the first. Where
the requester leaves the choice to the assistant ("Zhang or Chen, whoever's in", "either is
fine"), the one read first gets it, as before. The answer that names one of the two takes
the place of the pair in the request ("Chen" → "give this to Chen Jing, not sure").
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.lexicon import Lexed, Lexicon, Mention
from assistantx.core import english, language
from assistantx.core.office import Office
from assistantx.core.task_schema import Task

# The frames' own question, naming the two: "Who should get your pen: Wei Na or Wang Fang?"
WHO_OF_TWO = "Who should get "

# The most words of doubt between the two names ("or was it", "or I think maybe").
_MOST_BETWEEN = 5


@dataclass(frozen=True)
class Pair:
    """Two people named with "or" between them (token spans of the whole message)."""

    first: Mention
    second: Mention
    left_open: bool  # the requester said either will do


def doubted_pairs(lexed: Lexed) -> list[Pair]:
    """Each "X or Y" of two different colleagues, with only words of doubt between them."""
    between_ok = english.words("doubt_between")
    people = [m for m in lexed.mentions if m.kind == "person" and len(m.ids) == 1]
    out: list[Pair] = []
    for first, second in itertools.pairwise(people):
        if first.id == second.id or first.possessive or second.possessive:
            continue
        between = [t.word for t in lexed.tokens[first.end : second.start]]
        if "or" not in between or len(between) > _MOST_BETWEEN:
            continue
        if not set(between) <= between_ok:
            continue
        out.append(Pair(first, second, _left_open(lexed, second.end)))
    return out


def _left_open(lexed: Lexed, after: int) -> bool:
    """Whether the words after the pair leave the choice to the assistant: "either"
    ("either is fine", "either of them"), or "whoever"/"whichever" with a word of being at
    hand ("whoever's in", "whichever is free", "whoever is nearer"); "whoever has the
    deadline" is the requester's own test, which only they can apply."""
    words = [t.word for t in lexed.tokens[after:]]
    if set(words) & english.words("either_one"):
        return True
    at_hand = english.words("here") | english.words("whoever_at_hand")
    whoever = english.words("whoever_words")
    for n, word in enumerate(words):
        if word in whoever and set(words[n + 1 : n + 4]) & at_hand:
            return True
    return False


def either_doer(lexed: Lexed, tasks: Sequence[Task], requester: str) -> list[Task]:
    """The tasks with the second of two alternative doers no longer their recipient: "Could
    my contract get the approval stamp? Mao or Sun can do it, whoever's free" is one stamp,
    by either, and the contract comes back to the requester (the one read as the doer does
    it); neither of two people offered to do the work is whom its result goes to."""
    out = list(tasks)
    for pair in doubted_pairs(lexed):
        two = {pair.first.id, pair.second.id}
        for n, task in enumerate(out):
            if task.actor in two and task.recipient in two and task.actor != task.recipient:
                out[n] = task.model_copy(update={"recipient": requester})
    return out


def doubted_recipient(
    office: Office, lexed: Lexed, tasks: Sequence[Task], requester: str
) -> str | None:
    """The question whom a task's item goes to, when its recipient was named in doubt
    beside another colleague (None when no recipient was, or either will do)."""
    for pair in doubted_pairs(lexed):
        if pair.left_open:
            continue
        for task in tasks:
            two = (pair.first.id, pair.second.id)
            if task.recipient not in two or task.actor in two or task.item is None:
                continue
            name = office.item_type(task.item).name
            if task.owner == requester:
                whose = f"your {name}"
            elif task.owner is not None:
                whose = f"{office.person(task.owner).name}'s {name}"
            else:
                whose = f"the {name}"
            one, other = (office.person(p.id).name for p in (pair.first, pair.second))
            return f"{WHO_OF_TWO}{whose}: {one} or {other}?"
    return None


def chosen_of_two(lex: Lexicon, text: str, question: str, answer: str) -> str | None:
    """The request with the doubted pair replaced by the one the answer names ("Wang Fang"
    → "bring my pen to Wang Fang, whoever has the deadline today"); None when the question
    is not this one or the answer names neither or both."""
    if not question.startswith(WHO_OF_TWO):
        return None
    said = lex.read(answer)
    named = {i for m in said.mentions if m.kind == "person" for i in m.ids}
    lexed = lex.read(text)
    spans = list(language.WORD.finditer(text.replace("’", "'")))
    for pair in doubted_pairs(lexed):
        chosen = named & {pair.first.id, pair.second.id}
        if len(chosen) != 1 or pair.left_open:
            continue
        start = spans[pair.first.start].start()
        end = spans[pair.second.end - 1].end()
        rest = text[end:]
        if rest[:1] == "?":
            rest = "." + rest[1:]  # "or was it Wang?": the doubt's own question mark
        name = lex.office.person(chosen.pop()).name
        return f"{text[:start]}{name}{rest}"
    return None
