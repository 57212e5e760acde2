"""When, said in an idiom of time rather than a time ("when you get a sec", "when you've a
minute", "in a tick", "whenever"): set aside before the pieces are judged, so its noun is never
read as a thing asked for ("there is no sec in this office") and what is left is read alone
("can u bring it down to me" still asks which item "it" is). An idiom whose noun goes on into
a phrase ("in a second envelope") or is the office's own item is left as said."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core.task_schema import Evidence

# The nouns of a short while: "a sec", "a mo", "a tick", "a spare minute".
_WHILE = (
    r"(?:spare\s+|free\s+|quick\s+|few\s+)?"
    r"(?:secs?|seconds?|mins?|minutes?|mo|moments?|tick|jiffy|chance|bit|while|tic)"
)
_YOU = r"(?:you|u|ya|yo)"
_HAVE = r"(?:'ve\s+got|'ve|\s+have\s+got|\s+have|\s+get|\s+got|\s+find|\s+are\s+free|'re\s+free)"
# "when you get a sec", "whenever you've a minute", "in a tick", "whenever (you can)": each
# must end its clause (a stop, a comma, a join or a courtesy, or the end of the message).
_END = r"(?=\s*(?:$|[.,;:!?)…-]|(?:and|then|please|pls|plz|thanks|thank|thx|ta|cheers|x)\b))"
_IDIOM = re.compile(
    r"(?:,\s*)?\b(?:"
    rf"when(?:ever)?\s+{_YOU}{_HAVE}\s+(?:a|the)\s+{_WHILE}"
    rf"|in\s+a\s+{_WHILE}"
    rf"|whenever(?:\s+{_YOU}\s+can|\s+{_YOU}(?:'re|\s+are)\s+free)?"
    rf"){_END}",
    re.IGNORECASE,
)


def without_time_idioms(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """``text`` without its idioms of time, each kept as evidence of how it was read."""
    found: list[Evidence] = []

    def drop(match: re.Match[str]) -> str:
        said = re.findall(r"[a-z]+", match.group(0).lower())
        if said[-1] in terms.lex.items:
            return match.group(0)  # the office's own thing, not a while
        found.append(Evidence(words=match.group(0).strip(" ,"), meaning="when: soon, no time"))
        return ""

    left = _IDIOM.sub(drop, text)
    return (re.sub(r"\s{2,}", " ", left).strip(), found) if found else (text, [])
