"""Statement: "my laptop cable is too short", "I spilled my tea", "tea time soon": context
beside a request, with the items and people it names for the rewrites.

Told with no verb or subject the speech acts read: a remark on the day ("so misty today",
``remark``), a thing's need for work nobody here does ("the holly needs watering",
``unserved_need``), the speaker's own lack with no request ("out of pens at home, I'll grab
some on my way back", ``own_lack``), and what is said to whoever owns a thing ("whoever's mug
this is, take it home", ``told_to_whoever``)."""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading._objects import modifiers
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.obligation import PERSON_WORK, obliged_to, obliged_verb
from assistantx.agents.symbolic.reading.screen.english import starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.screen.title_cased_part import title_cased_part
from assistantx.agents.symbolic.reading.speaker_lack import given_thing, speaker_lacks
from assistantx.agents.symbolic.reading.speech import content
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language, wording
from assistantx.core.english import entries as english_entries
from assistantx.core.english import words as english_words
from assistantx.core.office import Facility
from assistantx.core.task_schema import Evidence


def statement(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if title_cased_part(msg, piece):
        return None  # "..., School of Pharmacy, King's Building": a name said on, no clause
    if conditional_addition(msg, piece):
        return None  # "bring me a hard hat. and a tea if the kettle's on": the tea asked too
    if obligation_asked(msg, piece):
        return None  # "Zhang has to sign my lease, can you sort that": what "that" asks
    if owner_work_asked(msg, piece):
        return None  # "Robin has to sign my condition report.": its owner asks for it
    if destination_stated(terms, msg, piece):
        return None  # "my parcel has to go off to Galway, post it": where "it" goes
    if not piece.asks and context_fragment(terms, msg, piece):
        # "Min's been asking for crisps. get her a bag": the one it is about, for "her"
        people = tuple(f"person:{p}" for p in terms.named(piece.lexed, "person"))
        return Finding("statement", piece, "context beside the request", context=people)
    if not piece.asks and verbless_aside(terms, msg, piece):
        return Finding("statement", piece, "an aside beside the request, context only")
    if not piece.asks and generic_explanation(terms, msg, piece):
        return Finding("statement", piece, "why the request is made, context only")
    if plea_to_others(msg, piece):
        return Finding(
            "statement",
            piece,
            "a plea to others, asking nothing of the assistant",
            message=(
                "I hear you, but that's said to whoever is doing it: I don't know who they "
                "are, so I can't pass it on or do anything about it."
            ),
        )
    if told_to_whoever(msg, piece):
        return Finding("statement", piece, "said to whoever owns the thing, context only")
    if not piece.asks and remark(terms, piece):
        return Finding("statement", piece, "a remark on the day, context only")
    if not piece.asks and unserved_need(terms, piece):
        return Finding("statement", piece, "a thing's need for work nobody here does, context only")
    if not piece.asks and own_lack(terms, msg, piece):
        return Finding("statement", piece, "the speaker's own lack, asking nothing")
    if (
        not piece.asks
        and own_supply(piece.words)
        and any(own_lack(terms, msg, p) for p in msg.pieces if p is not piece)
    ):
        return Finding("statement", piece, "the speaker's own plan to get more, context only")
    offered = lack_offer(terms, msg, piece) if not piece.asks else None
    if offered is not None:
        return offered
    praise = not piece.asks and praise_remark(piece)
    told = praise or lack_beside_request(terms, msg, piece)
    if not told and (piece.asks or not piece.acts.statement):
        return None
    named = (
        tuple(stated_items(terms, piece, requester) or one_held(terms, msg, piece))
        + tuple(f"person:{p}" for p in terms.named(piece.lexed, "person"))
        + tuple(f"product:{p}" for p in stated_products(terms, piece))
    )
    said = "praise for someone's work" if praise else "a statement"
    return Finding("statement", piece, f"{said}, context only", context=named)


# Words before a thing added to the request before it ("*oh and* a tea ..."), the article of
# the thing, and the words after it before its condition ("a tea *too* if ...").
_ADDING = frozenset({"oh", "ah", "and", "also", "plus", "maybe"})
_ONE_OF = frozenset({"a", "an", "some", "one", "another", "any"})
_AS_WELL = frozenset({"too", "as", "well", "also", "please", "pls", "plz"})


def conditional_addition(msg: Message, piece: Piece) -> bool:
    """ "could you bring me a hard hat? and a tea if the kettle's on", "... a tea too if it's
    no trouble": after a request, one more thing named with no verb of its own and a
    condition on whether it can be had ("if" and what follows) is that thing asked for too,
    not a statement: the condition is about availability, which the errand finds out (a
    thing that cannot be had is said so at the end, never dropped in silence)."""
    if not any(p.acts.request for p in msg.pieces if p.end <= piece.start):
        return False
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    words = [t.word for t in tokens]
    if "if" not in words:
        return False
    cut = words.index("if")
    k = 0
    while k < cut and words[k] in _ADDING:
        k += 1
    if k >= cut or words[k] not in _ONE_OF:
        return False
    k += 1
    thing = next((m for m in mentions if m.start == k), None)
    if thing is None or thing.kind != "item":
        return False
    rest = words[thing.end : cut]
    return all(w in _AS_WELL for w in rest) and cut + 1 < len(words)


def obligation_asked(msg: Message, piece: Piece) -> bool:
    """ "Zhang has to sign my lease, can you sort that": a person obliged to do a person's
    work, then a request that names nothing of its own ("sort that", "arrange it"): the
    statement is what the request asks for, not context beside it. A request for that same
    work done to the thing, with no doer ("Zhang Wei has to sign my contract. Can you get it
    signed and back to me?"), names nothing of its own either: the work said again, and the
    fetching it takes ("get ... signed"); so does one that only takes the thing to them and
    back ("Rose has to sign off my timesheet. could you take it to her and bring it back?")."""
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    words = [t.word for t in tokens]
    work: set[str] = set()
    for m in mentions:
        if m.kind != "person" or m.possessive or not obliged_to(words, m.end, PERSON_WORK):
            continue
        verb = obliged_verb(words, m.end)
        work.update(x.ids[0] for x in mentions if x.kind == "cue" and x.start == verb and x.ids)
        work.add("")  # a person obliged: asked for by a request that names nothing
    if not work:
        return False
    later = [p for p in msg.pieces if p.start > piece.end and p.acts.request]
    if not later:
        return False
    for p in later:
        cues = [m for m in p.lexed.mentions if m.kind == "cue"]
        # the work said again as done to the thing ("get it *signed*"), never a doer's verb
        # ("get her to sign it": her own doing, read by the request itself)
        again = any(
            m.ids and m.ids[0] in work and p.lexed.tokens[m.start].word in _PARTICIPLES
            for m in cues
        ) or any(t.word in _WORK_DONE for t in p.lexed.tokens)  # "get that done"
        # "take it to her and bring it back": the thing's way to the one obliged and back,
        # the trip the work takes (its doer said only by a pronoun, no one else named)
        trip = any(t.word == "back" for t in p.lexed.tokens)
        for m in p.lexed.mentions:
            if m.kind in ("item", "person", "facility"):
                return False
            moves = m.ids[:1] == ("give",)
            if m.kind == "cue" and not (
                (again and (moves or m.ids[0] in work)) or (trip and moves)
            ):
                return False
    return True


def owner_work_asked(msg: Message, piece: Piece) -> bool:
    """ "Robin has to sign my condition report before it goes back": someone's work by hand
    on the speaker's own thing, in a message that asks nothing else, is the owner's request
    for that work. Beside a request of its own ("..., can you bring me a loupe") it is the
    reason for that request, context."""
    if not piece.acts.owner_work:
        return False
    return not any(p.acts.request for p in msg.pieces if p is not piece)


_COPULAS = english_words("copulas")
_PARTICIPLES = english_words("service_participles")
# the work said again without its verb ("could you get that *done*", "have it *sorted*")
_WORK_DONE = frozenset({"done", "sorted", "handled"})

# The words of going before a statement's destination ("has to go *off to* Galway"); the
# readings stage (``destination``) reads the same "to" as where a send-out sends "it".
# ("go *back* to the supplier": the thing goes there all the same)
_GOING = frozenset({"go", "goes", "going", "gone", "out", "off", "away", "over", "back"})
_OBJECT_PRONOUNS = frozenset({"it", "them", "this", "that"})


# "this form needs to go by courier to ...", "my parcel has to go off to ... by post": the
# thing said (with "this"/"my"/a name's), the obligation to go, and what follows it
_GOES_BY = re.compile(
    r"\b(?P<thing>(?:this|these|that|those|my|our|the|[^\W\d_][\w-]*['’]s)"
    r"(?:\s+[\w-]+){1,4}?)\s+"
    r"(?:needs?\s+to|ha(?:s|ve)\s+(?:got\s+)?to|should|must|is\s+to|are\s+to|ought\s+to)"
    r"\s+go\b(?P<rest>[^.!?;]*)",
    re.IGNORECASE,
)
_BY_MEANS = re.compile(r"\b(?:by|via)\s+(?P<means>[^\W\d_]+)\b", re.IGNORECASE)


def sent_by_means(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """ "this form needs to go by courier to Harrow Homes, 3 Kiln Lane": a thing of the
    office that has to go somewhere by the means of one of its send-out services (a verb or
    the means of its name: "by courier", "by post") asks for that service, read as "send
    this form by courier to ..."; the thing keeps its words ("this form": the speaker's). A
    thing that only has to go somewhere ("has to go to Lee") is read as before."""
    for found in _GOES_BY.finditer(text):
        rest = found.group("rest")
        means = _BY_MEANS.search(rest)
        if means is None or language.fold(means.group("means")) not in terms.send_out_verbs:
            continue
        if not re.search(r"\bto\b", rest, re.IGNORECASE):
            continue
        thing = found.group("thing")
        if not terms.names_an_item(thing):
            continue
        said = f"send {thing}{rest}"
        evidence = Evidence(words=found.group(0).strip(), meaning=said.strip())
        return text[: found.start()] + said + text[found.end() :], [evidence]
    return text, []


def destination_stated(terms: Terms, msg: Message, piece: Piece) -> bool:
    """ "my parcel has to go off to Galway Hostel, post it off please": a statement that an
    item goes somewhere ("to" after a word of going), followed in the next piece by a
    request that sends "it" out with one of the office's send-out services, says where the
    request sends it: it stays with the request, not set aside as context."""
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    words = [t.word for t in tokens]
    if not any(m.kind == "item" for m in mentions):
        return False
    if not any(w == "to" and words[k - 1] in _GOING for k, w in enumerate(words) if k):
        return False
    later = [p for p in msg.pieces if p.start > piece.end][:3]
    request = next((p for p in later if p.acts.request), None)
    if request is None:
        return False
    said = [t.word for t in request.lexed.tokens]
    return any(
        w in terms.send_out_verbs and k + 1 < len(said) and said[k + 1] in _OBJECT_PRONOUNS
        for k, w in enumerate(said)
    )


# what a verb's object may open with: with one of these after it, the word is a verb
_OBJECT_OPENERS = english_words("object_starts") | frozenset({"me", "us", "it", "them", "one"})


def verbless_aside(terms: Terms, msg: Message, piece: Piece) -> bool:
    """ "need the kick stool from Page's desk, reserve shelf again": a trailing fragment
    after a request whose first word, a service's verb or any other verb, is followed by a
    bare noun the office does not know ("reserve shelf", "print room"), and that names
    nothing of the office, is a noun compound said in passing, not a second request."""
    if not any(p.acts.request for p in msg.pieces if p.end <= piece.start):
        return False
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    if any(m.kind not in ("word", "cue") for m in mentions) or len(tokens) < 2:
        return False
    head, noun = tokens[0].word, tokens[1].word
    verb = head in terms.lex.cue_words or head in terms.en.service_verbs
    if not verb or noun in _OBJECT_OPENERS or noun in terms.thing_words:
        return False
    if tokens[1].possessive or not language.is_noun(noun) or language.is_finite_verb(noun):
        return False
    # nothing after the compound but words that are no object either ("again", "today"),
    # or the compound is the subject of a verb ("reserve shelf is full again")
    rest = [t.word for t in tokens[2:]]
    if rest and (rest[0] in _COPULAS or language.is_finite_verb(rest[0])):
        return True
    return not any(language.is_noun(w) and w not in terms.en.courtesy for w in rest)


# the subject's verb after a plural noun: "books need moving", "the files are heavy",
# "boxes will pile up" (a modal); any other verb form is read from the dictionary
_SUBJECT_VERBS = _COPULAS | english_words("request_modals")


def generic_explanation(terms: Terms, msg: Message, piece: Piece) -> bool:
    """ "can u fetch Dara's book cart? storybooks need moving": after a request, a piece
    with no request wording whose subject is a kind of thing said in the plural, with no
    one's name or "my" or "it" ("books need moving", "the folders are heavy"), says why the
    request is made; it asks for no item of its own. A singular thing ("the storybook needs
    moving"), anyone's thing ("my folders need ..."), a bare list ("folders please") or a
    piece that opens with a verb is read as before."""
    if piece.acts.request or not any(p.acts.request for p in msg.pieces if p.end <= piece.start):
        return False
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    if any(m.kind not in ("word", "cue", "item") for m in mentions):
        return False  # a person, "me"/"my", a pronoun, a place: not a generic kind
    items = [m for m in mentions if m.kind == "item"]
    if not items or (mentions[0].kind == "cue" and mentions[0].start == 0):
        return False  # nothing named, or a verb first ("move the books")
    for m in items:
        last = tokens[m.end - 1]
        after = tokens[m.end].word if m.end < len(tokens) else ""
        if last.possessive or not language.is_plural_noun(last.word):
            return False
        if after in terms.en.courtesy or not (
            after in _SUBJECT_VERBS or language.verb_lemmas(after)
        ):
            return False  # "folders please", "books too": a list, not a subject
    return True


# whose a thing is, said before it: "*my* stapler spring" is a part of someone's stapler
_OWNERS = english_words("owner_determiners")


def context_fragment(terms: Terms, msg: Message, piece: Piece) -> bool:
    """ "Tea time soon. Could you bring me a ruler?": a fragment with no request wording
    whose items only modify other words ("tea time"), beside a sentence that asks for
    something, is context; it never adds an errand of its own."""
    if piece.acts.request:
        return False
    others = [p for p in msg.pieces if p is not piece and p.start > piece.end]
    if not any(p.acts.request for p in others):
        return False
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    items = [m for m in mentions if m.kind in ("item", "cue")]
    if not items or any(language.verb_lemmas(t.word) & terms.lex.cue_words for t in tokens):
        return False
    modifying = modifiers(tokens, mentions)

    def compound(m: Mention) -> bool:  # "tea time": the item names a kind of time
        if m.possessive:
            return False  # "my tuner's battery died": the thing whose part it is, no kind
        if m.start > 0 and tokens[m.start - 1].word in _OWNERS:
            return False  # "my stapler spring just snapped": someone's thing, and its part
        after = tokens[m.end].word if m.end < len(tokens) else ""
        # "a thermometer down in kennels": a word that is also an adverb of place or
        # direction says where the item is wanted, not what kind of thing it names
        adverb = "ADV" in language.lemmas(after)
        return language.is_noun(after) and after not in terms.en.courtesy and not adverb

    return all((m.start in modifying and not m.possessive) or compound(m) for m in items)


def stated_products(terms: Terms, piece: Piece) -> list[str]:
    """The products of the office a statement names by a word that is also a service's verb
    ("the new *labels* are in my file": the label sheets the label service makes), read as
    the thing, not the verb: a later request that makes "them" makes that product."""
    tokens = piece.lexed.tokens
    out: list[str] = []
    for n, m in enumerate(piece.lexed.mentions):
        word = " ".join(t.word for t in tokens[m.start : m.end])
        item = terms.lex.items.get(word)
        if m.kind != "cue" or item is None or terms.office.item_type(item).kind != "product":
            continue
        if n == 0 and m.start == 0:
            continue  # first word: a verb ("label my file")
        out.append(item)
    return list(dict.fromkeys(out))


def stated_items(terms: Terms, piece: Piece, requester: str) -> list[str]:
    """The items a statement names, as "item|whose": "my stapler" → stapler|my,
    "the book ... belongs to Yang" → book|Yang Lei's (a later "it" keeps its owner). An
    item that only modifies another ("wipes *for the cups*") is not what the statement is
    about, so a later "some" never means it."""
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    words = [t.word for t in tokens]
    modifying = modifiers(tokens, mentions)
    out: list[str] = []
    for n, m in enumerate(mentions):
        part_of = _owned_part_of(terms, words, m)
        if part_of is not None:
            out.append(f"{part_of}|{'my' if words[m.start - 1] == 'my' else ''}")
            continue
        if m.kind != "item" or len(m.ids) != 1 or m.start in modifying:
            continue
        if out and _after_cause(words, m.start):
            continue  # "my cup is dirty from lunch": the cup is what is told of, not lunch
        told_of = out or any(w in _OWNERS for w in words[: m.start])
        if told_of and _work_to_do(words, m):
            continue  # "my pen's died and I've got forms to sign": the pen is told of
        k = _past_describing_words(tokens, mentions, n)
        before = mentions[k - 1] if k else None
        whose = ""
        if before is not None and before.kind == "self" and before.possessive:
            whose = "my"
        elif before is not None and before.kind == "person" and before.possessive:
            whose = _whose_name(terms, before)
        elif before is not None and before.kind == "pronoun" and before.possessive:
            people = {p.ids for p in mentions[:k] if p.kind == "person" and len(p.ids) == 1}
            if len(people) == 1:  # "Yang said I could borrow his book"
                whose = f"{terms.office.person(next(iter(people))[0]).name}'s"
        elif (holder := holder_of(mentions, n, words)) is not None:
            whose = _whose_name(terms, holder)  # "Bram has a stopwatch"
        elif (giver := _leave_giver(terms, mentions, n, words)) is not None:
            whose = _whose_name(terms, giver)  # "Baker said I could borrow the cake knife"
        else:
            for k in range(len(words) - 1):
                if words[k : k + 2] == ["belongs", "to"]:
                    owner = [x for x in mentions if x.kind == "person" and x.start > k]
                    if owner and len(owner[0].ids) == 1:
                        whose = f"{terms.office.person(owner[0].ids[0]).name}'s"
        out.append(f"{m.ids[0]}|{whose}")
    return out


def _owned_part_of(terms: Terms, words: Sequence[str], m: Mention) -> str | None:
    """ "my *cup* handle just snapped", "her stapler spring broke": a thing of the office
    after whose it is and before a plain noun that is none of the office's words is the thing
    a part of which is told of (the lexicon reads it as the noun's modifier); its item."""
    if m.kind != "word" or m.end - m.start != 1 or m.start == 0 or m.end >= len(words):
        return None
    if words[m.start - 1] not in _OWNERS:
        return None
    item = terms.lex.items.get(words[m.start])
    part = words[m.end]
    if item is None or part in terms.office_words or not language.is_noun(part):
        return None
    return item


def _work_to_do(words: Sequence[str], m: Mention) -> bool:
    """Whether the item at ``m`` is said in a clause of what someone has to do, after the
    thing a statement told of: "I've got a stack of *reports* to print" (the thing, then "to"
    and a verb), "a cage of notes to *book* out" (a word of the office's said as the verb
    after "to"). The thing told of before it ("my pen's died") is what "another one" means."""
    if m.start > 0 and words[m.start - 1] == "to" and m.end - m.start == 1:
        if language.verb_lemmas(words[m.start]):
            return True
    after = words[m.end : m.end + 2]
    return len(after) == 2 and after[0] == "to" and bool(language.verb_lemmas(after[1]))


# what opens a phrase of when or from what, after the thing a statement is about ("my cup is
# dirty *from* lunch", "the stapler's jammed *since* the meeting")
_CAUSES = english_words("cause_prepositions")


def _after_cause(words: Sequence[str], at: int) -> bool:
    """Whether the word at ``at`` follows one of ``_CAUSES``, with at most an article between."""
    k = at - 1
    if k >= 0 and words[k] in ("the", "a", "an", "this", "that"):
        k -= 1
    return k >= 0 and words[k] in _CAUSES


# "his leftover soup", "Wren's big red ruler": words that describe the item between it and
# whose it is said to be
_DESCRIBING_WORDS = 2


def _past_describing_words(tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> int:
    """The index of the first mention of the describing words right before item mention
    ``n`` (``n`` itself when there are none): plain words, adjacent, no pause between."""
    k = n
    while (
        k > 0
        and n - k < _DESCRIBING_WORDS
        and mentions[k - 1].kind == "word"
        and not mentions[k - 1].possessive
        and mentions[k - 1].end == mentions[k].start
        and not tokens[mentions[k].start].after_pause
    ):
        k -= 1
    if k > 0 and mentions[k - 1].possessive and mentions[k - 1].end == mentions[k].start:
        return k  # "his leftover soup": the possessive owns the item past its describing words
    return n


_POSSESSION_VERBS = english_words("possession_verbs")


_ONE = frozenset({"one", "ones"})
# how ``one_held`` marks its item for the rewrites: said last, it is what "it" means
ONE_HELD = "one held:"


def one_held(terms: Terms, msg: Message, piece: Piece) -> list[str]:
    """ "Ivy's headset died. *Rhys has a spare one*": a statement that one person has "one"
    (a describing word or two between) names no item itself; it is the item named last in
    the message before it, theirs ("headset|Rhys Ames's"), so a later "it" is the one they
    have, not the one said before it (marked ``ONE_HELD``). Nothing named before: nothing."""
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    words = [t.word for t in tokens]
    people = [m for m in mentions if m.kind == "person"]
    if len(people) != 1 or any(m.kind in ("item", "self") for m in mentions):
        return []
    person = people[0]
    between = words[person.end :]
    verb = ["has"] if person.possessive else between[:1]
    if not verb or verb[0] not in _POSSESSION_VERBS:
        return []
    rest = between[0 if person.possessive else 1 :]
    rest = rest[1:] if rest[:1] == ["got"] else rest  # "has got one"
    ones = [k for k, w in enumerate(rest) if w in _ONE]
    if not ones and rest[:1] in (["a"], ["an"]) and rest[1:2] and rest[1] in _SPARE:
        ones = [2]  # "Rhys has a spare": the describing word standing for the thing
        rest = [*rest[:2], "one", *rest[2:]]
    if not ones or ones[0] > 3 or not set(rest[: ones[0]]) <= _HELD_ONE_BEFORE:
        return []
    if any(language.is_noun(w) and w not in _ONE for w in rest[ones[0] + 1 : ones[0] + 2]):
        return []  # "one battery", "a spare battery": a thing of its own
    earlier = [
        m
        for p in msg.pieces
        if p.end <= piece.start
        for m in p.lexed.mentions
        if m.kind == "item" and len(m.ids) == 1
    ]
    if not earlier:
        return []
    return [f"{ONE_HELD}{earlier[-1].ids[0]}|{_whose_name(terms, person)}"]


# what may stand between a verb of having and "one": "a spare one", "another one", "an old one"
_SPARE = frozenset({"spare", "extra"})
_HELD_ONE_BEFORE = _SPARE | {"a", "an", "another", "old", "new", "second"}


def holder_of(mentions: Sequence[Mention], n: int, words: list[str]) -> Mention | None:
    """The one person a statement says has the item ``mentions[n]`` ("Bram has a stopwatch",
    "Femi's got a spare radio"): a later "it" is theirs, not another of its kind. The mention
    may name several people ("Robin" where two are called Robin): who is meant is asked."""
    people = [m for m in mentions[:n] if m.kind == "person"]
    if len(people) != 1:
        return None
    between = words[people[0].end : mentions[n].start]
    verb = between[:1] if not people[0].possessive else ["has"]  # "Femi's got": has got
    return people[0] if verb and verb[0] in _POSSESSION_VERBS else None


def _leave_giver(
    terms: Terms, mentions: Sequence[Mention], n: int, words: list[str]
) -> Mention | None:
    """The one colleague a statement reports as letting the speaker have "the" thing
    ("Baker said I could borrow *the* cake knife"), where they own one of that kind: the
    thing they let the speaker have is theirs, so a later "it" is theirs, not anyone's (which
    fetched another colleague's). Where they own none, "the" is the office's shared one."""
    item = mentions[n]
    if item.start == 0 or words[item.start - 1] != "the":
        return None
    people = [m for m in mentions[:n] if m.kind == "person"]
    if len(people) != 1 or people[0].possessive:
        return None
    between = words[people[0].end : item.start - 1]
    if not any(starts_with(between, 0, mark) for mark in _REPORTED_LEAVES):
        return None
    if not set(people[0].ids) & set(terms.office.owners_of(item.ids[0])):
        return None
    return people[0]  # a name several people share is asked about ("Yang's book")


def _whose_name(terms: Terms, person: Mention) -> str:
    """The owner a statement names, for the rewritten request: the person's full name, or,
    where the name is several people's ("Robin's" with two Robins), the name as written, so
    the readings ask which one is meant; never dropped, which would make it anyone's."""
    if len(person.ids) == 1:
        return f"{terms.office.person(person.ids[0]).name}'s"
    said = person.text.strip()
    return said if said.lower().endswith(("'s", "’s")) else f"{said}'s"


def _phrases(key: str) -> tuple[tuple[str, ...], ...]:
    return tuple(tuple(entry.split()) for entry in english_entries(key))


_LACKS = _phrases("lack_marks")
_REPORTED_LEAVES = _phrases("reported_leave_marks")
_LACK_PLACES = _phrases("lack_place_openers")
_HOMES = english_words("home_nouns")
_HOME_DETERMINERS = frozenset({"my", "our", "the", "his", "her"})
_SUPPLY_OPENERS = _phrases("own_supply_openers")
_SUPPLY_VERBS = english_words("own_supply_verbs")
_SELF_LACKS = _phrases("self_lack_phrases")


def _said_at(words: Sequence[str], phrase: tuple[str, ...]) -> list[int]:
    """Where ``phrase`` ends in ``words``, each time it is said."""
    size = len(phrase)
    return [n + size for n in range(len(words) - size + 1) if tuple(words[n : n + size]) == phrase]


def _at_home(words: Sequence[str]) -> bool:
    """ "at home", "in my flat", "back at the house": a place outside the office."""
    for opener in _LACK_PLACES:
        for end in _said_at(words, opener):
            rest = words[end:]
            if rest[:1] and rest[0] in _HOME_DETERMINERS:
                rest = rest[1:]
            if rest[:1] and rest[0] in _HOMES:
                return True
    return False


def own_supply(words: Sequence[str]) -> bool:
    """ "I'll grab some on my way back", "will buy more later": the speaker's own plan to
    get more of something."""
    w = [x for x in words if x not in ("just", "probably", "then", "also")]
    return any(
        tuple(w[: len(opener)]) == opener
        and w[len(opener) : len(opener) + 1]
        and w[len(opener)] in _SUPPLY_VERBS
        for opener in _SUPPLY_OPENERS
    )


def own_lack(terms: Terms, msg: Message, piece: Piece) -> bool:
    """ "run out of pens at home haha, I'll grab some on my way back": a lack of a thing said
    of a place outside the office, or beside the speaker's own plan to get more, with no
    request anywhere in the message, is the speaker's news: nothing here lacks it, or they
    will see to it themselves ("out of pens, can you bring me one?" asks)."""
    if piece.acts.request or piece.acts.imperative or piece.acts.question is not None:
        return False
    if not any(m.kind == "item" for m in piece.lexed.mentions):
        return False
    words = piece.words
    if not any(_said_at(words, lack) for lack in _LACKS) and not (
        words[:1] == ["no"] and ("left" in words or _at_home(words))
    ):
        return False
    others = [p for p in msg.pieces if p is not piece]
    plans = [p for p in others if own_supply(p.words)]
    if any(
        p.asks or p.acts.request or p.acts.imperative or p.acts.question is not None
        for p in others
        if p not in plans
    ):
        return False  # "out of pens at home, can you bring me one?": asked
    return _at_home(words) or bool(plans)


def told_lack(terms: Terms, piece: Piece) -> bool:
    """ "I've run out of wipes", "no pens left": the speaker's own lack of one of the
    office's items (``speaker_lack``)."""
    said = content(piece.words)
    return speaker_lacks(said, given_thing(terms.lex))


def lack_beside_request(terms: Terms, msg: Message, piece: Piece) -> bool:
    """ "I ran out of paper. Could you bring me a pen?": the speaker's lack, read as their
    want when it is all they say (``speaker_lack``), is why they ask when another piece of
    the message asks: told, context only (its thing stays for "some" in "... find me some")."""
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.question is not None:
        return False
    if not told_lack(terms, piece):
        return False
    return any(
        p.asks or p.acts.request or p.acts.imperative or p.acts.question is not None
        for p in msg.pieces
        if p is not piece
    )


def lack_offer(terms: Terms, msg: Message, piece: Piece) -> Finding | None:
    """ "I'm out on a job in twenty minutes and I haven't got a hi-vis vest": the speaker's
    own lack of a thing the office keeps for anyone, with no request anywhere in the message,
    is met with an offer ("Shall I bring you a hi-vis vest from the stores?"), never fetched
    on the statement alone. A lack said of home, or beside the speaker's own plan to get
    more ("out of paper at home, will buy some"), stays words (``own_lack``)."""
    acts = piece.acts
    if acts.request or acts.imperative or acts.question is not None or acts.condition:
        return None
    words = piece.words
    if not any(_said_at(words, lack) for lack in _SELF_LACKS) or _at_home(words):
        return None
    items = terms.named(piece.lexed, "item")
    if len(items) != 1:
        return None
    t = terms.office.item_type(items[0])
    supplier = terms.office.supplier(items[0]) or _maker(terms, items[0])
    if supplier is None or t.kind not in ("belonging", "product"):
        return None
    others = [p for p in msg.pieces if p is not piece]
    if any(own_supply(p.words) for p in msg.pieces):
        return None  # "I haven't got a pen, I'll grab one on the way": their own plan
    if any(
        p.asks or p.acts.request or p.acts.imperative or p.acts.question is not None for p in others
    ):
        return None  # a request beside it is read as usual
    a_thing = wording.a_thing(t.name, mass=t.mass)
    one = wording.some_or_one(t.name, mass=t.mass)
    verb = "get" if t.kind == "product" else "bring"
    return Finding(
        "statement",
        piece,
        f"the speaker's lack of {a_thing}, which the {supplier.name} keeps: offered",
        message=f"The {supplier.name} can give you {a_thing}.",
        offer=f"{verb} me {a_thing}",
        shall=f"Shall I {verb} you {one}?",
    )


def _maker(terms: Terms, item: str) -> Facility | None:
    """The facility that makes ``item`` from nothing for anyone (a cupboard that hands out
    notepads, a coffee machine), if any."""
    free = {o.id for o in terms.office.operations if o.product == item and o.input is None}
    return next(
        (f for f in terms.office.facilities if item in f.products and set(f.operations) & free),
        None,
    )


_DEGREES = english_words("remark_degrees")
_REMARK_TAILS = english_words("remark_tails")
# "lovely day *to* eat lunch outside", "grim morning *for* a site visit"
_DAYS = english_words("remark_days")
_GOOD_FOR = frozenset({"to", "for"})


def remark(terms: Terms, piece: Piece) -> bool:
    """ "so foggy today", "such a sunny morning", "what a miserable day": a remark on the
    weather or the day, with no verb: degree words, adjectives (a colleague's name that is
    also one, "so misty today", is the adjective here), and words of the day. It names
    nothing of the office and asks nothing; or names what the day is good for ("lovely day
    to eat lunch outside"), whatever that names."""
    if piece.acts.request or piece.acts.imperative or piece.acts.question is not None:
        return False
    words = content(piece.words)
    n = 0
    while n < len(words) and words[n] in _DEGREES:
        n += 1
    degrees = n
    while n < len(words) and _adjective(terms, words[n]):
        n += 1
    adjectives = n - degrees
    rest = words[n:]
    if adjectives and len(rest) > 2 and rest[0] in _DAYS and rest[1] in _GOOD_FOR:
        return not (
            piece.acts.need or piece.acts.wish
        )  # "lovely day to eat lunch outside": what the day is good for, told
    if any(
        m.kind in ("item", "facility", "place", "self", "pronoun") for m in piece.lexed.mentions
    ):
        return False
    if not adjectives or not all(w in _REMARK_TAILS for w in rest):
        return False
    return bool(degrees or rest)


_PRAISED_WORK = english_words("praised_work")
_PRAISE_WHOLE = tuple(tuple(p.split()) for p in english_entries("praise_remarks"))
# praise of a thing ("lovely thing"), never which thing ("one more thing", "the last thing")
_THINGS = frozenset({"thing", "things", "kit"})
_WHICH_THING = frozenset(
    {
        "one",
        "more",
        "other",
        "another",
        "last",
        "next",
        "first",
        "only",
        "same",
        "main",
        "final",
        "extra",
        "whole",
        "different",
        "real",
        "small",
        "big",
        "little",
    }
)
_ASKING = english_words("request_markers") | english_words("request_modals")


def praise_remark(piece: Piece) -> bool:
    """ "sterling effort on the clean-up yesterday, everyone", "great job today, team", "well
    done all": praise of someone's work, with no verb of its own: degree words, adjectives
    (a colleague's name that is also one, "sterling", "grand", is the adjective here), then
    a noun of work ("effort", "job"), or a whole phrase of praise ("well done"), and no
    request wording after it. It asks nothing; whatever it names is context."""
    if piece.acts.request or piece.acts.imperative or piece.acts.question is not None:
        return False
    words = content(piece.words)
    whole = next((p for p in _PRAISE_WHOLE if tuple(piece.words[: len(p)]) == p), None)
    if whole is not None:  # "well done": "well" is also an opener, left out of ``content``
        words, n = piece.words, len(whole)
    else:
        n = 0
        while n < len(words) and words[n] in _DEGREES:
            n += 1
        adjectives = n
        while n < len(words) and _praise_adjective(words[n]):
            n += 1
        if n == adjectives or n >= len(words) or words[n] not in _PRAISED_WORK:
            return False
        if words[n] in _THINGS and set(words[:n]) & _WHICH_THING:
            return False  # "one more thing - could I ...": which thing, no praise
        n += 1
    return not set(words[n:]) & (_ASKING | {"you", "u"} - {"thank"})


def _praise_adjective(word: str) -> bool:
    return "ADJ" in language.lemmas(word)


def _adjective(terms: Terms, word: str) -> bool:
    read = language.lemmas(word)
    return "ADJ" in read and word not in terms.lex.items and word not in terms.lex.cue_words


_NEEDS = frozenset({"needs", "need"})
_NEED_REACH = 7  # "the holly in the big pot by the door needs ...": the subject's words
_SUBJECT_OPENERS = frozenset({"the", "this", "that", "these", "those", "our"})


def unserved_need(terms: Terms, piece: Piece) -> bool:
    """ "the holly by the door needs watering", "the fern needs to be repotted": a thing (no
    person, no item of the office) said to need work that no errand, task or service of the
    office does. It asks the robot nothing it could do, and it is no one's request for a
    person ("Holly needs a stapler" names a colleague); work the office does ("the banner
    needs laminating" where a laminator is offered) is read as before."""
    if piece.acts.request or piece.acts.imperative or piece.acts.question is not None:
        return False
    tokens = piece.lexed.tokens
    words = [t.word for t in tokens]
    at = next((n for n, w in enumerate(words[:_NEED_REACH]) if w in _NEEDS), None)
    if at is None or not at or words[0] not in _SUBJECT_OPENERS:
        return False
    if any(
        m.kind in ("person", "item", "self", "facility") and m.start < at
        for m in piece.lexed.mentions
    ):
        return False
    after = words[at + 1 :]
    if after[:2] == ["to", "be"] and after[2:3]:
        verb = after[2]
        if not language.is_past_participle(verb):
            return False
    elif after[:1] and after[0].endswith("ing") and _gerund(after[0]):
        verb = after[0]
    else:
        return False
    forms = {verb} | language.verb_lemmas(verb)
    office = terms.lex.cue_words | terms.lex.operation_words | terms.service_verbs
    return not forms & office


def _gerund(word: str) -> bool:
    """ "watering", "repotting" (a verb the dictionary may not know): a gerund, not a noun
    such as "something" or "ceiling"."""
    return bool(language.verb_lemmas(word)) or not language.lemmas(word)


_WHOEVERS = frozenset({"whoevers", "whosever"})
_TO_THE_ROBOT = frozenset({"you", "u", "robot"})


_PLEA_SUBJECTS = tuple(
    sorted((tuple(p.split()) for p in english_entries("plea_subjects")), key=lambda p: -len(p))
)
_PLEA_STOPS = tuple(tuple(p.split()) for p in english_entries("plea_stops"))
_PLEA_TAILS = tuple(
    sorted((tuple(p.split()) for p in english_entries("plea_stop_tails")), key=lambda p: -len(p))
)
_PLEA_MODALS = frozenset({"can", "could", "will", "would", "please", "pls", "plz", "just"})


def _stop_at(words: list[str], n: int) -> int | None:
    """Where a word of asking to stop that starts at ``n`` ends ("stop", "cut it out")."""
    stop = next((s for s in _PLEA_STOPS if tuple(words[n : n + len(s)]) == s), None)
    return None if stop is None else n + len(stop)


def _bare_stop(words: list[str]) -> bool:
    """ "please stop", "stop it now", "just stop": asking to stop, and nothing more."""
    k = 0
    while k < len(words) and words[k] in _PLEA_MODALS:
        k += 1
    end = _stop_at(words, k)
    if end is None:
        return False
    while end < len(words):
        tail = next((t for t in _PLEA_TAILS if tuple(words[end : end + len(t)]) == t), None)
        if tail is None:
            return False
        end += len(tail)
    return True


def plea_to_others(msg: Message, piece: Piece) -> bool:
    """A plea to unknown others, which asks nothing of the assistant: "whoever keeps nicking
    the oat milk, please stop" (a bare "please stop" after a piece that opens with
    "whoever"), "to whoever keeps taking my stapler: stop it", "can people stop leaving mugs
    in the sink" (someone unnamed, then asking them to stop). "can you ask whoever has the
    oat milk to bring it back" asks the assistant and is read as before."""
    words = content(piece.words)
    if set(words) & _TO_THE_ROBOT:
        return False
    if words[:1] == ["to"]:
        words = words[1:]  # "to whoever keeps ...": said to them
    k = 0
    while k < len(words) and words[k] in _PLEA_MODALS:
        k += 1
    subject = next((s for s in _PLEA_SUBJECTS if tuple(words[k : k + len(s)]) == s), None)
    if subject is not None:
        after = k + len(subject)
        while after < len(words) and words[after] in _PLEA_MODALS:
            after += 1
        if _stop_at(words, after) is not None:
            return True  # "can people stop ...", "everyone please stop ..."
        if subject[0].startswith("whoever") and any(
            _stop_at(words, n) is not None for n in range(after, len(words))
        ):
            return True  # "whoever keeps taking my stapler: please stop"
        if subject[0].startswith("whoever") and any(
            _bare_stop(content(p.words)) for p in msg.pieces if p.start >= piece.end
        ):
            return True  # "whoever keeps moving my stapler|, stop it": who it is said to
    if not _bare_stop(words):
        return False
    return any(
        content(p.words)[:2] and content(p.words)[int(content(p.words)[0] == "to")] in _PLEA_OPENERS
        for p in msg.pieces
        if p.end <= piece.start
    )


# The words that open a sentence said of whoever does something ("whoever keeps ...")
_PLEA_OPENERS = frozenset({"whoever", "whoevers", "whosever"})


def told_to_whoever(msg: Message, piece: Piece) -> bool:
    """ "whoever's mug is on my desk, please come get it": after a sentence about whoever
    owns a thing, a request that names nobody and nothing but "it" ("come get it", "take it
    home") is said to that owner, not to the robot; "..., can you bring it to Zhang" asks
    the robot and is read as before."""
    if not (piece.acts.request or piece.acts.imperative):
        return False
    if not any(
        content(p.words)[:1] and content(p.words)[0] in _WHOEVERS
        for p in msg.pieces
        if p.end <= piece.start
    ):
        return False
    if set(piece.words) & _TO_THE_ROBOT:
        return False
    return not any(
        m.kind in ("person", "self", "item", "facility", "place") for m in piece.lexed.mentions
    )
