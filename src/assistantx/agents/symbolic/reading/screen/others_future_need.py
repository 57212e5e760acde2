"""A colleague's need said in the future tense ("Mark's going to need the calculator after
lunch", "Zhang'll need the stapler tomorrow", "she is gonna need a ruler"): still that
colleague's need, said as a fact, so it is written as the present the reader knows ("Mark
needs the calculator after lunch"), restated and asked before anything moves ("Shall I bring a
calculator to Mark?"). Without this the "'s" of "Mark's going to" reads as Mark owning the
calculator, and the need as the speaker's own: Mark's calculator fetched for the speaker.

Only a subject that is one of the office's people (by a word of their name) or a third
person's pronoun is read so; "I'll need", "we're going to need" are the speaker's future need
(``reading.future_need``)."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core.task_schema import Evidence

_FUTURE = re.compile(
    r"\b(?P<subject>[^\W\d_]+)"
    r"(?:['’]s\s+(?:going\s+to|gonna)|\s+is\s+(?:going\s+to|gonna)"
    r"|['’]re\s+(?:going\s+to|gonna)|\s+are\s+(?:going\s+to|gonna)"
    r"|['’]ll|\s+will|\s+shall)"
    r"(?P<adverb>\s+(?:probably|definitely|also|likely|still))?"
    r"\s+need\b",
    re.IGNORECASE,
)
_SINGULAR = frozenset({"he", "she"})
_PLURAL = frozenset({"they"})


def others_future_need(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """``text`` with a colleague's future need written in the present ("X needs")."""
    found: list[Evidence] = []

    def present(match: re.Match[str]) -> str:
        subject = match.group("subject")
        key = subject.lower()
        if key in _PLURAL:
            verb = "need"
        elif key in _SINGULAR or key in terms.lex.name_words or key in terms.lex.people:
            verb = "needs"
        else:
            return match.group(0)  # "I'll need", "we're going to need", "it will need"
        said = f"{subject}{match.group('adverb') or ''} {verb}"
        found.append(Evidence(words=match.group(0), meaning=f"{said}: a need said for later"))
        return said

    return _FUTURE.sub(present, text), found
