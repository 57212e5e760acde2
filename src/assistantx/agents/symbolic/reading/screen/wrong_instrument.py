"""A facility named as the instrument of work it does not do: "can you melt down the old mugs
in the microwave?", "shred my stapler in the printer", "laminate my badge with the kettle".
The facility (after "in", "with", "on", "using", "through", ...) is where the work is asked
to be done, and the verb is none of its services' verbs: declined, naming what the facility
does ("The microwave can heat lunches; I can't melt down the old mugs in it."), never its
product made and handed over (fix180a class 2) nor its own service run on the thing.

Only a verb that asks for work: one the reader has no rule for ("melt"), a verb that destroys
("shred"), or a verb of a service English knows and this facility does not run ("laminate my
stapler in the printer"); a verb of another of the office's machines is asked about as before
("print my file on the 3D printer": plot or 3D print?). A verb that moves or places a thing
("put my lunch in the microwave", "leave the form in the printer"), a vague or making verb
("sort my lunch in the microwave", "get me a coffee with the machine"), any other verb the
reader has a rule for, and slang verbs of putting ("chuck my drawings into the recycling
bin": english.yaml ``tossing_verbs``) are read as before; so is work on a person ("meet me in
the lounge"), and a facility that does no work ("hide his stapler in the fridge": declined as
the verb's own rule says)."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.english import DETERMINERS
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece, sub_pieces
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.screen.unknown_work import (
    ADDRESSED,
    ANY_MAKING,
    DATA_VERBS,
    MAKING,
    MOVING,
    VAGUE,
)
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Facility, Office
from assistantx.core.wording import things_worked_on, works_on

# The words that make a facility the instrument: "in the microwave", "with the printer"
_BY = frozenset({"in", "into", "inside", "with", "on", "using", "through", "via"})
_DESTROYING = frozenset(
    entry.split()[0] for entry in english.entries("destructive") if " " not in entry
)
_TOSSING = english.words("tossing_verbs")  # "chuck it in the bin": put there
_PEOPLE = frozenset({"me", "us", "him", "her", "them", "you", "everyone", "everybody"})
# "I", "we" before the verb: the speaker's own doing, nothing asked of me
_SPEAKER = frozenset({"i", "id", "im", "ive", "we", "me", "if", "mind"})


def wrong_instrument(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if not any(m.kind == "facility" for m in piece.lexed.mentions):
        return None
    for sub in sub_pieces(piece):
        words = sub.words
        at = sub.verb_at(terms.en.lead_in)
        if at >= len(words) or set(words[:at]) & _SPEAKER:
            continue
        if at and not ((piece.acts.request or piece.asks) and set(words[:at]) & ADDRESSED):
            continue  # asked at the head ("shred it in ..."), or put to me ("can you ...")
        verb = words[at]
        if not language.lemmas(verb).get("VERB"):
            continue
        if verb not in language.verb_lemmas(verb):
            continue  # "freezing in the meeting room": a state told, no verb asked (plain)
        forms = {verb, *language.verb_lemmas(verb)}
        if forms & (MOVING | VAGUE | MAKING | ANY_MAKING | _TOSSING):
            continue
        if at + 1 >= len(words) or words[at + 1] in _PEOPLE:
            continue  # "meet me in the lounge": whom, no thing worked on
        lexed = terms.lex.read(sub.text)
        found = _instrument(lexed.tokens, lexed.mentions, terms.office)
        if found is None:
            continue
        facility, prep_at = found
        if not facility.operations:
            continue  # "hide his stapler in the fridge": no work of its own to swap in
        if forms & _verbs_of(terms.office, facility):
            continue  # "laminate my badge in the laminator": its own work
        if not _asks_work(terms, forms):
            continue
        if not any(m.kind in ("item", "self") or m.start < prep_at for m in lexed.mentions):
            continue
        said = " ".join(t.text for t in lexed.tokens[at:prep_at])
        return Finding(
            "unsupported",
            piece,
            f"the {facility.name} asked for work it does not do: {verb}",
            message=(
                f"{does(terms.office, facility)}; I can't {said} in it, and I won't make "
                "or bring something else instead. I did nothing."
            ),
        )
    return None


def _instrument(
    tokens: Sequence[Token], mentions: Sequence[Mention], office: Office
) -> tuple[Facility, int] | None:
    """The facility said after "in", "with", "on", ... (determiners between), and where that
    word is."""
    for m in mentions:
        if m.kind != "facility":
            continue
        k = m.start - 1
        while k >= 0 and tokens[k].word in DETERMINERS:
            k -= 1
        if k > 0 and tokens[k].word in _BY:
            return office.facility(m.ids[0]), k
    return None


def _verbs_of(office: Office, facility: Facility) -> set[str]:
    """The words of the facility's services' verbs and names ("heat", "nuke", "print")."""
    out: set[str] = set()
    for op_id in facility.operations:
        op = office.operation(op_id)
        for phrase in (*op.verbs, op.name):
            out.update(language.fold(w) for w in language.words(phrase))
    return out


def _asks_work(terms: Terms, forms: set[str]) -> bool:
    """Whether the verb asks for work done to a thing: one the reader has no rule for, one
    that destroys, or a service's verb (the office's or English's)."""
    if forms & _DESTROYING:
        return True
    services = {
        language.fold(w)
        for op in terms.office.operations
        for v in op.verbs
        for w in language.words(v)[:1]
    }
    if forms & services:
        return False  # "print my file on the 3D printer": which machine is asked, as before
    if forms & terms.en.service_verbs:
        return True
    return not (forms & terms.lex.cue_words or forms & terms.office_words or forms & DATA_VERBS)


def does(office: Office, facility: Facility) -> str:
    """What the facility does, said: "The microwave can heat lunches" (also the office's
    machines listed where a test it lacks is asked for: ``unknown_test``)."""
    said = []
    for op_id in facility.operations:
        op = office.operation(op_id)
        what = op.name
        if op.input is not None:  # "laminate papers", "run an IR on samples"
            what = works_on(op, things_worked_on(office.item_type(op.input).name))
        said.append(what)
    return f"The {facility.name} can {' or '.join(said)}"
