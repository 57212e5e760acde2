"""A colleague's thing described with words the office does not list: a description, never an
owner or a part of the request.

English puts a noun's description between the possessive and the noun: "Chase's setting-out
file", "Zhang's year-end report", "Mao's crane lift plan file". The office lists the noun
("file", "report") but not the description, and a hyphenated compound is read as two words,
so "setting-out" left "Wang's setting" as a thing nobody could name ("I'm not sure what you
mean by 'Wang's setting'"). Two rules, both about English and the office's own names:

- ``without_hyphened_description``: a possessive ("Wang's", "my"), then a description that
  holds a hyphenated compound and names nothing of the office, then an item of the office:
  the description is dropped, the owner's item stays ("Wang's setting-out file" → "Wang's
  file"). Descriptions of plain nouns ("Zhang's budget report") the frames already read.
- ``named_later``: a colleague's thing said in words the office has no item for ("could I
  have Wang's budget plan?"), then, in a later sentence or clause, "the <item>" with nobody
  else named between ("just send me the file"): the later words name what that thing is, so
  the item's word is said after the description ("Wang's budget plan file"); "the file" then
  refers back to it, the same owner's, and the later clause gives the recipient.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.aligned import aligned_reading
from assistantx.agents.symbolic.reading.back_reference_recipient import recipient_as_need
from assistantx.agents.symbolic.reading.lexicon import Lexicon, Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

# The words that may describe a thing but name nothing ("a", "for", "and"): a run holding one
# is a phrase of its own, not one thing's description.
_FUNCTION = (
    english.words("determiners")
    | english.words("party_prepositions")
    | english.words("modifier_prepositions")
    | english.words("clause_joins")
    | english.words("pronouns")
    | english.words("subject_pronouns")
    | english.words("self_words")
    | english.words("courtesy")
    | english.words("asking_words")
    | english.words("copulas")
)
# Mentions a description may hold: plain words, and a task word inside a compound ("the
# handing-over slides"); a person, an item, a place or a pronoun is a party of its own.
_DESCRIBING = frozenset({"word", "cue"})
_LONGEST = 4  # words of one description ("quarter-end site visit")
_OWNERS = frozenset({"person", "self"})
_THE = "the"
_NEGATORS = english.words("negators")


def without_hyphened_description(lex: Lexicon, text: str) -> str:
    """``text`` with a hyphened description between a possessive and an office's item left
    out ("Wang's setting-out file" → "Wang's file"); unchanged where there is none."""
    spans, tokens, mentions = aligned_reading(lex, text)
    if spans is None:
        return text
    cuts: list[tuple[int, int]] = []
    joined = _joined(text, spans)
    for n, opener in enumerate(mentions):
        if not _owner(opener):
            continue
        end = _description_end(tokens, mentions, n + 1, opener.end, joined)
        if end is None or not any(i in joined for i in range(opener.end + 1, end)):
            continue
        item = _mention_at(mentions, end)
        if item is None or item.kind != "item" or item.possessive:
            continue
        cuts.append((spans[opener.end][0], spans[end][0]))
    for start, stop in reversed(cuts):
        text = text[:start] + text[stop:]
    return text


def named_later(lex: Lexicon, text: str) -> str:
    """``text`` with a colleague's thing the office has no item for said with the item a
    later clause names as "the <item>" ("Wang's budget plan? just send me the file" →
    "Wang's budget plan file? ..."); unchanged where nothing later names it."""
    spans, tokens, mentions = aligned_reading(lex, text)
    if spans is None:
        return text
    for n, opener in enumerate(mentions):
        if opener.kind != "person" or not opener.possessive or len(opener.ids) != 1:
            continue
        end = _description_end(tokens, mentions, n + 1, opener.end)
        if end is None or not _ends_clause(tokens, end):
            continue
        head = tokens[end - 1].word
        if mentions_kind(mentions, end - 1) != "word" or not language.is_noun(head):
            continue
        if any(head in phrase.split() for phrase in lex.items):
            continue  # "Maren's folder" beside her blue and red folders: which one, asked
        later = _later_item(tokens, mentions, end)
        if later is None:
            continue
        said = text[spans[later.start][0] : spans[later.end - 1][1]]
        at = spans[end - 1][1]
        return text[:at] + " " + said + text[at:]
    return text


def mentions_kind(mentions: Sequence[Mention], token: int) -> str:
    """The kind of the mention over ``token`` ("" where none covers it)."""
    for m in mentions:
        if m.start <= token < m.end:
            return m.kind
    return ""


def _owner(m: Mention) -> bool:
    """Whether ``m`` says whose a thing is: "my", "Wang's"."""
    return m.kind in _OWNERS and m.possessive and len(m.ids) <= 1


def _mention_at(mentions: Sequence[Mention], start: int) -> Mention | None:
    return next((m for m in mentions if m.start == start), None)


def _description_end(
    tokens: Sequence[Token],
    mentions: Sequence[Mention],
    k: int,
    start: int,
    joined: frozenset[int] = frozenset(),
) -> int | None:
    """The token after the longest description from ``start`` (``mentions[k]`` on): plain
    words of one phrase, no function word but inside a hyphenated compound (``joined``: the
    tokens a hyphen joins to the one before, "handing-*over*"); None where no word
    describes."""
    at = start
    for m in mentions[k:]:
        if m.start != at or m.kind not in _DESCRIBING or at - start >= _LONGEST:
            break
        t = tokens[m.start]
        if t.opens or t.after_pause or t.possessive:
            break
        if t.word in _FUNCTION and m.start not in joined:
            break
        if not all(tokens[i].word.isalpha() for i in range(m.start, m.end)):
            break
        at = m.end
    return at if at > start else None


def _joined(text: str, spans: Sequence[tuple[int, int]]) -> frozenset[int]:
    """The tokens a hyphen alone joins to the token before ("setting-*out*")."""
    return frozenset(i for i in range(1, len(spans)) if text[spans[i - 1][1] : spans[i][0]] == "-")


def _ends_clause(tokens: Sequence[Token], end: int) -> bool:
    """Whether the phrase ending before token ``end`` ends its clause or sentence."""
    return end >= len(tokens) or tokens[end].opens or tokens[end].after_pause


_PARTY = frozenset({"person", "place", "facility", "item"})


def _later_item(tokens: Sequence[Token], mentions: Sequence[Mention], end: int) -> Mention | None:
    """The first "the <item>" after token ``end`` with no other party named before it, not
    anyone's ("the file"); None where another party or nothing comes first."""
    for m in mentions:
        if m.start < end:
            continue
        if m.kind == "item" and not m.possessive and len(m.ids) == 1:
            before = [t.word for t in tokens[max(0, m.start - 2) : m.start]]
            if before[-1:] != [_THE] or _NEGATORS & set(before):
                return None  # "not the blue folder": the one not meant names nothing
            return m
        if recipient_as_need(tokens, m):
            continue  # "Zhang needs the file": whom it is for, no owner of it
        if m.kind in _PARTY or (m.kind == "pronoun" and m.possessive):
            return None
    return None
