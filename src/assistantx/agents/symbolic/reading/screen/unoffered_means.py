"""A means of sending out that the office does not have: "can my contract go out with the
courier to Leeds?" where only a franking machine posts, "could my letter go out with the
post to Hull?" where only a courier desk sends.

The requester chose the means; another service sends by another way (another price, another
day, another carrier), so it is never used in its place unasked. Said as the means of a
sending verb ("send it *by* courier", "go out *with* the post"), a word of English that names
a way of sending (``english.yaml``: ``send_out_means``) and that names none of the office's
send-out services (their ids, verbs, names and the names of the facilities that run them) is
said not to be here, and what the office has is offered: "There's no courier here. Shall I
frank it instead?", a yes reading the request with the facility said as its means
(``screen.facility_means``). A means the office has is left to the reader as before."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.destination import means_words
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english, language
from assistantx.core.office import Office, Operation

# The words of English that name a way of sending a thing out of the office.
_MEANS = english.words("send_out_means")
# A sending, putting or going verb, its thing, then the means ("send my form by courier",
# "can my contract go out with the courier"); what comes after the means is kept.
_VERB = r"\b(?:send|sends|sent|put|pop|get|go|goes|going|went)\b"
_BY = r"(?P<by>via|with|by|through|in|using)"
_SAID = re.compile(
    rf"{_VERB}[^.!?;]*?\s{_BY}\s+(?P<the>(?:the|a)\s+)?(?P<means>[a-z]+)\b(?P<next>\s+[a-z]+)?",
    re.IGNORECASE,
)

# A clause of how a thing came ("the letter that *came* in the post"): the means it arrived
# by, no means asked for.
_ARRIVED = re.compile(r"\b(?:that|which|came|come|arrived|arrives|delivered)\b", re.IGNORECASE)


def unoffered_means(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    office = terms.office
    sending = [op for op in office.operations if op.sends_out and office.runnable(op.id)]
    if not sending:
        return None  # nothing sends out here: the reader says what it can do, as before
    for found in _SAID.finditer(piece.text):
        if _ARRIVED.search(found.group(0)):
            continue  # "get me the letter that came in the post": how it came, no sending
        means = found.group("means").lower()
        if means not in _MEANS or _names_a_service(office, means):
            continue
        after = (found.group("next") or "").strip().lower()
        if after and language.is_noun(after) and after not in ("today", "tomorrow"):
            continue  # "with the post room key": a word of another noun's name
        return _offered(office, piece, found, means, sending)
    return None


def _offered(
    office: Office, piece: Piece, found: re.Match[str], means: str, sending: list[Operation]
) -> Finding:
    """The finding: the means is not here; the office's one way offered, or its ways asked."""
    said = f"There's no {means} here, so I can't send it that way."
    if len(sending) > 1:
        verbs = [_verb(op) for op in sending]
        ways = f"{', '.join(verbs[:-1])} or {verbs[-1]}"
        return Finding(
            "unplaced",
            piece,
            f"no {means} here",
            message=f"{said} I can {ways} it: which should I do?",
        )
    op = sending[0]
    verb = _verb(op)
    facility = _its_facility(office, op)
    offer = ""
    if facility is not None:  # "... with the franking machine to Leeds": its own means
        start, end = found.start("by"), found.end("means")
        offer = f"{piece.text[:start]}{found.group('by')} the {facility}{piece.text[end:]}"
    return Finding(
        "instead",
        piece,
        f"no {means} here; {op.name} offered",
        message=f"{said} Shall I {verb} it instead?",
        offer=offer,
    )


def _names_a_service(office: Office, word: str) -> bool:
    """Whether ``word`` is a word of a send-out service of the office: its id, a verb, its
    name or the means it says, or a name of a facility that runs it."""
    for op in office.operations:
        if not op.sends_out:
            continue
        names = [op.id, op.name, *op.verbs, *means_words(op.name)]
        for facility in office.facilities:
            if op.id in facility.operations:
                names += [facility.id, facility.name, *facility.synonyms]
        said = {w for name in names for w in language.fold(name).replace("_", " ").split()}
        if word in said or any(word in language.verb_forms(w) for w in said if w.isalpha()):
            return True
    return False


def _its_facility(office: Office, op: Operation) -> str | None:
    """The name of the one facility that runs ``op`` and nothing else, if there is one."""
    runs = [f for f in office.facilities if tuple(f.operations) == (op.id,)]
    return runs[0].name if len(runs) == 1 else None


def _verb(op: Operation) -> str:
    """The service's verb to offer it by: the means its name says ("send by courier":
    "courier") before its first verb ("dispatch"), as the requester would say it."""
    means = means_words(op.name)
    return means[0] if means else (op.verbs[0] if op.verbs else op.name)
