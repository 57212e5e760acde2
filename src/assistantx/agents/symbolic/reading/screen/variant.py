"""A made thing asked for in a variant the office does not make: "an iced tea" where the urn
makes tea, "a master key card" where the encoder makes ordinary door cards.

The office declares what each operation makes (its product); the frames read the product's
name and would make the ordinary one, dropping the words that asked for something else. The
screen reads the words right before a product's name in a request (after its determiner,
number, verb or preposition) and sorts them by what the dictionary says they are:

- an **authority** modifier (``authority_modifiers`` in english.yaml: master, all-access,
  admin, skeleton ...): more access than the office's product gives. Declined: a message
  cannot grant it, and asking "shall I make an ordinary one?" would make a credential nobody
  asked for.
- a **variant** modifier, which names a kind of the thing rather than a quality of it: a past
  participle of a process done to it ("iced", "decaffeinated", "toasted"), a noun that forms
  a compound with it ("oat", "guest", "replacement" excepted below), or a word the dictionary
  does not know ("decaf"). Asked: "Shall I make an ordinary tea instead?", a yes reading the
  request without those words, a no doing nothing.
- an adjective of quality ("strong", "quick", "hot", "large", "nice", "spare") is no variant:
  the thing is made as the office makes it. So is a replacement word ("new", "another",
  "fresh", "extra"), the participle of one of the office's own services ("printed") and
  anything after the name ("a tea, quick").

An adjective that also names a variant ("herbal", "black") the dictionary cannot tell from a
quality; where the package's table of general English things (``data/categories.yaml``)
knows the whole phrase as a thing of its own ("herbal tea", "black coffee"), it is a variant
all the same (asked), unless the office names it as an item of its own. Other adjectives are
read as qualities, on purpose.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.categories import categories
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.content_named import named_by_content
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.reason_content import content_of_a_reason
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.tokens import Token, gaps
from assistantx.core import english, language
from assistantx.core.wording import a_thing

_AUTHORITY = tuple(tuple(language.words(entry)) for entry in english.entries("authority_modifiers"))
# Words a modifier run never goes past: what starts the phrase, links it, or asks for it.
_STOPS = (
    english.words("determiners")
    | english.words("screen_determiners")
    | english.words("object_starts")
    | english.words("party_prepositions")
    | english.words("modifier_prepositions")
    | english.words("location_prepositions")
    | english.words("lead_in")
    | english.words("courtesy")
    | english.words("dative_verbs")
    | english.words("handing_verbs")
    | english.words("clause_joins")
    | english.words("self_words")
    | english.words("pronouns")
    | english.words("to_facility_prepositions")
    | english.words("from_facility_prepositions")
    | english.words("through_prepositions")
    | english.words("instrument_prepositions")
    | english.words("time_prepositions")
    | english.words("clause_breaks")
    # "three copies": how many, never a kind of copy
    | english.words("number_words")
    | {"of", "as", "then", "one", "ones", "up", "down", "back", "away", "over", "around"}
)
_QUALITY_ANYWAY = english.words("replacement_words") | english.words("service_participles")
OFFICE_KINDS = frozenset({"person", "group", "item", "place", "facility", "cue", "self"})
MOST_MODIFIERS = 3


@dataclass(frozen=True)
class Variant:
    item_type: str
    words: tuple[str, ...]  # the modifiers as written
    authority: bool
    start: int  # the modifiers' characters in the message
    end: int


def variant(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """The screen's rule: a request piece asking for a product in a variant not made here."""
    del requester  # the earlier rules of the table took the pieces that ask nothing
    found = _variant(terms, msg, piece)
    if found is None:
        return None
    office = terms.office
    kind = office.item_type(found.item_type)
    asked = a_thing(f"{' '.join(found.words)} {kind.name}", mass=kind.mass)
    if found.authority:
        return Finding(
            "unsupported",
            piece,
            f"a variant with more authority than the office makes: {asked}",
            message=(
                f"Sorry, I can't make {asked}: I can only get the ordinary {kind.name} made "
                "here, and a message cannot grant more access than that."
            ),
        )
    ordinary = a_thing(f"ordinary {kind.name}", mass=kind.mass)
    offer = f"{msg.text[: found.start]}{msg.text[found.end :].lstrip()}"
    return Finding(
        "instead",
        piece,
        f"a variant the office does not make: {asked}",
        message=(
            f"I can get {ordinary} made here, but {asked} is not something this office "
            f"makes. Shall I get you {ordinary} instead?"
        ),
        offer=offer,
    )


def _variant(terms: Terms, msg: Message, piece: Piece) -> Variant | None:
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    office_at = {k for m in mentions if m.kind in OFFICE_KINDS for k in range(m.start, m.end)}
    breaks = gaps(piece.text, tokens)
    for m in mentions:
        if m.kind != "item" or not _made_here(terms, m) or _named_for(tokens, mentions, m):
            continue
        if _in_a_proper_name(tokens, breaks, m):
            continue  # "post my parcel to Blue Kettle Coffee": a place's name, no product
        start = m.start
        while (
            start > 0
            and m.start - start < MOST_MODIFIERS
            and (start - 1) not in office_at
            and not breaks[start].strip()
            and modifier(terms, tokens[start - 1], first=start == 1)
        ):
            start -= 1
        said = tokens[start : m.start]
        if not said:
            continue
        words = tuple(t.word for t in said)
        # an authority phrase may start with a word that stops a modifier ("all-access")
        reach = tuple(t.word for t in tokens[max(0, start - 1) : m.start])
        authority = any(_has(reach, phrase) and set(phrase) & set(words) for phrase in _AUTHORITY)
        if not authority and named_by_content(terms.office, m.ids[0]):
            continue  # "Wang's budget planning file": which file, by its topic
        if (
            not authority
            and not set(words) & _FINISHES
            and _owned_made_from(terms, tokens, start, m.ids[0])
        ):
            continue  # "plot my genoa panels": made from the speaker's own, by its topic
        if not authority and content_of_a_reason(terms.office, msg, piece, m.ids[0], words):
            continue  # "Wang needs the budget printout. Print my file for him": its content
        if (
            not authority
            and not any(_names_a_kind(terms, w) for w in words)
            and not _a_thing_of_its_own(terms, words, m.ids[0])
        ):
            continue
        if authority:
            said = tokens[max(0, start - 1) : m.start] if reach != words else said
        span = span_of(msg, piece, said)
        if span is not None:
            return Variant(m.ids[0], tuple(t.text for t in said), authority, *span)
    return None


# The words a proper name after "to" or "at" may hold uncapitalised ("Bank *of* England")
_NAME_JOINS = frozenset({"of", "and", "&", "the", "on", "upon", "de", "la"})
# What opens the name of a place a thing goes to or is at
_PLACE_OPENERS = frozenset({"to", "at"})


def _in_a_proper_name(tokens: tuple[Token, ...], breaks: tuple[str, ...], m: Mention) -> bool:
    """Whether the product's name is written capitalised inside a proper name of two words or
    more, opened by "to" or "at" ("post my parcel to *Blue Kettle Coffee* on Mill Street",
    "ship it to *Coffee Republic*"): a business, a street or a town, where the thing goes;
    the office's product word in it is a part of the name, never a product asked for."""
    if not all(t.text[:1].isupper() for t in tokens[m.start : m.end]):
        return False
    start = m.start
    while start > 0 and not breaks[start].strip() and _name_word(tokens[start - 1]):
        start -= 1
    end = m.end
    while end < len(tokens) and not breaks[end].strip() and _name_word(tokens[end]):
        end += 1
    while start < m.start and tokens[start].word in _NAME_JOINS:
        start += 1  # "to the Blue Kettle Coffee": the article is no part of the name
    if start == 0 or tokens[start - 1].word not in _PLACE_OPENERS:
        return False
    return sum(1 for t in tokens[start:end] if t.text[:1].isupper()) >= 2


def _name_word(token: Token) -> bool:
    return token.text[:1].isupper() or token.word in _NAME_JOINS


def _named_for(tokens: tuple[Token, ...], mentions: tuple[Mention, ...], m: Mention) -> bool:
    """Whether the product was already asked for earlier in the piece and this mention comes
    after "for" ("make up a kit for my 10Y2 electrolysis practical"): the words there name
    what the thing is for (the lesson), not another kind of it."""
    earlier = [e for e in mentions if e.kind == "item" and e.ids == m.ids and e.end <= m.start]
    if earlier and "for" in {t.word for t in tokens[earlier[0].end : m.start]}:
        return True
    return _what_another_is_for(tokens, mentions, m)


def _what_another_is_for(
    tokens: tuple[Token, ...], mentions: tuple[Mention, ...], m: Mention
) -> bool:
    """Whether the product is what another thing asked before it is for or used on: "a foam
    board *to mount the RAG week poster*", "Drew's artwork *for the climbing soc banner*".
    The words before it say which poster the other thing serves, never a kind of it to make."""
    before = [e for e in mentions if e.kind == "item" and e.end <= m.start and e.ids != m.ids]
    if not before:
        return False
    between = [t.word for t in tokens[before[-1].end : m.start]]
    if "for" in between:
        return True
    return any(
        w == "to" and k + 1 < len(between) and language.verb_lemmas(between[k + 1])
        for k, w in enumerate(between)
    )


_OWNERS = frozenset({"my", "our", "your", "his", "her", "their"})
# how a made thing is made ("colour", "laminated"): a variant asked, whoever's it is
_FINISHES = english.words("product_finishes")


def _owned_made_from(terms: Terms, tokens: tuple[Token, ...], start: int, item_type: str) -> bool:
    """Whether the product ``item_type`` is said after whose it is ("my", "Kai's") and the
    office makes it only from something put in (a cut file, a document): the words between
    say which of their things it is made from ("my *genoa* panels"), never a kind the office
    does not make; a product made from nothing ("my iced tea") keeps its variant."""
    if start == 0:
        return False
    whose = tokens[start - 1]
    if whose.word not in _OWNERS and not whose.possessive:
        return False
    makers = [op for op in terms.office.operations if op.product == item_type]
    return bool(makers) and all(op.input is not None for op in makers)


def _made_here(terms: Terms, mention: Mention) -> bool:
    office = terms.office
    return len(mention.ids) == 1 and office.making(mention.ids[0]) is not None


def modifier(terms: Terms, token: Token, *, first: bool) -> bool:
    """Whether a word before a product's name may modify it (not a determiner, a number, a
    verb that asks for it, a preposition, a pronoun); the first word of a piece in a verb's
    plain form is the verb ("run off box labels"), not a modifier."""
    word = token.word
    if word in _STOPS or word.isdigit() or token.possessive:
        return False
    if first and word in language.verb_lemmas(word) and not _authority_word(word):
        return False
    return word not in terms.lex.cue_words and word not in terms.service_verbs


def _names_a_kind(terms: Terms, word: str) -> bool:
    """A variant's word: a process done to the thing ("iced"), a noun with no adjective
    reading ("oat", "guest"), or a word the dictionary does not know ("decaf")."""
    if word in _QUALITY_ANYWAY or word in terms.service_verbs:
        return False
    read = language.lemmas(word)
    if not read:
        return True  # "decaf": no quality the dictionary knows
    if language.is_past_participle(word):
        return True
    return "ADJ" not in read and "NOUN" in read


def _a_thing_of_its_own(terms: Terms, words: tuple[str, ...], item_type: str) -> bool:
    """Whether the modifiers and the product's name together name a thing of its own in the
    package's table of general English things (``data/categories.yaml``: "herbal tea",
    "black coffee" beside "tea" and "coffee"), one the office does not name: an adjective
    the dictionary cannot tell from a quality ("herbal", "black") still asks for a kind."""
    name = language.fold(terms.office.item_type(item_type).name)
    members = {m for c in categories() for m in c.members}
    return any(
        (said := f"{' '.join(words[-n:])} {name}") in members and said not in terms.lex.items
        for n in range(1, len(words) + 1)
    )


def _authority_word(word: str) -> bool:
    return any(word in phrase for phrase in _AUTHORITY)


def _has(words: tuple[str, ...], phrase: tuple[str, ...]) -> bool:
    n = len(phrase)
    return any(words[k : k + n] == phrase for k in range(len(words) - n + 1))


def span_of(msg: Message, piece: Piece, said: tuple[Token, ...]) -> tuple[int, int] | None:
    pattern = r"[\s\W]*".join(re.escape(t.text) for t in said)
    found = re.compile(pattern).search(msg.text.replace("’", "'"), piece.start)
    return (found.start(), found.end()) if found else None
