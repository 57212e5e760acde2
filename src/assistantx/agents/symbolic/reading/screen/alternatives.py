"""Two things offered as alternatives the speaker is unsure of: "can you bring me the thing for
cutting tape? or the scissors, not sure which I need", "a ruler or maybe a calculator",
"the stapler or the scissors, whichever". One of them is wanted, so both are never fetched
(fix180a class 5): one question names the options ("Which would you like: the tape dispenser
or the scissors?").

Two of the office's things of different kinds joined by "or" (with "maybe", "perhaps", a
determiner between: ``choice_between``), beside a mark of doubt: "? or", "or maybe", or one of
``unsure_choice_marks`` ("not sure which", "whichever", "either"). "X and Y" asks for both;
"X or Y" with no doubt said is read as before."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.destructive import commanded
from assistantx.agents.symbolic.reading.screen.english import DETERMINERS, starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.rewrites import purposes
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_MARKS = tuple(tuple(e.split()) for e in english.entries("unsure_choice_marks"))
_BETWEEN = english.words("choice_between")
_ASKED_OR = re.compile(r"\?\s*or\b", re.IGNORECASE)
_REACH = 2  # at most this many words between the first thing and "or" ("cutting *tape*? or")


def alternatives(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if not (piece.acts.request or piece.acts.imperative or commanded(terms, piece)):
        return None
    if "or" not in (t.word for t in msg.lexed.tokens):
        return None
    # "the thing for cutting tape? or ...": the thing a purpose describes, read as the request
    # reads it ("a scissors")
    described, _ = purposes(terms, msg.text)
    lexed = msg.lexed if described == msg.text else terms.lex.read(described)
    tokens, mentions = lexed.tokens, lexed.mentions
    words = [t.word for t in tokens]
    items = [m for m in mentions if m.kind == "item" and len(m.ids) == 1]
    for k, word in enumerate(words):
        if word != "or":
            continue
        first = [m for m in items if m.end <= k and k - m.end <= _REACH]
        if not first or {"and", "or"} & set(words[first[-1].end : k]):
            # "a scissors tape? or ...": the thing's own word read as a modifier
            named = [n for n in range(max(0, k - _REACH), k) if words[n] in terms.lex.items]
            if not named:
                continue
            ids: tuple[str, ...] = (terms.lex.items[words[named[-1]]],)
        else:
            ids = first[-1].ids
        j = k + 1
        while j < len(words) and (words[j] in _BETWEEN or words[j] in DETERMINERS):
            j += 1
        second = [m for m in items if m.start == j]
        if not second or second[0].ids == ids:
            continue
        hedged = any(w in _BETWEEN for w in words[k + 1 : j])
        if not (hedged or _ASKED_OR.search(described) or _unsure(words)):
            continue
        one, other = (terms.office.item_type(i).name for i in (ids[0], second[0].ids[0]))
        return Finding(
            "which",
            piece,
            f"two things offered as alternatives: {one} or {other}",
            message=f"Which would you like: the {one} or the {other}?",
        )
    return None


def _unsure(words: list[str]) -> bool:
    return any(starts_with(words, n, mark) for n in range(len(words)) for mark in _MARKS)
