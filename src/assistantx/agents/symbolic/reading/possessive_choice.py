"""The question "Bill Ferreira's ruler, or any ruler?" and its answer. "can u grab bills
ruler" where Bill keeps no ruler may be Bill's (the writer left out the apostrophe) or the
plain word before anyone's ruler (``bare_possessives.doubted_possessives``); the reader asks,
and the answer rewrites the request: "Bill's" (or his name, "his") makes the word Bill's
possessive, "any" ("anyone's", "doesn't matter") makes it "any", so the request is read
again with nothing left in doubt. Any other answer leaves the question open."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.core import language

_OR_ANY = ", or any "
# answers that take anyone's: the word of the question's second reading, or indifference
_ANY_WORDS = frozenset(
    {"any", "anyone", "anyones", "anybody", "anybodys", "whoever", "whichever", "either"}
)
_INDIFFERENT = re.compile(r"\b(doesn'?t|does not|don'?t|do not) matter\b|\bno matter\b", re.I)
# answers that take the named colleague's without saying the name again
_THEIRS_WORDS = frozenset({"his", "hers", "theirs", "their", "hes", "shes", "them", "him", "her"})


def theirs_or_any(name: str, item: str) -> str:
    """The question asked when "<name>s ITEM" may be ``name``'s (which they lack) or any."""
    return f"Do you mean {name}'s {item}{_OR_ANY}{item}? {name} has none that I know of."


def with_possessive_chosen(lex: Lexicon, text: str, question: str, answer: str) -> str | None:
    """``text`` with the doubted word rewritten as the ``answer`` chose ("bills" → "Bill's"
    or "any"), or None where ``question`` is no such question or the answer chose neither."""
    if _OR_ANY not in question:
        return None
    doubted = lex.doubted_possessives(text)
    if len(doubted) != 1:
        return None
    base, _item, written = doubted[0]
    ids = {*lex.people.get(base, ()), *lex.name_words.get(base, ())}
    named = {p for m in lex.read(answer).mentions if m.kind == "person" for p in m.ids}
    words = {language.fold(w).replace("'", "") for w in re.findall(r"[\w']+", answer)}
    chose_any = bool(words & _ANY_WORDS) or bool(_INDIFFERENT.search(answer))
    chose_theirs = bool(named & ids) or bool(words & _THEIRS_WORDS)
    if chose_any == chose_theirs:
        return None  # neither, or both: still in doubt, asked again
    spelled = written[:-1] + "'s" if chose_theirs else "any"
    return re.sub(rf"\b{re.escape(written)}\b", spelled, text, count=1)
