"""A noun compound with a time, said after a request: "can u bring them over, ground run in
10", "..., print deadline at 5", "..., copy run at 3pm". The fragment names an event (the
ground run, the print deadline) and when it is: why and by when the request before it is
wanted, not a service asked for, even where a word of it is a service's verb ("run",
"print") or a modifier glued to one would make another service ("ground run"). It is
context, and the request before it is done.

Only a bare compound counts: two or three words the dictionary knows as nouns (an office's
own words too), the last a noun, then "in"/"at"/"by" and a time and nothing else. "print my
file in 10 minutes" (a determiner, an object), "run it at 3" (a pronoun) and a fragment with
nobody's request before it are read as before."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import DETERMINERS
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english, language

_TIME_PREPOSITIONS = frozenset({"in", "at", "by"})
# the words a time after those says ("in 10", "at 3pm", "at half two", "in a few mins")
_COUNTS = english.words("clock_words") | english.words("number_words")
_TIME_WORDS = (
    _COUNTS
    | english.words("span_words")
    | frozenset({"a", "an", "past", "to", "min", "mins", "m", "h", "pm", "am", "oclock", "ish"})
    | frozenset({"sharp", "today", "tomorrow", "tonight", "or", "so"})
)
# who is asked or spoken to never opens an event's name ("you in 10?")
_NOT_IN_A_NAME = english.words("request_askees") | english.words("subject_pronouns")
_SHORTEST, _LONGEST = 2, 3  # "ground run", "end of day run" is a phrase, not a compound


def timed_event(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """The fragment said as context, where it is a bare noun compound and a time after a
    request in a piece before it; None otherwise."""
    if piece.asks or not any(p.acts.request for p in msg.pieces if p.end <= piece.start):
        return None
    if any(m.kind not in ("word", "cue", "item") or m.possessive for m in piece.lexed.mentions):
        return None  # a colleague, "my", "it", a place: more than an event's name
    words = [t.word for t in piece.lexed.tokens]
    at = next((n for n, w in enumerate(words) if w in _TIME_PREPOSITIONS), None)
    if at is None or not _SHORTEST <= at <= _LONGEST or not _a_time(words[at + 1 :]):
        return None
    compound = words[:at]
    if not all(_in_a_name(terms, w) for w in compound) or not language.is_noun(compound[-1]):
        return None
    return Finding("statement", piece, "an event and its time beside the request, context only")


def _in_a_name(terms: Terms, word: str) -> bool:
    """Whether ``word`` can be a word of an event's noun compound: a noun, or one of the
    office's words; never a determiner, a pronoun or who is asked."""
    if word in DETERMINERS or word in _NOT_IN_A_NAME or word in terms.en.courtesy:
        return False
    return word.isalpha() and (language.is_noun(word) or word in terms.office_words)


def _a_time(words: list[str]) -> bool:
    """Whether ``words`` are a time and nothing else: a number or a clock word at least,
    with its unit ("10", "3pm", "half two", "5 mins", "a minute")."""
    if not words or not all(w in _TIME_WORDS or w[:1].isdigit() for w in words):
        return False
    return any(w[:1].isdigit() or w in _COUNTS or w in english.words("span_words") for w in words)
