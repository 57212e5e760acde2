"""Work the reader has no verb for: "can you sew up the hem on my sample", "could you polish my
boots", "please tidy up my report". A plain verb asked of the robot that is no errand verb the
reader knows and no service of the office says work on its object that nothing here does, so
it never falls through to a transfer of that object (which would bring the requester their
own thing, a wrong physical action): declined, with what the office can do.

A vague verb of work ("sort out my mug", "deal with my lunch", the English data's verbs that
stand for work unnamed) on a thing of the requester's is asked where one service of the office
works on it ("Shall I heat your lunch?"; a yes runs it), left to the frames stage's question
by name where several do (``reading.work_unsaid``), and declined where none does.

Only a verb the dictionary knows as a verb, said at the head of the request (alone, or after
"can you", "please"), with a thing of the office after it and no recipient or destination
("chuck me my stapler", "pop it over to Wang" carry a thing: a known errand, read as before).
"""

from __future__ import annotations

import itertools
import re

from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece, sub_pieces
from assistantx.agents.symbolic.reading.screen.service import decline_service
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english, language
from assistantx.core.office import Office

# Every verb the English data names for a rule of the reader ("nab" of taking, "pop" of going,
# "sort" of making or of work unnamed): a verb with a rule is no unknown work.
_DATA_VERBS = frozenset(
    w
    for key, entries in english.entries_of().items()
    if key.endswith("_verbs") or key in ("destructive", "cues")
    for entry in entries
    for w in entry.split()
)
# The verbs that move a thing, whatever else the office uses them for ("get", "take", "pass"):
# never a service's verb alone ("pour" and "brew" make; "get" also fetches)
_MOVING = (
    (english.words("dative_verbs") - english.words("making_verbs"))
    | english.words("self_taking_verbs")
    | english.words("handing_verbs")
    | english.words("putting_verbs")
)
_TOSSING = english.words("tossing_verbs")
_MAKING = english.words("making_verbs")  # "make", "pour", "brew": whatever the office makes
# the making verbs said of any work at all ("make my report into a pdf", "make me a copy")
_ANY_MAKING = frozenset({"make", "do", "get", "produce", "create", "prepare"})
# The verbs that stand for work without naming it ("do", "sort", "deal", "handle").
_VAGUE = english.words("work_pro_verbs")
# what a facility named as the instrument reads the same way (``wrong_instrument``)
DATA_VERBS, MOVING, MAKING, ANY_MAKING, VAGUE = _DATA_VERBS, _MOVING, _MAKING, _ANY_MAKING, _VAGUE
_PARTICLES = english.words("verb_particles")
# Particles of carrying a thing across the office ("over", "across", "round", "back"): the
# verb moves its object, an errand however it is said
_CARRYING = english.words("errand_particles") | {"back", "along"}
# Who or where a thing goes ("to Wang", "into the meeting room", "me" after the verb)
_GOING = frozenset({"to", "into", "onto", "towards", "till", "til"})
_RECEIVERS = frozenset({"me", "us", "him", "her", "them", "everyone", "everybody"})
# "I", "we" before the verb: the speaker's own doing or need, not work asked of the robot
_SPEAKER = frozenset({"i", "id", "im", "ive", "we", "me", "to", "if", "do", "mind", "help"})
_POSSESSIVES = frozenset({"my", "our", "your"})
# Who a request before the verb is put to ("can *you* ...", "*please* ...", "could *someone*
# ..."): without one, a modal's verb is the speaker's ("could murder a coffee")
_ADDRESSED = (english.words("request_askees") - {"i", "we", "the"}) | {
    "please",
    "pls",
    "plz",
    "kindly",
}
ADDRESSED = _ADDRESSED  # the same, for ``wrong_instrument``
# "my way", "his way": whose way a thing is sent, a receiver
_WAYS_OF = frozenset({"my", "our", "his", "her", "their", "your"})
# A noun phrase's first word: the verb's object follows it at once ("polish *my* boots"), never
# a clause ("just so you know *I* need ...", "hope *you* won't mind ...")
_OPENING = english.words("determiners") - {"me"}
# The determiners that say a particular thing, one there already to work on ("*the* desk")
_DEFINITE = frozenset({"the", "this", "that", "these", "those"})
_PARTICULAR = _DEFINITE | _POSSESSIVES
_NAME_REACH = 3  # the words of a thing's name after "the": "the Amati copy", "the old desk"
_WORDS = re.compile(r"\b[^\W\d_][\w'’-]*")
# Where a thing is put, said after it ("chuck my prunings *in* the compost", "*on* charge"):
# a placement, another rule's; said before it ("the hem *on* my sample") it is the object's
_PUT = frozenset({"to", "into", "onto", "in", "on", "at", "from", "via", "inside", "under"})


def unknown_work(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """Work on a thing asked with a verb the reader has no rule for (declined), or with a
    vague verb of work (asked or declined, see the module); None for anything else."""
    for sub in sub_pieces(piece):
        words = sub.words
        at = sub.verb_at(terms.en.lead_in)
        if at >= len(words) or set(words[:at]) & _SPEAKER:
            return None  # "I need to iron my shirt": the speaker's own doing
        if at and not (piece.acts.request or piece.asks):
            return None  # asked only at the head ("varnish my desk") or in a request's words
        if at and not set(words[:at]) & _ADDRESSED:
            return None  # "could murder a coffee": the speaker's own wish, nothing asked of me
        verb = words[at]
        lemmas = language.verb_lemmas(verb) or frozenset({verb})
        if not language.lemmas(verb).get("VERB") or (
            language.is_past_verb(verb) and verb not in lemmas
        ):
            # no verb ("stapler please"), or one told ("dropped my pen"); a base form that is
            # also its past ("reset", "cut") is the verb asked
            return None
        # "pour up my impressions": a verb only of the office's services, none of which works
        # on or makes the thing after it (checked below, once the thing is read)
        misfit = _service_only(terms, verb, lemmas)
        # "tip Zhang's cable", "hurl Wang's stapler": a verb only of tossing a thing somewhere,
        # no errand's, read below on a colleague's thing said nowhere to go
        tossed = _only_tossed(terms, verb, lemmas)
        if _known(terms, verb, lemmas) and not misfit and not tossed:
            vague = bool(lemmas & _VAGUE)
            if not vague:
                return None
        else:
            vague = False
        rest = words[at + 1 :]
        particle = 0
        while particle < len(rest) and rest[particle] in _PARTICLES | {"with"}:
            particle += 1
        if set(rest) & (_GOING | _CARRYING) or (rest and rest[0] in _RECEIVERS):
            return None  # "chuck me my pen", "pop it over to Wang": carried somewhere
        whole = piece.words  # "chuck a hairnet and some tape my way": the whole list goes
        if any(w == "way" and b in _WAYS_OF for b, w in itertools.pairwise(whole)):
            return None  # "chuck a hairnet my way": towards the speaker, an errand
        after = " ".join(rest[particle:])
        lexed = terms.lex.read(after)
        if vague and (with_whom := _sorted_with(terms, piece, lexed)) is not None:
            return with_whom  # "sort out the contract thing with Wang": what, asked
        # "lacquer the violin for me": a verb with no particle on a thing said definitely is
        # work on that thing, the speaker its beneficiary ("track down a stapler for me" gets
        # one, as before)
        # "polish my boots", "engrave my ring for the customer": the speaker's own thing is
        # as particular, there already to be worked on
        worked = not particle and bool(lexed.tokens) and lexed.tokens[0].word in _PARTICULAR
        if not _object_first(lexed) or _goes_somewhere(lexed, for_self=worked):
            return None
        if tossed and not _colleagues_first(lexed, requester):
            return None  # "chuck my lunch", "tip the paper": read as before
        if at == 0 and not particle and not _opens_phrase(lexed):
            return None  # "coffee plz, double espresso": a word of the thing's kind, no verb
        whole_sub = terms.lex.read(sub.text)
        if not misfit and any(
            m.kind == "cue"
            and not _noun_use(whole_sub, m.start)
            and not _goal_after_for(whole_sub, m.start)
            for m in whole_sub.mentions
        ):
            return None  # "fire-proof my banner": the office's verb, as the lexicon reads it
        items = [m for m in lexed.mentions if m.kind == "item" and len(m.ids) == 1]
        said = " ".join(words[at : at + 1 + particle])
        if misfit:
            # "pour up my impressions in stone": the speaker's own thing, which nothing the
            # verb names works on or makes; never a transfer of it, nor the service's product
            if not (rest[particle:] and rest[particle] in _POSSESSIVES):
                return None  # "pour a water", "pour one": the service's product, as before
            owned = rest[particle + 1] if len(rest) > particle + 1 else ""
            if not any(m.kind == "item" for m in lexed.mentions) and not language.is_noun(owned):
                return None  # "pour my usual": no thing after "my", the drink asked as before
            if any(_made(terms.office, {verb, *lemmas}, m.id) for m in items):
                return None  # "pour my coffee": a thing the office makes, asked as before
            if any(m.kind in ("place", "facility") for m in lexed.mentions[1:]):
                return None  # "... in the kitchen": a placement, another rule's
            return _declined(terms, piece, said)
        if not items and not vague and _service_word_as_object(lexed):
            # "frame this print": the office's work named as a thing, worked on by a verb
            # nothing here has; never the print asked for
            return _declined(terms, piece, said)
        if not items and not vague and worked and _named_thing(lexed, _names(sub.text)):
            # "lacquer the Amati copy", "varnish the desk": a thing the office does not list,
            # which no verb of its work or errands names; a person does it, never the robot
            return _declined(terms, piece, said)
        if not items and not vague and _any_goal_after_for(whole_sub):
            # "dust my cheque for prints": the verb's goal, never the office's print run on
            # whatever the speaker's words could mean
            return _declined(terms, piece, said)
        if not items:
            return None  # "could you tidy up the kitchen": nothing of the office to carry
        thing = items[-1].id  # "the hem on my sample": the last thing said is worked on
        if {t.word for t in lexed.tokens[items[-1].end :]} & _PUT:
            return None  # "chuck my prunings in the compost": the thing put somewhere
        if not vague:
            return _declined(terms, piece, said)
        if not (rest[particle:] and rest[particle] in _POSSESSIVES):
            return None  # "sort a coffee for me": a thing got, as before
        return _asked(terms, piece, said, thing)
    return None


# How the question about vague work with a colleague opens ("What should I do about the
# document with Wang Fang?"), so the parser reads the answer against it (``answered_with``)
VAGUE_WITH = "What should I do about the "
_ASKED_WITH = re.compile(rf"^{re.escape(VAGUE_WITH)}(?P<thing>.+?) with (?P<person>.+?)\?")


def answered_with(question: str, answer: str) -> str | None:
    """The answer to the question about vague work with a colleague, with its "it" said as
    the speaker's thing and its "her"/"him"/"them" as the colleague ("take it to her" →
    "take my document to Wang Fang"); None for any other question."""
    asked = _ASKED_WITH.match(question)
    if asked is None:
        return None
    said = re.sub(r"\bit\b", f"my {asked.group('thing')}", answer, flags=re.IGNORECASE)
    return re.sub(r"\b(?:her|him|them)\b", asked.group("person"), said, flags=re.IGNORECASE)


def _sorted_with(terms: Terms, piece: Piece, lexed: Lexed) -> Finding | None:
    """A vague verb of work on a thing "with" a colleague ("can you sort out the contract
    thing with Wang"): the colleague is whom the matter is settled with, never the thing's
    receiver; what is to be done is asked, nothing moves (it was handed to Wang)."""
    words = [t.word for t in lexed.tokens]
    if "with" not in words:
        return None
    at = words.index("with")
    people = [m for m in lexed.mentions if m.kind == "person" and m.start == at + 1]
    things = [m for m in lexed.mentions if m.kind == "item" and m.end <= at]
    if len(people) != 1 or len(people[0].ids) != 1 or not things:
        return None
    person = terms.office.person(people[0].ids[0]).name
    thing = terms.office.item_type(things[-1].ids[0]).name
    question = (
        f"{VAGUE_WITH}{thing} with {person}? Tell me what you need, for example that I take it "
        f"to {person}."
    )
    return Finding("which", piece, "vague work with a colleague", message=question)


def _known(terms: Terms, verb: str, lemmas: frozenset[str]) -> bool:
    """Whether the reader has a rule for the verb: a task cue of the lexicon, a service's
    verb of this office or of the English data, or a verb the data names for another rule."""
    forms = {verb, *lemmas}
    return bool(
        forms & terms.lex.cue_words
        or forms & terms.service_verbs
        or forms & terms.en.service_verbs
        or forms & terms.office_words
        or forms & _DATA_VERBS
    )


def _only_tossed(terms: Terms, verb: str, lemmas: frozenset[str]) -> bool:
    """Whether the verb is one only of tossing a thing in or on something ("chuck", "tip",
    "hurl", "stash": english.yaml tossing_verbs), none of the office's work, task words or
    verbs of giving and fetching: with nowhere said, it never asks for the thing brought
    (fix186a class 2: "tip Zhang's cable" fetched it for the speaker)."""
    forms = {verb, *lemmas}
    return bool(forms & _TOSSING) and not (
        forms & terms.lex.cue_words
        or forms & terms.service_verbs
        or forms & terms.en.service_verbs
        or forms & terms.office_words
        or forms & _MOVING
    )


def _colleagues_first(lexed: Lexed, requester: str) -> bool:
    """Whether the words after the verb open with a colleague's possessive ("Zhang's")."""
    first = lexed.mentions[0] if lexed.mentions else None
    return (
        first is not None
        and first.start == 0
        and first.kind == "person"
        and first.possessive
        and first.ids != (requester,)
    )


def _service_only(terms: Terms, verb: str, lemmas: frozenset[str]) -> bool:
    """Whether the verb is English's for making ("pour", "brew"), a verb only of the office's
    services that take nothing in ("pour" of its water) and of no errand: what it may mean
    here is only making their products, so a
    thing of the speaker's after it is work nothing here does (fix169a class 3: "can you pour
    up my impressions in stone?" handed the requester their own impressions, or made them a
    water). A service that works on an input ("heat") declines a wrong one in its own words."""
    forms = {verb, *lemmas}
    ops = [op for op in terms.office.operations if forms & set(op.verbs)]
    if not forms & _MAKING or forms & (_MOVING | _VAGUE):
        return False  # "frank my letter": a service's own verb may work on what it is said of
    if not ops:
        # an office with no service of the verb at all ("pour up my impressions" where nothing
        # pours): the same, but for the verbs that make anything ("make my document a copy")
        return not forms & _ANY_MAKING
    return all(op.input is None for op in ops)


def _made(office: Office, forms: set[str], thing: str) -> bool:
    """Whether the verb asks for ``thing`` made: a service of the verb makes it, or the verb
    is English's for making anything ("pour my coffee" where brewing makes the coffee; never
    "steep my notebook" where a cupboard hands out notebooks)."""
    general = bool(forms & _MAKING)
    return any(
        op.product == thing and (general or forms & set(op.verbs)) for op in office.operations
    )


def _noun_use(lexed: Lexed, at: int) -> bool:
    """Whether the word at token ``at`` follows a determiner ("frame *this print*", "the
    scan"): a noun there, never the office's verb asked."""
    if at > 0 and lexed.tokens[at - 1].word in _OPENING:
        return True
    # "the Amati copy": a copy of a named instrument or model, after a capitalised name that
    # follows a determiner; never the copy operation's product
    named = lexed.tokens[at - 1] if at > 1 else None
    after = lexed.tokens[at + 1 : at + 2]
    return (
        named is not None
        and (not after or after[0].word == "for")  # "let the Gaffer sign my form": a verb
        and named.text[:1].isupper()
        and not named.opens
        and lexed.tokens[at - 2].word in _OPENING
    )


def _goal_after_for(lexed: Lexed, at: int) -> bool:
    """Whether the word at token ``at`` is a plural noun after "for" ("dust my cheque *for
    prints*", "search my bag for stamps"): what the asked verb's work looks for, its goal;
    never the office's service whose product or verb shares the word ("for printing", a
    gerund, names the service as the purpose and is no plural)."""
    before = [t.word for t in lexed.tokens[max(0, at - 2) : at]]
    if not before or not (before[-1] == "for" or before[-2:] == ["for", "any"]):
        return False
    return language.is_plural_noun(lexed.tokens[at].word)


def _any_goal_after_for(lexed: Lexed) -> bool:
    return any(m.kind == "cue" and _goal_after_for(lexed, m.start) for m in lexed.mentions)


def _service_word_as_object(lexed: Lexed) -> bool:
    """Whether the verb's object is a word of the office's work said as a noun, right after
    the determiner that opens it ("this print", "the scans")."""
    return _noun_use(lexed, 1) and any(m.kind == "cue" and m.start == 1 for m in lexed.mentions)


def _opens_phrase(lexed: Lexed) -> bool:
    """Whether the words after the verb open a noun phrase by a word that can only open one:
    a determiner ("polish *my* boots") or a colleague's possessive ("disable *Jack's* badge",
    fix180a class 1: the verb nothing here does on a colleague's thing was read as fetching
    it); never a word of the thing's own kind ("coffee plz, double espresso")."""
    if lexed.tokens[0].word in _OPENING:
        return True
    first = lexed.mentions[0] if lexed.mentions else None
    return first is not None and first.start == 0 and first.kind == "person" and first.possessive


def _object_first(lexed: Lexed) -> bool:
    """Whether the words after the verb open with its object: a determiner or possessive, or
    a thing or a colleague's possessive named at once ("mend Wang's stapler")."""
    if not lexed.tokens:
        return False
    if lexed.tokens[0].word in _OPENING:
        return True
    first = lexed.mentions[0] if lexed.mentions else None
    return (
        first is not None
        and first.start == 0
        and (first.kind == "item" or (first.kind == "person" and first.possessive))
    )


def _names(text: str) -> frozenset[str]:
    """The words capitalised inside ``text`` (not its first word), folded: names."""
    said = _WORDS.findall(text)[1:]
    return frozenset(w.lower() for w in said if w[:1].isupper() and not w.isupper())


def _named_thing(lexed: Lexed, names: frozenset[str]) -> bool:
    """Whether the words after the definite determiner name a thing: a noun, or a capitalised
    name ("the Amati copy"), with no person, place or facility among them."""
    if any(m.kind in ("person", "place", "facility") for m in lexed.mentions):
        return False
    said = [t.word for t in lexed.tokens[1:]]
    if "for" in said[1:]:
        # "varnish the desk for me", "engrave my ring for the customer": whom it is done for
        said = said[: said.index("for")]
    # the noun phrase alone, never a clause after it ("let the Gaffer sign my form")
    return 0 < len(said) <= _NAME_REACH and all(w in names or language.is_noun(w) for w in said)


def _goes_somewhere(lexed: Lexed, *, for_self: bool = False) -> bool:
    """A person named other than as an owner ("for Wang", "for me"), or a place or machine:
    the thing goes there or is done there, no work the reader lacks a verb for ("could you
    track down a stapler for me" gets one, whatever the verb). The speaker is no receiver of
    their own thing ("could you polish my stapler for me": work on it, asked of me)."""
    own = for_self or any(m.kind == "self" and m.possessive for m in lexed.mentions)
    return any(
        (m.kind == "person" and not m.possessive)
        or (m.kind == "self" and not m.possessive and not own)
        or m.kind in ("place", "facility")
        for m in lexed.mentions
    )


def _declined(terms: Terms, piece: Piece, said: str) -> Finding:
    found = decline_service(terms, piece, said)
    message = found.message.replace(
        "nothing in this office offers that", "nothing in this office does that"
    )
    return Finding("unsupported", piece, f"no work of this office: {said}", message=message)


def _asked(terms: Terms, piece: Piece, said: str, thing: str) -> Finding | None:
    """The services of the office on the requester's thing, asked: one offered; none
    declined (nothing here works on it); several left to the frames stage, which asks which
    by name and reads the answer (``reading.work_unsaid``)."""
    verbs = _services_on(terms.office, thing)
    name = terms.office.item_type(thing).name.split()[-1]
    if not verbs:
        return _declined(terms, piece, said)
    if len(verbs) == 1:
        offer = re.sub(rf"\b{re.escape(said)}\b", verbs[0], piece.text, count=1, flags=re.I)
        if offer == piece.text:  # "sort my lunch out": the particle apart from its verb
            offer = re.sub(
                rf"\b{re.escape(said.split()[0])}\b", verbs[0], piece.text, count=1, flags=re.I
            )
            # the particle left at the end ("heat my lunch out") belongs to the vague verb
            offer = re.sub(rf"\s+(?:{'|'.join(sorted(_PARTICLES))})(?=[\s.!?,]*$)", "", offer)
        return Finding(
            "instead",
            piece,
            f"vague work on a thing one service works on: {verbs[0]}",
            message=f"Shall I {verbs[0]} your {name}?",
            offer=offer,
        )
    return None


def _services_on(office: Office, thing: str) -> tuple[str, ...]:
    """The first verb of each service the office runs on an item of ``thing``'s type; its
    signable paper is also signed, and sealed where it has a seal (``reading.work_unsaid``)."""
    signing = ("sign", "seal") if office.seal_tool() is not None else ("sign",)
    return tuple(
        op.verbs[0].split()[0]
        for op in office.operations
        if op.input == thing and op.verbs and not op.sends_out and office.runnable(op.id)
    ) + (signing if thing == office.signable_type() else ())
