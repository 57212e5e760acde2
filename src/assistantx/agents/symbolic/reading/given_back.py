"""A colleague's thing given back to them: "return Wang's stapler", "can you return the
stapler to Wang", "give Wang his stapler back", "take Zhang's book back to him". A verb of
giving back (the verb "return", or a verb of handing with "back" after it) with an owner said
(a colleague's possessive, "his"/"her" bound to a named colleague, or the "to" colleague the
thing goes to) says the speaker has the owner's thing now: they were lent it, so the office's
record that the owner holds it is out of date. The robot collects it from the speaker and hands
it to its owner; it never asks the owner to lend it, nor borrows another colleague's.

Only a request: the past ("Wang returned my stapler") is a statement, read elsewhere. The
speaker's own thing given to a colleague ("return my book to Zhang", "give Wang my stapler")
goes as before, and so does a thing the speaker asks for themselves ("bring me Wang's stapler
back"). With no owner and nobody to give it to ("return the stapler") the reader asks whose it
is."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core.task_schema import Task

# The verb that gives back by itself, and the verbs of handing that do with "back" after them
# ("give it back", "take Wang's stapler back to him", "hand Zhang back his book").
_RETURN = "return"
_HANDING = frozenset({"give", "take", "bring", "hand", "pass", "carry", "drop", "send"})
_BACK = "back"
# What may stand before a request's verb of giving back: nothing (the clause's start), a
# request's lead ("please", "can you"), a join. After anything else the word is no request's
# verb: "Wang's tax return", "in return" (nouns), "I'll give it back later" (the speaker's own
# doing, told).
_VERB_LEADS = frozenset(
    {"please", "pls", "plz", "kindly", "can", "could", "would", "will", "you", "u", "ya"}
    | {"and", "then", "also", "just", "now", "so", "ok", "okay", "pl", "maybe"}
)
# The verbs of a request of its own about the same thing ("borrow Pat's tape and take it back
# to her"): the message takes the thing from someone, so the speaker does not have it.
# (Not "need"/"want": "Wang needs his stapler, please return it to him" takes nothing.)
_TAKING = frozenset({"borrow", "bring", "collect", "fetch", "find", "get", "grab", "pick", "take"})
# A request of its own after "and"/"then": a verb of handing, or a lead before one.
_JOINS = frozenset({"and", "then"})
_LEADS = frozenset({"please", "pls", "plz", "can", "could", "would", "will", "also", "kindly"})
_PRONOUNS = frozenset({"it", "them", "this", "that", "these", "those"})


def _clauses(tokens: Sequence[Token]) -> list[tuple[int, int]]:
    """The spans of the message's clauses: a sentence, a part after a comma, or a request of
    its own after "and"/"then" ("bring me a pen and return Wang's stapler"); "and" between two
    things ("Wang's stapler and scissors") joins no clauses."""
    starts = [0]
    for n, t in enumerate(tokens[1:], 1):
        after = tokens[n + 1].word if n + 1 < len(tokens) else ""
        if t.opens or t.after_pause:
            starts.append(n)
        elif t.word in _JOINS and (after in _HANDING | _LEADS or after == _RETURN):
            starts.append(n)
    return list(zip(starts, [*starts[1:], len(tokens)], strict=True))


def _about(
    task: Task, tokens: Sequence[Token], mentions: Sequence[Mention]
) -> list[Sequence[Token]]:
    """The clauses that speak of ``task``'s thing: those naming it, and those referring to a
    thing by a pronoun without naming one ("please return it to him"); the whole message when
    no clause names it."""
    spans = _clauses(tokens)
    named = [m for m in mentions if m.kind == "item" and task.item in m.ids]
    items = [m for m in mentions if m.kind == "item"]
    about = []
    for a, b in spans:
        if any(a <= m.start < b for m in named) or (
            not any(a <= m.start < b for m in items)
            and any(t.word in _PRONOUNS for t in tokens[a:b])
        ):
            about.append(tokens[a:b])
    return about if named else [tokens]


def _given_back_here(task: Task, tokens: Sequence[Token], mentions: Sequence[Mention]) -> bool:
    """Whether a clause about ``task``'s thing gives it back, not to the speaker, and no other
    clause about it asks for it to be taken from someone first."""
    about = _about(task, tokens, mentions)
    back = [c for c in about if gives_back(c) and not _asks_for_self(c)]
    taken = [c for c in about if not gives_back(c) and any(t.word in _TAKING for t in c)]
    return bool(back) and not taken


def gives_back(tokens: Sequence[Token]) -> bool:
    """Whether the words ask for a thing to be given back: the verb "return", or a verb of
    handing with "back" after it."""
    for n, t in enumerate(tokens):
        led = n == 0 or t.opens or t.after_pause or tokens[n - 1].word in _VERB_LEADS
        if not led or t.possessive:
            continue
        if t.word == _RETURN:
            return True
        if t.word in _HANDING and any(u.word == _BACK for u in tokens[n + 1 : n + 7]):
            return True
    return False


def _asks_for_self(tokens: Sequence[Token]) -> bool:
    """ "bring me Wang's stapler back": the speaker wants it (not "for me": on their behalf)."""
    return any(
        t.word == "me" and (n == 0 or tokens[n - 1].word != "for") for n, t in enumerate(tokens)
    )


def given_back_by_speaker(
    task: Task, tokens: Sequence[Token], mentions: Sequence[Mention], requester: str
) -> Task:
    """``task`` as the speaker's giving back of a colleague's thing, when the words give back
    and name its owner: from the speaker (``source``) to the owner."""
    if task.kind != "transfer" or task.item is None or task.source is not None:
        return task
    if not _given_back_here(task, tokens, mentions):
        return task
    owner = task.owner
    if owner is None and task.recipient not in (None, requester):
        owner = task.recipient  # "return the stapler to Wang": the one it goes back to
    if owner is None or owner == requester:
        return task  # "return my book to Zhang": the speaker's own, given
    if task.recipient not in (owner, requester):
        return task  # "return Wang's stapler to Zhang": not back to its owner; as said
    return task.model_copy(update={"owner": owner, "recipient": owner, "source": requester})


def unowned_return(
    task: Task, tokens: Sequence[Token], mentions: Sequence[Mention], requester: str
) -> bool:
    """ "return the stapler": given back, but to nobody said and of nobody said; asked."""
    return (
        task.kind == "transfer"
        and task.item is not None
        and task.owner is None
        and task.source is None
        and task.recipient == requester
        and _given_back_here(task, tokens, mentions)
    )


def returned_to_whom(name: str) -> str:
    """The question of a thing given back with no owner and nobody to give it to."""
    return f"Whose {name} is it, and who should I give it back to?"
