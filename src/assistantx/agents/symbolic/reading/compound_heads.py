"""An office item's name as the first noun of a compound noun: "my *wine* list file", "the
new *wine* list" name a file and a list, never the office's wine.

In English the head of a compound noun is its last noun; the nouns before it only say what
kind of one it is. An item name followed, inside the same noun phrase, by a noun the office
does not know ("list") is such a modifier: the mention is read as a plain word, so no stage
after the lexicon takes it for the thing. What the phrase then names is its head: another of
the office's items ("file": the requester's file) or a thing the office does not have ("the
wine list": nothing to fetch, asked or declined as any unknown thing would be).

A word counts as a noun of the compound only where nothing else reads it: a dictionary noun
that is no adverb or adjective ("the wine *today*", "take my file *home*" say when and where,
"a pen *real* quick" how), no clause opener ("a radio *cause* ..."), no function word, no
finite verb ("my stapler *works*"), no unit ("a scissors *pair*"), no word of the office (a
name, a task word, a place), written in lower case and not after a pause or a sentence break.
The dictionary's parts of speech are English, not the office's, so the rule holds for any
office. A number or letter label between the name and the noun ("the *level* 3 drawings")
leaves the name a modifier (``number_labels``).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from assistantx.agents.symbolic.reading.number_labels import past_label
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

_COMMON = english.words("common")
# The English lists of what papers and files are called ("rota", "log"): nouns wherever they
# are said, though the dictionary lacks some ("rota") or knows only the verb ("log"); after
# an item's name ("the coffee *rota*", "the sample *log*") each is the compound's head.
# A format word ("my invoice *pdf*") is no head: it says the form of the thing before it.
_DOCUMENT_NOUNS = (
    english.words("paper_nouns") | english.words("paper_heads") | english.words("file_nouns")
) - english.words("electronic_formats")
# A unit after an item's name measures the item ("a scissors pair"): not a head of its own.
_UNITS = english.words("portion_words") | english.words("unit_nouns")
# "dye my trousers *navy*": a colour after a name says its colour, no head it modifies
_COLOURS = english.words("colour_names")
# Words that open a clause of their own ("a radio *cause* ..."), though also nouns.
_OPENERS = english.words("reason_conjunctions") | english.words("clause_breaks")
# "a stopwatch *i* can borrow": a pronoun starts a clause of its own (the dictionary lists
# the letter "i" as a noun).
_PRONOUNS = (
    english.words("self_words")
    | english.words("subject_pronouns")
    | english.words("object_pronouns")
    | english.words("pronouns")
)


# What counts more than one thing before a name ("*some* cable ties", "*two* cable ties"):
# the plural after the name is then the phrase's head, never a verb with the name as subject.
_COUNTING = (
    english.words("partitive_quantities") | english.words("number_words") | {"these", "those"}
) - {"one", "bit", "half"}


# "the" and its kind before a name said as a verb's object ("cut *the* cable ties")
_DEFINITE = frozenset({"the", "my", "your", "our", "his", "her", "their", "these", "those"})
# verbs that may open a question or a clause of their own ("did the cable ties arrive")
_AUXILIARIES = frozenset({"be", "do", "have", "will", "can", "shall", "may", "must"})


def _object_of_a_verb(tokens: Sequence[Token], start: int) -> bool:
    """Whether the name at ``start`` opens a verb's object ("need to cut the cable ties"): a
    determiner before it, and a verb (no helping verb) before that, with no pause between."""
    if start < 2 or tokens[start - 1].word not in _DEFINITE or tokens[start - 1].after_pause:
        return False
    verb = tokens[start - 2]
    lemmas = language.verb_lemmas(verb.word)
    return bool(lemmas) and not lemmas & _AUXILIARIES and not tokens[start].after_pause


def modifies_a_noun(
    tokens: Sequence[Token], end: int, known: Callable[[str], bool], start: int | None = None
) -> bool:
    """Whether the word at ``end`` (right after an item's name) is a noun the name modifies:
    the name is then the first part of a compound whose head comes later. ``start``: where
    the name begins, where a counting word before it ("some cable ties") makes a plural that
    is also a verb's form ("ties") the head: "some cable" is no subject of "ties"."""
    if end >= len(tokens) or tokens[end - 1].possessive:
        return False
    # "the level 3 drawings": the labelled name modifies the noun after its label
    labelled = past_label(tokens, end)
    if labelled >= len(tokens):
        return False
    t = tokens[labelled]
    if t.opens or t.after_pause:
        return False
    if _says_how_it_is(tokens, labelled):
        return False
    # after a label a plural that is also a verb ("the level 3 plans") is the noun: a
    # labelled thing is no subject of a request's verb
    counted = (
        start is not None
        and start > 0
        and language.is_plural_noun(t.word)
        and (tokens[start - 1].word in _COUNTING or _object_of_a_verb(tokens, start))
    )
    return compound_noun(t, known, verb_too=labelled > end or counted)


# The determiners that open "the coffee one": a definite pick among things named before.
_PICKING = frozenset({"the", "this", "that"})
_ONE_WORDS = 3  # the most other nouns between "the" and "one" ("the coffee rota one")


def modifies_one(tokens: Sequence[Token], start: int, end: int) -> bool:
    """Whether the name from ``start`` to ``end`` describes the pro-form "one" after it: "Lee's
    spreadsheet? *the coffee one*", "a cup, *the coffee one*", "Lee's file? *the sample log
    one*". "one" stands for a thing named before, so it is the phrase's head and every noun
    between "the" and it only says which of that thing: no second thing. "one more", "one
    sugar" (after a pause) and "the coffee, one" keep their reading."""
    if start < 1 or tokens[end - 1].possessive:
        return False
    first = start
    while first > 0 and start - first < _ONE_WORDS and _inside(tokens[first - 1]):
        first -= 1  # "the *sample* log one": other nouns before the name
    if first < 1 or tokens[first - 1].word not in _PICKING or tokens[first].opens:
        return False
    last = end
    while last < len(tokens) and last - end < _ONE_WORDS and _inside(tokens[last]):
        last += 1  # "the sample *log* one"
    if last >= len(tokens):
        return False
    one = tokens[last]
    if one.word != "one" or one.opens or one.after_pause or tokens[last - 1].possessive:
        return False
    return last + 1 >= len(tokens) or tokens[last + 1].word != "more"


def _inside(t: Token) -> bool:
    """A word that may stand between "the" and "one" in such a phrase: a plain word in lower
    case, no function word, no pause before it."""
    return (
        t.text.isalpha()
        and t.text[:1].islower()
        and not t.opens
        and not t.after_pause
        and not t.possessive
        and t.word != "one"
        and t.word not in _COMMON
        and t.word not in _PRONOUNS
    )


def names_a_paper(tokens: Sequence[Token], end: int, known: Callable[[str], bool]) -> bool:
    """Whether the word at ``end`` (right after a facility's or an item's name) is a paper's or
    a file's noun heading the phrase: "the *van* schedule", "the *laminator* budget one" say
    which schedule or budget by its topic; the facility names no work and no place there. Only
    the English nouns of papers and files count: "the fridge *drawer*" stays the fridge."""
    if end >= len(tokens) or tokens[end - 1].possessive:
        return False
    t = tokens[end]
    return (
        not t.opens and not t.after_pause and t.word in _DOCUMENT_NOUNS and compound_noun(t, known)
    )


def _says_how_it_is(tokens: Sequence[Token], end: int) -> bool:
    """ "a stopwatch *going* spare", "my drill *sitting* idle": a verb's -ing form followed
    by a word that describes (or by nothing) says what the item is doing, no compound's head;
    "wine *tasting* notes" (a noun after it) stays a compound."""
    if not language.is_present_participle(tokens[end].word):
        return False
    if end + 1 >= len(tokens) or tokens[end + 1].after_pause:
        return True
    parts = language.lemmas(tokens[end + 1].word)
    return "ADJ" in parts or "ADV" in parts


def compound_noun(t: Token, known: Callable[[str], bool], *, verb_too: bool = False) -> bool:
    """A word that can only be a noun inside a noun phrase here (see the module's note);
    ``verb_too``: a noun that is also a finite verb's form counts ("plans")."""
    word = t.word
    if not t.text.isalpha() or not t.text[:1].islower() or t.corrected:
        return False  # "won't": a contraction, no noun; "Tobin": a name
    if word in _COMMON or word in _UNITS or word in _OPENERS or word in _PRONOUNS or known(word):
        return False
    if word in _DOCUMENT_NOUNS and not language.is_finite_verb(word):
        return True  # "the coffee rota", "the sample log": a paper or file by its topic
    parts = language.lemmas(word)
    # "real quick", "home", "back", and a colour ("navy")
    describes = "ADV" in parts or "ADJ" in parts or word in _COLOURS
    return "NOUN" in parts and not describes and (verb_too or not language.is_finite_verb(word))
