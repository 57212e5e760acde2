"""A colleague's thing said in words the office does not list, asked to be forwarded: "forward
me Wang's budget pack", "email me Zhang's handover notes", "ping us her rota".

Only an electronic file can be forwarded, sent or emailed to someone; a colleague's
possessive before a phrase of plain words no name of the office reads, as the object of such a
verb, is therefore that colleague's file. Left a plain word, the phrase made its part of the
request vanish while another part ("... and print my own file too") was done: a part dropped
without a word. Where the office keeps no file the caller leaves the phrase as it was (asked
about). "send" and "ping" move things too ("send me Wang's stapler"), so they count only
with the speaker as their first object ("send me ...", "ping us ...")."""

from __future__ import annotations

from collections.abc import Collection, Sequence

from assistantx.agents.symbolic.reading.mention_view import MentionView as Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

_FORWARDING = english.words("send_words")
# verbs that send a thing to the speaker ("send me", "ping us"), electronic or not by
# themselves: a forward only with the speaker right after them
_TO_THE_SPEAKER = frozenset({"send", "sent", "ping", "pinged"})
_SPEAKER = frozenset({"me", "us"})
_COMMON = english.words("common")
_ASKING = english.words("asking_words")
_MOST_WORDS = 3  # "Wang's quarterly budget pack"


def forwarded_phrase(
    tokens: Sequence[Token], mentions: Sequence[Mention], n: int, named: Collection[str]
) -> int | None:
    """Where ``mentions[n]`` is a colleague's possessive ("Wang's", "her") after a forwarding
    verb, the index of the last word of the plain phrase it owns ("budget *pack*"), or None.
    ``named``: the words of the office's item names (a phrase with one is the office's own
    thing, read by the stages that know it)."""
    owner = mentions[n]
    if owner.kind not in ("person", "pronoun") or not owner.possessive:
        return None
    if not _forwarding_before(tokens, owner.start):
        return None
    head, end = None, owner.end
    for k in range(n + 1, min(len(mentions), n + 1 + _MOST_WORDS)):
        m = mentions[k]
        if m.kind != "word" or m.start != end or tokens[m.start].opens:
            break
        word = m.ids[0]
        if word in _COMMON or word in _ASKING or not word.isalpha() or not _may_describe(word):
            break  # "Wang's budget pack to Zhang", "... pack please": the phrase ends here
        if word in named:
            return None  # "Wang's budget file": the office's own word, read as before
        head, end = k, m.end
    if head is None:
        return None
    after = mentions[head + 1] if head + 1 < len(mentions) else None
    if after is not None and after.start == end and after.kind == "item":
        return None  # "Wang's budget file": the office's own item, read as before
    found = language.lemmas(mentions[head].ids[0])
    if found and "NOUN" not in found and "VERB" not in found:
        return None  # "forward me Wang's latest": no noun heads it
    return head


def _may_describe(word: str) -> bool:
    """A word of a noun phrase: a noun, an adjective, a participle, or one the dictionary
    does not know ("payslip"); never a preposition, a pronoun, an adverb."""
    found = language.lemmas(word)
    return not found or bool({"NOUN", "VERB", "ADJ", "PROPN"} & set(found))


def _forwarding_before(tokens: Sequence[Token], k: int) -> bool:
    """Whether a forwarding verb governs the phrase at token ``k``: just before it
    ("forward Wang's ..."), or before the speaker as its first object ("send me Wang's
    ...")."""
    j = k - 1
    if j >= 1 and tokens[j].word in _SPEAKER and not tokens[j].opens:
        return tokens[j - 1].word in _FORWARDING | _TO_THE_SPEAKER
    return j >= 0 and tokens[j].word in _FORWARDING
