"""An outside address said in comma-separated parts to the sentence's end ("to Harlow Council
planning department, Civic Centre, Water Gardens, Harlow"): once a send-out's destination has
begun, parts that are each a proper name or a numbered street line, up to the end of the
sentence, are all the address. A word in them that names an operation, an item or a colleague
of the office ("*Water* Gardens", "*Printers* Yard", "*Mill* Road") is part of a street's or a
building's name there, never a request nor a party: an address's parts are capitalised names,
and a clause of its own ("it has to go today", "then print me a tag") never is one."""

from __future__ import annotations

from collections.abc import Collection, Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

# The most words of one part ("Unit 4 Dockside Road", "Harlow Council planning department").
_PART_WORDS = 6
# Small words a proper name holds between its capitalised words ("Bank of England").
_JOINS = frozenset({"the", "of", "and", "&", "for", "on", "upon", "de", "la"})
# English's prepositions: "Mrs Patel *at* 14 Elm Road" is a person and where she is, two
# things, never one street's name (a street's own small words are no English preposition)
_RELATIONS = english.words("prepositions_and_joins") | english.words("party_prepositions")
# What ends a part (a comma) or the sentence (the rest).
_SENTENCE_ENDS = frozenset(".!?;\n")
# Words that are never a place's, said after a comma as a clause or a courtesy.
_NEVER_PLACE = frozenset(
    {"please", "pls", "thanks", "thank", "thx", "asap", "today", "tonight", "tomorrow", "now"}
)


def address_run(
    tokens: Sequence[Token],
    gaps: Sequence[str],
    comma: int,
    stop: int,
    names: Collection[int] = (),
) -> int | None:
    """Where an address that goes on past the comma before token ``comma`` ends, when every
    part from there to the sentence's end (or ``stop``) is an address part; None when any
    part is not (then the destination's other rules decide). ``names``: token indices of a
    colleague's or a place's name of the office; a part that is only such a name is said to
    them or about the office ("..., Kit"), never the address."""
    if comma >= stop or gaps[comma].strip() != ",":
        return None
    start = k = comma
    parts: list[Sequence[Token]] = []
    while True:
        if k < stop and (k == start or not _breaks(gaps[k])):
            k += 1
            continue
        if not address_part(tokens[start:k], range(start, k), names):
            return None
        parts.append(tokens[start:k])
        if k >= stop or any(c in _SENTENCE_ENDS for c in gaps[k]):
            return k if not lone_word(parts) else None
        start = k
        k += 1


def lone_word(parts: Sequence[Sequence[Token]]) -> bool:
    """Whether the parts after the place are one capitalised word alone ("to the tax office,
    Frank"): a name said to someone as readily as a town, so it is no address by this rule
    (the destination's other rules read it)."""
    return len(parts) == 1 and len(parts[0]) == 1 and not any(c.isdigit() for c in parts[0][0].text)


def _breaks(gap: str) -> bool:
    """Whether the gap before a token ends a part: a comma, or the sentence's end."""
    return any(c in _SENTENCE_ENDS or c == "," for c in gap)


def address_part(part: Sequence[Token], at: Sequence[int], names: Collection[int]) -> bool:
    """Whether one comma-separated part is a part of an address: a proper name or a
    numbered line ("Civic Centre", "4 Coffee Lane", "Leeds LS1 4DY"), no day nor month, and
    not a colleague's name alone (``at``: the part's token indices, ``names``: those of the
    office's names)."""
    if not part or len(part) > _PART_WORDS:
        return False
    if all(k in names for k in at):
        return False  # "to Acme Ltd, Kit": said to Kit
    if any(t.word in _NEVER_PLACE for t in part):
        return False
    if any(language.is_weekday(t.word) or language.is_month(t.word) for t in part):
        return False  # "to Ofcom, Monday": when, not where
    named = [t.text[:1].isupper() or any(c.isdigit() for c in t.text) for t in part]
    # a numbered street line is a name in any language: a small word in lower case between
    # its capitalised words or its number joins them ("Rua *do* Almada 120", "Unter *den*
    # Linden 5", "14 *rue* de Seine")
    numbered = any(c.isdigit() for t in part for c in t.text)
    return named[0] and all(
        n
        or t.word in _JOINS
        or (numbered and t.word not in _RELATIONS and _between_names(named, k))
        for k, (n, t) in enumerate(zip(named, part, strict=True))
    )


def _between_names(named: Sequence[bool], k: int) -> bool:
    """Whether a capitalised word or a number stands somewhere before the word at ``k`` and
    somewhere after it in the part ("14 *rue* de Seine": the number before, "Seine" after the
    small word "de")."""
    return any(named[:k]) and any(named[k + 1 :])
