"""The same work asked again for another, said as an addition: "print the rota for me. also
print it for Sam", "..., and print it for Sam too", "... print it for Sam as well". The
second request's "it" is the first request's thing, and "also"/"too"/"as well" say that the
work is done once more, not instead: the thing is written in the place of "it" ("also print
the rota for Sam"), so the reader makes two tasks, one for each, as it does when the thing is
said twice. Read as the one request said again, the later "for Sam" would take the requester's
printout away from them.

Only where the request before names one thing the office knows (``correction.thing_kept``,
the rule that keeps a withdrawn request's thing for "no wait, print it for Sam"), and the
added request opens with a request verb of its own and names no thing itself.
"""

from __future__ import annotations

import re
from itertools import pairwise

from assistantx.agents.symbolic.reading.screen.correction import opens_request, thing_kept
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language
from assistantx.core.task_schema import Evidence

# Where an added request starts: a sentence of its own, or "and" after a comma.
_STARTS = re.compile(r"[.!?;]\s*|,\s*(?:and\s+)?|\s+and\s+(?=also\b)", re.IGNORECASE)
_SENTENCE = re.compile(r"[.!?;\n]")
_CLAUSE = re.compile(r"[,.!?;\n]|\s[-–—]+\s")
# The words before an added request's verb: "also", "and also", "actually", "please"
_OPENING = re.compile(r"^(?:(?:and|then|also|actually|please|pls|plz|can you|could you)\b[,]?\s*)+")
# The words that make a request said after another one more of the same, not instead of it
_ADDING = frozenset({"also", "too", "again", "another", "aswell"})
_AS_WELL = ("as", "well")


def adds(words: list[str]) -> bool:
    """Whether a sentence's words say it adds to the request before ("also", "too", "as
    well", "again", "another")."""
    return bool(_ADDING & set(words)) or any(pair == _AS_WELL for pair in pairwise(words))


def same_work_added(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """``text`` with the first request's thing in the place of an added request's "it"
    (the evidence says so); unchanged where there is no such added request."""
    for found in _STARTS.finditer(text):
        before = text[: found.start()]
        if not before.strip():
            continue
        rest = text[found.end() :]
        sentence = _SENTENCE.split(rest, maxsplit=1)[0]
        if not adds(language.words(sentence)):
            continue
        lead = _OPENING.match(rest.lower())
        skip = lead.end() if lead else 0
        clause = _CLAUSE.split(rest[skip:], maxsplit=1)[0]
        tokens = terms.lex.tokens(clause)
        if not opens_request(terms, tokens):
            continue
        earlier = _SENTENCE.split(before)[-1] or before
        kept = thing_kept(terms, earlier, tokens, rest[skip:])
        if kept == rest[skip:]:
            continue  # names a thing of its own, or the request before names no one thing
        fixed = text[: found.end()] + rest[:skip] + kept
        meaning = "the same work once more, on the thing of the request before"
        return fixed, [Evidence(words=sentence.strip()[:200], meaning=meaning)]
    return text, []
