"""Anyone's: a colleague's item asked for with no owner named ("my stapler is broken, can
someone lend me theirs?", "does anyone have a spare I could borrow?").

"theirs" after "someone"/"anyone" is no person's own item but one of whoever has one, and "a
spare" with no noun after it is one of the thing the message is about. Both are rewritten to
"one", which the rewrites after this one read as the item the requester stated (their broken
stapler: another stapler, anyone's), so the planner asks the owners in turn, each for their
own yes, or takes the office's ownerless one; with no item stated it is still asked about.
Only an indefinite asker makes "theirs" anyone's: "Hal has one, could he lend me his" is
Hal's, read elsewhere.
"""

from __future__ import annotations

import re

from assistantx.core.task_schema import Evidence

# Whom a request for anyone's item is put to: "can someone ...", "does anybody ...".
_INDEFINITE = re.compile(
    r"\b(?:some|any|every)(?:one|body)\b|\b(?:any|one|either) of (?:you|them|us)\b", re.IGNORECASE
)
# "theirs", "yours", "one of theirs": the indefinite asker's own item, i.e. anyone's
_THEIRS = re.compile(r"\b(?:one of )?(?:theirs|yours)\b", re.IGNORECASE)
# "a spare" with no noun after it: before a pronoun, a preposition, a clause end
_SPARE = re.compile(
    r"\ba spare\b(?=\s*(?:[,.!?;]|$|\s+(?:i|we|for|to|please|that|which|you|me|if|by)\b))",
    re.IGNORECASE,
)


def anyones(text: str) -> tuple[str, list[Evidence]]:
    """``text`` with anyone's item said as "one", and what was read so."""
    evidence: list[Evidence] = []

    def one(match: re.Match[str]) -> str:
        evidence.append(Evidence(words=match.group(0), meaning="one of anyone's"))
        return "one"

    asker = _INDEFINITE.search(text)
    if asker is not None:
        head, tail = text[: asker.end()], text[asker.end() :]
        text = head + _THEIRS.sub(one, tail)
    text = _SPARE.sub(one, text)
    return text, evidence
