"""The forms of an office's operation verb that can ask for its work, and where such a word is
a noun instead.

A simple past that is no participle ("ran" of "run", "wrote" of "write") only tells what
happened ("mine ran out in May"); the participle ("get it run off") and every other form can
ask for the work, so they stay the operation's cue words. The lemma is still the verb's, so
"Ida already ran it" is still read as done (``speech``'s had-already reads lemmas).

After a preposition and a determiner, at the end of its phrase, an operation's word names an
event ("before *the run*", "after *the print run*"): a noun, no request for the work."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office, Operation

_DETERMINERS = english.words("modifier_determiners")
_FUNCTION_WORDS = english.words("common")
# The words of the generic tasks (bring, send, take ...): a ``done:`` word of theirs ("sent
# with the courier") keeps its own reading.
_CUE_WORDS = frozenset(w for words in english.word_table("cues").values() for w in words)
_PREPOSITIONS = english.words("time_prepositions") | english.words("modifier_prepositions")
# What may end the phrase after the event's noun: a clause's join, or another preposition.
_PHRASE_ENDS = _PREPOSITIONS | english.words("clause_joins") | {"so", "then", "please"}


def asking_forms(verb: str) -> set[str]:
    """The forms of ``verb`` that can ask for its work: every form but a simple past that
    differs from the participle ("run": run, runs, running, not "ran")."""
    forms = set(language.verb_forms(verb))
    head = verb.lower().strip().partition(" ")[0]
    told = language.past_only_forms(head)
    return {f for f in forms if f.partition(" ")[0] not in told or f.partition(" ")[0] == head}


def done_forms(op: Operation, office: Office) -> set[str]:
    """The office's own word for what ``op`` did ("rewound", "restrung", "spooled" in its
    ``done:``), which names the work as its verbs' participle does ("get it restrung"): the
    ``done:`` field's first word where it is a form of one of the operation's verbs, a word
    the dictionary knows as no verb's form at all, or a participle of a verb that is no
    generic task's word and no other operation's (never "sent" of "sent with the courier",
    which keeps its own reading)."""
    if not op.done:
        return set()
    first = language.fold(op.done).split()[0].strip(".,;:!?")
    if not first.isalpha() or first in _FUNCTION_WORDS:
        return set()
    own = {f for verb in op.verbs for f in language.verb_forms(verb.split()[0])}
    lemmas = language.verb_lemmas(first)
    if first in own or not lemmas:
        return {first}
    others = {
        f
        for other in office.operations
        if other.id != op.id
        for verb in other.request_phrases
        for f in language.verb_forms(verb.split()[0])
    }
    if language.is_past_participle(first) and not lemmas & (_CUE_WORDS | others):
        return {first}
    return set()


def event_noun(tokens: Sequence[Token], i: int, verbs: frozenset[str]) -> bool:
    """Whether the operation word at ``i`` is part of a noun after a preposition and a
    determiner, at the end of its phrase: "before the run", "after the print run"."""
    start = i
    while start > 0 and not tokens[start].opens and tokens[start - 1].word in verbs:
        start -= 1
    end = i
    while end + 1 < len(tokens) and not tokens[end + 1].opens and tokens[end + 1].word in verbs:
        end += 1
    if start < 2 or tokens[start].opens or tokens[start - 1].opens:
        return False
    if tokens[start - 1].word not in _DETERMINERS or tokens[start - 2].word not in _PREPOSITIONS:
        return False
    nxt = end + 1
    return nxt >= len(tokens) or tokens[nxt].opens or tokens[nxt].word in _PHRASE_ENDS
