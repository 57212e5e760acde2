"""Destructive: "throw away Wang's stapler", "hide ...", "get rid of ...": declined, unless
the office offers it as a service ("shred" where a shredder is). So is a request that puts a
thing into a waste container ("chuck Reed's clipboard in the skip"), whatever its verb: a
verb the reader does not know must not turn disposal into an errand, and the container, no
place of the office, is no destination to deliver to.

A verb that destroys only what it is said of ("rip up", "cut up", "snap": english.yaml
destructive_of_others) is declined when its object is a colleague's thing ("cut up Ana's
contract", "tear Ana's notes up"): that thing is never fetched for it. Said of the speaker's
own or of no one's ("cut up my old draft", "snap a photo of the board") it reads as before.
So is a service asked for a result of damage on a colleague's thing ("put Ana's jumper through
the washer so it shrinks"; english.yaml damage_results)."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.english import DETERMINERS, starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.named_words import named_at
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece, sub_pieces
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.screen.verb_in_item_name import opens_item_name
from assistantx.core import english, language

# "in the skip", "into a bin", "to the rubbish": where a put-request sends its thing.
_INTO = english.words("to_facility_prepositions") | {"down"}
# "mine went in the compost": a word the speaker names themself or their own with is the
# subject, never a verb in its plain form (though "mine" is one too).
_SELF = english.words("self_words")


def destructive(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    names = terms.lex.items.keys() | terms.lex.facilities.keys()  # spelled as said
    for sub in sub_pieces(piece):
        at = sub.verb_at(terms.en.lead_in)
        for verb in terms.en.destructive:
            if verb[0] in terms.lex.operation_words:
                continue  # "shred my drafts" where a shredder is offered: a service
            if len(verb) == 1 and _onto_a_service(terms, piece):
                continue  # "throw my radio on the charger": put there for its service
            if starts_with(sub.words, at, verb):
                if len(verb) == 1 and named_at(piece, sub, at):
                    continue  # "Bin needs a stapler": a colleague called Bin, no verb
                if opens_item_name(piece, sub, at, len(verb), names):
                    continue  # "bin bags to desk 5": the office's supply of that name
                return _declined(terms, piece, " ".join(verb))
        for verb in terms.en.destructive_of_others:
            if verb[0] in terms.lex.operation_words:
                continue  # the office's own work by that verb: a service
            if opens_item_name(piece, sub, at, len(verb), names):
                continue  # "cut flowers for Ana's desk": the office's thing of that name
            owner = _others_object(terms, piece, sub.words, at, verb, requester)
            if owner is not None:
                return _declined(terms, piece, f"{' '.join(verb)} {owner}'s things", what="")
    if commanded(terms, piece) and _damage_meant(msg, piece):
        owner = _colleague(terms, piece, requester)
        if owner is not None:
            # "put Ana's jumper through the washer so it shrinks": a service asked to damage
            # a colleague's thing; "wash my jumper on 90" or a wash for a stain is read as ever
            return _declined(terms, piece, f"damage {owner}'s things", what="")
    if commanded(terms, piece) and (found := _waste_container(terms, piece)) is not None:
        container, offered = found
        if not offered:
            return _declined(terms, piece, f"put things in the {container}", what="")
        owner = _colleague(terms, piece, requester)
        if owner is not None and piece.acts.statement:
            # "chuck Ellis's drawings in the recycling": the office's own disposal, by a
            # verb that is no errand, of a colleague's thing: refused, not noted as told
            return _declined(terms, piece, f"put {owner}'s things in the {container}", what="")
    if commanded(terms, piece) and (said := _thrown_away(terms, piece)) is not None:
        return _declined(terms, piece, said, what="")
    return None


_DRAINS = tuple(tuple(p.split()) for p in english.entries("drain_places"))
_DISCARDING = english.words("discarding_verbs")
_AWAY = english.words("discarding_particles")
# Who a thing thrown "out" goes to after all ("chuck me out a pen", "tip some out for Wang")
_RECEIVING = english.words("receiver_pronouns") | {"for", "to"}


def _thrown_away(terms: Terms, piece: Piece) -> str | None:
    """What the request throws away, said as the refusal names it: its thing sent "down the
    drain" (or the sink, the loo) whatever the verb, emptied "into the sink" by a verb of
    discarding, or thrown "away"/"out" by one ("chuck Zhang's cable out", "pour away Wang's
    coffee") with no one it goes to. A verb of the office's own work or of giving ("take it
    out", "print out my report") and a verb of storing ("stash it away") are never one."""
    words = piece.words
    at = piece.verb_at(terms.en.lead_in)
    if at >= len(words):
        return None
    verb = words[at]
    forms = {verb, *language.verb_lemmas(verb)}
    discarding = bool(forms & _DISCARDING)
    served = bool(forms & terms.lex.operation_words)  # "pour out a coffee": the office's work
    for n in range(at + 1, len(words)):
        word = words[n]
        k = n + 1
        while k < len(words) and words[k] in DETERMINERS:
            k += 1
        drain = next((d for d in _DRAINS if starts_with(words, k, d)), None)
        if drain is not None and (word == "down" or (discarding and word in _INTO)):
            return f"pour things down the {' '.join(drain)}"
        if word not in _AWAY or not discarding or (served and word != "away"):
            continue  # "pour away" throws away even where the office pours
        if not (k < len(words) and words[k] == "of"):
            if not set(words[at + 1 :]) & _RECEIVING:
                return f"{verb} things {word}"
    return None


_RESULT_OPENERS = tuple(tuple(p.split()) for p in english.entries("damage_result_openers"))
_DAMAGE = tuple(tuple(p.split()) for p in english.entries("damage_results"))
_DIRT = english.words("dirt_nouns")
_NOT = english.words("statement_negations") | {"not", "never", "without", "less"}
_RESULT_REACH = 4  # "so *the pins* break", "till *the print on it* comes off"


def _damage_meant(msg: Message, piece: Piece) -> bool:
    """Whether the piece, or the one right after it, says its request is for damage: a word
    that opens a result ("so", "till", "until", "so that"), then within a few words a result
    of damage ("it shrinks", "it's burnt", "the pins break", "it stops working"), whose
    subject is no dirt ("till the stain comes off": cleaning)."""
    after = [p for p in msg.pieces if p.start >= piece.end][:1]
    for part in (piece, *after):
        words = [w for w in part.words if w not in ("its", "it", "is", "gets", "get")]
        for n in range(1, len(words)):
            opener = next((o for o in _RESULT_OPENERS if starts_with(words, n, o)), None)
            if opener is None:
                continue
            start = n + len(opener)
            for k in range(start, min(len(words), start + _RESULT_REACH)):
                found = next((d for d in _DAMAGE if starts_with(words, k, d)), None)
                if found is None:
                    continue
                # "so it doesn't break": kept from harm; "till the stain comes off": cleaned
                if not set(words[start:k]) & (_DIRT | _NOT):
                    return True
    return False


_DETERMINERS = frozenset({"the", "that", "this", "those", "these"})
_INSIDE = frozenset({"in", "inside", "from"})


def _others_object(
    terms: Terms,
    piece: Piece,
    words: list[str],
    at: int,
    verb: tuple[str, ...],
    requester: str,
) -> str | None:
    """The colleague whose thing is the object of ``verb`` at ``at``, by name: their
    possessive name right after the whole verb ("rip up Ana's notes"), or right after its
    first word with the rest of the verb after the thing ("rip Ana's notes up")."""
    if not words or at >= len(words) or words[at] != verb[0]:
        return None
    if starts_with(words, at, verb):
        after = at + len(verb)
        owner = _possessive_at(terms, piece, words, after, requester)
        if owner is None and after < len(words) and words[after] in _DETERMINERS:
            # "melt down the ring in Colin's job bag": a thing said to be in a colleague's
            # container is theirs
            inside = (k for k in range(after + 2, after + 5) if k < len(words))
            at_inside = next((k for k in inside if words[k] in _INSIDE), None)
            if at_inside is not None:
                owner = _possessive_at(terms, piece, words, at_inside + 1, requester)
        return owner
    if len(verb) == 1:
        return None
    owner = _possessive_at(terms, piece, words, at + 1, requester)
    if owner is None:
        return None
    rest = verb[1:]
    # the thing named after the name: a few words, then the rest of the verb
    return owner if any(starts_with(words, k, rest) for k in range(at + 3, at + 7)) else None


def _possessive_at(
    terms: Terms, piece: Piece, words: list[str], at: int, requester: str
) -> str | None:
    """The colleague named with 's at word ``at`` ("Ana's", "Sun Li's"), by name."""
    if at >= len(words):
        return None
    tokens = piece.lexed.tokens  # "Reed's" is the token "reed", the word "reeds"
    for m in piece.lexed.mentions:
        if m.kind != "person" or not m.possessive or len(m.ids) != 1:
            continue
        if m.ids[0] == requester:
            continue
        if words[at] in (tokens[m.start].word, tokens[m.start].word + "s"):
            return terms.office.person(m.ids[0]).name
    return None


def _onto_a_service(terms: Terms, piece: Piece) -> bool:
    """Whether the piece puts its thing on or into a facility of the office that runs an
    operation ("throw my radio on the charger", "toss it in the laminator"): the verb only
    says how it is put there for that work, nothing is disposed of."""
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    for m in mentions:
        if m.kind != "facility" or not terms.office.facility(m.ids[0]).operations:
            continue
        k = m.start - 1
        while k >= 0 and tokens[k].word in DETERMINERS:
            k -= 1
        if k > 0 and tokens[k].word in _INTO:
            return True
    return False


def _colleague(terms: Terms, piece: Piece, requester: str) -> str | None:
    """The colleague whose thing the piece names ("Ellis's drawing set"), by name; none
    where a name opens the piece ("Mark's drawings went in the recycling": told, the name
    no verb)."""
    mentions = piece.lexed.mentions
    if mentions and mentions[0].start == 0 and mentions[0].kind == "person":
        return None
    for m in mentions:
        if m.kind == "person" and m.possessive and len(m.ids) == 1 and m.ids[0] != requester:
            return terms.office.person(m.ids[0]).name
    return None


def commanded(terms: Terms, piece: Piece) -> bool:
    """Whether the piece tells the robot to do something: request wording, or a verb in its
    plain form first, after any lead-in or not ("chuck ...", "ditch ...", "go to Zhang's desk
    and take ..."), a verb the office's words need not know."""
    if piece.acts.request:
        return True
    words = piece.words
    at = piece.verb_at(terms.en.lead_in)
    return any(
        k < len(words) and words[k] not in _SELF and words[k] in language.verb_lemmas(words[k])
        for k in {0, at}
    )


def _waste_container(terms: Terms, piece: Piece) -> tuple[str, bool] | None:
    """The waste container a request puts its thing into ("in the skip"), and whether the
    words are the office's own facility ("the confidential recycling bin", a service there)
    or its own service ("in the compost" where composting is offered: the service asked)."""
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    words = [t.word for t in tokens]
    for n, word in enumerate(words):
        if word not in _INTO or n == 0:
            continue
        k = n + 1
        while k < len(words) and words[k] in DETERMINERS:
            k += 1
        for phrase in terms.en.waste_containers:
            end = k + len(phrase)
            if not starts_with(words, k, phrase):
                continue
            if _named_person(mentions, k, end):
                continue  # "send my file to Skip": a colleague so called (container_names)
            office_name = any(
                m.kind in ("facility", "item", "place") and m.start < end and k < m.end
                for m in mentions
            ) or any(w in terms.lex.operation_words for w in phrase)
            return " ".join(phrase), office_name
    return None


def _named_person(mentions: Sequence[Mention], start: int, end: int) -> bool:
    """Whether the container's words at ``start`` are read as a colleague's name: "to Skip",
    "Bin's", or "to skip" while asked whom (or what) is meant. After an article the name
    reading makes them the word ("in the skip"), so the container stays."""
    return any(m.kind == "person" and m.start == start and m.end <= end for m in mentions)


def _declined(terms: Terms, piece: Piece, said: str, what: str = " anything") -> Finding:
    return Finding(
        "destructive",
        piece,
        f"destructive: {said}",
        message=(
            f"Sorry, I won't {said}{what}: I don't dispose of, damage or take "
            f"people's things. {terms.capabilities()}"
        ),
    )
