"""A thing asked for from a facility that the office does not list: "bring me 50 ml of
chloroform from the chem store", where the store only makes ethanol. The word that heads the
object, right before "from/at/in/out of" the facility, names the thing; when it is no item of
the office (no mention of one) and no everyday filler ("one", "some"), it is that unlisted
thing, declined by name, never swapped for what the facility makes or keeps, unless it is a
variety of the one thing the facility makes ("a flat white from the coffee machine":
``variety_of``)."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.categories import categories, is_member
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import ItemType, Office

_COMMON = english.words("common")
_FROM_WORDS = frozenset({"from", "at", "in", "of", "out"})
_VAGUE = english.words("vague_things")
_VESSELS = english.words("vessel_nouns")
_POURABLE = english.words("pourable_words")
_LEFT = english.words("left_behind_verbs")
_LEFT_SUBJECTS = english.words("left_behind_subjects")
_RELATIVES = frozenset({"that", "which"})
# the times after now ("tonight", "later on"), said after "for" ("a coffee for tonight")
_LATER = tuple(tuple(p.split()) for p in english.entries("later_times"))
_TIME_OPENERS = frozenset({"for", "by", "until", "till"})
_WHERE = frozenset({"at", "in", "on", "by", "near", "beside", "next"})
# What ends the place said after "left at": a courtesy, whom for, a time.
_PLACE_ENDS = english.words("courtesy") | {"please", "pls", "thanks", "for", "earlier", "today"}
_PLACE_ENDS |= {"yesterday", "this", "last", "and", "so", "because", "if", "when"}


def left_behind(tokens: Sequence[Token], mentions: Sequence[Mention]) -> str | None:
    """ "bring me the thing I left at the printer", "grab the stuff I forgot in the meeting
    room": a vague word for a thing ("thing", "stuff", "bits") the speaker says they left at
    a place is their own thing there, but which thing is not said: the question what it is
    ("What did you leave at the printer?"), never "left" read as a thing the office lacks."""
    words = [t.word for t in tokens]
    for n, word in enumerate(words):
        if word not in _VAGUE or n + 2 >= len(words):
            continue
        k = n + 1
        if words[k] in _RELATIVES:
            k += 1
        if k + 1 >= len(words) or words[k] not in _LEFT_SUBJECTS or words[k + 1] not in _LEFT:
            continue
        k += 2
        if k < len(words) and words[k] in ("behind", "there"):
            k += 1
        if k >= len(words) or words[k] not in _WHERE:
            return "What did you leave there, and where is it?"
        end = k + 1
        while end < len(words) and words[end] not in _PLACE_ENDS and not tokens[end].opens:
            if tokens[end].after_pause:
                break
            end += 1
        if end == k + 1:
            return None
        place = " ".join(t.text for t in tokens[k:end])
        return f"What did you leave {place}?"
    return None


def _before_time(mentions: Sequence[Mention], k: int) -> int:
    """The index of the mention before a time said after "for" that ends at ``k`` ("for
    tonight", "for later on", "by Friday"): a time is never the thing asked for, the word
    before it is; ``k`` itself where no such time ends there."""
    words = [m.ids[0] if m.kind == "word" and m.ids else "" for m in mentions[: k + 1]]
    spans = [p for p in _LATER if len(p) <= k + 1 and tuple(words[k + 1 - len(p) : k + 1]) == p]
    if language.is_weekday(words[k]):
        spans.append((words[k],))
    for p in sorted(spans, key=len, reverse=True):
        at = k - len(p)
        if at >= 0 and words[at] in _TIME_OPENERS:
            return at - 1
    return k


def unlisted_thing(mentions: Sequence[Mention]) -> tuple[str, str] | None:
    """The unlisted thing asked for from a facility and that facility's id, or None."""
    for n, m in enumerate(mentions):
        if m.kind != "facility" or n < 2:
            continue
        k = n - 1
        while k >= 0 and mentions[k].kind == "word" and mentions[k].ids[0] in _FROM_WORDS:
            k -= 1  # "out of the store", "from the store"
        if k == n - 1 or k < 0:
            continue
        k = _before_time(mentions, k)  # "a couple of comps for tonight from the box office"
        if k < 0:
            continue
        head = mentions[k]
        if head.kind != "word" or head.possessive:
            continue
        word = head.ids[0]
        if word in _COMMON or not word.isalpha() or len(word) < 3:
            continue
        return head.text.lower(), m.ids[0]
    return None


def variety_of(
    office: Office, mentions: Sequence[Mention], facility_id: str
) -> tuple[tuple[str, ...], str] | None:
    """ "a chocolate bar from the vending machine", "a flat white from the coffee machine": an
    unlisted thing asked for from a facility that makes one product and keeps nothing, where
    the thing and the product are of one kind of the categories' table (a snack, a hot
    drink): the words that named it and the product's name, so the request is read as for
    the product. A thing of no shared kind ("chloroform" from a store that makes ethanol) is
    still declined by name."""
    source = _sole_product_source(office, mentions, facility_id)
    if source is None:
        return None
    product, k = source
    k = _before_time(mentions, k)  # "a flat white for tonight from the coffee machine"
    said: list[str] = []
    while k >= 0 and len(said) < 3 and _plain_word(mentions[k]):
        said.insert(0, mentions[k].ids[0])
        k -= 1
    for n in range(len(said)):  # the longest phrase first: "chocolate bar", then "bar"
        if _same_kind(" ".join(said[n:]), (product.name, *product.synonyms)):
            return tuple(said[n:]), product.name
    return None


def _sole_product_source(
    office: Office, mentions: Sequence[Mention], facility_id: str
) -> tuple[ItemType, int] | None:
    """The one product of a facility that keeps nothing for anyone, and the mention index of
    the last word said before "from"/"of" and the facility's name; None where the facility
    makes several things or none, keeps supplies, or is not said after such a word."""
    facility = office.facility(facility_id)
    if len(facility.products) != 1 or facility.supplies:
        return None
    at = next(
        (n for n, m in enumerate(mentions) if m.kind == "facility" and m.ids == (facility_id,)),
        None,
    )
    if at is None:
        return None
    k = at - 1
    while k >= 0 and mentions[k].kind == "word" and mentions[k].ids[0] in _FROM_WORDS:
        k -= 1
    if k == at - 1:
        return None
    return office.item_type(facility.products[0]), k


def vessel_of(
    office: Office, mentions: Sequence[Mention], facility_id: str
) -> tuple[tuple[str, ...], str] | None:
    """ "fill me a wash bottle of milli-q", "a jug from the urn", "a flask of the dewar": a
    vessel the office does not list (a word no name reads), said of or from a facility that
    makes one product to be poured (one of its names has a word of ``pourable_words``) and
    keeps nothing, is asked for that product: the vessel's words and the product's name, so
    the request is read as for the product. A facility that makes nothing, or several things,
    or things that are not poured (printouts) is no such source; the vessel is declined."""
    source = _sole_product_source(office, mentions, facility_id)
    if source is None:
        return None
    product, k = source
    names = (product.name, *product.synonyms)
    if not any(w in _POURABLE for name in names for w in language.words(name)):
        return None
    if k < 0 or not _plain_word(mentions[k]):
        return None
    if mentions[k].ids[0] not in _VESSELS:
        return None
    said = [mentions[k].ids[0]]
    if k > 0 and _plain_word(mentions[k - 1]):  # "a *wash* bottle"
        said.insert(0, mentions[k - 1].ids[0])
    return tuple(said), product.name


def _plain_word(m: Mention) -> bool:
    word = m.ids[0] if m.ids else ""
    return m.kind == "word" and not m.possessive and word.isalpha() and word not in _COMMON


def _same_kind(thing: str, product_names: Sequence[str]) -> bool:
    """Whether the thing and one of the product's names are of one category of the table."""
    return any(
        is_member(c, thing) and any(is_member(c, p) or p in c.names for p in product_names)
        for c in categories()
    )
