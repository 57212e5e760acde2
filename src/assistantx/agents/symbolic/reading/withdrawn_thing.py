"""A withdrawal that names one of the things a request lists withdraws that thing only: "bring
me a stapler and a pen. actually forget the stapler" still brings the pen (before, the whole
request was dropped, "OK, I've dropped that request"). The request is read without the thing
and its "and", and the withdrawal with it (and the reason told after it in its sentence,
"..., I found one"): "bring me a pen."

Only a withdrawal after the request (a pause or a stop between), whose words after its head
("forget", "scratch", "never mind", ...) name one item of the office, and only where the
request names that item in a list of things joined by "and" or a comma beside another thing
of the office ("a stapler and a pen", "a pen, a ruler and a stapler"). A withdrawal naming
nothing ("actually forget it", "never mind") or the request's one thing ("bring me a stapler.
forget the stapler") withdraws the whole request, as before."""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

from assistantx.agents.symbolic.reading.lexicon import Lexicon, Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

# the words that open a withdrawal with an object ("forget", "never mind", "scratch")
_HEADS = tuple(
    sorted(
        {
            tuple(p.split())
            for p in (
                *english.entries("withdraw_heads"),
                *english.entries("correction_withdrawals"),
            )
        },
        key=len,
        reverse=True,
    )
)
# what may be said before the head ("actually", "oh wait", "sorry") or after it, before the
# thing ("the", "that")
_LEAD = frozenset(
    {"actually", "oh", "ok", "okay", "sorry", "no", "wait", "hmm", "um", "and", "but", "so"}
) | english.words("correction_interjections")
_ARTICLES = english.words("modifier_determiners") | {"about", "on", "with", "for", "any", "some"}
# what may stand between the listed things: "a stapler *and* a pen", "a pen*,* a ruler"
_JOIN = re.compile(r"^\s*(?:,\s*(?:and\s+)?|and\s+)$", re.IGNORECASE)
# a withdrawal's clause: after a pause or a stop, up to the next one or the end
_CLAUSE = re.compile(r"(?:[,;.!?…]+|\s[-–—]+)\s*(?P<said>[^,;.!?…\-–—]+?)\s*(?=[,;.!?…]|\s[-–—]|$)")
_MOST_THING_WORDS = 4
# the words that open a listed thing's phrase ("*a* pen", "*the* stapler")
_OPENERS = english.words("modifier_determiners") | {"some", "any", "one"}


def withdrawn_thing(text: str, lex: Lexicon, item_types: Callable[[str], set[str]]) -> str:
    """``text`` with a withdrawal of one listed thing read as the request without it."""
    for clause in _CLAUSE.finditer(text):
        thing = _withdrawn(clause.group("said"), item_types)
        if thing is None:
            continue
        before = text[: clause.start()]
        kept = _without_listed(before, thing, lex)
        if kept is None:
            continue
        after = _without_reason(text[clause.end() :], lex)
        return (kept.rstrip(" ,;") + after).strip() or text
    return text


def _without_reason(after: str, lex: Lexicon) -> str:
    """What follows the withdrawal, less the rest of its sentence where that asks nothing
    (no verb of the office's work): the reason the thing is withdrawn ("..., I found one")."""
    stop = re.search(r"[.!?;…]", after)
    said = after[: stop.start()] if stop is not None else after
    if any(m.kind == "cue" for m in lex.read(said).mentions):
        return after
    return after[len(said) :]


def _withdrawn(said: str, item_types: Callable[[str], set[str]]) -> str | None:
    """The one item type the withdrawal ``said`` names after its head, or None."""
    words = [language.fold(w) for w in language.WORD.findall(said.replace("’", "'"))]
    while words and words[0] in _LEAD:
        words = words[1:]
    head = next((h for h in _HEADS if tuple(words[: len(h)]) == h), None)
    if head is None:
        return None
    rest = words[len(head) :]
    while rest and rest[0] in _ARTICLES:
        rest = rest[1:]
    if not rest or len(rest) > _MOST_THING_WORDS:
        return None
    types = item_types(" ".join(rest))
    return next(iter(types)) if len(types) == 1 else None


def _without_listed(before: str, thing: str, lex: Lexicon) -> str | None:
    """``before`` without the listed thing of type ``thing`` and its join; None where the
    request names it not in a list beside another thing (or not at all, or twice)."""
    spans = [m.span() for m in language.WORD.finditer(before.replace("’", "'"))]
    tokens = lex.tokens(before)
    if len(tokens) != len(spans):
        return None
    items = [m for m in lex.scan(tokens) if m.kind == "item"]
    named = [n for n, m in enumerate(items) if thing in m.ids]
    if len(items) < 2 or len(named) != 1:
        return None
    n = named[0]
    start = _phrase_start(tokens, lex.scan(tokens), items[n])
    end = spans[items[n].end - 1][1]
    if n > 0:
        # "... a stapler and *a pen*": from the thing before it, its join and the thing
        prev_end = spans[items[n - 1].end - 1][1]
        if _JOIN.match(before[prev_end : spans[start][0]]):
            return before[:prev_end] + before[end:]
    if n + 1 < len(items):
        # "*a stapler* and a pen": the thing and its join, up to the thing after it
        nxt = _phrase_start(tokens, lex.scan(tokens), items[n + 1])
        if _JOIN.match(before[end : spans[nxt][0]]):
            return before[: spans[start][0]] + before[spans[nxt][0] :]
    return None


def _phrase_start(tokens: Sequence[Token], mentions: Sequence[Mention], item: Mention) -> int:
    """Where the phrase of ``item`` starts: at its article or its owner's possessive."""
    start = item.start
    owner = next((m for m in mentions if m.end == start and m.possessive), None)
    if owner is not None:
        start = owner.start
    while start > 0 and tokens[start - 1].word in _OPENERS:
        start -= 1
    return start
