"""One object, two services: "I need this photocopied and signed by Mark", "get my contract
copied and stamped", "can my document be scanned and then signed by Grace?". A clause that
opens with a service's past participle and names no object of its own ("and signed by
Mark", "and then stamped") goes on with the object of the clause before, as English
coordinates participles over one noun; the services are done in the order said.

A clause with an object of its own ("copy my memo and sign the form") or a bare verb ("and
sign for the parcel") is not read so."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.core import english, language

# Words that may come between the "and" and the participle: "and *then* signed".
_LINKS = english.words("shared_object_links")


def opens_with_participle(mentions: Sequence[Mention]) -> bool:
    """Whether the clause's first word (after "then", "also") is a service cue said as a
    past participle, with no thing named and no pronoun after it."""
    rest = list(mentions)
    while rest and rest[0].kind == "word" and rest[0].ids[0] in _LINKS:
        rest = rest[1:]
    if not rest or rest[0].kind != "cue":
        return False
    if not language.is_past_participle(language.fold(rest[0].text)):
        return False
    return not any(m.kind == "item" or m.possessive or m.kind == "pronoun" for m in rest)


# The pronouns a clause may leave for the next participle to name ("get *it* copied and
# stamped"): a thing, never a person.
_THING_POINTERS = frozenset({"it", "this", "that", "them", "these", "those"})


def waits_for_object(mentions: Sequence[Mention]) -> bool:
    """Whether a clause that made no task asks for a service on a pronoun's thing by a past
    participle ("get it copied"): the participle coordinated after it ("and stamped") works
    on the same thing, so once that clause finds the thing, this clause's service is on it
    too, never dropped in silence."""
    pointed = any(
        m.kind == "pronoun" and not m.possessive and m.text.lower() in _THING_POINTERS
        for m in mentions
    )
    said = any(
        m.kind == "cue" and language.is_past_participle(language.fold(m.text)) for m in mentions
    )
    return pointed and said and not any(m.kind == "item" for m in mentions)
