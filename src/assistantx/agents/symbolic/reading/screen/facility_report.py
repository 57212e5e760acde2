"""Facility report: "scanner's jammed btw", "the label printer's out of ribbon again, ugh": a
facility of the office said to be in some state, with no request wording and no question.
Answered in words; nothing moves, and the facility's name is never read as its operation's
verb ("scanner" is no "scan this").

A complaint of what it does is a report the same way: "the shredder's making a horrible
grinding noise again", "the kettle keeps tripping the fuse" (a participle after the facility,
or "keeps" and one). A participle that says it is only at its work ("the printer's warming
up", ``facility_at_work``) is told with nothing wrong; an errand's own verb with one of the
office's things after it ("the coffee machine is making my coffee") is read as before. A
fault is answered with what the assistant cannot do about it: it repairs nothing."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.elsewhere import state_said
from assistantx.agents.symbolic.reading.screen.english import starts_with
from assistantx.agents.symbolic.reading.screen.facility_place import (
    facility_after_place,
    failure_said,
)
from assistantx.agents.symbolic.reading.screen.felt_state import felt_state
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english, language

_FAULTS = tuple(tuple(p.split()) for p in english.entries("facility_faults"))
_WORKING = tuple(tuple(p.split()) for p in english.entries("facility_working"))
_AT_WORK = english.words("facility_at_work")
_KEEPS = tuple(
    sorted((tuple(p.split()) for p in english.entries("facility_keeps")), key=lambda p: -len(p))
)
_SAID_BACK = english.wording("said_back")
REPAIR = "I can't repair it myself, so please tell whoever looks after it."
# the context entry of a thing a facility is said to lack ("lacked:paper"): a later "some" or
# "one" stands for it, never "it" ("the printer's out of paper, can you fix it")
LACKED = "lacked:"


def facility_report(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.question is not None:
        return None
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    k = 0
    while k < len(mentions) and mentions[k].kind == "word":
        if tokens[mentions[k].start].word not in terms.en.fact_openers:
            break
        k += 1
    # "the kitchen coffee machine", "copy room printer": where it stands said before it
    k = facility_after_place(tokens, mentions, k)
    if k < len(mentions) and mentions[k].kind == "word":
        return None
    if k < len(mentions) and mentions[k].kind == "place" and len(mentions[k].ids) == 1:
        return _place_felt(terms, piece, mentions[k])  # "print room's boiling today"
    if k >= len(mentions) or mentions[k].kind != "facility" or len(mentions[k].ids) != 1:
        return None
    subject = mentions[k]
    rest = [t.word for t in tokens[subject.end :]]
    name = terms.office.facility(subject.ids[0]).name
    copula = next((c for c in terms.en.copulas if starts_with(rest, 0, c)), None)
    felt = felt_state(rest[len(copula) :] if copula else rest, terms.lex.cue_words)
    if (
        (copula or subject.possessive)
        and felt
        and "ADJ" in language.lemmas(felt[-1])
        and not any(f[:1] == (felt[-1],) for f in (*terms.en.conditions, *_FAULTS, *_WORKING))
    ):
        # "binding room's freezing again": how it feels, an adjective; no fault to repair
        return _report(piece, f"the {name} is {' '.join(felt)}", fault=False)
    keeps = next((p for p in _KEEPS if starts_with(rest, 0, p)), None)
    # "the kettle keeps tripping the fuse"
    if keeps is not None and _doing(terms, piece, rest[len(keeps) :], subject.end + len(keeps)):
        return _report(piece, f"the {name} {' '.join(state_said(rest))}", fault=True)
    failed = failure_said(rest)
    if failed:  # "the kettle has died again": a fault, said with "has"
        return _report(piece, f"the {name} has {' '.join(failed)}", fault=True)
    copula = next((c for c in terms.en.copulas if starts_with(rest, 0, c)), None)
    if copula is None and not subject.possessive:
        return None  # "the scanner jammed my strip": told as what it did, read elsewhere
    told = rest[len(copula) :] if copula else rest
    state = state_said(told)
    if told[:1] and told[0] in _AT_WORK:  # "the printer's warming up": told, nothing wrong
        return _report(piece, f"the {name} is {' '.join(state)}", fault=False)
    if _doing(terms, piece, told, subject.end + len(copula or ())):
        return _report(piece, f"the {name} is {' '.join(state)}", fault=True)  # "making a noise"
    if not any(starts_with(state, 0, f) for f in (*terms.en.conditions, *_FAULTS)):
        # "drying room's absolutely roasting again": how it feels, told; no service asked
        felt = felt_state(told, terms.lex.cue_words)
        if felt is None:
            return None
        return _report(piece, f"the {name} is {' '.join(felt)}", fault=False)
    working = any(starts_with(state, 0, f) for f in _WORKING)
    # "the printer's out of paper, anyone got some": the thing it lacks is what "some" is
    lacked = tuple(f"{LACKED}{item}" for item in terms.named(piece.lexed, "item"))
    return _report(piece, f"the {name} is {' '.join(state)}", fault=not working, context=lacked)


def _place_felt(terms: Terms, piece: Piece, subject: Mention) -> Finding | None:
    """ "print room's boiling today": how a place of the office feels, told."""
    rest = [t.word for t in piece.lexed.tokens[subject.end :]]
    copula = next((c for c in terms.en.copulas if starts_with(rest, 0, c)), None)
    if copula is None and not subject.possessive:
        return None
    # "kitchen's boiling today": a place is hot, or a machine there at its work; either
    # way told, no service asked (a request says it: "boil the kettle", "a brew please")
    office = terms.office
    felt = felt_state(rest[len(copula) :] if copula else rest, frozenset())
    if felt is None:
        return None
    name = office.location(subject.ids[0]).name.lower()
    return _report(piece, f"the {name} is {' '.join(felt)}", fault=False)


def _doing(terms: Terms, piece: Piece, state: list[str], at: int) -> bool:
    """Whether the state opens with a participle that tells what a facility does wrong
    ("making a horrible noise", "eating my paper"): not one of it only at its work
    ("warming up"), nor an errand's verb with a thing of the office after it ("making my
    coffee")."""
    if not state or not state[0].endswith("ing") or state[0] in _AT_WORK:
        return False
    if not language.is_present_participle(state[0]):
        return False
    if not language.verb_lemmas(state[0]) & terms.lex.cue_words:
        return True
    return not any(
        m.kind in ("item", "person", "facility") for m in piece.lexed.mentions if m.start > at
    )


def _report(piece: Piece, said: str, *, fault: bool, context: tuple[str, ...] = ()) -> Finding:
    """The report, answered in words; a fault with what the assistant cannot do about it
    (``context``: the things it names, which a later "some" may stand for)."""
    said = " ".join(_SAID_BACK.get(w, w) for w in said.split())
    message = f"Thanks for letting me know {said}."
    return Finding(
        "statement",
        piece,
        f"a report: {said}",
        message=f"{message} {REPAIR}" if fault else message,
        context=context,
    )
