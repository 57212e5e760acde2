"""A need said for a time after now: "I'll need scissors tomorrow", "gonna need a ruler",
"we're going to need the calculator", "need a ruler for the workshop later", "... at 3".

English puts a need off in two ways: by the tense of its verb (a future form before it) or by
a time after now said in the need's own clause. Either way the speaker has not asked for the
thing now, and only a request moves the robot: the need is answered (``screen.condition``),
never fetched at once. "now" or "asap" in the same words make it a need of now all the same
("I'll need it now for the meeting later"); a time said after the need's clause has ended
belongs to another clause ("I need a ruler and I'll give it back later").

The words are English's, from ``data/english.yaml``; nothing here knows an office.
"""

from __future__ import annotations

import itertools

from assistantx.core import english, language

_FUTURE_FORMS = tuple(tuple(p.split()) for p in english.entries("future_forms"))
_NOW = tuple(tuple(p.split()) for p in english.entries("now_words"))
# the times after now ("tonight", "later on"), the longest said first
_LATER = sorted((tuple(p.split()) for p in english.entries("later_times")), key=len, reverse=True)
_JOINERS = english.words("clause_joiners")
_CLOCK = english.words("clock_words")
_SPAN_WORDS = english.words("span_words")
_SPAN_FILLERS = english.words("span_fillers")
# what opens an event's noun phrase after "for" ("for a consult at 3", "for my 2 o'clock")
_EVENT_OPENERS = [["a"], ["an"], ["the"], ["my"], ["our"], ["his"], ["her"], ["their"], ["this"]]
# The speaker as a future's subject ("I'll", "we're", "I am"), and an adverb between
# the future form and the verb ("I'll probably need ...").
_SPEAKER = frozenset({"i", "we", "ill", "well", "im", "were", "am", "are"}) | english.words(
    "possibility_words"
)
_FUTURE_WORDS = english.words("future_forms") | frozenset({"also", "definitely", "still"})


def _purpose_opens(words: list[str], n: int) -> bool:
    """ "for" at ``n`` opens what the thing is for: an event ("for the review at 2") or a
    doing ("for wrapping presents tonight", "for parking at the docks tomorrow"). A time
    said inside it is the purpose's: the thing is had before then, so it is wanted now."""
    if words[n] != "for" or n + 1 >= len(words):
        return False
    after = words[n + 1]
    if [after] in _EVENT_OPENERS:
        return True
    # a verb's -ing form right after "for" is a doing, never a time ("for tonight" is kept
    # apart by the caller; no time word is a verb's -ing form)
    if after.endswith("ing") and language.is_present_participle(after):
        return True
    # a bare noun with a time after it ("for fieldwork tomorrow", "for class on Friday"):
    # an occasion and its time, never a span ("for an hour") nor a time itself
    return _bare_occasion(words, n + 1)


def _bare_occasion(words: list[str], at: int) -> bool:
    """Whether ``words[at]`` is a noun, no time or span word, right before a later time."""
    noun = words[at]
    if noun in _SPAN_WORDS or any(p[0] == noun for p in _LATER) or not language.is_noun(noun):
        return False
    rest = words[at + 1 :]
    if rest[:1] == ["on"] and rest[1:2] and language.is_weekday(rest[1]):
        return True
    return any(tuple(rest[: len(p)]) == p for p in _LATER)


def _has(words: list[str], phrases: tuple[tuple[str, ...], ...]) -> bool:
    return any(tuple(words[n : n + len(p)]) == p for n in range(len(words)) for p in phrases)


def future_form(before: list[str]) -> bool:
    """The words before a need verb put it in the future: "I'll", "we're going to", "gonna"
    (the future form is the last thing before the verb, an adverb aside: "I'll probably")."""
    return _has(before[-3:], _FUTURE_FORMS)


def speakers_future(before: list[str]) -> bool:
    """The words before a need verb are the speaker's future: a future form, with the
    speaker or nobody as its subject ("I'll", "we're going to", "gonna", "I will probably");
    "Mark will need ..." is Mark's need, read as a third person's."""
    if not future_form(before):
        return False
    return all(w in _SPEAKER or w in _FUTURE_WORDS for w in before)


def said_now(words: list[str]) -> bool:
    """ "... now", "... asap": the time is now, whatever else is said."""
    return _has(words, _NOW)


def clock_time(words: list[str]) -> bool:
    """ "at 3", "at 3pm", "at noon", "at half two": a time of day, said after "at"."""
    return any(a == "at" and (b[:1].isdigit() or b in _CLOCK) for a, b in itertools.pairwise(words))


def without_events(words: list[str]) -> list[str]:
    """``words`` without each event a thing is said to be for ("for the review at 2", "for my
    3pm call", up to the next clause's joiner): the event's time says by when the thing is
    needed, so it is needed now, never that it can wait. A span ("for the afternoon", "for an
    hour") is how long the thing is had, not an event: it and its time are kept. A time said
    right after "for" ("a stapler I can borrow for tonight", "for later") is the time it is
    used, as an event's is: had by then, so now; said without "for" ("bring me one tonight")
    it is when the thing is wanted, and kept. A doing said after "for" ("for wrapping
    presents tonight") is a purpose as an event is, and goes with its time."""
    out: list[str] = []
    n = 0
    while n < len(words):
        if words[n] == "for":
            use = next((p for p in _LATER if tuple(words[n + 1 : n + 1 + len(p)]) == p), None)
            if use is not None:
                n += 1 + len(use)
                continue
        if _purpose_opens(words, n) and not _span(words[n + 1 :]):
            n = next((k for k in range(n + 2, len(words)) if words[k] in _JOINERS), len(words))
            continue
        out.append(words[n])
        n += 1
    return out


def _span(words: list[str]) -> bool:
    """ "the afternoon", "a few hours", "an hour": a while, said after "for"."""
    head = next((w for w in words if w not in _SPAN_FILLERS), None)
    return head in _SPAN_WORDS


def need_clause(words: list[str], at: int) -> list[str]:
    """The words of the need's own clause from its verb at ``at``: up to the first word that
    joins another clause ("... and I'll give it back later"), or to a purpose's event ("for
    a consult at 3", "for the meeting at 2": the time is the event's, which the thing is
    needed before, not when it may come)."""
    end = next(
        (n for n in range(at + 1, len(words)) if words[n] in _JOINERS or _purpose_opens(words, n)),
        len(words),
    )
    return words[at:end]
