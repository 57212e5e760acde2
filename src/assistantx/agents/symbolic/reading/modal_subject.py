"""A modal never takes a verb in -s: "May needs her tape back", "Will wants his calculator",
"Can says it's fine". English puts the bare verb after a modal ("may need", "will want"),
so a modal-looking word right before a verb's third-person form is not the modal but the
subject of that verb: a colleague whose name is also the word. The speech acts read such a
word as a plain third-person subject, so "May needs ..." is someone's need now, not the
speaker's possible need later ("may need ..."). A modal before a bare verb or a pronoun
("may I borrow a ruler", "will you bring me tape") stays a modal."""

from __future__ import annotations

from assistantx.core import english, language

# The true modal auxiliaries (english.yaml lists "need(s)" among them for the past-event
# screen; a plain verb in -s after "needs" is no sign of anything).
_MODALS = english.words("modal_auxiliaries") - {"need", "needs"}
# What the word is read as: a third-person subject, as "Pat" in "Pat needs her tape".
_SUBJECT = "she"


def is_subject_not_modal(word: str, following: str) -> bool:
    """Whether ``word``, a modal by its spelling, is the subject of ``following`` (a verb in
    -s, which no modal takes): a name that is also the modal word."""
    return word in _MODALS and language.is_third_person_verb(following)


def modals_as_subjects(words: list[str]) -> list[str]:
    """``words`` with each modal-looking word that stands before a verb in -s read as the
    third-person subject it is (the verb's form says so; the words are folded)."""
    out = list(words)
    for n in range(len(words) - 1):
        if is_subject_not_modal(words[n], words[n + 1]):
            out[n] = _SUBJECT
    return out
