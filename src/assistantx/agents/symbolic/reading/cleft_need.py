"""The speaker's need said as a cleft: "it's a stapler I need", "it's the big scissors I'm
after", "what I need is a stapler" said as "I need a stapler", read as any need of theirs (a
request for them, also as the part after a withdrawal: "a pen - no wait I've got one, it's a
stapler I need": before, the cleft was read as a statement and nothing was asked).

The thing is one to four words between "it's" and the speaker ("I", "we"); the want after the
speaker is a word or phrase of ``cleft_wants``; a negated thing ("it's not a pen I need")
and an errand for someone ("it's Zhang I need to see") keep their readings.
"""

from __future__ import annotations

import re

from assistantx.core import english


def _any_of(key: str) -> str:
    phrases = sorted(english.entries(key), key=len, reverse=True)
    return "|".join(r"\s+".join(re.escape(w) for w in p.split()) for p in phrases)


# "I need", "I'm after", "im after", "we are looking for": the speaker, a "be" said with it
# or not, and the want
_SPEAKER_WANTS = (
    r"(?P<subject>i|we)(?:(?:\s*['’]\s*|\s+|)(?:m|am|re|are))?\s+"
    rf"(?:really\s+|actually\s+)?(?:{_any_of('cleft_wants')})"
)
# not before "to" (an errand: "it's Zhang I need to see") nor another word of the want
_WANT_ENDS = r"(?!\s+to\b)(?=\s|$|[,.;:!?\-–—)])"
_THING = r"(?P<thing>[^\W\d_]+(?:[\s-]+[^\W\d_]+){0,3}?)"
_IT_IS = re.compile(
    rf"\b(?:it\s*['’]?\s*s|it\s+is)\s+{_THING}\s+(?:that\s+|which\s+)?{_SPEAKER_WANTS}{_WANT_ENDS}",
    re.IGNORECASE,
)
_WHAT_IS = re.compile(
    rf"\bwhat\s+{_SPEAKER_WANTS}\s+(?:is|are)\s+(?!to\b|for\b)(?=[^\W\d_])",
    re.IGNORECASE,
)
_NEGATIONS = frozenset({"not", "no", "never", "nothing", "isn", "isnt"})


def _need(m: re.Match[str]) -> str:
    thing = m.group("thing")
    if set(thing.lower().split()) & _NEGATIONS:
        return m.group(0)
    return f"{m.group('subject')} need {thing}"


def cleft_needs(text: str) -> str:
    """``text`` with each cleft of the speaker's need said as "I need <thing>"."""
    text = _IT_IS.sub(_need, text)
    return _WHAT_IS.sub(lambda m: f"{m.group('subject')} need ", text)
