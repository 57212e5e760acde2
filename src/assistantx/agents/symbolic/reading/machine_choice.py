"""A thing at hand put through a machine that offers several services, none of them said:
"put this through the printer" where the printer both prints files and copies papers. Which
service is meant decides what the robot does (a print of a file, or a copy of a paper), and
nothing in the words decides it, so the question names the services the machine offers, each
on the requester's own thing it works on: "Print your file, or copy your document?". The
answer ("copy", "the document", "print it") is read as the purpose of putting it through
("put this through the printer to copy it"), which the reader then reads as that service.

Only a request read as nothing at all asks this (a facility named by one service's doer
noun, "the copier", or a service's verb said, is read as before), and only for a machine
whose services the requester could ask of it: each works on an item type the requester has,
and none sends the thing out of the office."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.at_hand import POINTERS
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language
from assistantx.core.office import Office


@dataclass(frozen=True)
class Choice:
    """One service of the machine, on the item type it works on."""

    verb: str  # the service's first verb ("print")
    verbs: tuple[str, ...]  # every verb that asks for it ("copy", "photocopy", ...)
    item: str  # the item type it works on ("file")
    name: str  # how the item is said: its name's head noun ("file" of "electronic file")


def machine_choices(
    office: Office, tokens: Sequence[Token], mentions: Sequence[Mention], requester: str
) -> list[Choice]:
    """The services of the one machine a thing at hand is put through, when there are two or
    more the requester could mean and the words name none of them; else []."""
    if not any(m.kind == "pronoun" and m.text.lower() in POINTERS for m in mentions):
        return []
    if any(m.kind == "item" for m in mentions):
        return []  # "run my file through the printer": the thing says which
    machines = {m.id for m in mentions if m.kind == "facility" and len(m.ids) == 1}
    if len(machines) != 1:
        return []
    (machine,) = machines
    # the words outside the machine's own name ("the printing machine" says no service)
    named = {k for m in mentions if m.kind == "facility" for k in range(m.start, m.end)}
    said = {t.word for k, t in enumerate(tokens) if k not in named}
    choices: list[Choice] = []
    for op_id in office.facility(machine).operations:
        op = office.operation(op_id)
        if op.input is None or op.sends_out or not op.verbs or not office.runnable(op_id):
            continue
        if said & {f for v in op.verbs for f in language.verb_forms(v.split()[0])}:
            return []  # its verb is said: not this question's to ask
        if requester not in office.owners_of(op.input):
            continue  # not the requester's to ask of the machine
        # the head noun of the item's name, as said in a short question ("electronic file":
        # "your file")
        name = office.item_type(op.input).name.split()[-1]
        verbs = tuple(v.split()[0] for v in op.verbs)
        choices.append(Choice(verbs[0], verbs, op.input, name))
    return choices if len({c.item for c in choices}) >= 2 else []


def service_question(choices: Sequence[Choice]) -> str:
    """ "Print your file, or copy your document?": each service on the requester's thing."""
    said = [f"{c.verb} your {c.name}" for c in choices]
    said[0] = said[0][:1].upper() + said[0][1:]
    return f"{', '.join(said[:-1])}, or {said[-1]}?"


def service_answered(choices: Sequence[Choice], answer: str) -> Choice | None:
    """The one service the answer names, by its verb (any form) or its item's name."""
    words = set(language.words(language.fold(answer)))
    found = [
        c
        for c in choices
        if words & {f for v in c.verbs for f in language.verb_forms(v)} or c.name in words
    ]
    return found[0] if len(found) == 1 else None


def with_service(text: str, choice: Choice) -> str:
    """The request with the chosen service said as its purpose ("put this through the
    printer" → "put this through the printer to copy it"): the reader reads the thing at
    hand as the requester's item that service works on."""
    return f"{_END.sub('', text)} to {choice.verb} it"


_END = re.compile(r"[\s,]*(?:please|pls|thanks|thank you)?[\s.!?]*$", re.IGNORECASE)
