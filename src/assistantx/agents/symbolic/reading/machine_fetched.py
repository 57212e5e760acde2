"""A machine asked to be brought: "can you bring me the printer", "bring me a shredder", "can
you bring me a scanner" where the office's scanning is done at its document scanner (blind
round 255: declined "there is no scanner in this office"). The office's machines stay where
they are; a machine named as the thing fetched (a facility by its name or its names' head
noun: "scanner" of "document scanner") is no item to carry, and what the speaker wants done
with it is asked, in the verb its noun is made from where one is ("a copier" of the printer
that also copies: "... shall I copy something for you?"). A noun made from a service's verb
that names no machine here ("a recharger" of a charging shelf) is a device the office lacks,
declined as before. A thing of the office named so ("printer paper", a "barcode scanner"
the office lends) is the thing, read as before."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language
from assistantx.core.office import Facility, Office

# the words between the fetching verb and the machine ("bring *me the* printer")
_BEFORE = frozenset(
    {"me", "us", "him", "her", "them", "a", "an", "the", "our", "your", "that", "this", "one"}
)
_NAME_WORDS = 3  # "the big document scanner"


def machine_fetched(
    office: Office, tokens: Sequence[Token], mentions: Sequence[Mention]
) -> str | None:
    """The question of a fetch whose thing is one of the office's machines; None where the
    thing asked for is no machine, or an item of the office is named."""
    cue = next((m for m in mentions if m.kind == "cue" and "give" in m.ids), None)
    if cue is None or any(m.kind == "item" and m.start >= cue.end for m in mentions):
        return None
    k = cue.end
    while k < len(tokens) and tokens[k].word in _BEFORE:
        k += 1
    facility = next((m for m in mentions if m.kind == "facility" and m.start == k), None)
    found: Facility | None
    if facility is not None:
        end = facility.end
        found = office.facility(facility.id)
    else:
        end, found = _named_machine(office, tokens, k)
    if found is None or not found.operations:
        return None
    if any(t.possessive for t in tokens[cue.end : end]):
        return None  # "bring Grace's kettle": whose machine is asked about by its own rule
    if end < len(tokens) and language.is_noun(tokens[end].word) and tokens[end].word != "please":
        return None  # "the printer tray": a part of the machine, read as before
    runnable = [op for op in found.operations if office.runnable(op)]
    if not runnable:
        return None
    said = tokens[end - 1].word
    verbs = [v for op in runnable for v in (*office.operation(op).verbs, office.operation(op).name)]
    # "a copier" of the printer that also copies: the work its noun says, else its first
    verb = next((v for v in verbs if said in _agent_nouns(v)), verbs[0])
    return (
        f"The {found.name} is one of the office's machines and stays where it is, so I can't "
        f"bring it to you. What would you like done with it: shall I {verb} something for you?"
    )


def _named_machine(office: Office, tokens: Sequence[Token], k: int) -> tuple[int, Facility | None]:
    """Where the machine said from ``k`` ends and which it is: a word ending one of the
    facilities' names ("scanner" of "document scanner")."""
    for n in range(min(_NAME_WORDS, len(tokens) - k), 0, -1):
        word = tokens[k + n - 1].word
        matches = [f for f in office.facilities if _names_machine(f, word)]
        if len(matches) == 1:
            return k + n, matches[0]
    return k, None


def _names_machine(facility: Facility, word: str) -> bool:
    """Whether ``word`` is the head noun of one of the facility's names ("scanner" of
    "document scanner"). A noun made from its work's verb that no name of it ends in
    ("recharger" of a charging shelf) is some device the office lacks, declined by name."""
    return word in {
        language.fold(n).lower().split()[-1] for n in (facility.name, *facility.synonyms) if n
    }


def _agent_nouns(verb: str) -> set[str]:
    """ "scan" → "scanner", "shred" → "shredder", "copy" → "copier", "print" → "printer"."""
    out = {f"{verb}er", f"{verb}r"}
    if len(verb) > 2 and verb[-1] not in "aeiouwxy" and verb[-2] in "aeiou":
        out.add(f"{verb}{verb[-1]}er")
    if verb.endswith("y"):
        out.add(f"{verb[:-1]}ier")
    return out
