"""An obligation before a verb: "Zhang *has to* sign", "Hal *must* seal", "Ida *needs to*
countersign". The person before it is the one who does the work the verb names, whatever
the phrase ("has to", "must", "ought to" ...): the phrases are general English
(``english.yaml``: ``obligations``), the work words are the task kinds a person does."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core import english, language, task_kinds

# The words of the work only a person does (sign, seal ...), by the task kinds' cues.
PERSON_WORK = frozenset(w for k in task_kinds.person_kinds() for w in english.word_table("cues")[k])

_OBLIGATIONS = tuple(
    sorted(
        {tuple(language.words(p)) for p in english.entries_of()["obligations"]},
        key=lambda p: -len(p),
    )
)


def obliged_verb(words: Sequence[str], at: int) -> int | None:
    """Where the verb after an obligation phrase starting at ``at`` is ("has to *sign*"),
    or None when no obligation phrase starts there."""
    for phrase in _OBLIGATIONS:
        if tuple(words[at : at + len(phrase)]) == phrase and at + len(phrase) < len(words):
            return at + len(phrase)
    return None


def obliged_to(words: Sequence[str], at: int, work: frozenset[str]) -> bool:
    """Whether ``words`` from ``at`` say an obligation to do one of ``work`` ("must sign")."""
    verb = obliged_verb(words, at)
    return verb is not None and words[verb] in work
