"""Whom a request is for, said after it: "can you print my file? it's Fern who needs the hard
copy, not me", "... Fern needs it, not me", "..., it's for Fern", "Fern's the one who needs
it". The person named so is the recipient of the one task the request made, which would
otherwise come to the requester. A name in that position is a person even where it is also an
ordinary word ("it's fern who needs it"): "it's X who needs" says X is someone."""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from assistantx.agents.symbolic.reading.lexicon import Lexed, Mention
from assistantx.core.task_schema import TaskFrame


def _word(m: Mention | None, *words: str) -> bool:
    return m is not None and m.kind == "word" and m.ids[:1] in [(w,) for w in words]


def _needs(m: Mention | None, tokens_word: str) -> bool:
    return m is not None and m.kind == "cue" and tokens_word in ("needs", "need", "wants")


def _person(m: Mention | None, name_words: Mapping[str, set[str]]) -> str | None:
    """The one colleague ``m`` names: a person mention, or a word that is one colleague's name."""
    if m is None or m.kind not in ("person", "word"):
        return None
    ids = list(m.ids) if m.kind == "person" else sorted(name_words.get(m.ids[0], set()))
    return ids[0] if len(ids) == 1 else None


def _it_is(ms: Sequence[Mention], n: int) -> int | None:
    """Where the words after "it's" / "it is" at ``n`` start (None: no such opener there); "is
    it for ..." (a question) is no opener."""
    m = ms[n]
    if m.kind != "pronoun" or m.possessive:
        return None
    if m.text.lower().replace("’", "'") == "it's":
        return n + 1
    if m.text.lower() == "it" and _word(ms[n + 1] if n + 1 < len(ms) else None, "is"):
        return n + 2
    return None


def needer(lexed: Lexed, requester: str, name_words: Mapping[str, set[str]]) -> str | None:
    """The one person the message says the request is for, in the words above, or None."""
    ms, words = list(lexed.mentions), [t.word for t in lexed.tokens]

    def at(k: int) -> Mention | None:
        return ms[k] if 0 <= k < len(ms) else None

    found: set[str] = set()
    for n, m in enumerate(ms):
        after = _it_is(ms, n)
        if after is not None:
            who = _person(at(after), name_words)
            if who is not None and _word(at(after + 1), "who"):
                nxt = at(after + 2)
                if nxt is not None and _needs(nxt, words[nxt.start]):
                    found.add(who)  # "it's Fern who needs it"
            if _word(at(after), "for"):
                who = _person(at(after + 1), name_words)
                if who is not None and at(after + 2) is None:
                    found.add(who)  # "..., it's for Fern" (said last)
        who = _person(m, name_words) if m.kind == "person" else None
        if who is None:
            continue
        if m.possessive and _word(at(n + 1), "one") and _word(at(n + 2), "who"):
            found.add(who)  # "Fern's the one who needs it"
        nxt = at(n + 1)
        if not m.possessive and nxt is not None and _needs(nxt, words[nxt.start]):
            obj, neg, me = at(n + 2), at(n + 3), at(n + 4)
            denied = _word(neg, "not") and me is not None and me.kind == "self"
            if obj is not None and obj.kind in ("pronoun", "item") and denied:
                found.add(who)  # "Fern needs it, not me"
    found.discard(requester)
    return next(iter(found)) if len(found) == 1 else None


def for_needer(frame: TaskFrame, who: str | None) -> TaskFrame:
    """The frame's one task, which would come to the requester, goes to ``who`` instead."""
    if who is None or len(frame.tasks) != 1:
        return frame
    task = frame.tasks[0]
    if task.recipient != frame.requester or task.owner == who:
        return frame
    return frame.model_copy(update={"tasks": [task.model_copy(update={"recipient": who})]})
