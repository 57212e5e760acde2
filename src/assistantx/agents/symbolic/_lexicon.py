"""The office's vocabulary, scanned out of free text: people, item types and facilities.

Every name comes from the office file (names, aliases, synonyms, plurals), so another office
works unchanged; the English function words and generic task verbs are the package's data
(``data/english.yaml``). Matching is longest-phrase-first, then single name words; a word
that names several people is kept as an ambiguous mention, never resolved by guessing. Small
typos ("stapeler", "cofee") are corrected against the same vocabulary, but only for words
that are not ordinary English; a misspelt name that is as close to another person's name
("Zhnag": Zhang or Zheng) is ambiguous, since fetching from the wrong colleague is worse
than asking.
"""

from __future__ import annotations

import difflib
import re
from dataclasses import dataclass, field
from typing import Literal

from assistantx.core import english
from assistantx.core.office import Office
from assistantx.core.task_schema import SHAPE_KIND
from assistantx.memory.names import TITLES, normalize

MentionKind = Literal["person", "item", "facility", "self", "pronoun", "cue", "word"]

# Task cues: the English verbs (and nouns) that say what to do, keyed by task kind (the
# package's English data file). Not office-specific: the verbs of the office's own operations
# are added per office (``Lexicon.from_office``), under the task kind of their shape.
CUES: dict[str, frozenset[str]] = english.word_table("cues")
CUE_WORDS = frozenset(w for words in CUES.values() for w in words)

SELF_WORDS = english.words("self_words")
PRONOUNS = english.words("pronouns")
OTHER_POSSESSIVES = english.words("other_possessives")
# Words that connect a person to a role in the sentence.
PREPOSITIONS = english.words("party_prepositions")

# Ordinary English that must never be "corrected" into a name, and is never a name word
# unless written with a capital letter.
COMMON = english.words("common")
# Name words that are also English words only count when capitalized in the original.
_ENGLISH_NAME_WORDS = english.words("names_that_are_words")

# Words that open a verb's object: the word before one of them is in a verb's place.
_VERB_OBJECT_STARTS = english.words("object_starts")

_SUBJECT_PRONOUNS = english.words("subject_pronouns")
_MONTHS = english.words("month_names")
_MONTH_PREPOSITIONS = english.words("month_prepositions")
_POLITE = english.words("polite")

# How close a misspelt name must be to a person's name to count as possibly meaning them.
_NAME_TYPO_CUTOFF = 0.8

_TOKEN = re.compile(r"[A-Za-z0-9]+(?:['’][A-Za-z]+)?")


@dataclass(frozen=True)
class Token:
    text: str  # original spelling
    word: str  # lower-case, possessive removed, typo-corrected
    possessive: bool
    typed: str = ""  # ``word`` before the typo correction

    @property
    def corrected(self) -> bool:
        return bool(self.typed) and self.typed != self.word


@dataclass(frozen=True)
class Mention:
    kind: MentionKind
    start: int  # token index
    end: int  # exclusive
    ids: tuple[str, ...] = ()  # person/item-type/facility ids (several = ambiguous)
    possessive: bool = False
    text: str = ""

    @property
    def id(self) -> str:
        return self.ids[0]


@dataclass
class Lexicon:
    """Phrase tables built from one office."""

    office: Office
    people: dict[str, set[str]] = field(default_factory=dict)  # phrase → person ids (tier 0)
    name_words: dict[str, set[str]] = field(default_factory=dict)  # word → ids (tier 1)
    items: dict[str, str] = field(default_factory=dict)  # phrase → item type id
    facilities: dict[str, str] = field(default_factory=dict)  # phrase → facility id
    max_words: int = 1
    cues: dict[str, frozenset[str]] = field(default_factory=dict)  # task kind → words
    cue_words: frozenset[str] = frozenset()
    vocabulary: list[str] = field(default_factory=list)
    _vocabulary_set: frozenset[str] = frozenset()

    @classmethod
    def from_office(cls, office: Office) -> Lexicon:
        lex = cls(office)
        cues = {k: set(v) for k, v in CUES.items()}
        for op in office.operations:
            kind = SHAPE_KIND.get(op.shape(office))
            if kind is not None:
                cues.setdefault(kind, set()).update(
                    form for verb in op.verbs for form in inflections(normalize(verb))
                )
        lex.cues = {k: frozenset(v) for k, v in cues.items()}
        lex.cue_words = frozenset(w for v in cues.values() for w in v)
        for p in office.people:
            for name in (p.id, p.name, *p.aliases):
                key = normalize(name)
                if key:
                    lex.people.setdefault(key, set()).add(p.id)
            for word in p.name.split():
                lex.name_words.setdefault(normalize(word), set()).add(p.id)
        for t in office.item_types:
            for name in (t.id.replace("_", " "), t.name, *t.synonyms):
                key = normalize(name)
                if not key:
                    continue
                for variant in (key, _plural(key)):
                    lex.items.setdefault(variant, t.id)
        for f in office.facilities:
            for name in (f.name, *f.synonyms, f.id.replace("_", " ")):
                key = normalize(name)
                if key:
                    lex.facilities.setdefault(key, f.id)
        phrases = [*lex.people, *lex.items, *lex.facilities]
        lex.max_words = max(len(p.split()) for p in phrases)
        words = {w for p in phrases for w in p.split()} | set(lex.name_words) | lex.cue_words
        lex.vocabulary = sorted(w for w in words if len(w) >= 4)
        lex._vocabulary_set = frozenset(lex.vocabulary)
        return lex

    # -- tokens --------------------------------------------------------------------------
    def tokens(self, text: str) -> list[Token]:
        out: list[Token] = []
        raws = [m.group(0) for m in _TOKEN.finditer(text.replace("’", "'"))]
        for n, raw in enumerate(raws):
            lower = raw.lower()
            possessive = lower.endswith("'s") or lower.endswith("s'")
            word = re.sub(r"'s$|'$", "", lower).replace("'", "")
            if not possessive and word.endswith("s'"):
                word = word[:-1]
            # a word right before a determiner is a verb: "printe my file" is print, not printer
            verb_slot = n + 1 < len(raws) and raws[n + 1].lower() in _VERB_OBJECT_STARTS
            out.append(Token(raw, self._correct(word, verb_slot=verb_slot), possessive, word))
        return out

    def _correct(self, word: str, *, verb_slot: bool = False) -> str:
        """Fix a small typo in an office word or a cue; leave English and numbers alone.

        In a verb's place the task verbs are tried first, so a misspelt verb is never turned
        into a noun that is closer by letters (a typo keeps its part of speech)."""
        if len(word) < 4 or word.isdigit() or word in COMMON or self._known(word):
            return word
        if verb_slot:
            verbs = difflib.get_close_matches(word, sorted(self.cue_words), n=1, cutoff=0.8)
            if verbs:
                return verbs[0]
        for n in range(len(word) - 1):  # one swapped pair of letters: "zhnag", "pirnt"
            swapped = word[:n] + word[n + 1] + word[n] + word[n + 2 :]
            if swapped in self._vocabulary_set:
                return swapped
        if len(word) < 5:
            return word
        close = difflib.get_close_matches(word, self.vocabulary, n=1, cutoff=0.85)
        return close[0] if close else word

    def _known(self, word: str) -> bool:
        return (
            word in self.cue_words
            or word in self.name_words
            or word in self.people
            or word in self.items
            or word in self.facilities
            or word in TITLES
        )

    # -- mentions ------------------------------------------------------------------------
    def scan(self, tokens: list[Token]) -> list[Mention]:
        """Mentions in text order; titles and articles are skipped inside phrases."""
        content = [i for i, t in enumerate(tokens) if t.word not in TITLES]
        mentions: list[Mention] = []
        k = 0
        while k < len(content):
            found = self._match_at(tokens, content, k)
            if found is None:
                i = content[k]
                mentions.append(self._single(tokens, i))
                k += 1
                continue
            mention, used = found
            mentions.append(mention)
            k += used
        return mentions

    def _match_at(
        self, tokens: list[Token], content: list[int], k: int
    ) -> tuple[Mention, int] | None:
        for n in range(min(self.max_words, len(content) - k), 0, -1):
            idx = content[k : k + n]
            # a possessive ends a phrase ("zhang's stapler" is two mentions)
            if any(tokens[i].possessive for i in idx[:-1]):
                continue
            phrase = " ".join(tokens[i].word for i in idx)
            start, end = idx[0], idx[-1] + 1
            poss = tokens[idx[-1]].possessive
            text = " ".join(tokens[i].text for i in idx)
            if phrase in self.people and self._name_ok(tokens, idx):
                ids = self._person_ids(tokens, idx, self.people[phrase])
                return Mention("person", start, end, ids, poss, text), n
            if phrase in self.facilities:
                return Mention("facility", start, end, (self.facilities[phrase],), poss, text), n
            if phrase in self.items and not (n == 1 and phrase in self.cue_words):
                return Mention("item", start, end, (self.items[phrase],), poss, text), n
        return None

    def _single(self, tokens: list[Token], i: int) -> Mention:
        t = tokens[i]
        w = t.word
        if w in self.name_words and self._name_ok(tokens, [i]):
            ids = self._person_ids(tokens, [i], self.name_words[w])
            return Mention("person", i, i + 1, ids, t.possessive, t.text)
        if w in SELF_WORDS:
            return Mention("self", i, i + 1, (), w in ("my", "mine"), t.text)
        if w in PRONOUNS or w in OTHER_POSSESSIVES:
            return Mention("pronoun", i, i + 1, (), w in OTHER_POSSESSIVES, t.text)
        if w in self.cue_words:
            kinds = tuple(k for k, words in self.cues.items() if w in words)
            return Mention("cue", i, i + 1, kinds, t.possessive, t.text)
        if w in self.items:  # a cue word that is also an item name ("print", "copy")
            return Mention("item", i, i + 1, (self.items[w],), t.possessive, t.text)
        return Mention("word", i, i + 1, (w,), t.possessive, t.text)

    def _person_ids(self, tokens: list[Token], idx: list[int], ids: set[str]) -> tuple[str, ...]:
        """The people a name may mean; a corrected one-word name adds everyone as close."""
        found = set(ids)
        if len(idx) == 1 and tokens[idx[0]].corrected:
            typed = tokens[idx[0]].typed
            keys = [k for k in (*self.people, *self.name_words) if " " not in k]
            for key in difflib.get_close_matches(typed, keys, n=8, cutoff=_NAME_TYPO_CUTOFF):
                found |= self.people.get(key, set()) | self.name_words.get(key, set())
        return tuple(sorted(found))

    def _name_ok(self, tokens: list[Token], idx: list[int]) -> bool:
        """An English-looking single name word counts only when capitalized."""
        if len(idx) != 1:
            return True
        i = idx[0]
        t = tokens[i]
        if t.word in _ENGLISH_NAME_WORDS or t.word in COMMON:
            if t.possessive:
                return True  # "May's stapler"
            nxt = tokens[i + 1].word if i + 1 < len(tokens) else ""
            prev = tokens[i - 1].word if i > 0 else ""
            if nxt in _SUBJECT_PRONOUNS:
                return False  # "Will you ...", "May I ...": a modal verb
            if prev in _MONTH_PREPOSITIONS and t.word in _MONTHS:
                return False  # "in May"
            if (i == 0 or prev in _POLITE) and nxt in _VERB_OBJECT_STARTS:
                return False  # "Mark my form as urgent": a verb in the verb's place
            return t.text[:1].isupper()
        return True


def inflections(verb: str) -> set[str]:
    """'print' → print, prints, printed, printing; 'copy' → copies, copied; 'heat' → heated."""
    if not verb or " " in verb:
        return {verb} if verb else set()
    forms = {verb, _plural(verb)}
    if verb.endswith("e"):
        forms |= {verb + "d", verb[:-1] + "ing"}
    elif verb.endswith("y") and not verb.endswith(("ay", "ey", "oy")):
        forms |= {verb[:-1] + "ied", verb + "ing"}
    elif _doubles(verb):  # "scan" → scanned, scanning
        forms |= {verb + verb[-1] + "ed", verb + verb[-1] + "ing"}
    else:
        forms |= {verb + "ed", verb + "ing"}
    return forms


def _doubles(verb: str) -> bool:
    """Short consonant-vowel-consonant verbs double their last letter (scan, ship, stop)."""
    vowels = "aeiou"
    return (
        len(verb) >= 3
        and verb[-1] not in vowels + "wxy"
        and verb[-2] in vowels
        and verb[-3] not in vowels
        and sum(c in vowels for c in verb) == 1
    )


def _plural(phrase: str) -> str:
    if phrase.endswith("s"):
        return phrase
    if phrase.endswith(("ch", "sh", "x")):
        return phrase + "es"
    if phrase.endswith("y") and not phrase.endswith(("ay", "ey", "oy")):
        return phrase[:-1] + "ies"
    return phrase + "s"
