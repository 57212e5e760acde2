"""The proper name of a place outside the office, said where a thing goes, is done or comes
from ("send my job off for hallmarking at the *Birmingham Assay Office*", "courier my proofs
to the *Leeds Print Works*", "to the *Baker Street office*", "post my form to *Print Express
Ltd*"): after "to", "at", "for" or "from" (and an article), capitalised words that end in the
noun of a kind of place, a firm or a street ("Office", "Works", "Centre", "Ltd", "Street",
"House"), or capitalised words and then such a noun in lower case ("the Baker Street
office"). English puts a place's own name before the noun of its kind, so the whole run is
that place's name: a word of it that is also a service's verb ("Assay", "Print", "Copy"), a
colleague's name ("Baker") or a thing's name ("Stapler") names none of them, and is read as
a plain word of the name (``outside_names``, in the readings stage).

A name of the office's own said in capitals ("at the Print Room", "to the Post Room
Office") is the office's: a run that the office's place, facility or group names whole, but
for its last noun of a kind of place, is no place outside. A single capitalised name before a
lower-case noun of a place ("to Baker office") may be a colleague's room said without the
apostrophe, and is left as it was."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.named_place import place_head
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english

# The prepositions before a place a thing goes to, is done at or comes from.
_BEFORE = frozenset({"to", "at", "for", "from"})
_ARTICLES = frozenset({"the"})
# The last word of a firm's or a street's name ("Print Express *Ltd*", "Baker *Street*").
_FIRM_OR_STREET = english.words("firm_suffixes") | english.words("street_words")
# The office's own names: said whole (but for a kind of place after them), the office's.
_OFFICE_NAMES = frozenset({"place", "facility", "group"})
_CLAUSE_END = frozenset(".!?;,:\n")


def _kind_of_place(word: str) -> bool:
    return place_head(word) or word in _FIRM_OR_STREET


def _capitalised(token: Token) -> bool:
    return token.text[:1].isupper()


def outside_names(
    tokens: Sequence[Token], gaps: Sequence[str], mentions: Sequence[Mention]
) -> list[tuple[int, int]]:
    """The token spans (start, end) of the proper names of places outside the office said
    after a preposition of where (``gaps``: the punctuation before each token)."""
    found: list[tuple[int, int]] = []
    k = 0
    while k < len(tokens) - 1:
        span = _name_after(tokens, gaps, mentions, k)
        if span is None:
            k += 1
            continue
        found.append(span)
        k = span[1]
    return found


def _ends(gap: str) -> bool:
    return any(c in _CLAUSE_END for c in gap)


def _name_after(
    tokens: Sequence[Token], gaps: Sequence[str], mentions: Sequence[Mention], k: int
) -> tuple[int, int] | None:
    if tokens[k].word not in _BEFORE or not tokens[k].text[:1].islower():
        return None
    start = k + 1
    if start < len(tokens) and tokens[start].word in _ARTICLES and not _ends(gaps[start]):
        start += 1
    run = start
    while (
        run < len(tokens)
        and _capitalised(tokens[run])
        and not tokens[run].opens
        and (run == start or not _ends(gaps[run]))
    ):
        run += 1
        if tokens[run - 1].possessive:
            break
    if run == start or start >= len(tokens) or _ends(gaps[start]):
        return None
    if tokens[run - 1].possessive:
        return None  # "to Sam Baker's desk": a colleague's
    last = tokens[run - 1]
    if run - start >= 2 and _kind_of_place(last.word):
        end = run  # "the Birmingham Assay Office", "Print Express Ltd", "Baker Street"
        kind_at = run - 1
    elif (
        run < len(tokens)
        and not _ends(gaps[run])
        and tokens[run].text[:1].islower()
        and not tokens[run].possessive
        and place_head(tokens[run].word)
        and (run - start >= 2 or not _a_person(mentions, start, run))
    ):
        end = run + 1  # "the Baker Street office", "the Northfield depot"
        kind_at = run
    else:
        return None
    if _the_offices(mentions, start, end, kind_at):
        return None
    return start, end


def _a_person(mentions: Sequence[Mention], start: int, end: int) -> bool:
    return any(m.kind == "person" and m.start <= start and m.end >= end for m in mentions)


def _the_offices(mentions: Sequence[Mention], start: int, end: int, kind_at: int) -> bool:
    """Whether the name is one of the office's own: one mention of it covers the whole run
    ("the Print Room"), or a place, facility or group of it covers all but the noun of a kind
    of place at the end ("the Post Room Office")."""
    for m in mentions:
        if m.start <= start and m.end >= end:
            return True
        if m.kind in _OFFICE_NAMES and m.start <= start and m.end >= kind_at:
            return True
    return False


def as_outside_words(
    tokens: Sequence[Token], mentions: Sequence[Mention], spans: Sequence[tuple[int, int]]
) -> list[Mention]:
    """``mentions`` with each one inside a place's name outside (``spans``) read as a plain
    word of that name: never a service, a colleague, a thing or a place of the office."""
    if not spans:
        return list(mentions)
    out: list[Mention] = []
    for m in mentions:
        inside = any(start <= m.start < end for start, end in spans)
        if inside and m.kind not in ("word", "self", "pronoun"):
            m = Mention("word", m.start, m.end, (tokens[m.start].word,), False, m.text)
        out.append(m)
    return out
