"""What a paper is for, said after it: "I need Zhang's signature on my requisition for the new
staplers", "print my order for the new chairs". After a work on a paper (sign, stamp, approve,
print, copy: ``paper_work_words``, or the office's own sealing and signing), "for the (new)
<thing>" right after the paper's phrase says what the paper is about, never a second thing to
fetch: read as a thing, the office's stapler took the request over and was asked about
("what do you want me to do with the stapler?") while the paper went unsigned.

Only a thing right after "for", an article or owner word and two modifiers at most ("for the
new staplers", "for our stopwatches"), that is no paper itself, after a phrase the paper work
governs in the same clause: the office's paper or file named, or the requester's or a definite
noun the office does not know ("my requisition", "the order"). "bring me a stapler for the
form" and "sign my form and bring the stapler" are no such phrase."""

from __future__ import annotations

from collections.abc import Collection, Sequence

from assistantx.agents.symbolic.reading.mention_view import MentionView as Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language, task_kinds
from assistantx.core.task_schema import FILE_KIND, SHAPE_KIND

_WORK_WORDS = english.words("paper_work_words")
# the works on a paper a cue may name in an office's own words ("notarise": seal): a
# person's work on it, or the kind of an operation that works on an input (not one that
# makes its product from nothing)
_WORK_CUES = frozenset(task_kinds.person_kinds()) | frozenset(
    k for shape, k in SHAPE_KIND.items() if k != FILE_KIND and shape != "make"
)
_OPENERS = frozenset({"the", "our", "my", "these", "those", "this", "that", "a", "an", "some"})
_MODIFIERS = 2  # the words between the opener and the thing ("the new red staplers")
_PAPER_WORDS = 3  # the words of an unknown paper's name after its owner ("my purchase order")


def paper_subjects(
    tokens: Sequence[Token], mentions: Sequence[Mention], papers: Collection[str]
) -> set[int]:
    """The indexes of the item mentions in ``mentions`` that say what a paper worked on
    before them is for."""
    out: set[int] = set()
    for n, m in enumerate(mentions):
        if m.kind != "item" or not m.ids or set(m.ids) & set(papers) or m.possessive:
            continue
        at = _for_before(tokens, mentions, n)
        if at is not None and _worked_paper_before(tokens, mentions, at, papers):
            out.add(n)
    return out


def _for_before(tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> int | None:
    """Where the "for" stands that opens the phrase of mention ``n``: "for the new staplers"."""
    k = mentions[n].start - 1
    plain = 0
    while k >= 0 and plain < _MODIFIERS and _plain_at(mentions, n, k) and not tokens[k + 1].opens:
        if tokens[k].word in _OPENERS or tokens[k].word == "for":
            break
        k -= 1
        plain += 1
    if k >= 0 and tokens[k].word in _OPENERS and not tokens[k + 1].opens:
        k -= 1
    if k < 1 or tokens[k].word != "for" or tokens[k + 1].opens or tokens[k].after_pause:
        return None
    return k


def _plain_at(mentions: Sequence[Mention], n: int, k: int) -> bool:
    """Whether token ``k`` before mention ``n`` is a plain word (no thing, no person)."""
    return not any(m.start <= k < m.end and m.kind != "word" for m in mentions[:n])


def _worked_paper_before(
    tokens: Sequence[Token], mentions: Sequence[Mention], at: int, papers: Collection[str]
) -> bool:
    """Whether the words before the "for" at ``at`` end with a paper's phrase that a work on
    papers said earlier in the clause governs."""
    before = [m for m in mentions if m.end <= at]
    if not before or before[-1].end != at:
        return False
    last = before[-1]
    start: int | None = None
    if last.kind == "item" and set(last.ids) & set(papers):
        start = last.start
    elif last.kind in ("word", "cue"):
        start = _unknown_paper_start(tokens, before)
    if start is None:
        return False
    for k in range(start - 1, -1, -1):
        if _work_at(tokens, mentions, k):
            return True
        if tokens[k].opens:
            return False
    return False


def _unknown_paper_start(tokens: Sequence[Token], before: Sequence[Mention]) -> int | None:
    """Where the phrase of a noun the office does not know starts, when an owner word or
    an article opens it ("my requisition", "the purchase order"); None otherwise."""
    k = len(before) - 1
    while k >= 0 and len(before) - k <= _PAPER_WORDS and before[k].kind in ("word", "cue"):
        start = before[k].start
        if tokens[start].opens or tokens[start].word in _OPENERS:
            return None
        if start >= 1 and tokens[start - 1].word in _OPENERS:
            return start - 1  # "the purchase order": the article has no mention
        if k >= 1 and before[k - 1].kind == "self" and before[k - 1].end == start:
            return before[k - 1].start if before[k - 1].possessive else None
        k -= 1
    return None


def _work_at(tokens: Sequence[Token], mentions: Sequence[Mention], k: int) -> bool:
    """Whether token ``k`` says a work on papers: its word, or a cue of such work."""
    word = tokens[k].word
    if word in _WORK_WORDS or language.verb_lemmas(word) & _WORK_WORDS:
        return True
    return any(m.kind == "cue" and m.start == k and set(m.ids) & _WORK_CUES for m in mentions)
