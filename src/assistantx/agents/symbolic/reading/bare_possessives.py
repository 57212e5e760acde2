"""A possessive written without its apostrophe: "could u bring idas ruler", "borrow Ottos
ruler" (Ida's, Otto's). A word that is a colleague's one-word name plus "s", itself no name
and no English word, right before a word of one of the office's items in the same clause,
is that name's possessive. Read on the tokens before the typo correction, which would
otherwise make "ottos" plain "otto" ("bring Otto the ruler": Otto would receive his own
ruler). An English word ("hunters pad", "marks ruler") is the possessive only where the
colleague it names keeps that item (Hunter has a pad): otherwise ("bills ruler" where Bill has
none) it is left as written, and whose is not taken from the word. "James' ruler" is already a
possessive (the tokenizer's "s'"). A word of English's closed classes ("this", "his") is
never a possessive, even where a colleague is called by it without its "s" ("Thi").
"""

from __future__ import annotations

from collections.abc import Collection, Mapping, Sequence
from dataclasses import replace

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

_SHORTEST_NAME = 2  # "Al" + "s"
_FUNCTION_WORDS = english.words("common")


def read_bare_possessives(
    tokens: Sequence[Token],
    names: Collection[str],
    item_words: Collection[str],
    owned: Mapping[str, Collection[str]] | None = None,
) -> list[Token]:
    """``tokens`` with each apostrophe-less possessive of a name read as the name's
    possessive. ``names``: the office's one-word names of people (folded); ``item_words``:
    the words that open an item's name (folded); ``owned``: a name → the words that open
    the names of the items the person it names keeps."""
    out = list(tokens)
    for n, t in enumerate(tokens):
        nxt = tokens[n + 1] if n + 1 < len(tokens) else None
        if nxt is None or nxt.opens or nxt.after_pause or nxt.word not in item_words:
            continue
        if _bare_possessive(t, names, (owned or {}).get(t.word[:-1], ()), nxt.word):
            base = t.word[:-1]
            out[n] = replace(t, word=base, typed=base, possessive=True)
    return out


def _bare_possessive(t: Token, names: Collection[str], kept: Collection[str], item: str) -> bool:
    word = t.word
    return (
        not t.possessive
        and word.endswith("s")
        and len(word) > _SHORTEST_NAME
        and word[:-1] in names
        and word not in names
        and _may_be_a_possessive(word, item, kept)
    )


def _may_be_a_possessive(word: str, item: str, kept: Collection[str]) -> bool:
    """A word no English knows ("idas") may be a name's possessive; an English word only
    where the dictionary reads it as a form of the name's word ("hunters": hunter, "marks":
    mark) and the colleague keeps that item. A word that is no form of it ("this" of Thị,
    "his", "was") and a function word never are: the "s" is part of another word."""
    if word in _FUNCTION_WORDS:
        return False
    if language.is_english_word(word):
        base = word[:-1]
        return item in kept and any(base in forms for forms in language.lemmas(word).values())
    return True
