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
work or names is left as it is.

A name is a thing, not an act: a verb none of whose forms is a word of another item type's
names is lent ("claims stamp" lends no "claim" where the office's papers are "claim forms",
so "hand my claim form to Wang" stays a claim form), and a lent form inside a name said whole
("bring me the approved stamp", "Lee's claim folder") is that name's word, not the work."""

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
    # the forms as whole words, any case, after the names of several words that hold one
    # (matched first, so a form inside a name is left); None: no form
    pattern: re.Pattern[str] | None

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
            others = _other_name_words(office, tool)
            for verb in sorted(derived_verbs((kept.name, *kept.synonyms))):
                lent = same_forms(verb, own)
                if others.intersection(lent):  # "claim" where papers are "claim forms"
                    continue
                for form, said in lent.items():
                    if form not in taken:
                        forms.setdefault(form, said)
        if not forms:
            return cls(forms, None)
        return cls(forms, _word_pattern(tuple(sorted(forms)), _names_holding(office, forms)))

    def read(self, text: str) -> str:
        """``text`` with each lent form said as the work's own ("get it notarised" → "get it
        sealed"); a capital stays a capital, a name said whole stays as said."""
        if self.pattern is None:
            return text
        return self.pattern.sub(self._said, text)

    def _said(self, m: re.Match[str]) -> str:
        said = m.group(0)
        lent = self.forms.get(said.lower())
        return said if lent is None else _cased(lent, said)


def _other_name_words(office: Office, tool: str) -> frozenset[str]:
    """The words of every item type's names but the tool's own."""
    return frozenset(
        w
        for t in office.item_types
        if t.id != tool
        for name in (t.name, *t.synonyms)
        for w in language.words(name)
    )


def _names_holding(office: Office, forms: Collection[str]) -> tuple[str, ...]:
    """The office's names of several words (items' and facilities') with a lent form among
    their words: "approved stamp" is the tool, "claim folder" a folder."""
    names = [n for t in office.item_types for n in (t.name, *t.synonyms)]
    names += [n for f in office.facilities for n in (f.name, *f.synonyms)]
    return tuple(
        name
        for name in names
        if len(words := language.words(name)) > 1 and any(w in forms for w in words)
    )


def _word_pattern(words: tuple[str, ...], names: tuple[str, ...]) -> re.Pattern[str]:
    """Whole names first, longest first, then the forms: a name is matched where it starts."""
    said = [r"\s+".join(map(re.escape, n.split())) for n in names]
    ordered = sorted(set(said), key=len, reverse=True) + [re.escape(w) for w in words]
    return re.compile(r"\b(?:" + "|".join(ordered) + r")\b", re.IGNORECASE)


def _cased(word: str, like: str) -> str:
    return word[:1].upper() + word[1:] if like[:1].isupper() else word
