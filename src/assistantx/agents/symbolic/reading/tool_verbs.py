"""The verbs an office's work tool lends its work by English derivation: where the seal is a
"notary stamp" (or a "notarial seal"), "get my affidavit *notarised*" asks for the seal's work
as "get it stamped" does. English makes verbs of nouns and adjectives with a few suffixes:
"-ize"/"-ise" after a word in "-y", "-ary", "-al", "-ic" ("notary", "notarial" → "notarize"),
"-ify" from a noun in "-ification"/"-ificate" ("certificate" → "certify"), the verb under an
agent noun ("embosser" → "emboss") or under a participle ("certified" → "certify"). A derived
verb counts only where the dictionary knows it as a verb, so a coinage nobody uses
("companize" of "company seal") asks for nothing; its British "-ise" spelling is read as its
"-ize" one.

Only the words of the tool's own names (the office's data) lend verbs. The parser reads each
lent form as the same form of the work's own verb ("notarised" → "sealed"), before any rule
reads the message, so every rule that knows the work's words ("get it sealed", "needs
sealing") reads the lent verb the same way; a form that is already a word of the office's
work or names is left as it is."""

from __future__ import annotations

import re
from collections.abc import Collection, Iterable, Mapping
from dataclasses import dataclass

from assistantx.core import language, task_kinds
from assistantx.core.office import Office

# The endings a noun or adjective drops before "-ize" ("notar-y", "notar-ial").
_IZE_DROPS = ("iary", "ary", "ial", "al", "ic", "y")
# A noun of the act or its paper, whose verb ends in "-ify" ("certification", "certificate").
_IFY_FROM = ("ification", "ificate")
# Agent nouns: the tool by what it does ("embosser", "perforator").
_AGENT = ("er", "or")
_STEM = 3  # the fewest letters left before a suffix ("notar-y"): "by" lends nothing
# The forms a verb is said in, by the dictionary's tags (its base form besides).
_TAGS = ("VBZ", "VBG", "VBD", "VBN")


def derived_verbs(names: Iterable[str]) -> frozenset[str]:
    """The verbs (base forms) the words of ``names`` derive to, the names' own words aside."""
    words = {w for name in names for w in language.words(name)}
    return frozenset({v for w in words for v in _derived(w)} - words)


def _derived(word: str) -> set[str]:
    """The verbs the dictionary knows that ``word`` derives to."""
    candidates: set[str] = set(language.lemmas(word).get("VERB", ()))  # "certified"
    for end in _IZE_DROPS:
        if word.endswith(end) and len(word) - len(end) >= _STEM:
            candidates.add(word[: -len(end)] + "ize")
    for end in _IFY_FROM:
        if word.endswith(end):
            candidates.add(word[: -len(end)] + "ify")
    for end in _AGENT:
        if word.endswith(end) and len(word) - len(end) >= _STEM:
            candidates.add(word[: -len(end)])
    return {c for c in candidates if c != word and word_is_verb(c)}


def word_is_verb(word: str) -> bool:
    """Whether the dictionary knows ``word`` as a verb's base form."""
    return word in language.lemmas(word).get("VERB", ())


def same_forms(verb: str, own: str) -> dict[str, str]:
    """Each form of ``verb`` (and of its British "-ise" spelling) → the same form of ``own``
    ("notarized" → "sealed", "notarising" → "sealing")."""
    lent = language.verb_inflections(verb)
    mine = language.verb_inflections(own)
    out = {verb: own}
    for tag in _TAGS:
        for form in lent.get(tag, ()):
            if mine.get(tag):
                out[form] = mine[tag][0]
    if verb.endswith("ize"):  # "notarise", "notarised": the same verb, British spelling
        out |= {f.replace("iz", "is"): o for f, o in out.items() if "iz" in f}
    return out


@dataclass(frozen=True)
class LentVerbs:
    """The lent forms of one office, each with the form of its work's own verb."""

    forms: Mapping[str, str]
    pattern: re.Pattern[str] | None  # the forms as whole words, any case; None: no form

    @classmethod
    def from_office(cls, office: Office, taken: Collection[str]) -> LentVerbs:
        """The verbs the office's tools lend (``taken``: the office's words of work and
        names, never re-read)."""
        forms: dict[str, str] = {}
        for spec in task_kinds.kinds():
            tool = task_kinds.tool_type(spec.id, office)
            own = spec.id  # the work's own verb ("seal")
            if tool is None or not word_is_verb(own):
                continue
            kept = office.item_type(tool)
            for verb in sorted(derived_verbs((kept.name, *kept.synonyms))):
                for form, said in same_forms(verb, own).items():
                    if form not in taken:
                        forms.setdefault(form, said)
        return cls(forms, _word_pattern(tuple(sorted(forms))) if forms else None)

    def read(self, text: str) -> str:
        """``text`` with each lent form said as the work's own ("get it notarised" → "get it
        sealed"); a capital stays a capital."""
        if self.pattern is None:
            return text
        return self.pattern.sub(lambda m: _cased(self.forms[m.group(0).lower()], m.group(0)), text)


def _word_pattern(words: tuple[str, ...]) -> re.Pattern[str]:
    return re.compile(r"\b(?:" + "|".join(map(re.escape, words)) + r")\b", re.IGNORECASE)


def _cased(word: str, like: str) -> str:
    return word[:1].upper() + word[1:] if like[:1].isupper() else word
