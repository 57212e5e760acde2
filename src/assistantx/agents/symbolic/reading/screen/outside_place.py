"""A thing asked to go where someone lives or to a street: "drop Frank's drawings round to
the applicant's house on Elm Road", "take my parcel to 12 Mill Lane". The robot works inside
the office; such a place is outside it, so the request is declined in words, with the reason,
before anything in it is read as an errand (read as an errand, the drawings were fetched from
Frank and brought to the requester). Where the office has a service that sends things out
(a courier, the post) and the message names it, the place is that service's destination and
is read as before; a place of the office ("to Hal's desk", "to the post room") is no home.

An errand outside the building is declined the same way: "can you pop down to the post office
and buy a book of stamps", "get me a coffee from the place across the street", "drive over to
the client's office and pick up their contract". The robot cannot leave the building nor buy
anything, so such a request is never read as the office's own errand (a stamp fetched from a
colleague, a coffee from the office's machine). What says so (``_errand_outside``): a town's
shop or service named after a preposition ("to the post office", "from the pharmacy"), its
name the head of its phrase ("the bank holiday rota" names no bank); a phrase that places
something outside ("across the street", "in town"); an outsider's workplace ("the client's
office"); or a verb of leaving the building opening the request ("drive over to ...", "nip
out and ..."). A name of the office's own ("the post room", a facility called "the cafe")
is the office's; a send-out service named beside it sends things there, read as before."""

from __future__ import annotations

import itertools
from collections.abc import Collection, Sequence

from assistantx.agents.symbolic.reading.fault_subject import subject_of_fault
from assistantx.agents.symbolic.reading.screen.english import split_words
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.outsider import sends_its_input, sends_out
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

_HOMES = english.words("home_nouns")
_SHOPS = tuple(tuple(e.split()) for e in english.entries("outside_shops"))
_LOCATORS = tuple(tuple(e.split()) for e in english.entries("outside_locators"))
_WORKPLACES = english.words("outside_workplaces")
_OUTSIDERS = english.words("outsider_nouns")
_LEAVING = tuple(tuple(e.split()) for e in english.entries("outside_leaving_verbs"))
_COMMON = english.words("common")
# Before a town's shop: where the errand goes or comes from ("to the post office", "at the
# bank", "from the deli"), a few words back at most ("to the little deli")
_GOING = frozenset({"to", "at", "from", "into", "in", "round", "down", "over", "outside"})
_GOING_REACH = 4
# After a shop's name, words that still place it ("the deli opposite", "the bank outside")
_STILL_PLACING = frozenset({"opposite", "outside", "nearby"})
_SPEAKER = frozenset({"i", "we", "id", "im", "need", "want", "like"})
_STREETS = english.words("street_words")
_TO = frozenset({"to", "round", "over", "at"})
_REACH = 5  # "to the new applicant's house": the words between "to" and the place
# After "go", the words of going somewhere ("go to", "go down to", "go over to")
_TO_GO = frozenset({"to", "down", "over", "round", "across", "into"})
# Between a verb of going and its "to" ("get down to", "drive over to", "head back to")
_PARTICLES = frozenset({"down", "over", "round", "across", "back", "up", "out", "along"})
# A finite "be"/"have" right after the first word makes that word a subject ("mine is at the
# repair shop", "Drive has gone to the depot"): a statement, no verb told to the robot
_BE_HAVE = frozenset({"is", "was", "are", "were", "has", "had"})


def _infinitive(tokens: Sequence[Token], k: int) -> bool:
    """Whether the word at ``k``, after "to", is a verb in its plain form ("to write", "to
    check"): "to" is then the infinitive's, and what follows is the verb's object, no place
    the thing goes. A name ("to Jack's flat"), a capital, or a home's word is no verb here."""
    if k >= len(tokens):
        return False
    t = tokens[k]
    if t.possessive or not t.text[:1].islower() or t.word in _HOMES or t.word in _STREETS:
        return False
    return t.word in language.verb_lemmas(t.word)


def _purpose_going(tokens: Sequence[Token]) -> set[int]:
    """The "to"s of an infinitive of purpose's verb of going and of its place ("I need the
    keys to get to the Marsh Lane site", "an umbrella to walk down to the station"): the place
    is where the speaker goes, the reason for the thing, not where the thing is taken ("bring
    it to 12 Mill Lane" has no infinitive before its "to"). Only a verb with no object before
    its "to" is one of going ("to take it to ..." still takes the thing there)."""
    found: set[int] = set()
    for n in range(len(tokens) - 2):
        t = tokens[n + 1]
        # "drive" is a street's word too ("Elm Drive"), but never one with "to" right after it
        verb = not t.possessive and t.text[:1].islower() and t.word in language.verb_lemmas(t.word)
        if tokens[n].word != "to" or not verb:
            continue
        k = n + 2
        while k < len(tokens) and tokens[k].word in _PARTICLES:
            k += 1  # "to get down to", "to drive over to"
        if k < len(tokens) and tokens[k].word == "to":
            found |= {n, k}
    return found


def _outside_at(piece: Piece, office_at: set[int]) -> bool:
    tokens = piece.lexed.tokens
    words = [t.word for t in tokens]
    going = _purpose_going(tokens)  # "the keys to get to the site": why the thing is wanted
    for n, w in enumerate(words):
        if w != "to" or n in going or _infinitive(tokens, n + 1):
            continue  # "a pen to write the client's address with": a purpose, no destination
        for k in range(n + 1, min(n + 1 + _REACH, len(words))):
            if k in office_at:
                break  # "to Hal's desk", "to the post room": the office's own place
            if words[k] in _HOMES and k > n + 1:
                return True  # "to the applicant's house", "to her flat"
            if words[k] in _STREETS and tokens[k - 1].text[:1].isupper() and k > n + 1:
                return True  # "to 12 Mill Lane"
    return False


def _at(words: list[str], n: int, phrase: tuple[str, ...]) -> bool:
    return tuple(words[n : n + len(phrase)]) == phrase


def _shop_at(words: list[str], n: int, office_at: set[int], rooms: Collection[str]) -> int:
    """The length of a town's shop named at ``n`` as where an errand goes ("to the post
    office"), or 0. A shop's word that opens the names of the office's own places
    (``rooms``: "the cafe" of a "Cafe counter" and a "Cafe kitchen") is the office's, unless
    a phrase placing it outside follows ("the cafe round the corner")."""
    for shop in _SHOPS:
        end = n + len(shop)
        if not _at(words, n, shop) or office_at.intersection(range(n, end)):
            continue
        if " ".join(shop) in rooms and not any(_at(words, end, loc) for loc in _LOCATORS):
            continue
        nxt = words[end] if end < len(words) else ""
        if nxt and nxt not in _COMMON and nxt not in _STILL_PLACING and language.is_noun(nxt):
            continue  # "the bank holiday rota", "the shop floor": a modifier, no shop
        if any(w in _GOING for w in words[max(0, n - _GOING_REACH) : n]):
            return len(shop)
    return 0


def _errand_outside(terms: Terms, piece: Piece, office_at: set[int]) -> bool:
    """Whether the request sends the robot out of the building (see the module's note)."""
    tokens = piece.lexed.tokens
    words = [t.word for t in tokens]
    mentions = piece.lexed.mentions
    outside: list[range] = []
    # an office place, facility or colleague named as where: the errand is in the office
    in_office = any(
        m.kind in ("place", "facility") or (m.kind == "person" and not m.possessive)
        for m in mentions
    )
    verb = piece.verb_at(terms.en.lead_in)
    # "fax my letter to the bank": an office service's verb sends the thing there
    served = verb < len(words) and words[verb] in terms.service_verbs
    for n in range(len(words)):
        found = _shop_at(words, n, office_at, terms.lex.room_openers)
        if found and not (served and n >= 2 and "to" in words[n - 2 : n]):
            outside.append(range(n, n + found))
            continue
        if in_office:
            continue
        for locator in _LOCATORS:
            # "the machine round the corner": a word of the office's own things before it
            if _at(words, n, locator) and not (n and words[n - 1] in terms.office_words):
                outside.append(range(n, n + len(locator)))
        if (
            n == verb
            and any(
                _at(words, n, leaving) and not _lacking(words, n + len(leaving))
                for leaving in _LEAVING
            )
            and not subject_of_fault(words, n)  # "Drive in slot 4 has died": a report
        ):
            outside.append(range(n, n + 1))
        if (
            words[n] in _OUTSIDERS
            and tokens[n].possessive
            and n + 1 < len(words)
            and words[n + 1] in _WORKPLACES
        ):
            outside.append(range(n, n + 2))  # "to the client's office"
    if not outside:
        return False
    # a send-out service named beside it ("courier this to the bank"): its destination
    within = {k for r in outside for k in r}
    sending = terms.send_out_verbs | {
        w for f in terms.office.facilities for w in split_words(f.name) if _sends(terms, f.id)
    }
    if sends_its_input(terms, tokens, mentions):
        return False  # "send my parcel off to the deli on Mill Road": the service's destination
    return not any(w in sending for k, w in enumerate(words) if k not in within)


def _lacking(words: list[str], end: int) -> bool:
    """ "run out *of* pens": a leaving verb's "out" and then "of" is a lack, no going out ("out
    of the office" is a locator of its own)."""
    return words[end - 1 : end + 1] == ["out", "of"]


def _own_plan(terms: Terms, piece: Piece) -> bool:
    """ "I need to pop to the bank": the speaker's own going, no errand asked of anyone
    ("I need you to pop to the bank" asks it)."""
    before = piece.words[: piece.verb_at(terms.en.lead_in)]
    return bool({"i", "we", "id", "im"}.intersection(before)) and not {"you", "u"} & set(before)


def _told_to_go(terms: Terms, piece: Piece) -> bool:
    """ "drive over to ...", "run to the pharmacy and ...": a verb the office has no word for
    opening the piece, told to the robot (no "I"/"we" before it: "I need to pop to the bank"
    is the speaker's own plan); "go to ..." too, though "go" and "to" are lead-in words ("go
    print it")."""
    verb = piece.verb_at(terms.en.lead_in)
    if verb >= len(piece.words) or _SPEAKER.intersection(piece.words[:verb]):
        return False
    if subject_of_fault(piece.words, verb):
        return False  # "Drive in slot 4 has died": the subject of a fault, no command
    if piece.words[verb + 1 : verb + 2] and piece.words[verb + 1] in _BE_HAVE:
        return False  # "mine's at the repair shop": a subject and its verb, no command
    if any(a == "go" and b in _TO_GO for a, b in itertools.pairwise(piece.words[: verb + 1])):
        return True  # "go to the Starbucks across the street and ...": "go" is a lead-in word
    return bool(language.verb_lemmas(piece.words[verb]))


def _sends(terms: Terms, facility_id: str) -> bool:
    office = terms.office
    return any(office.operation(op).sends_out for op in office.facility(facility_id).operations)


def outside_place(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    del requester
    asks = piece.acts.request or piece.acts.imperative
    if not (asks or _told_to_go(terms, piece)):
        return None
    office_at = {
        k
        for m in piece.lexed.mentions
        if m.kind in ("place", "facility", "person", "group")
        for k in range(m.start, m.end)
        if not m.possessive
    }
    if _errand_outside(terms, piece, office_at) and not _own_plan(terms, piece):
        return Finding(
            "unsupported",
            piece,
            "an errand outside the office",
            message=(
                "Sorry, I can't run errands outside the office: I can't leave the building "
                "or buy anything there. I only go to people and places here. I did nothing."
            ),
        )
    if not asks or sends_out(terms, msg):
        return None
    if not _outside_at(piece, office_at):
        return None
    return Finding(
        "unsupported",
        piece,
        "a place outside the office",
        message=(
            "Sorry, I can't take things outside the office: I only go to people and places "
            "here. If someone here should have it, tell me who. I did nothing."
        ),
    )
