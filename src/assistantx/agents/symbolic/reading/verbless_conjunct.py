"""A second conjunct said without its verb takes the verb of the request before it (English
gapping): "get Wang to sign my contract, and a coffee for me" is "..., and *get* a coffee for
me"; "take my stapler to Wang and Sun a coffee" is "... and *take* Sun a coffee".

Read as it was written, the conjunct had no verb of its own: after "get Wang to sign", the
"get" belongs to Wang's signing (get someone to do something), so the coffee was left to the
signing, which cannot act on it, and the reader asked what to do with it; after "take X to
Wang", "Sun a coffee" was read as a second recipient of the stapler. Two shapes, each right
after "and" in a sentence that asks for something:

- after "get <person> to <work>", a thing the work does not act on (the office's belongings
  and the things it makes; never a paper or file, which the work may take too: "get Wang to
  sign my contract and the invoice") opened by an article: "get" is inserted, for the
  requester (or whoever "for <person>" names);
- after a giving verb whose thing went "to <person>", another person and a noun phrase, or
  "for" someone (the speaker too) and a noun phrase: the same verb is inserted, giving that
  person the thing ("take Sun a coffee", "bring a coffee to Zhang and *bring* for me a
  water": the coffee had gone to the speaker, and the water was lost); a thing the office
  has no name for ("for me a tea") takes the verb too, and is declined or asked about as
  "bring for me a tea" is, never lending its receiver to the coffee;
- after "I need <thing> <participle> [by <person>]" (a service or a colleague's work wanted
  done on the thing), a thing that is fetched or made, opened by an article: the need is
  inserted ("I need my contract signed by Wang, and *I need* a coffee"). The participle ends
  the first need's thing, so the second thing is no second object of the work: it was left
  to the signing, which cannot act on a coffee, and asked about.

"get Wang to sign my contract and Zhang", "I need my contract signed by Wang and Zhang" (no
thing after the name) and "bring Wang my stapler and my scissors" (a thing with no verb
missing: the verb's own second object) are left as written."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.aligned import aligned_reading
from assistantx.agents.symbolic.reading.indirect_object import opens_noun_phrase
from assistantx.agents.symbolic.reading.lexicon import Lexicon, Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

_DATIVE_VERBS = english.words("dative_verbs")
# "get Wang to sign": the verbs that have someone else do the work
_CAUSING = frozenset({"get"})
# the kinds of thing a colleague's work (signing, sealing) never takes: what is fetched or made
_FETCHED_KINDS = frozenset({"belonging", "product"})
# "I need ...", "we want ...": the speaker's need whose thing a participle follows
_NEEDERS = frozenset({"i", "we"})
_NEEDS = frozenset({"need", "want"})
# how far the need's thing may open after the need's verb ("need *my* contract")
_THING_REACH = 3
# articles that open the conjunct's thing ("and *a* coffee", "and *some* water")
_ARTICLES = frozenset({"a", "an", "some", "the", "another"})
# the articles that open a thing the office has no name for ("for me *a* tea")
_UNKNOWN_OPENERS = english.words("second_thing_articles")


def with_gapped_verbs(lex: Lexicon, text: str) -> str:
    """``text`` with the verb of the request put into each conjunct that left it unsaid."""
    spans, tokens, mentions = aligned_reading(lex, text)
    if spans is None or not mentions:
        return text
    inserts: list[tuple[int, str]] = []
    for n, t in enumerate(tokens):
        if t.word != "and" or n + 1 >= len(tokens) or tokens[n + 1].after_pause:
            continue
        start = _sentence_start(tokens, n)
        verb = _causing_before(tokens, mentions, start, n)
        if verb is not None and _fetched_thing_at(lex, tokens, mentions, n + 1):
            inserts.append((spans[n + 1][0], verb))
            continue
        verb = _giving_to_before(tokens, mentions, start, n)
        if verb is not None and (
            _person_and_thing_at(tokens, mentions, n + 1)
            or _for_someone_and_thing_at(tokens, mentions, n + 1)
        ):
            inserts.append((spans[n + 1][0], verb))
            continue
        verb = _need_done_before(tokens, mentions, start, n)
        if verb is not None and _fetched_thing_at(lex, tokens, mentions, n + 1):
            inserts.append((spans[n + 1][0], verb))
    for at, verb in reversed(inserts):
        text = f"{text[:at]}{verb} {text[at:]}"
    return text


def _sentence_start(tokens: Sequence[Token], at: int) -> int:
    k = at
    while k > 0 and not tokens[k].opens:
        k -= 1
    return k


def _mention_at(mentions: Sequence[Mention], at: int) -> Mention | None:
    return next((m for m in mentions if m.start == at), None)


def _causing_before(
    tokens: Sequence[Token], mentions: Sequence[Mention], start: int, end: int
) -> str | None:
    """The "get" of "get <person> to <work>" between ``start`` and ``end``, as typed."""
    for k in range(start, end):
        if tokens[k].word not in _CAUSING:
            continue
        who = _mention_at(mentions, k + 1)
        if who is None or who.kind != "person" or who.possessive or who.end + 1 >= end:
            continue
        work = _mention_at(mentions, who.end + 1)
        if tokens[who.end].word == "to" and work is not None and work.kind == "cue":
            return tokens[k].text.lower()
    return None


def _need_done_before(
    tokens: Sequence[Token], mentions: Sequence[Mention], start: int, end: int
) -> str | None:
    """The "I need" of "I need <thing> <participle> [by <person>]" right before "and"
    (``end``), as typed: the thing wanted with work done on it, and nothing after."""
    for k in range(start + 1, end):
        if tokens[k].word not in _NEEDS or tokens[k - 1].word not in _NEEDERS:
            continue
        thing = next(
            (m for m in mentions if m.kind == "item" and k < m.start <= k + _THING_REACH), None
        )
        if thing is None or thing.end >= end:
            continue
        if any(m.kind not in ("word", "self") and k < m.start < thing.start for m in mentions):
            continue  # "I need Wang to sign my contract": no thing of the need's own first
        if not language.is_past_participle(tokens[thing.end].word):
            continue
        after = thing.end + 1
        if after == end or _by_person_to(tokens, mentions, after, end):
            return f"{tokens[k - 1].text} {tokens[k].text.lower()}"
    return None


def _by_person_to(tokens: Sequence[Token], mentions: Sequence[Mention], at: int, end: int) -> bool:
    """Whether "by <person>" runs from ``at`` to ``end`` ("signed *by Wang*")."""
    if tokens[at].word != "by":
        return False
    who = _mention_at(mentions, at + 1)
    return who is not None and who.kind == "person" and who.end == end


def _fetched_thing_at(
    lex: Lexicon, tokens: Sequence[Token], mentions: Sequence[Mention], at: int
) -> bool:
    """Whether an article and a thing that is fetched or made, not worked on, open at ``at``
    ("a coffee", "some water", "a stapler")."""
    if tokens[at].word not in _ARTICLES:
        return False
    thing = _mention_at(mentions, at + 1)
    if thing is None or thing.kind != "item":
        return False
    return all(lex.office.item_type(i).kind in _FETCHED_KINDS for i in thing.ids)


def _giving_to_before(
    tokens: Sequence[Token], mentions: Sequence[Mention], start: int, end: int
) -> str | None:
    """The giving verb of the clause before "and" (``end``) when its thing went "to" the
    person said right before "and" ("take my stapler to Wang and ..."), as typed."""
    last = next((m for m in mentions if m.end == end), None)
    if last is None or last.kind != "person" or last.start == 0:
        return None
    if tokens[last.start - 1].word != "to":
        return None
    verbs = [k for k in range(start, last.start) if tokens[k].word in _DATIVE_VERBS]
    return tokens[verbs[0]].text.lower() if verbs else None


def _person_and_thing_at(tokens: Sequence[Token], mentions: Sequence[Mention], at: int) -> bool:
    """Whether a person opens at ``at``, a noun phrase right after them that names a thing
    ("Sun a coffee")."""
    who = _mention_at(mentions, at)
    if who is None or who.kind != "person" or who.possessive:
        return False
    if not opens_noun_phrase(tokens, who.end):
        return False
    return any(m.kind == "item" and who.end < m.start <= who.end + 3 for m in mentions)


def _unknown_thing_at(tokens: Sequence[Token], mentions: Sequence[Mention], at: int) -> bool:
    """Whether an article and a noun no name of the office reads open at ``at`` ("a tea"
    where the office has none): a thing all the same, whose verb is the one gapped (then
    declined or asked about as such, never lending its receiver to the thing before)."""
    if at + 1 >= len(tokens) or tokens[at].word not in _UNKNOWN_OPENERS:
        return False
    noun = _mention_at(mentions, at + 1)
    if noun is not None and noun.kind != "word":
        return False
    return language.is_noun(tokens[at + 1].word) and not tokens[at + 1].after_pause


def _for_someone_and_thing_at(
    tokens: Sequence[Token], mentions: Sequence[Mention], at: int
) -> bool:
    """Whether "for" a person or the speaker opens at ``at``, a noun phrase right after them
    that names a thing ("for me a tea", "for Sun a coffee")."""
    if tokens[at].word != "for":
        return False
    who = _mention_at(mentions, at + 1)
    if who is None or who.kind not in ("person", "self") or who.possessive:
        return False
    if not opens_noun_phrase(tokens, who.end):
        return False
    if _unknown_thing_at(tokens, mentions, who.end):
        return True  # "for me a tea": a thing the office has none of, still a thing
    return any(m.kind == "item" and who.end < m.start <= who.end + 3 for m in mentions)
