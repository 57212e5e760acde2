"""Unsupported service: "scan my contract" or "make me a cup of tea" where nothing in the
office offers it: declined, never swapped for something else; the speaker's own doing
("I need to pay the bill") beside a request is context."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.at_hand import POINTERS
from assistantx.agents.symbolic.reading.fault_subject import subject_of_fault
from assistantx.agents.symbolic.reading.name_inner_words import inside_a_name
from assistantx.agents.symbolic.reading.screen.causative_service import (
    causative_service,
    joined_service,
)
from assistantx.agents.symbolic.reading.screen.english import DETERMINERS
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.kept import kept_thing
from assistantx.agents.symbolic.reading.screen.made_product import unmade_product
from assistantx.agents.symbolic.reading.screen.outsider import outsider_recipient
from assistantx.agents.symbolic.reading.screen.passed_through import through_a_facility
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece, sub_pieces
from assistantx.agents.symbolic.reading.screen.purpose_object import used_on
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english, language

# Who a request asks ("can someone ...", "could anybody ..."): never a verb's modifier.
_ASKEES = english.words("request_askees")
# "can he get it printed": a subject pronoun before the verb is who does or has it done,
# never a noun that modifies the verb ("he" is also helium's symbol)
_SUBJECTS = english.words("subject_pronouns")
# How a thing is said to be, right after its name ("phone dead", "laptop nearly flat", "phone
# out of charge"): the word is that thing, the subject of a state, no service's verb
_STATES = tuple(
    tuple(entry.split())
    for key in ("conditions", "facility_faults")
    for entry in english.entries(key)
)


def unsupported(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if kept_thing(terms, msg.lexed, piece.text) is not None:
        return None  # "Jürgen's soup from the kitchen": his thing kept there, no service
    found = unsupported_service(terms, piece)
    if found is not None and own_doing(terms, piece) and asked_elsewhere(terms, msg, piece):
        # "I need to pay the bill. Could you bring me a calculator?": what the speaker
        # will do themselves is context for the request beside it, not asked of me
        return Finding("statement", piece, "the speaker's own doing, context only")
    if found is not None and asked_elsewhere(terms, msg, piece) and state_told(terms, piece):
        # "need a charging cable, phone at 2%": the service word is a thing, its state the
        # reason for the request beside it (a fragment with no verb), not a service asked for
        return Finding("statement", piece, "why the request is made, context only")
    outside = outsider_recipient(terms, msg, piece) if found is not None else None
    if found is not None and outside is not None:
        # "... and email them to the client": the other half cannot be done either, and is
        # said so, not asked about
        nor = f"Nor can I send anything to {outside}: I hand things only to people of this office."
        return unsupported_service(terms, piece, nor=nor)
    if found is not None and found.message.startswith(_NO_PRODUCT):
        word = found.meaning.removeprefix(_NOT_OFFERED)
        rest = doable_rest(terms, msg, piece, word)
        if rest is not None:
            # "bring a coffee to Zhang and bring for me a tea": the tea is said not to be here,
            # and the coffee still offered, never the whole message declined
            return Finding(
                "instead",
                piece,
                f"{found.meaning}; the rest still asked: {rest!r}",
                message=f"Sorry, I can't get you any {word}: nothing in this office offers "
                f"that, and I won't swap it for something else. Shall I still "
                f"{_as_told(terms, rest)}?",
                offer=rest,
            )
    return found


_NO_PRODUCT = "Sorry, I can't get you any "
_NOT_OFFERED = "not offered here: "
_JOINS = r"(?:and|then|but|also|plus)"
# the requester's words said back to them ("bring *me* a coffee" → "bring you a coffee")
_SAID_BACK = {"me": "you", "my": "your", "mine": "yours", "i": "you", "myself": "yourself"}


def doable_rest(terms: Terms, msg: Message, piece: Piece, word: str) -> str | None:
    """The message without the part of ``piece`` that asks for ``word`` (a thing nothing in
    the office offers), where that part is a request of its own (its own verb) and what is
    left still asks something (another piece's request, or another part of this piece with
    a verb of its own); None otherwise ("bring me a tea and a stapler": the stapler is no
    request of its own, the whole is declined as before)."""
    parts = sub_pieces(piece)
    lead_in = terms.en.lead_in

    def asks(part_words: list[str]) -> bool:
        return any(terms.request_verb(part_words, n) for n in range(len(part_words)))

    gone = next((p for p in parts if word in p.words), None)
    if gone is None or not asks(gone.words[gone.verb_at(lead_in) :]):
        return None
    others = [p for p in parts if p is not gone]
    # another piece asks only with a verb or a thing of its own: "could I get a coffee,
    # strong one please" says more of the coffee, no second request
    if any(asks(p.words) for p in others) or any(
        p.acts.request and (asks(p.words) or terms.names_an_item(p.text))
        for p in msg.pieces
        if p is not piece
    ):
        text = msg.text[: gone.start] + " " + msg.text[gone.end :]
    else:
        # "bring me a tea and a stapler": the thing said last in its part, another thing of
        # the office after it with no verb of its own: that thing is still asked by the verb
        after = next((p for p in others if p.start > gone.start), None)
        said = re.search(
            rf"\b(?:(?:a|an|some|any|the)\s+)?{re.escape(word)}\W*$", gone.text, re.IGNORECASE
        )
        if after is None or said is None or not terms.names_an_item(after.text):
            return None
        text = msg.text[: gone.start + said.start()] + " " + msg.text[after.start :]
    text = re.sub(rf"\b{_JOINS}\s+(?:{_JOINS}\b\s*)+", lambda m: m.group(0).split()[0] + " ", text)
    text = re.sub(rf"^[\s,.;]*{_JOINS}?\b[\s,]*", "", text, flags=re.IGNORECASE)
    text = re.sub(rf"[\s,]*\b{_JOINS}[\s,.;]*$", "", text, flags=re.IGNORECASE)
    text = re.sub(r"\s+", " ", text).strip(" ,;")
    return text or None


def _as_told(terms: Terms, rest: str) -> str:
    """What is left of a request, said back to the requester after "Shall I still ...": its
    lead-in ("could you", "please") left out, "me"/"my" said as "you"/"your"."""
    words = rest.rstrip(".!?").split()
    while words and words[0].lower().strip(",") in terms.en.lead_in and len(words) > 1:
        words = words[1:]
    said = [_SAID_BACK.get(w.lower(), w) for w in words]
    if said and said[0][:1].isupper() and said[0].lower() in terms.lex.cue_words:
        said[0] = said[0].lower()
    plain = [w.lower().strip(",.!?") for w in said]
    if said and not any(terms.request_verb(plain, n) for n in range(len(plain))):
        said = ["bring", "you", *said]  # "a tea, a stapler please": "bring you a stapler"
    return " ".join(said)


def own_doing(terms: Terms, piece: Piece) -> bool:
    """ "I need to pay ...", "we have to scan ...": the speaker's own activity ("to"
    and a verb after a first-person subject), not "I need you to ..."."""
    w = content(piece.words)
    if not w or w[0] not in terms.self_words or set(w) & {"you", "u"}:
        return False
    return "to" in w[1:4]


_WHEN = english.words("state_tails") | frozenset({"later", "now", "soon", "first", "next"})


def state_told(terms: Terms, piece: Piece) -> bool:
    """ "phone at 2%", "phone dead", "phone nearly flat": a word of a service said first,
    then how the thing it names is (a state, a level with a number) and no object: a noun
    and its state, told, never the service asked for ("phone Ana", "phone the lab")."""
    if piece.asks or piece.acts.question is not None:
        return False
    w = content(piece.words)
    while w and w[0] in ("my", "the", "our"):
        w = w[1:]
    if len(w) < 2 or w[0] not in terms.en.service_verbs or set(w) & {"you", "u", "please"}:
        return False
    rest = w[1:]
    while rest and set(language.lemmas(rest[0])) == {"ADV"} and not _level(rest):
        rest = rest[1:]  # "nearly", "almost", "completely" (never the "on" of "on 3%")
    if not rest:
        return False
    if _level(rest):
        return True  # "phone at 2%", "phone on 5 percent", "phone on nearly 3%"
    if any(tuple(rest[: len(state)]) == state for state in _STATES):
        return True  # "phone dead", "phone out of charge"
    if rest[0] in _WHEN:
        return False  # "phone later", "phone tonight": when the call is asked for
    kinds = set(language.lemmas(rest[0]))
    return "ADJ" in kinds and "VERB" not in kinds  # "phone flat", never "phone home"


def _level(words: list[str]) -> bool:
    """ "at 2%", "on 5 percent", "on about 3%": a level with its number, after "at"/"on" (an
    adverb between); the dictionary's adverb "on" ("carry on") is read here as the level's."""
    if not words or words[0] not in ("at", "on"):
        return False
    rest = words[1:]
    # "about", "nearly", and chat's hedging "like" ("on like 3%") before the number
    while rest and (rest[0] == "like" or set(language.lemmas(rest[0])) == {"ADV"}):
        rest = rest[1:]
    return bool(rest) and any(c.isdigit() for c in rest[0])


def asked_elsewhere(terms: Terms, msg: Message, piece: Piece) -> bool:
    return any(p.acts.request for p in msg.pieces if p is not piece)


def unsupported_service(terms: Terms, piece: Piece, *, nor: str = "") -> Finding | None:
    """The first service the piece asks for that nothing here offers, declined; ``nor``:
    what else in it cannot be done, said before what can."""
    before: tuple[list[str], int] | None = None
    for sub in sub_pieces(piece):
        words = sub.words
        at = sub.verb_at(terms.en.lead_in)
        while at + 1 < len(words) and (words[at] in _ASKEES or _doers(terms, words, at)):
            at += 1  # "could someone scan ...": the verb after who is asked
        caused = causative_service(terms, words, at)
        if caused is None and before is not None:
            caused = joined_service(terms, *before, words)  # "... stamped and then scanned"
        if caused is not None:  # "get my report laminated" where nothing laminates
            return decline_service(terms, piece, caused, nor=nor)
        before = (words, at)
        modified = modified_service(terms, words, at)
        if modified is not None:
            typed = r"[\s-]+".join(re.escape(w) for w in modified.split())
            said = re.search(rf"\b{typed}\b", piece.text, re.IGNORECASE)
            return decline_service(terms, piece, said.group(0) if said else modified, nor=nor)
        if (
            at < len(words)
            and words[at] in terms.en.service_verbs
            and not _subject_noun(words, at)
            and not subject_of_fault(words, at)  # "Drive in slot 4 has died": a report
        ):
            verb = words[at]
            nxt = words[at + 1] if at + 1 < len(words) else ""
            # a word said only inside a longer name of a thing ("heat" of "heat pack") is
            # no word of the office where it heads the request: it is the verb asked
            ours = verb in terms.lex.cue_words or (
                verb in terms.office_words and not _only_in_a_name(terms, words, at)
            )
            if not ours or (verb not in terms.lex.cue_words and nxt in DETERMINERS):
                if through_a_facility(terms, piece.text):
                    continue  # "feed this through the shredder": that facility's service
                return decline_service(terms, piece, verb, nor=nor)
        cue = next((n for n, w in enumerate(words) if terms.request_verb(words, n)), None)
        if cue is None:
            continue
        used = used_on(words) or range(0)  # "something to wipe up *the tea*": used on, not asked
        for n in range(cue + 1, len(words)):
            w = words[n]
            if n in used:
                continue
            if n <= cue + 2 and _for_whom(terms, words, cue + 1):
                continue  # "bring for me a tea": whom it is for, said before the thing
            if w in terms.en.modifier_prepositions or words[n - 1] in ("my", "our"):
                break
            if w in terms.en.service_products and w not in terms.office_words:
                if possessive_of_name(piece.text, w, terms.office_words):
                    continue  # "Chip's scanner": a colleague's, not "chips"
                if names_a_thing(terms, words, n):
                    continue  # "the scan settings file": a word of the file's name
                return decline_service(terms, piece, w, product=True, nor=nor)
    # "make Mark a copy of my document" where nothing copies: never the document handed over
    return unmade_product(terms, piece)


# whom a thing is for, said between the verb and the thing ("bring *for me* a tea")
_FOR = "for"
_RECEIVERS = english.words("receiver_pronouns")


def _for_whom(terms: Terms, words: list[str], at: int) -> bool:
    """Whether "for" and whom the thing is for ("me", "him", a colleague's name) stand at
    ``at``, right after the verb and before its thing ("bring for me a tea"): the receiver
    said first, as "bring me a tea" says it, so the thing after it is still read."""
    if at + 2 >= len(words) or words[at] != _FOR:
        return False
    return words[at + 1] in _RECEIVERS or terms.is_person_word(words[at + 1])


# an article opens a noun phrase: the service's word after it is a noun
_ARTICLES = frozenset({"a", "an", "the"})


def _subject_noun(words: list[str], at: int) -> bool:
    """ "the courier needs a pen": a service's word after an article and before a finite
    verb is the noun that verb's subject ends with (a person, a thing), never the service
    asked for (a verb follows no article)."""
    nxt = words[at + 1] if at + 1 < len(words) else ""
    return at > 0 and words[at - 1] in _ARTICLES and language.is_finite_verb(nxt)


def _only_in_a_name(terms: Terms, words: list[str], at: int) -> bool:
    """Whether the word at ``at`` is one the office says only inside a longer name of a
    thing, and that name is not said whole there ("heat up my lunch", not "heat pack")."""
    return words[at] in terms.name_inner_words and not inside_a_name(terms.lex, words, at)


def _doers(terms: Terms, words: list[str], at: int) -> bool:
    """Whether the word at ``at`` is a plural noun of people said as the subject of one of
    the office's own verbs of work ("can the binders repair my book", "could the IT guys fix
    it"): who does the work, asked for it, never a modifier making another service."""
    verb = words[at + 1] if at + 1 < len(words) else ""
    return (
        words[at] not in terms.office_words
        and words[at].isalpha()
        and language.is_plural_noun(words[at])
        and verb in terms.service_verbs
        and (verb in terms.lex.cue_words or verb in terms.office_words)
    )


def names_a_thing(terms: Terms, words: list[str], n: int) -> bool:
    """Whether the word at ``n`` goes on, with up to two plain nouns, to the name of a thing
    of the office ("the scan *settings file*", "the scan *log doc*"): a word of that thing's
    noun phrase, no service asked."""
    for k in range(n + 1, min(n + 4, len(words))):
        w = words[k]
        if w in terms.lex.item_heads:
            return True
        if (
            w in DETERMINERS
            or w in terms.en.modifier_prepositions
            or w in terms.office_words
            or not w.isalpha()
            or (language.is_finite_verb(w) and not language.is_noun(w))
        ):
            return False
    return False


def modified_service(terms: Terms, words: list[str], at: int) -> str | None:
    """ "3D print my model", "laser cut this", "screen print my logo": a modifier glued to
    the verb of one of the office's services makes it another service, which the office
    does not offer unless it has the modifier's word too ("laser print" where a laser
    printer is listed); the modified verb, never the plain service run instead. A modifier
    is a word with a digit ("3d"), or one the dictionary knows as a noun and not as an
    adverb or adjective ("laser", not "now", "quick" or "first"), that is none of the
    office's words and no verb that leads another ("go print it")."""
    if at + 2 < len(words) and words[at + 2] in terms.service_verbs:
        # "3-D print": a number and a letter, one modifier written in two parts
        if words[at].isdigit() and len(words[at + 1]) == 1 and words[at + 1].isalpha():
            if words[at] + words[at + 1] in terms.office_words:
                return None  # "3-D print" where the office has its "3D print"
            return f"{words[at]} {words[at + 1]} {words[at + 2]}"
    if at + 1 >= len(words) or words[at + 1] not in terms.service_verbs:
        return None
    word = words[at]
    if word in terms.office_words or word in terms.en.serial_verbs or word in _ASKEES | _SUBJECTS:
        return None  # "could someone print it": who is asked, no modifier of the verb
    if word in POINTERS or word in DETERMINERS:
        return None  # "I need this photocopied": the object before its participle
    kinds = set(language.lemmas(word))
    glued = any(c.isdigit() for c in word) and any(c.isalpha() for c in word)
    if glued or ("NOUN" in kinds and not kinds & {"ADV", "ADJ"}):
        return f"{word} {words[at + 1]}"
    return None


def decline_service(
    terms: Terms, piece: Piece, word: str, *, product: bool = False, nor: str = ""
) -> Finding:
    what = f"get you any {word}" if product else word  # "any": mass and count nouns alike
    said = [
        f"Sorry, I can't {what}: nothing in this office offers that, and I won't swap it for "
        "something else.",
        nor,
        terms.capabilities(),
    ]
    return Finding(
        "unsupported",
        piece,
        f"not offered here: {word}",
        message=" ".join(s for s in said if s),
    )


# -- rewrites ------------------------------------------------------------------------


def possessive_of_name(text: str, word: str, office_words: frozenset[str]) -> bool:
    """Whether ``word`` ("chips") is how a name's possessive ("Chip's") was folded."""
    if not word.endswith("s") or word[:-1] not in office_words:
        return False
    return re.search(rf"\b{re.escape(word[:-1])}['’]s\b", text, re.IGNORECASE) is not None
