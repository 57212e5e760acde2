"""A service's word said as a modifier of the noun of a purpose: "Zoe needs my loupe for the
*signature* comparisons, could you take it to her", "bring me scissors for the *print*
trimming", "for the *copy* check". After "for" (and its determiner), a service's word right
before another noun only says which event or work the thing is for (the comparisons of
signatures); it asks for no signing, printing or copying ("Which item do you mean to be
signed?" was the answer). The modifier is left out, as a describing -ing form is
(``attributive_work``), and the purpose is read as said ("for the comparisons").

Only the words of the office's own services and of its colleagues' work ("sign", "signature",
"print", an operation's noun such as "lamination") are read, never an errand's ("for the
take"); never a service's word that ends the phrase ("for signature", "for the print": the
service named, as before), one before a word that is no noun ("for signature on my form",
"for copying today"), nor one that belongs to a name of the office ("for the print room").

Describing words may stand between the determiner and the modifier ("for the big print run",
"for a massive copy job"): up to two words that can only be read as adjectives here (never a
service's word, never a noun's only reading), after a determiner, are kept and the modifier is
left out as before ("for the big run"). Without a determiner no such word is skipped: "for Wang
print my file" keeps its command.
"""

from __future__ import annotations

import re
from collections.abc import Collection

from assistantx.agents.symbolic.reading.attributive_work import NOT_NOUNS
from assistantx.core import english, language

_DETERMINERS = "|".join(
    sorted(english.words("determiners") | english.words("held_copy_owners"), key=len)[::-1]
)
_PHRASE = re.compile(
    rf"\bfor\s+(?P<det>(?:{_DETERMINERS})\s+)?(?P<modifier>[a-z]+)\s+(?P<noun>[a-z]+)\b",
    re.IGNORECASE,
)
# "for the big print run": a determiner, then describing words before the modifier
_DESCRIBED = re.compile(
    rf"\bfor\s+(?P<det>(?:{_DETERMINERS})\s+)(?P<rest>[a-z]+(?:\s+[a-z]+){{2,3}})\b",
    re.IGNORECASE,
)
_MOST_DESCRIBING = 2
# words after the modifier that are no noun it modifies ("for the signature *please*")
_NOT_NOUNS = NOT_NOUNS | english.words("request_markers")


def without_purpose_modifier(
    text: str, service_words: Collection[str], office_phrases: Collection[str]
) -> str:
    """``text`` with each of ``service_words`` (the office's services' and colleagues' work
    words, any form) said between "for (the)" and a noun left out ("for the signature
    comparisons" → "for the comparisons"); ``office_phrases``: the office's names of things,
    facilities and places, which keep theirs ("for the print room")."""

    def plain(match: re.Match[str]) -> str:
        modifier, noun = match.group("modifier").lower(), match.group("noun").lower()
        if modifier.endswith("ing") or modifier not in service_words:
            return match.group(0)  # "for signing forms": the work itself, read as before
        if noun in _NOT_NOUNS or "NOUN" not in language.lemmas(noun):
            return match.group(0)
        said = f"{modifier} {noun}"
        if any(said in p or p == modifier for p in office_phrases):
            return match.group(0)
        return f"for {match.group('det') or ''}{match.group('noun')}"

    def described(match: re.Match[str]) -> str:
        words = match.group("rest").split()
        for n in range(1, min(_MOST_DESCRIBING, len(words) - 2) + 1):
            if not all(_describing(w, service_words) for w in words[:n]):
                break
            modifier, noun = words[n].lower(), words[n + 1].lower()
            if modifier.endswith("ing") or modifier not in service_words:
                continue
            if noun in _NOT_NOUNS or "NOUN" not in language.lemmas(noun):
                continue
            said = f"{modifier} {noun}"
            if any(said in p or p == modifier for p in office_phrases):
                continue
            kept = [*words[:n], *words[n + 1 :]]
            return f"for {match.group('det')}{' '.join(kept)}"
        return match.group(0)

    return _DESCRIBED.sub(described, _PHRASE.sub(plain, text))


def _describing(word: str, service_words: Collection[str]) -> bool:
    """A word read only as describing the noun after it: an adjective, never a service's
    word, and never a word that is only a noun or a verb ("for the team print run": the
    team's run is left as said)."""
    lemmas = language.lemmas(word.lower())
    return word.lower() not in service_words and "ADJ" in lemmas
