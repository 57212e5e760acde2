"""A machine's work said not done yet, then asked for by a pro-form with no machine named: "my
badge hasn't been laminated yet, can you get it done", "my form still isnt stamped, can you
sort that", "the banner hasnt been laminated, get it done pls".

The first clause's participle ("laminated") names the work: English says it once and refers
back to it with "get it done" / "sort it (out)" / "have that sorted", whose "it" is the thing
the clause named. Read alone, "get it done" names no work, and who should get the thing was
asked. The pro-form is said again as the verb of the one operation on a thing whose verb's
participle or ``done:`` word it is ("..., can you laminate it"), which the later stages read
as that service on the thing, handed back to the speaker.

Only a negated state or perfect passive ("hasn't been", "isn't", "still not"), a participle
of exactly one operation that works on a thing (two operations with that participle: left
as before, and asked), and a pro-form after it with no place after it ("get it done in the
badge office" is ``worked_room``'s, "take it to the laminator" carries). The first clause
alone stays a statement. Nothing here knows an office's words: they come from its file.
"""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.asking_forms import done_forms
from assistantx.core import language
from assistantx.core.office import Office

# "hasn't been laminated", "has not yet been stamped", "isnt stamped", "are not yet bound",
# "still not laminated"
_UNDONE = re.compile(
    r"\b(?:(?:has|have)(?:n['’]?t|\s+not)\s+(?:yet\s+)?(?:been|got|gotten)"
    r"|(?:is|are|was|were)(?:n['’]?t|\s+not)(?:\s+yet)?(?:\s+been)?"
    r"|still\s+not(?:\s+been)?)\s+(?P<work>[a-z]+)\b",
    re.IGNORECASE,
)
# "get it done", "have that sorted", "sort it", "sort that out", "sort out it"
_PRO_FORM = re.compile(
    r"\b(?:(?:get|have)\s+(?P<a>it|that|this|them)\s+(?:done|sorted)(?:\s+out)?"
    r"|sort\s+(?P<b>it|that|this|them)(?:\s+out)?|sort\s+out\s+(?P<c>it|that|this|them))\b"
    r"(?!\s+(?:in|at|to|into|with|by)\b)",
    re.IGNORECASE,
)
# a clause boundary between the statement and the ask
_BOUNDARY = re.compile(r"[,.;!?\n]|\b(?:so|and|but)\b", re.IGNORECASE)


class UndoneService:
    """The rewrite for one office: each participle of exactly one operation on a thing, with
    the verb that asks for it."""

    def __init__(self, office: Office) -> None:
        verbs: dict[str, dict[str, str]] = {}
        for op in office.operations:
            if op.input is None:
                continue
            said = next((v.lower() for v in op.request_phrases if " " not in v.strip()), None)
            if said is None:
                continue
            words = {
                f
                for v in op.request_phrases
                if " " not in v.strip()
                for f in language.verb_forms(v)
                if language.is_past_participle(f)
            } | done_forms(op, office)
            for w in words:
                verbs.setdefault(w, {}).setdefault(said, op.name)
        self._verbs = verbs

    def __call__(self, text: str) -> tuple[str, str | None]:
        """``text`` with the pro-form said as the work's verb, or as it is with which work is
        meant asked, where the participle is that of two operations' verbs."""
        for m in _UNDONE.finditer(text):
            verbs = self._verbs.get(m.group("work").lower())
            if not verbs:
                continue
            ask = _PRO_FORM.search(text, m.end())
            if ask is None or not _BOUNDARY.search(text, m.end(), ask.start()):
                continue
            if _UNDONE.search(text, m.end(), ask.start()):
                continue  # another state said nearer the ask is its work
            obj = ask.group("a") or ask.group("b") or ask.group("c")
            if len(verbs) > 1:
                names = sorted(set(verbs.values()))
                return text, f"Which should I do: {', '.join(names[:-1])} or {names[-1]}?"
            verb = next(iter(verbs))
            return f"{text[: ask.start()]}{verb} {obj}{text[ask.end() :]}", None
        return text, None
