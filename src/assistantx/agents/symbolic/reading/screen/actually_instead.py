"""A sentence that opens with "actually" and says a request of its own takes back the request
before it: "print the rota for me. actually, print it for Sam" asks for one printout, Sam's.
English uses "actually" there as it uses "no wait" or "sorry": the speaker changes their mind.
It is read as that correction (``correction``: the request broken off is withdrawn, and its
thing is kept where the new request says it by "it"), so whatever the reader makes of the
words later (an answer put in the place of "it") the withdrawn request never comes back.

An addition said so ("actually, print one for Sam too", "actually, also bring a pen") adds,
and "actually" after a comma or inside a sentence ("it's actually for Sam") is no correction:
both are left as said.
"""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.correction import opens_request
from assistantx.agents.symbolic.reading.screen.same_work_added import adds
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language
from assistantx.core.task_schema import Evidence

_ACTUALLY = re.compile(r"(?P<end>[.!?;])\s*actually\b[,:]?\s*", re.IGNORECASE)
_SENTENCE = re.compile(r"[.!?;\n]")
_CLAUSE = re.compile(r"[,.!?;\n]|\s[-–—]+\s")


def actually_instead(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """``text`` with a sentence-opening "actually" before a request of its own said as the
    correction "no wait" (the evidence says so); unchanged where there is none."""
    for found in _ACTUALLY.finditer(text):
        if not text[: found.start()].strip():
            continue  # nothing before it to take back
        rest = text[found.end() :]
        sentence = _SENTENCE.split(rest, maxsplit=1)[0]
        if adds(language.words(sentence)):
            continue
        clause = _CLAUSE.split(rest, maxsplit=1)[0]
        if not opens_request(terms, terms.lex.tokens(clause)):
            continue
        said = text[found.start("end") + 1 : found.end()].strip()
        fixed = f"{text[: found.end('end')]} no wait, {rest}"
        meaning = f"{said!r} before a request of its own: takes back the request before it"
        return fixed, [Evidence(words=text[found.start() :].strip()[:200], meaning=meaning)]
    return text, []
