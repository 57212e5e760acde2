"""A possessive written without its apostrophe: "could u bring idas ruler", "borrow Ottos
ruler" (Ida's, Otto's). A word that is a colleague's one-word name plus "s", itself no name
and no English word, right before a word of one of the office's items in the same clause,
is that name's possessive; so is one before words that describe the item first ("can i get
wangs budget spreadsheet", "priyas viability spreadsheet": Wang's, Priya's spreadsheet), up to
a few words none of which is a function word or a name, so that the name is never read as the
recipient of a double object ("get Priya the spreadsheet"). Read on the tokens before the
typo correction, which would otherwise make "ottos" plain "otto" ("bring Otto the ruler":
Otto would receive his own ruler). An English word ("hunters pad", "marks ruler") is the
possessive only where the colleague it names keeps that item (Hunter has a pad): otherwise
("bills ruler" where Bill has none) it is left as written, and whose is not taken from the
word: the two readings (Bill's, which he lacks, or anyone's) then lead to different errands,
so ``doubted_possessives`` names it for the reader to ask which. "James' ruler" is already
a possessive (the tokenizer's "s'"). A word of English's closed classes ("this", "his") is
never a possessive, even where a colleague is called by it without its "s" ("Thi").
"""

from __future__ import annotations

from collections.abc import Collection, Mapping, Sequence
from dataclasses import replace

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

_SHORTEST_NAME = 2  # "Al" + "s"
# words that may describe the item between the possessive and the item's word ("wangs *Q3
# budget* spreadsheet"); more is a clause of its own, not one noun phrase
_MOST_MODIFIERS = 3
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
        item = _item_after(tokens, n, names, item_words)
        if item is None:
            continue
        if _bare_possessive(t, names, (owned or {}).get(t.word[:-1], ()), item):
            base = t.word[:-1]
            out[n] = replace(t, word=base, typed=base, possessive=True)
    return out


def _item_after(
    tokens: Sequence[Token], n: int, names: Collection[str], item_words: Collection[str]
) -> str | None:
    """The word of an item's name that token ``n`` would be the possessive of: the next
    token, or the first after a few describing words in the same noun phrase ("budget" of
    "wangs budget spreadsheet"). None where a pause, a new sentence, a function word ("idas
    for the ruler") or a name comes first: the noun phrase, if any, ended there."""
    for k in range(n + 1, min(n + 2 + _MOST_MODIFIERS, len(tokens))):
        nxt = tokens[k]
        if nxt.opens or nxt.after_pause:
            return None
        if nxt.word in item_words:
            return nxt.word
        if nxt.possessive or nxt.word in _FUNCTION_WORDS or nxt.word in names:
            return None
    return None


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


def doubted_possessives(
    tokens: Sequence[Token],
    names: Collection[str],
    item_words: Collection[str],
    owned: Mapping[str, Collection[str]],
) -> list[tuple[str, str, str]]:
    """The (name, item word, word as written) of each English word that is a colleague's
    name plus "s", right before an item that colleague keeps none of ("can u grab bills
    ruler": ("bill", "ruler", "bills") where Bill keeps no ruler). The writer may mean
    Bill's (whom to ask for it) or the plain word (anyone's): different errands, and
    nothing in the words decides, so the reader asks rather than pick one."""
    out: list[tuple[str, str, str]] = []
    for n, t in enumerate(tokens):
        item = _item_after(tokens, n, names, item_words)
        if item is None or t.possessive:
            continue
        word = t.word
        base = word[:-1]
        if (
            word.endswith("s")
            and len(word) > _SHORTEST_NAME
            and base in names
            and word not in names
            and word not in _FUNCTION_WORDS
            and language.is_english_word(word)
            and item not in owned.get(base, ())
            and any(base in forms for forms in language.lemmas(word).values())
        ):
            out.append((base, item, t.text))
    return out
