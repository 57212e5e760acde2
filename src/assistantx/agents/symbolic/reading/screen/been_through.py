"""Where someone has been, told beside a request to deliver to them, is no absence.

"Zhang's been out in the rain all morning, bring him a coffee", "Grace has been out on site
all day, take her a ruler when she's back": a state said in the perfect or the past tells
what the person went through up to now, and the same message asking to deliver to them says
the speaker expects them to receive it. Such a statement is not a present absence: the hint
that they are away is dropped, and whether they can receive is found by asking, as for anyone.

A state said in the present stays an absence ("Dara is away, take her some batteries",
"Zhang is out today, so take it to Wang instead"), and so does a past one about someone the
message does not deliver to ("Mark's been off sick all week, give the ruler to Grace").
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core import english, language
from assistantx.core.task_schema import Evidence, Hint, Task

_COPULAS = tuple(
    sorted((tuple(p.split()) for p in english.entries("copulas")), key=lambda p: -len(p))
)
_PAST = tuple(
    sorted((tuple(p.split()) for p in english.entries("past_copulas")), key=lambda p: -len(p))
)


def _said_in_the_past(said: str) -> bool:
    """Whether the first copula of a stated fact is a past or perfect one ("has been",
    "was"); the present ("is", "'s") or none at all is not."""
    words = language.words(said)
    for n in range(len(words)):
        if any(words[n : n + len(p)] == list(p) for p in _PAST):
            return True
        if any(words[n : n + len(p)] == list(p) for p in _COPULAS):
            return False
    return False


def _went_through(hint: Hint, recipients: set[str]) -> bool:
    """Whether a hint of absence is only where its person has been: said in the past or
    perfect, of someone the message delivers to."""
    return (
        hint.kind == "availability"
        and hint.value == "away"
        and hint.person in recipients
        and _said_in_the_past(hint.said)
    )


def present_hints(hints: Sequence[Hint], tasks: Sequence[Task]) -> list[Hint]:
    """The hints that still hold at the time of speaking, given what the message asks."""
    recipients = {t.recipient for t in tasks}
    return [h for h in hints if not _went_through(h, recipients)]


def reworded_evidence(
    evidence: Sequence[Evidence], hints: Sequence[Hint], kept: Sequence[Hint]
) -> list[Evidence]:
    """The evidence with each dropped absence said for what it was read as: where the
    person has been, so the reading a user sees matches the plan."""
    dropped = {h.said for h in hints if h not in kept}
    return [
        Evidence(
            words=e.words,
            meaning="where they have been, not an absence: "
            "they are delivered to in the same message",
        )
        if e.words in dropped and e.meaning.startswith("a fact:")
        else e
        for e in evidence
    ]
