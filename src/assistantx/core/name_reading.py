"""Whether a one-word name that is also an English word means the person or the word.

A colleague's given name may be an ordinary word ("Penny", "Ivy", "Mark", "Grace"); written
in lower case ("take it to penny", "drop it on ivy's desk") it is still the person when the
syntax around it says so. The reader's lexicon and the runtime's consent guard both decide
with this one function, so the guard never refuses a hand-over to the person the reader read
(nor lets through one to a word the reader never took for a person).

Syntax decides: "to Mark", "Mark's", "give mark a pen", "Pat hurt her hand", "it's fern who
needs it", "can Penny sign it?", "get holly to sign it", "have holly sign it" (the doer of a
verb) make a person;
"the grace period", "to be honest", "Will you", "in May", "Mark my form" make the word. When
neither says anything a capital letter makes the person; when they disagree, or a capitalized
word sits where only the word fits, the reading is "ask". A title the office declares with its
article ("the Provost" as someone's alias) is that person wherever it is written so: the
article, which otherwise makes the word ("the grace period"), is part of the declared name.
"""

from __future__ import annotations

from collections.abc import Container, Sequence
from dataclasses import dataclass
from typing import Literal, Protocol

from assistantx.core import english, language

NameReading = Literal["person", "word", "ask"]

# "for a min", "some guy left his lunch", "every grace period": an indefinite article or a
# quantifier before a name word makes it a kind of thing or person, nobody by name
_INDEFINITE = frozenset({"a", "an", "some", "any", "another", "every", "each"})

_COMMON = english.words("common")
# Nouns the dictionary lacks that are words all the same ("cox"): a name word with a word reading.
_GAP_NOUNS = english.words("dictionary_gap_nouns")
_NUMBER_WORDS = english.words("number_words")
# what opens a verb's object ("drew *a* blank", "drew *the* short straw")
_OBJECT_OPENERS = frozenset({"a", "an", "the", "my", "his", "her", "our", "their", "some"})
_PERSON_BEFORE = english.words("person_before")
_NEGATED_FINITE = english.words("negated_finite_auxiliaries")
_WORD_BEFORE = english.words("word_before")
_DATIVE_VERBS = english.words("dative_verbs")
_VERB_OBJECT_STARTS = english.words("object_starts")
_DOER_VERBS_TO = english.words("doer_verbs_to")
_DOER_VERBS_BARE = english.words("doer_verbs_bare")
_SUBJECT_PRONOUNS = english.words("subject_pronouns")
_MONTH_PREPOSITIONS = english.words("month_prepositions")
_POLITE = english.words("polite")
_MODALS = english.words("request_modals")
_VERB_SLOT_BEFORE = english.words("verb_slot_before")
_VERB_SLOT_OBJECTS = english.words("verb_slot_objects")
# "is tam in today?": the verb that opens a question of whether someone is here, and the first
# words of what it asks (a person's being here or away: english.yaml's ``here`` and ``away``)
_PRESENCE_BE = english.words("presence_question_verbs")
_PRESENCE_BE_PLURAL = english.words("presence_question_verbs_plural")
# "if wren doesn't mind": a condition on someone's leave (english.yaml)
_CONSENT_IF = english.words("consent_conditions")
_MINDS = frozenset(english.entries("minding_after_name"))
# the verbs that take a clause; "hope" is a colleague's name in some offices, so its forms are
# never listed with the English data (as ``reading/screen/hope.py`` keeps them)
_CLAUSE_VERBS = english.words("clause_verbs") | frozenset({"hope", "hoping", "hopefully"})
_PRESENCE = (
    frozenset(p.split()[0] for p in (*english.entries("here"), *english.entries("away")))
    | english.words("presence_question_words")
) - {"not"}
# "hope so", "to be frank", "the stores are miles away": fixed phrases in which a name word is
# the ordinary word (english.yaml), each as its words; the second only after another word of
# its clause ("Miles away today" at the start may be Miles being away). "hope" itself is kept
# here, never in the English data (as ``_CLAUSE_VERBS``), with the words that follow it there
_IDIOMS = tuple(tuple(language.words(p)) for p in english.entries("name_idioms")) + tuple(
    ("hope", *language.words(tail)) for tail in english.entries("hoped_idiom_tails")
)
_IDIOMS_INSIDE = tuple(tuple(language.words(p)) for p in english.entries("name_idioms_inside"))
_IDIOM_KEEPERS = english.words("name_idiom_keepers")
# "is Miles away today?", "when's Miles off?": a copula asking after someone, no distance
_WH = english.words("wh_words")
_ASKING_COPULAS = _PRESENCE_BE | _PRESENCE_BE_PLURAL | {"s"}


@dataclass(frozen=True)
class NameSlot:
    """A one-word name where it stands: the word (folded), as written, and its neighbours in
    the same sentence (folded; "" at a sentence's edge)."""

    word: str
    written: str
    possessive: bool = False
    opens: bool = False  # the first word of a sentence
    prev: str = ""
    next: str = ""
    next_possessive: bool = False
    next_is_item: bool = False  # the next word names one of the office's items
    next_is_name: bool = False  # the next word is a word of someone's name
    next_after_pause: bool = False  # a comma (or colon) between the name and the next word
    after_next: str = ""  # the word after the next one (folded; "" at a sentence's edge)
    # the office declares "<prev> <word>" as someone's alias ("the Provost", "our Dean")
    declared_with_prev: bool = False
    prev_opens: bool = False  # the word before opens the sentence ("*is* tam in today?")
    after_next_is_name: bool = False  # the word after the next is a word of someone's name
    # the word stands in a fixed phrase that makes it the ordinary word ("hope so", "miles
    # away", "to be frank"), with no word before the phrase that makes it a person
    idiom: bool = False


class SlotWord(Protocol):
    """A word of a text as a reader split it: the reader's ``Token``, the consent guard's
    word (both split as the reader's tokenizer does)."""

    @property
    def word(self) -> str: ...  # folded, without a possessive 's

    @property
    def text(self) -> str: ...  # as written

    @property
    def possessive(self) -> bool: ...

    @property
    def opens(self) -> bool: ...  # the first word of a sentence

    @property
    def after_pause(self) -> bool: ...  # a comma (or colon) before it


def slot_at(
    words: Sequence[SlotWord],
    n: int,
    *,
    items: Container[str],
    name_words: Container[str],
    with_article: Container[tuple[str, str]] = (),
) -> NameSlot:
    """The name word ``words[n]`` where it stands, for ``read_name``: the reader and the
    guard take its neighbours the same way (the next word only within the sentence).
    ``items``: the office's one-word item names; ``name_words``: the words of people's names;
    ``with_article``: (article, word) pairs the office declares as someone's alias."""
    w = words[n]
    nxt = words[n + 1] if n + 1 < len(words) and not words[n + 1].opens else None
    after = words[n + 2] if nxt is not None and n + 2 < len(words) else None
    return NameSlot(
        word=w.word,
        written=w.text,
        possessive=w.possessive,
        opens=w.opens,
        prev=words[n - 1].word if n > 0 else "",
        next=nxt.word if nxt is not None else "",
        next_possessive=nxt is not None and nxt.possessive,
        next_is_item=nxt is not None and nxt.word in items,
        next_is_name=nxt is not None and nxt.word in name_words,
        next_after_pause=nxt is not None and nxt.after_pause,
        after_next=after.word if after is not None and not after.opens else "",
        declared_with_prev=n > 0 and (words[n - 1].word, w.word) in with_article,
        prev_opens=n > 0 and words[n - 1].opens,
        after_next_is_name=after is not None and not after.opens and after.word in name_words,
        idiom=in_idiom(words, n, name_words),
    )


def in_idiom(words: Sequence[SlotWord], n: int, name_words: Container[str] = ()) -> bool:
    """Whether the name word ``words[n]`` stands in one of the fixed phrases that make it the
    ordinary word (english.yaml's ``name_idioms``: "hope so, thanks", "to be frank the
    printer is useless", "the stores are miles away"), all of it within one clause (no
    sentence end nor pause inside). A word before the phrase that makes a person ("tell Hope
    you're well"), a name joined before it ("Tam and Miles away today"), or a copula asking
    after someone ("is Miles away today?", "when's Miles off?") keeps the name's own
    reading; so does a possessive ("Hope's so kind")."""
    if words[n].possessive:
        return False
    for phrases, inside in ((_IDIOMS, False), (_IDIOMS_INSIDE, True)):
        for phrase in phrases:
            start = _phrase_start(words, n, phrase)
            if start is None:
                continue
            if _idiom_kept_off(words, start, name_words, inside=inside):
                continue
            return True
    return False


def _phrase_start(words: Sequence[SlotWord], n: int, phrase: Sequence[str]) -> int | None:
    """Where ``phrase`` starts if it stands over ``words[n]`` within one clause."""
    for k, w in enumerate(phrase):
        if w != words[n].word:
            continue
        start = n - k
        span = words[start : start + len(phrase)]
        if start < 0 or len(span) != len(phrase):
            continue
        if all(
            t.word == p and (j == 0 or not (t.opens or t.after_pause))
            for j, (t, p) in enumerate(zip(span, phrase, strict=True))
        ):
            return start
    return None


def _idiom_kept_off(
    words: Sequence[SlotWord], start: int, name_words: Container[str], *, inside: bool
) -> bool:
    """Whether what stands before a fixed phrase starting at ``start`` keeps its name word a
    person: a word that makes one, a name joined to it, a copula asking after someone; and
    for a phrase read so only inside a clause, no word before it there at all."""
    first = words[start]
    if start == 0 or first.opens or first.after_pause:
        return inside
    prev = words[start - 1]
    if prev.word in _IDIOM_KEEPERS:
        return True
    before = words[start - 2] if start >= 2 and not prev.opens else None
    if prev.word in ("and", "or") and before is not None and before.word in name_words:
        return True  # "Tam and Miles away today": both named
    if prev.word in _ASKING_COPULAS:
        return prev.opens or (before is not None and before.word in _WH)
    return False


def is_word_name(word: str) -> bool:
    """Whether a (folded) name word is also an ordinary English word ("penny", "ivy", "may"):
    only such a name has a word reading at all. A month is one whatever the dictionary's
    frequency says of it ("June": "mine ran out in June" is a date)."""
    return (
        language.is_english_word(word)
        or word in _COMMON
        or word in _GAP_NOUNS
        or language.is_month(word)
    )


def read_name(slot: NameSlot) -> NameReading:
    """The reading of a one-word name: the person, the ordinary word, or ask which."""
    w = slot.word
    if not slot.opens and slot.prev in _INDEFINITE and not slot.possessive:
        return "word"  # "for a min", "some guy": nobody is "a Min"; the word, whatever the name
    if not slot.opens and numeral(slot.prev) and not slot.possessive:
        return "word"  # "for 5 min", "two miles": a count of the word, nobody counted
    if slot.opens and _past_verb_opening(slot):
        return "word"  # "Drew a blank on the rota": the speaker's dropped "I", a past verb
    if not is_word_name(w) or (slot.declared_with_prev and not slot.opens):
        return "person"
    if slot.idiom:
        return "word"  # "hope so", "he's still miles away", "to be frank": the phrase's word
    if _spoken_to(slot):
        return "person"
    if _verb_slot(slot):
        return "word"
    if _verb_frame(slot):
        # the syntax makes the verb; a capital says the writer may mean the person all the
        # same ("to Mark the boxes" slipped for "to Mark: the boxes"), so ask then
        return "ask" if slot.written[:1].isupper() else "word"
    if _titled_doer(slot):
        return "person"
    prev = "" if slot.opens else slot.prev
    nxt = slot.next
    capital = slot.written[:1].isupper()
    modal = nxt in _SUBJECT_PRONOUNS and (slot.opens or not prev)  # "Will you", "May I"
    finite_next = bool(nxt) and language.is_finite_verb(nxt)
    person = not modal and (
        slot.possessive
        or prev in _PERSON_BEFORE
        or (prev in _DATIVE_VERBS and (nxt in _VERB_OBJECT_STARTS or slot.next_is_item))
        or ((slot.opens or not prev) and (nxt in ("is", "was", "has") or finite_next))
        # "grace hasn't approved it": a negated auxiliary's subject, as "grace has" is
        or ((slot.opens or not prev) and nxt in _NEGATED_FINITE and not slot.next_after_pause)
        or nxt == "who"  # "it's fern who needs it": "who" is said of people only
        # "Can Penny sign my report?": the subject of a modal's question, before its verb
        or (prev in _MODALS and bool(nxt) and nxt in language.verb_lemmas(nxt))
        or _doer(prev, nxt, slot.after_next)
        or _presence_asked(slot)
        or _consenting(slot)
        or _clause_subject(slot)
        or _joined_names(slot)
        or _asked_for_theirs(slot)
        or _question_subject(slot)
    )
    if language.is_month(w) and not slot.possessive:
        day = language.is_day_number(prev) or language.is_day_number(nxt)
        if prev in _MONTH_PREPOSITIONS or day or prev == "of":
            return "word"  # "by May", "in June", "May 3rd", "the 3rd of May": a date
        if prev == "for":
            return "ask"  # "print the rota for May": for her, or the month's rota?
    word = (
        modal
        or (prev in _WORD_BEFORE and not (_presence_asked(slot) or _joined_names(slot)))
        or ((slot.opens or prev in _POLITE) and nxt in _VERB_OBJECT_STARTS)
        or _asked_verb(slot)
    )
    # "grace period": a noun right after it makes a compound
    compound = (
        bool(nxt)
        and not _doer(prev, nxt, slot.after_next)
        and not slot.next_possessive
        and nxt not in _COMMON
        and not slot.next_is_name
        and language.is_noun(nxt)
        and not finite_next
    )
    if person and word:
        return "ask"
    if person:
        return "person"
    if word or compound:
        return "ask" if capital and not slot.opens else "word"
    return "person" if capital else "word"


# "chase frank for his signature", "nudge bill about her stamp": what is asked of someone,
# said as theirs
_ASKED_OF = frozenset({"for", "about"})
_THEIRS = frozenset({"his", "her", "their"})
# "can you chase ...": the one asked, before the verb of what is asked
_YOU = frozenset({"you", "u", "ya"})


def _asked_for_theirs(slot: NameSlot) -> bool:
    """ "chase mark for his signature", "bug frank about her stamp": a name word followed by
    "for"/"about" and "his"/"her"/"their" is the one asked for something of their own; the
    pronoun says a person, never "a mark" nor "the frank" (an article makes the word)."""
    return (
        not slot.possessive
        and not slot.next_after_pause
        and slot.next in _ASKED_OF
        and slot.after_next in _THEIRS
    )


def _asked_verb(slot: NameSlot) -> bool:
    """ "can you chase frank for ...", "pls chase frank ...", "chase frank ...": a name word
    that is a plain verb, where the verb of a request goes (after "you" of "can you", after
    "please", or first, in lower case), with its object after it (a word of someone's name
    or a determiner), is the verb; a person there would have no verb ("can you Chase ...").
    "thank you Chase, ..." (a pause) and "thank you Chase for the pen" (no object) say
    nothing."""
    if slot.possessive or slot.next_after_pause or not _base_verb(slot.word):
        return False
    where = slot.prev in _YOU or slot.prev in _POLITE or (slot.opens and slot.written[:1].islower())
    return where and (slot.next_is_name or slot.next in _VERB_OBJECT_STARTS)


# "does mark still have ...", "did ken get ...": the auxiliary that opens a question whose
# subject comes next; "has bill got ...": "has" asking with "got"
_DO_AUXILIARIES = frozenset({"does", "did", "doesnt", "didnt"})
_HAS_AUXILIARIES = frozenset({"has", "hasnt"})


def _question_subject(slot: NameSlot) -> bool:
    """ "does mark still have his ruler?", "did ken get one?", "has bill got a charger?": a
    name word right after the "does"/"did"/"has" that opens a question, before a bare verb
    (an adverb such as "still" may come first), is the question's subject, a person: the
    word ("a mark", "the ken") would need an article there, and "does mark" as a verb has
    none. "does grace period apply" (a noun after it) is not."""
    if slot.opens or not slot.prev_opens or slot.possessive or slot.next_after_pause:
        return False
    if slot.prev in _HAS_AUXILIARIES:
        return slot.next == "got"
    if slot.prev not in _DO_AUXILIARIES:
        return False
    verb = slot.after_next if _adverb_only(slot.next) else slot.next
    return bool(verb) and _base_verb(verb)


def _adverb_only(word: str) -> bool:
    """Whether ``word`` is an adverb a question puts between its subject and verb ("does
    she *still* have", "did he *already* send"), no verb of its own."""
    return bool(word) and "ADV" in language.lemmas(word) and not _base_verb(word)


def _presence_asked(slot: NameSlot) -> bool:
    """ "is tam in today?", "was reed around?", "is wren free": a name word right after the
    "is" or "was" that opens a question, before a word that says whether someone is here or
    away, is whom the question asks about; "is grace period over" (a noun after it) is not."""
    if slot.opens or not slot.prev_opens or slot.possessive or slot.next_after_pause:
        return False
    return slot.prev in _PRESENCE_BE and slot.next in _PRESENCE


def _joined_names(slot: NameSlot) -> bool:
    """ "tam and wren are in", "are tam and wren in?": a name word that opens a sentence (or
    follows the "are"/"were" opening a question), joined by "and"/"or" to another name word,
    is the first of the people named together."""
    if slot.possessive or slot.next_after_pause or slot.next not in ("and", "or"):
        return False
    first = slot.opens or (slot.prev_opens and slot.prev in _PRESENCE_BE_PLURAL)
    return first and slot.after_next_is_name


def _consenting(slot: NameSlot) -> bool:
    """ "if wren doesn't mind", "unless reed minds": a name word between "if"/"unless" and a
    word of someone's minding or agreeing is whose leave is meant ("if bill is due": no)."""
    if slot.possessive or slot.next_after_pause or slot.prev not in _CONSENT_IF:
        return False
    return slot.next in _MINDS or f"{slot.next} {slot.after_next}" in _MINDS


def _clause_subject(slot: NameSlot) -> bool:
    """ "i know mark is busy", "i hope grace won't mind": a name word right after a verb
    that takes a clause, with a finite verb (or a negated auxiliary) after it, is that
    clause's subject; "i hope mark the boxes" has no verb after it."""
    if slot.possessive or slot.next_after_pause or slot.prev not in _CLAUSE_VERBS:
        return False
    nxt = slot.next
    return nxt in ("is", "was", "has") or nxt in _NEGATED_FINITE or language.is_finite_verb(nxt)


def _spoken_to(slot: NameSlot) -> bool:
    """ "Miles, I need your drill", "Ivy - can I borrow it?": a capitalised name word that
    opens a sentence, set off by a comma, colon or dash, is the colleague spoken to (a month
    so set off is left to the date rules: "June, as usual")."""
    return (
        slot.opens
        and slot.next_after_pause
        and not slot.possessive
        and slot.written[:1].isupper()
        and not language.is_month(slot.word)
    )


def _verb_slot(slot: NameSlot) -> bool:
    """ "I'd rather not have to mark it down", "we need to chase them": a name that is also a
    verb, where a bare verb goes ("to", "not", a modal) and right before "it"/"them", is the
    verb: a person named there would need a verb of their own after them (only a verb of
    giving takes a person and then "it": "give Mark it", never "to Mark it"). "to Mark, it's
    urgent" (a pause, or "it's") says nothing."""
    return (
        not slot.opens
        and not slot.possessive
        and slot.prev in _VERB_SLOT_BEFORE
        and slot.next in _VERB_SLOT_OBJECTS
        and not slot.next_possessive
        and not slot.next_after_pause
        and _base_verb(slot.word)
    )


# What a verb takes right after it, where a person would need a verb of their own first: a
# phrasal verb's particle ("to mark *up* 20 pages"), the opening of an object ("to chase
# *the* invoices", "to mark *20* pages", "to mark *him* down") (english.yaml)
_VERB_PARTICLES = english.words("verb_particles")
_OBJECT_PRONOUNS = english.words("object_pronouns") | _VERB_SLOT_OBJECTS
# "to Drew this afternoon", "to Mark first thing": a time after the recipient, not an object
_TIME_NOUNS = english.words("time_nouns")
_WHERE_AFTER_PARTICLE = english.words("location_prepositions") | {"there", "here", "on", "at"}


def _verb_frame(slot: NameSlot) -> bool:
    """ "I'm out of highlighters to mark up 20 pages", "a pen to chase the invoices": a name
    that is also a verb, where a bare verb goes ("to", "not", a modal), followed by what a
    verb takes (a particle, an object's determiner, a number, an object pronoun), is the
    verb by its syntax: a person after "to" ends the clause or is followed by what a
    recipient is ("to Mark please", "to Mark's desk", "to Mark, thanks", "to Mark in the post
    room", "to Mark to sign"). A time after the name ("to Drew this afternoon") is no
    object."""
    if slot.opens or slot.possessive or slot.next_possessive or slot.next_after_pause:
        return False
    if slot.prev not in _VERB_SLOT_BEFORE or not _base_verb(slot.word):
        return False
    nxt = slot.next
    if nxt in _VERB_OBJECT_STARTS or numeral(nxt):
        return slot.after_next not in _TIME_NOUNS
    if nxt in _VERB_PARTICLES:
        # "to Mark over in accounts", "to Chase up there": the particle says where the
        # recipient is, no phrasal verb
        return slot.after_next not in _WHERE_AFTER_PARTICLE
    return nxt in _OBJECT_PRONOUNS


# what follows a verb as its object, or the particle of a phrasal verb ("sign *off* my form")
_VERB_FOLLOWERS = _VERB_OBJECT_STARTS | _VERB_SLOT_OBJECTS | {"off", "up", "over", "me", "us"}


def numeral(word: str) -> bool:
    """A count said before a noun: digits ("5") or a number word ("two", "ten")."""
    return word.isdigit() or word in _NUMBER_WORDS


def _past_verb_opening(slot: NameSlot) -> bool:
    """ "Drew a blank", "Drew the short straw": a name word opening a sentence that the
    dictionary knows as a verb's past form ("drew" of "draw", not the plain "Mark"), with
    an object's determiner right after it, is a verb with its subject left out."""
    if slot.possessive or slot.next_after_pause or slot.next not in _OBJECT_OPENERS:
        return False
    verbs = language.lemmas(slot.word).get("VERB", ())
    return bool(verbs) and slot.word not in verbs


def _titled_doer(slot: NameSlot) -> bool:
    """ "can the Major sign my form", "have the Major stamp it": a capitalised name word
    after "the", with a plain verb and its object after it, is the subject of that verb. The
    word read as a noun ("the major") would be someone too, doing the same, and "the major
    sign" names nothing: the colleague called so, not a choice to ask about."""
    return (
        slot.prev == "the"
        and not slot.possessive
        and slot.written[:1].isupper()
        and not slot.next_after_pause
        and _base_verb(slot.next)
        and slot.after_next in _VERB_FOLLOWERS
    )


def _doer(prev: str, nxt: str, after_next: str) -> bool:
    """ "get holly to sign it", "have holly sign it": after a verb that has someone do
    something, the name followed by "to" and a verb, or by the bare verb, is who does it (a
    plant is never asked to sign); "get holly to the desk" (no verb after "to") says
    nothing."""
    if prev in _DOER_VERBS_TO and nxt == "to" and _base_verb(after_next):
        return True
    return prev in _DOER_VERBS_BARE and _base_verb(nxt)


def _base_verb(word: str) -> bool:
    """Whether ``word`` is a verb as the dictionary lists it (its own lemma: "sign", "print"),
    not an inflected form nor a word that is no verb ("the", "desk")."""
    return bool(word) and word in language.verb_lemmas(word)
