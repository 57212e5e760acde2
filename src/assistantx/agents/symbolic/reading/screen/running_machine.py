"""A machine said to be at work while it is asked to be opened or emptied: "open the kiln now
and get my pots out, I know it's still at 900 but I can't wait", "pull my pages out of the
printer now, I know it's mid-job", "get my mug out of the coffee machine while it's still
brewing". Opening a kiln, an oven or a press mid-cycle can burn or hurt whoever is near and
spoils the work; the speaker says so themself. Declined in words, nothing taken out and the
machine's own service never run (fixer fix60g class 1: the kiln's firing was run on the pot).

The message names one of the office's facilities, a word of opening it or taking a thing out
(english.yaml ``opening_out``), and the machine still at work: "still" before a state of
``running_states`` or a reading ("still at 900"), or "mid-" a run ("mid-job", "mid-cycle").
Said without that state ("get my lunch out of the microwave"), or waiting for the machine to
finish ("take my pages out when it's done"), it reads as before."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_STATES = sorted(english.entries("running_states"), key=len, reverse=True)
_OPENING = english.words("opening_out")
_AT_WORK = re.compile(
    r"\bstill\s+(?:(?:" + "|".join(re.escape(s).replace(r"\ ", r"[\s-]+") for s in _STATES) + r")\b"
    r"|at\s+\d)"
    r"|\b(?:it'?s|it\s+is|is|while)\s+(?:still\s+)?mid[\s-]+\w+",
    re.IGNORECASE,
)

# "when it's done", "once it has finished": the speaker waits for it
_WAITED = re.compile(
    r"\b(?:when|once|after|till|until)\s+(?:[\w'’]+\s+){0,3}?(?:"
    + "|".join(re.escape(s) for s in english.entries("finished_states"))
    + r")\b",
    re.IGNORECASE,
)


def running_machine(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    facilities = [m for m in piece.lexed.mentions if m.kind == "facility"]
    if not facilities or not _AT_WORK.search(msg.text.replace("’", "'")):
        return None
    if _WAITED.search(msg.text) or not {t.word for t in msg.lexed.tokens} & _OPENING:
        return None
    name = terms.office.facility(facilities[0].ids[0]).name
    return Finding(
        "destructive",
        piece,
        f"a running machine asked to be opened: the {name}",
        message=(
            f"Sorry, I won't open the {name} or take anything out of it while it is still at "
            "work: that could burn or hurt someone and spoil what is inside. Once it has "
            "finished I can take it out for you."
        ),
    )
