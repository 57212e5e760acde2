"""Copies "run off": "can you run off my report", "run me off two copies", "run a printout off
my file" ask for the office's printing or copying, the verb "run" with its particle "off",
never a variant of the thing ("some run barcode labels", round 252). The phrase is said again
with the office's own words: a made thing named after it is made ("run me off two copies" →
"make me two copies"), a paper or file alone is printed with the first of ``run_off_verbs``
the office has (else made), and the "off" between a made thing and its source is its "from"
("run a printout off my file" → "make a printout from my file"). "run my report over to
Wang", "run off to the kitchen", "I ran out of paper" are left as they are."""

from __future__ import annotations

import re

from assistantx.core import english
from assistantx.core.office import Office
from assistantx.memory.names import normalize

# what opens an object after "off" ("off my report", "off two copies", "off Wang's list")
_OBJECT = r"(?:my|your|his|her|our|their|the|a|an|this|that|these|those|some|\d+|[a-z]+'s)\b"
# the one it is run off for ("run *me* off a copy"); "run *them* off" names the papers
_TAKER = r"(?:(?P<taker>me|us)\s+)?"
_RUN_OFF = re.compile(
    rf"\brun\s+{_TAKER}off\s+(?={_OBJECT}|(?P<bare>[a-z]+\b))",
    re.IGNORECASE,
)
# "run a printout off my file": a thing of a few plain words between "run" and "off"
_RUN_THING_OFF = re.compile(
    rf"\brun\s+{_TAKER}(?P<thing>(?:[\w'-]+\s+){{0,3}}?[\w'-]+)\s+off\s+(?={_OBJECT})",
    re.IGNORECASE,
)
_NOT_A_THING = (
    english.words("clause_joins")
    | english.words("location_prepositions")
    | {
        "it",
        "them",
        "off",
        "out",
        "over",
        "round",
        "around",
        "across",
        "back",
        "up",
        "down",
        "to",
        "from",
    }
)
# what after "run off" says it is leaving, not what is run off ("run off to the kitchen",
# "run off on the copier")
_LEAVING = english.words("location_prepositions") | {
    "to",
    "with",
    "home",
    "now",
    "quickly",
    "and",
    "then",
    "for",
    "from",
    "into",
    "onto",
    "on",
    "again",
}


class RunOff:
    """The "run off" of one office: its products' words and its printing verb."""

    def __init__(self, office: Office) -> None:
        self.products = frozenset(
            normalize(n)
            for t in office.item_types
            if t.kind == "product"
            for n in (t.name, *t.synonyms)
        ) | english.words("run_off_products")
        verbs = {v.lower() for op in office.operations for v in op.verbs}
        self.verb = next((v for v in english.entries("run_off_verbs") if v in verbs), "make")

    def _names_product(self, rest: str) -> bool:
        # the object only, up to what it is of or for ("two copies *of my contract*")
        clause = re.split(
            r"[,.;!?]|\b(?:and|then|of|for|from|to|at|in|on|with|off)\b", rest, maxsplit=1
        )[0]
        words = normalize(clause).split()
        return any(
            " ".join(words[i : i + n]) in self.products
            or (n == 1 and _plural_of(words[i], self.products))
            for i in range(len(words))
            for n in (1, 2, 3)
            if i + n <= len(words)
        )

    def __call__(self, text: str) -> str:
        if not re.search(r"\brun\b", text, re.IGNORECASE) or not re.search(
            r"\boff\b", text, re.IGNORECASE
        ):
            return text
        text = _RUN_THING_OFF.sub(self._thing_off, text)
        return _RUN_OFF.sub(self._run_off, text)

    def _thing_off(self, m: re.Match[str]) -> str:
        thing = m.group("thing")
        if any(w.lower() in _NOT_A_THING for w in thing.split()):
            return m.group(0)
        taker = f"{m.group('taker')} " if m.group("taker") else ""
        return f"make {taker}{thing} from "

    def _run_off(self, m: re.Match[str]) -> str:
        bare = m.group("bare")
        if bare is not None and bare.lower() in _LEAVING:
            return m.group(0)
        taker = f"{m.group('taker')} " if m.group("taker") else ""
        verb = "make" if self._names_product(m.string[m.end() :]) else self.verb
        return f"{verb} {taker}"


def _plural_of(word: str, names: frozenset[str]) -> bool:
    return word.endswith("s") and (word[:-1] in names or word[:-2] in names)
