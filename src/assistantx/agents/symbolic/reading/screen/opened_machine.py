"""A machine opened to take a thing out: "open the microwave and take my lunch out", "can you
open the kiln and get my pots out". Opening a machine asks for nothing it does: the request is
the taking out, read as "take my lunch out of the microwave" is (a fetch from where the thing
is). Before, the machine's name was read as its service, and the lunch was heated again before
it was handed over. Said while the machine is still at work, the rewritten request is declined
by ``running_machine`` as before; "open the door" or a machine opened for nothing taken out
reads as before."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core.task_schema import Evidence

_OPENED = re.compile(
    r"\b(?:open|unlock)\s+(?P<machine>(?:the\s+)?[^\W\d_]+(?:\s+[^\W\d_]+){0,2}?)\s+and\s+"
    r"(?P<verb>take|get|grab|pull|fetch|fish)\s+(?P<thing>[^,.;:!?]+?)\s+out\b",
    re.IGNORECASE,
)


def opened_to_take(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """``text`` with "open <machine> and take <thing> out" written "take <thing> out of
    <machine>" where the machine is one of the office's facilities."""
    found: list[Evidence] = []

    def taken(match: re.Match[str]) -> str:
        machine = match.group("machine")
        said = re.sub(r"^the\s+", "", machine, flags=re.IGNORECASE)
        # read with its article: "microwave" alone is also the verb of heating
        lexed = terms.lex.read(f"the {said}")
        named = [m for m in lexed.mentions if m.kind != "word"]
        if not (
            len(named) == 1 and named[0].kind == "facility" and named[0].end == len(lexed.tokens)
        ):
            return match.group(0)
        out = f"{match.group('verb')} {match.group('thing')} out of the {said}"
        found.append(Evidence(words=match.group(0), meaning=out))
        return out

    return _OPENED.sub(taken, text), found
