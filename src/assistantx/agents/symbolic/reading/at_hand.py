"""The thing at hand: "copy this please", "can this go thru the scanner", "run it through the
laminator", "I need this photocopied and signed by Mark". A pronoun that names nothing said
before, as the object of a service on an item (its verb, its participle, or the item taken
through or to the facility that offers it), is what the requester holds out: their own item
of the type that service works on. Which type comes from the office file only: the input of
the operations the clause asks for (those of the facility said, else those whose verb is
said), or the paper a person's work (a signature, a seal) is done on, where the one who does
it is named.

"this"/"that" point at what is at hand; "it" points back, and with nothing said it is read so
only where the clause puts it through or into a machine ("get it signed by Wang" asks which
paper). A file is never read so ("print it" with nothing said is asked about:
antecedent.py), nor what a service sends out of the office, nor where the services asked
for work on different types, or the requester has none of the type.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.core import language, task_kinds
from assistantx.core.office import Office
from assistantx.core.task_schema import SHAPE_KIND

# The demonstratives that point at a thing held out ("copy this please"), and the pronouns
# that point back at something said ("it", "them"): with nothing said, those are read as a
# thing at hand only where the clause puts it through or into one of the office's machines
# ("run it through the laminator"); elsewhere ("get it signed by Wang") which one is asked,
# as antecedent.py asks of a file. "one", "something" ask for a kind, never a thing held.
DEICTICS = frozenset({"this", "that", "these", "those"})
ANAPHORS = frozenset({"it", "them"})
POINTERS = DEICTICS | ANAPHORS


def points_at_hand(mentions: Sequence[Mention], into_a_machine: bool) -> bool:
    """Whether the clause has a pronoun of a thing (not a person, not a possessive) that may
    be the thing held out; ``into_a_machine``: the clause takes it to a facility."""
    pointers = POINTERS if into_a_machine else DEICTICS
    return any(
        m.kind == "pronoun" and not m.possessive and m.text.lower() in pointers for m in mentions
    )


def held_type(
    office: Office,
    mentions: Sequence[Mention],
    cues: set[str],
    facilities: Sequence[str],
    requester: str,
    doer_said: bool,
) -> str | None:
    """The one item type the clause's services work on (the type of the thing at hand);
    None where they ask for no work on an item, work on a file, or on several types, where
    the requester has no item of it (it is not theirs, so whose is asked), or where the
    service sends the thing out of the office (what leaves for good is named, not guessed)."""
    types: set[str] = set()
    said = {
        lemma
        for m in mentions
        if m.kind == "cue"
        for w in language.words(m.text)
        for lemma in language.verb_lemmas(language.fold(w)) | {language.fold(w)}
    }
    for op in office.operations:
        if op.input is None or SHAPE_KIND.get(op.shape(office)) not in cues:
            continue
        if op.sends_out:
            continue  # "fax this to the council": which paper goes out is asked
        offered = any(op.id in office.facility(f).operations for f in facilities)
        named = any(language.fold(v.split()[0]) in said for v in op.verbs)
        if op.shape(office) == "treat" and not offered:
            # a treat service works on any belonging ("heat this up": a lunch, a tea?):
            # only the thing put through its machine is read as the type it takes
            continue
        if offered or (not facilities and named):
            types.add(op.input)
    for kind in task_kinds.person_kinds():
        # "get this signed by Mark": with nobody named to do it, "could you sign it?" asks
        # which paper, as a request to the robot to sign always did
        if kind in cues and doer_said:
            paper = task_kinds.item_type_of(kind, office)
            if paper is not None:
                types.add(paper)
    if len(types) != 1:
        return None
    (held,) = types
    if office.item_type(held).electronic or requester not in office.owners_of(held):
        return None
    return held
