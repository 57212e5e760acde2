"""How to reach a send-out's place, said in a clause after it ("fax my report to the county
hospital, *their number is 01632 960 123*"; "post it to the Leeds office. *The postcode is LS1
4AP*"; "..., *number: 0161 496 0000*").

The place's own phrase ends at its clause's end, so a number, a postcode or an address said in
the next clause was lost, and the operator sent the item with no number. English says such a
clause by a word that names a way of reaching a place (a number, a postcode, an address: the
``destination_details`` of ``data/english.yaml``, and the words of what the service asks for
when none is said, ``destination_asked``: "the fax number"), owned by the place ("their",
"its") or by nobody ("the", none), then what it is ("is", a colon, or nothing) and a value that
can be dialled or addressed: a number or code (a digit) or an email (an "@"); words alone
("the number is on the form") say none. The detail joins the place ("the county hospital,
number 01632 960 123") so the operator is told everything the requester said about where it
goes.

Never the requester's own number ("*my* number is ..., call me"): only the place's, or one
said with no owner.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

# Whose number it is: the place's ("their", "its") or nobody's ("the"); never the requester's.
_OWNERS = frozenset({"the", "their", "its", "theyre", "his", "her"})
# What joins the word to its value ("is", "'s", "="); a colon is punctuation between tokens.
_LINKS = frozenset({"is", "s", "was"})
# A word that names the detail, at most this many ("fax number", "post code").
_NAMING_WORDS = 2
# What the detail's value may run to after a comma of its own ("3 Mill Lane, Leeds").
_TAIL_WORDS = 3
# Words that end the value: courtesy, or a join to another clause.
_VALUE_ENDS = frozenset(
    {"please", "pls", "thanks", "thank", "thx", "cheers", "asap", "and", "so", "because"}
)
# Punctuation that closes a clause: sentence ends, commas, a dash set off by spaces.
_CLAUSE_MARKS = frozenset(".!?;,\n")
_SENTENCE_MARKS = frozenset(".!?;\n")
_DASH = re.compile(r"\s[-\u2013\u2014]+\s")  # a dash set off by spaces, never "01632-960"


@dataclass(frozen=True)
class Detail:
    """A clause after a send-out's place that says how to reach it."""

    start: int  # token span of the whole clause
    end: int
    said: str  # "number 01632 960 123": the naming word and its value, as written


def naming_words(asked: str) -> frozenset[str]:
    """The words that name a way of reaching a place for a service whose question is
    ``asked`` ("the fax number": fax, number), with English's own (address, postcode ...)."""
    own = {w for w in language.words(asked) if w.isalpha() and language.is_noun(w)}
    return english.words("destination_details") | frozenset(own)


def detail_after(
    tokens: Sequence[Token],
    gaps: Sequence[str],
    end: int,
    stop: int,
    naming: frozenset[str],
) -> Detail | None:
    """The clause right after a place that ends at token ``end`` (``gaps``: the punctuation
    before each token; ``stop``: where the request's words end) when it says how to reach the
    place, else None."""
    k = end
    while k < stop and tokens[k].word in ("please", "pls"):
        k += 1  # "to the county hospital please, their number is ..."
    if k >= stop or not _closes(gaps[k]):
        return None
    start = k
    if tokens[k].word == "and" and k + 1 < stop:
        k += 1  # "..., and their fax is ..."
    if tokens[k].word in _OWNERS:
        k += 1
    first = k
    while k < stop and k - first < _NAMING_WORDS and _names_detail(tokens[k], naming):
        k += 1
        if tokens[k - 1].possessive:
            break  # "the postcode's LS1 4AP": the "'s" is its "is"
    if k == first or k >= stop:
        return None
    named = " ".join(t.word for t in tokens[first:k])
    # "is", or "'s"; after an abbreviation's stop too ("fax no. is ...")
    if tokens[k].word in _LINKS and gaps[k].strip() in ("", "."):
        k += 1
    value = _value_end(tokens, gaps, k, stop)
    if value == k or not _addressable(tokens[k:value]):
        return None
    said = "".join((gaps[n] if n > k else "") + tokens[n].text for n in range(k, value))
    return Detail(start, value, f"{named} {said.strip()}")


def _names_detail(token: Token, naming: frozenset[str]) -> bool:
    return bool({token.word, token.typed} & naming)


def _value_end(tokens: Sequence[Token], gaps: Sequence[str], k: int, stop: int) -> int:
    """Where the value starting at ``k`` ends: its clause's end, or past a comma over a short
    part that is all names and codes ("3 Mill Lane, Leeds LS1 4AP")."""
    n = k
    while n < stop and (n == k or not _closes(gaps[n])) and tokens[n].word not in _VALUE_ENDS:
        n += 1
    while n < stop and gaps[n].strip() == "," and not any(c in _SENTENCE_MARKS for c in gaps[n]):
        more = n
        while (
            more < stop
            and (more == n or not _closes(gaps[more]))
            and tokens[more].word not in _VALUE_ENDS
        ):
            more += 1
        part = tokens[n:more]
        if not part or len(part) > _TAIL_WORDS or not all(_capitalised(t) for t in part):
            break
        n = more
    return n


def _addressable(value: Sequence[Token]) -> bool:
    """Whether words can be dialled or addressed: a number or code (a digit) or an email;
    a street's name holds its house number ("3 Mill Lane")."""
    if not value:
        return False
    return any(any(c.isdigit() for c in t.text) or "@" in t.text for t in value)


def _capitalised(token: Token) -> bool:
    return token.text[:1].isupper() or any(c.isdigit() for c in token.text)


def _closes(gap: str) -> bool:
    return any(c in _CLAUSE_MARKS for c in gap) or _DASH.search(gap) is not None


def detail_in_message(
    tokens: Sequence[Token],
    gaps: Sequence[str],
    said: Sequence[str],
    naming: frozenset[str],
) -> Detail | None:
    """The detail said after a send-out's words ``said`` (its verb through its place, as the
    request read them) in the whole message (``tokens``, ``gaps``): the screen sets a clause
    like "their number is ..." aside as a statement before the request is read, so it is
    looked for where the requester said it, right after those words."""
    width = len(said)
    if not width:
        return None
    words = [t.word for t in tokens]
    for k in range(len(words) - width + 1):
        if words[k : k + width] == list(said):
            return detail_after(tokens, gaps, k + width, len(tokens), naming)
    return None
