"""The parts of an announced list are each asked for: "2 things: my report printed, and Wang's
stapler if he's not using it". After "N things:" the speaker lists what they want in note
form, a noun phrase with or without a participle ("my report printed", "Wang's stapler",
"a coffee"), with no verb of asking; the count already said that each part is a request. So a
part that opens a noun phrase (a determiner, a possessive, a number) and says nothing about
the world is read as the speaker's need ("I need my report printed"); before, the second part
was dropped in silence.

A part with a verb of its own ("take my torch to Ida", "I need a coffee") is left as said, and
so is a part that states something ("the printer's jammed", "the kitchen is out of milk"): a
finite verb, or a possessive-looking "'s" before a state, before any condition the part has
("... if he's not using it" is the condition, not the part)."""

from __future__ import annotations

import itertools
import re

from assistantx.core import english

_NEED = "I need "
_DETERMINERS = frozenset(english.words("determiners")) - {"me", "that", "this"}
# the words of a finite verb that make a part a statement ("the kitchen is out of milk")
_FINITE = frozenset(
    {"is", "are", "was", "were", "has", "have", "had", "isnt", "arent", "wasnt", "hasnt", "got"}
)
# the states a thing is said to be in after "'s" ("the printer's jammed"): not an owner's thing
_STATES = frozenset(
    w
    for key in ("conditions", "facility_faults", "facility_failed", "damage_results")
    for w in english.entries(key)
    if " " not in w
) | {"out", "down", "off", "gone", "done", "here", "there"}
# the words that open a condition or a reason after the part ("if he's not using it")
_CONDITION = frozenset(
    {"if", "unless", "when", "once", "because", "as", "since", "so", "while", "provided"}
)
# "a, b and c": the parts, split at commas and at "and"
_SEPARATOR = re.compile(r"(\s*,\s*(?:and\s+)?|\s+and\s+)", re.IGNORECASE)
_WORD = re.compile(r"[\w'’]+")


def listed_as_needs(parts: str) -> str:
    """``parts`` (what follows an announced count, to its sentence's end) with each note-form
    part written as the speaker's need: "my report printed, and Wang's stapler" → "I need my
    report printed, and I need Wang's stapler"."""
    pieces = _SEPARATOR.split(parts)
    return "".join(
        _NEED + piece if n % 2 == 0 and _note_form(piece) else piece
        for n, piece in enumerate(pieces)
    )


def _note_form(part: str) -> bool:
    """Whether ``part`` is a noun phrase said as a want: it opens a noun phrase and, before any
    condition, states nothing."""
    words = [w.lower().replace("’", "'") for w in _WORD.findall(part)]
    if not words:
        return False
    first = words[0]
    opens = first in _DETERMINERS or first.endswith("'s") or first.isdigit()
    if not opens:
        return False
    main = words
    for n, w in enumerate(words):
        if w in _CONDITION:
            main = words[:n]
            break
    if any(w in _FINITE for w in main):
        return False
    return not any(
        a.endswith("'s") and (b in _STATES or b.endswith("ed")) for a, b in itertools.pairwise(main)
    )
