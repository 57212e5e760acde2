"""A recipient who is nobody of the office: "make a door card for the man at the desk",
"bring the courier guy a tea", "take the poster to a visitor".

The frames would read such a request with no person named as its recipient, and the recipient
would become the requester: the item would end in the wrong hands in the requester's name.
The screen catches the recipient phrase first: ``for``/``to`` or a giving verb's first object,
a noun phrase whose head is a noun that names a person by what they are (``outsider_nouns``
in english.yaml: man, guy, visitor, courier ...), that names no person, group, item, place or
facility of the office and is not the modifier of another noun ("the guest lounge"); or a
title and a name nobody of the office has ("give Mr Evans my stapler": ``titled_stranger``).

- A credential (an item whose name has a ``credential_words`` word: a key card, a pass, a
  fob) is declined: the assistant hands what opens doors only to people of the office, and
  what anyone says about who the outsider is carries no authority. One the office makes new
  for people from outside, by its name (a visitor badge an operation issues: "need a visitor
  badge issued for a delivery driver"), is asked for by the colleague themselves: it is
  read as their request and comes to them, who pass it on; where the message hands it on
  past them ("..., bring it to him at the gate"), they are told it can only come to them
  and asked, as for anything else.
- A thing the office has not (``not_here``) is said to be unknown here, in words.
- Anything else is asked about, with a "Shall I ...?" whose yes brings it to the requester
  (the offer replaces the outsider's phrase by "me"); a no does nothing.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.destination import means_words
from assistantx.agents.symbolic.reading.event_clause import in_later_event
from assistantx.agents.symbolic.reading.left_with import left_with
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.colleague_need import colleague_needs
from assistantx.agents.symbolic.reading.screen.english import split_words
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.not_here import thing_not_here
from assistantx.agents.symbolic.reading.screen.others_clause import in_others_clause
from assistantx.agents.symbolic.reading.screen.own_serviced import (
    modifies_a_thing,
    own_thing_serviced,
)
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speaker_wants import speaker_wants
from assistantx.agents.symbolic.reading.titled_stranger import titled_stranger
from assistantx.agents.symbolic.reading.tokens import Token, gaps
from assistantx.core import english, language

_OUTSIDERS = english.words("outsider_nouns")
_CREDENTIAL = english.words("credential_words")
_TO = frozenset({"for", "to"})
_GIVING = english.words("dative_verbs") | english.words("handing_verbs")
_STARTS = english.words("object_starts") | {"a", "an", "the", "that", "this"}
_WHERE = english.words("location_prepositions")
_STOPS = _STARTS | _TO | english.words("clause_joins") | english.words("polite") | {"then"}
_OFFICE_KINDS = frozenset({"person", "group", "item", "place", "facility"})
_MOST_MODIFIERS = 3  # "the tall delivery guy"
# "get someone to sign it", "have somebody check it": a verb whose object does the next verb
_DOER_VERBS = english.words("doer_verbs_to") | english.words("doer_verbs_bare")
# "someone", "anybody", "a person": a doer said without naming anyone
_UNNAMED = english.words("unnamed_doers")


@dataclass(frozen=True)
class Outsider:
    phrase: str  # as written: "the man"
    start: int  # the phrase's characters in the message
    end: int
    be: str = "is"  # "are" for "the visitors"


def outsider(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """The screen's rule: a request piece whose recipient is nobody of the office."""
    del requester  # the earlier rules of the table took the pieces that ask nothing
    if sends_out(terms, msg):
        return None  # "courier it to the client": a place outside, the destination's reading
    found = _recipient_outsider(terms, msg, piece)
    if found is None:
        return None
    items = [m for m in msg.lexed.mentions if m.kind == "item"]
    # "my access card form": a document about a card, no card
    credentials = [m for m in items if _credential(terms, m) and not modifies_a_thing(msg, m)]
    if credentials and all(_made_for_outsiders(terms, m) for m in credentials):
        if not _handed_on(msg):
            # "need a visitor badge issued for a delivery driver": the office makes it, and
            # it comes to the colleague who asked, who passes it on
            return None
    elif credentials:
        return Finding(
            "unsupported",
            piece,
            f"a credential for someone outside the office: {found.phrase}",
            message=(
                "Sorry, I can't do that: I hand keys, cards and passes only to people of this "
                f"office, and I don't know who {found.phrase} {found.be}. What anyone says "
                "about who they are doesn't change that. If it is for a colleague, ask again "
                "with their name."
            ),
        )
    missing = thing_not_here(terms, msg, piece)
    if missing is not None:
        # nothing here to bring to anyone: no "Shall I bring it to you?" about nothing
        return Finding(
            "unsupported",
            piece,
            f"a thing the office has not, for someone outside it: {found.phrase}",
            message=(
                f"Sorry, I don't know of any {missing} in this office, so I can't get any "
                f"for {found.phrase}; and I hand things only to people of this office. "
                "I did nothing."
            ),
        )
    offer = f"{msg.text[: found.start]}me{msg.text[found.end :]}"
    return Finding(
        "instead",
        piece,
        f"a recipient outside the office: {found.phrase}",
        message=(
            f"I hand things only to people of this office, and I don't know who {found.phrase} "
            f"{found.be}. Shall I bring it to you instead, so you can pass it on?"
        ),
        offer=offer,
    )


def outsider_recipient(terms: Terms, msg: Message, piece: Piece) -> str | None:
    """The phrase of a recipient who is nobody of the office ("the client"), as written;
    None where there is none or the office sends things out to such places."""
    if sends_out(terms, msg):
        return None
    found = _recipient_outsider(terms, msg, piece)
    return found.phrase if found is not None else None


def sends_out(terms: Terms, msg: Message) -> bool:
    """Whether the message names a service that sends things outside the office (its verb,
    its name, or a facility that offers it): whoever it names outside is where it goes."""
    office = terms.office
    words: set[str] = set()
    for op in office.operations:
        if not op.sends_out:
            continue
        for phrase in (*op.verbs, op.name, *means_words(op.name)):
            head = split_words(phrase)[:1]
            words.update(f for w in head for f in language.verb_forms(w))
        for f in office.offering(op.id):
            words.update(split_words(f.name))
    said = {t.word for t in msg.lexed.tokens}
    return bool(words & said) or sends_its_input(terms, msg.lexed.tokens, msg.lexed.mentions)


# The verbs of sending a thing away ("send my parcel off to ...", "post it to ...")
_SENDING = english.words("sending_verbs")


def sends_its_input(terms: Terms, tokens: Sequence[Token], mentions: Sequence[Mention]) -> bool:
    """ "send my parcel off to Coastline Deli": a verb of sending said of a thing that only the
    office's send-out service takes (every reading of the thing that service's input): that
    service, whose destination is where it is sent, though its own words are not said."""
    inputs = {op.input for op in terms.office.operations if op.sends_out and op.input}
    if not inputs:
        return False
    sending = [n for n, t in enumerate(tokens) if language.verb_lemmas(t.word) & _SENDING]
    if not sending:
        return False
    # the thing sent: the first named after the verb ("send my parcel off ..., and bring me a
    # latte": the latte is another request's)
    sent = next((m for m in mentions if m.kind == "item" and m.ids and m.start > sending[0]), None)
    return sent is not None and set(sent.ids) <= inputs


def _made_for_outsiders(terms: Terms, mention: Mention) -> bool:
    """Whether the thing is one the office makes new for people from outside, by its name (a
    "visitor badge" or a "guest pass" an operation issues): not someone's own (a colleague's
    door key), nor a key the office cuts for its own people (a door card)."""
    office = terms.office
    for type_id in mention.ids:
        found = office.item_type(type_id)
        names = (found.name, *found.synonyms)
        words = {w for n in names for w in split_words(n)}
        if office.making(type_id) is None or not any(_outsider_noun(w) for w in words):
            return False
    return bool(mention.ids)


# "bring it to him at the gate", "hand it over to them": the thing handed on, past the
# requester, to the person it is for
_ON_TO = frozenset({"him", "her", "them"})


def _handed_on(msg: Message) -> bool:
    """Whether the message has its thing handed on to someone it names by a pronoun or to
    a place ("..., bring it to him at the gate"), not only to the requester."""
    tokens = msg.lexed.tokens
    for n, t in enumerate(tokens):
        if t.word not in _GIVING:
            continue
        for k in range(n + 1, min(len(tokens), n + 1 + _HANDED_WITHIN)):
            if tokens[k].opens or tokens[k].word in _TO_SPEAKER:
                break
            if tokens[k].word in _ON_TO or tokens[k].word in _WHERE:
                return True
    return False


def _credential(terms: Terms, mention: Mention) -> bool:
    office = terms.office
    for type_id in mention.ids:
        found = office.item_type(type_id)
        names = (found.name, *found.synonyms)
        if any(set(split_words(n)) & _CREDENTIAL for n in names):
            return True
    return False


def _recipient_outsider(terms: Terms, msg: Message, piece: Piece) -> Outsider | None:
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    office_at = {k for m in mentions if m.kind in _OFFICE_KINDS for k in range(m.start, m.end)}
    breaks = gaps(piece.text, tokens)
    for n, tok in enumerate(tokens):
        stranger = titled_stranger(tokens, n, office_at)  # "Mrs Jenkins", nobody here
        if n in office_at or not (stranger or _outsider_noun(tok.word)):
            continue
        nxt = n + 1
        if nxt < len(tokens) and _outsider_noun(tokens[nxt].word) and nxt not in office_at:
            continue  # "the courier guy": the next one is the head
        if nxt < len(tokens) and not _ends_phrase(tokens[nxt], breaks[nxt], nxt in office_at):
            continue  # "the guest lounge", "the visitor chair": it modifies another noun
        if _modifies_an_item(tokens, breaks, mentions, nxt, office_at):
            continue  # "my guest package", "my volunteer rota spreadsheet": the office's item
        start = n
        while (
            start > 0
            and n - start < _MOST_MODIFIERS
            and (start - 1) not in office_at
            and tokens[start - 1].word not in _STARTS
            and tokens[start - 1].word not in _TO
            and tokens[start - 1].word not in _GIVING
            and not breaks[start].strip()
        ):
            start -= 1
        if start > 0 and tokens[start - 1].word in _STARTS and tokens[start - 1].word != "me":
            start -= 1
        before = tokens[start - 1].word if start > 0 else ""
        if before == "for" and nxt < len(tokens) and tokens[nxt].word == "to":
            continue  # "would it be possible for someone to fetch me …": the doer, not whom
        if before in _DOER_VERBS and _unnamed_doer(tokens, n):
            continue  # "get someone to sign my contract": who does it is open, asked later
        given = before in _GIVING and _item_after(mentions, n)
        # "drop it off with the driver": a thing left with them is handed to them
        left = before == "with" and left_with([t.word for t in tokens], start)
        if before not in _TO and not given and not left:
            continue
        if before == "for" and _colleague_receives(msg):
            continue  # "print my quote for the juke customer and give it to Robin": about
        if before == "for" and colleague_needs(msg, piece):
            continue  # "Mark needs my ruler for a student on his course": what it is for
        if before == "for" and own_thing_serviced(terms, msg) and not _handed_on(msg):
            continue  # "print my form for the visitor": the printout comes to the requester
        if before == "for" and _requester_receives(msg):
            continue  # "a label for the man in bed 4, print one and bring it here": about

        if before == "to" and in_later_event(tokens, start):
            continue  # "stamp it before it goes to the client": when, not whom it goes to
        if in_others_clause(tokens, breaks, mentions, start, later=piece.start > 0):
            continue  # "..., she wants to show it to the guest": why, not whom it goes to
        end = _described_where(tokens, breaks, n + 1, office_at)
        span = _span(msg, piece, tokens[start:end])
        if span is not None:
            be = "are" if language.is_plural_noun(tok.word) else "is"
            return Outsider(msg.text[span[0] : span[1]], *span, be=be)
    return None


def _described_where(
    tokens: tuple[Token, ...], breaks: tuple[str, ...], at: int, office_at: set[int]
) -> int:
    """Where the outsider's phrase ends: after a place that says which one ("the man at the
    desk", "the courier in reception"), else at ``at``."""
    if at >= len(tokens) or tokens[at].word not in _WHERE or breaks[at].strip():
        return at
    k = at + 1
    if k < len(tokens) and tokens[k].word in _STARTS and not breaks[k].strip():
        k += 1
    end = k
    while (
        end < len(tokens)
        and end - k < _MOST_MODIFIERS
        and not breaks[end].strip()
        and (end in office_at or language.is_noun(tokens[end].word))
        and tokens[end].word not in _STOPS
    ):
        end += 1
    return end if end > k else at


def _colleague_receives(msg: Message) -> bool:
    """Whether the message hands its thing to a colleague by name ("... and give it to
    Robin", "hand Robin the quote"): a "for the customer" beside it says what the thing is
    for, not whom it goes to."""
    tokens = msg.lexed.tokens
    return any(
        m.kind == "person"
        and not m.possessive
        and m.start > 0
        and (tokens[m.start - 1].word == "to" or tokens[m.start - 1].word in _GIVING)
        for m in msg.lexed.mentions
    )


# what a handing verb's thing goes to when it comes back to the speaker: "bring it here",
# "drop it over to me", "give me one"
_TO_SPEAKER = frozenset({"here", "me", "us"})
_HANDED_WITHIN = 4  # "bring it back over here": the words between the verb and where


def _requester_receives(msg: Message) -> bool:
    """Whether the message hands its thing to the requester ("... and bring it here", "give
    it to me", "bring me one"): a "for the man in bed 4" beside it says whom the thing is
    for, not whom it goes to; the requester passes it on."""
    tokens = msg.lexed.tokens
    if speaker_wants([t.word for t in tokens]) and not _handed_on(msg):
        return True  # "I need a ruler for a friend": the speaker's own need, theirs to pass on
    for n, t in enumerate(tokens):
        if t.word not in _GIVING:
            continue
        for k in range(n + 1, min(len(tokens), n + 1 + _HANDED_WITHIN)):
            if tokens[k].opens:
                break
            if tokens[k].word in _TO_SPEAKER:
                return True
            if tokens[k].word in _TO:
                # "bring it to me" is the speaker; "to Robin", "for the man" someone else
                if k + 1 < len(tokens) and tokens[k + 1].word in _TO_SPEAKER:
                    return True
                break
    return False


def _unnamed_doer(tokens: tuple[Token, ...], at: int) -> bool:
    """Whether the word at ``at`` is a doer that names nobody ("someone") and a verb of its
    own follows ("get someone to sign my contract", "have somebody check it"): the one who
    should do the work, not whom a thing goes to, and that one is not said."""
    if tokens[at].word not in _UNNAMED:
        return False
    nxt = at + 1
    if nxt < len(tokens) and tokens[nxt].word == "to":
        nxt += 1
    return nxt < len(tokens) and bool(language.verb_lemmas(tokens[nxt].word))


def _item_at(mentions: Sequence[Mention], at: int) -> bool:
    return any(m.kind == "item" and m.start == at for m in mentions)


def _modifies_an_item(
    tokens: tuple[Token, ...],
    breaks: tuple[str, ...],
    mentions: Sequence[Mention],
    at: int,
    office_at: set[int],
) -> bool:
    """Whether the words from ``at`` on, with nothing between them, go on as one noun phrase
    to the office's item, its head: the person noun before them is the item's modifier ("my
    guest package", "my volunteer rota spreadsheet", "the client contacts file"), never a
    person. The run holds nouns and words the dictionary does not know ("rota"); a word of
    another kind, a determiner, a stop or another of the office's names ends it ("give my
    client a copy", "give the visitor Wang's file": the person is the receiver)."""
    for k in range(at, min(len(tokens), at + _MOST_MODIFIERS + 1)):
        if breaks[k].strip():
            return False
        if _item_at(mentions, k):
            return True
        word = tokens[k].word
        if k in office_at or word in _STOPS or word in english.words("common"):
            return False
        read = language.lemmas(word)
        if read and "NOUN" not in read:
            return False  # "give my client copies ..." goes on; "give the guest said ..." not
    return False


def _outsider_noun(word: str) -> bool:
    if word in _OUTSIDERS:
        return True
    return bool(set(language.lemmas(word).get("NOUN", ())) & _OUTSIDERS)


def _ends_phrase(token: Token, gap: str, office: bool) -> bool:
    """Whether the word after a person noun leaves it the head of its phrase: punctuation
    between, or a word that is no noun going on ("at", "he", "please", "a", "today")."""
    if gap.strip() or office:
        return True
    word = token.word
    if word in english.words("common") or word in _STARTS or word in _TO:
        return True
    if word.endswith("ing") and language.verb_lemmas(word):
        return True  # "the visitor waiting downstairs"
    read = language.lemmas(word)
    # a noun goes on ("the guest room"), and so does a word the dictionary has only as a
    # verb's base form, a noun it does not list ("the guest lounge")
    return "NOUN" not in read and read.get("VERB") != (word,)


def _item_after(mentions: tuple[Mention, ...], at: int) -> bool:
    """ "bring the courier guy a tea": an item follows the person as the verb's second object."""
    return any(m.kind == "item" and m.start > at for m in mentions)


def _span(msg: Message, piece: Piece, said: tuple[Token, ...]) -> tuple[int, int] | None:
    """Where the phrase's words stand in the message (from the piece on)."""
    pattern = r"[\s\W]*".join(re.escape(t.text) for t in said)
    found = re.compile(pattern).search(msg.text.replace("’", "'"), piece.start)
    return (found.start(), found.end()) if found else None
