"""A problem stated, then a remedy asked for: "my coat is covered in dog hair and I'm on in ten,
got anything to sort it out?", "the hem's come down - have you got something to fix it?".

Asking for "anything to sort it out" after saying what is wrong is asking for the thing that
puts that problem right: the office's item declared for it. The problem's words are matched
against what the office's things are declared for (their ``purposes``: a lint roller "to
remove hair") and against their names' head nouns (a "fluff roller" for "covered in
fluff"; never a describing word, the "black" of a "black umbrella"); a thing the
problem itself names ("my coat") is what the problem is about, never its remedy. Where
exactly one thing fits, the ask names it ("got a lint roller?") and the reader's own reading
of that question answers it ("There is a lint roller in ... Shall I bring you one?"); where
several fit, or none, which is asked, never "I can't answer that".

A need said by a body part or a complaint ("got anything for my cut finger?", "anything for a
headache?", "got anything for my hands? they're raw") asks the same: the words of the
complaint, and of what is said after the ask, are matched against what the things are for
*beyond* the verb of their purpose (plasters "cover *cuts*"; the scissors' "cut" is their
verb, not a cut finger) and their head nouns. Where one thing fits the ask stays a
question about it ("got anything for my knees?": "got a plaster?", answered and offered,
"Shall I bring you one?": only the yes brings it; "..., please" asks for it), where several
fit which is asked, and where none does the reader says what the office has; a
complaint that names a thing of the office ("anything for my stapler?") is left as said.

The remedy verbs, their heads and the words of a problem that name nothing are English
(``remedy_verbs``, ``remedy_heads``, ``remedy_plain_words`` in data/english.yaml); the
things and what they are for are the office's.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.categories import which_question
from assistantx.core import english, language
from assistantx.core.office import Office

_alternatives = english.alternation  # the lists' phrases as one regex alternation


# "(have you) got anything to sort it out?", "do you have something to fix this with?"
_ASK = re.compile(
    rf"(?P<head>\b(?:{_alternatives('remedy_heads')}))\s+(?:to|that\s+(?:can|could|would|will))"
    rf"\s+(?P<verb>{_alternatives('remedy_verbs')})"
    r"(?:\s+(?:it|this|that|them|these|those))?(?:\s+(?:out|up|off))?(?:\s+with)?"
    r"(?=\s*(?:\?|$|please\b|pls\b|\.))",
    re.IGNORECASE,
)
# "(got) anything for my cut finger?", "anything for a headache": asked as a sentence of its
# own (never "bring me something for the meeting"), the complaint up to the ask's end
_FOR = re.compile(
    r"(?:^|(?<=[.!?])\s*)\s*(?:(?:have|has|do|does)\s+)?"
    r"(?:(?:you|u|we|anyone|anybody|someone|somebody)\s+)?(?:(?:got|have|has)\s+)?"
    rf"(?P<head>\b(?:{_alternatives('remedy_heads')}))\s+for\s+"
    r"(?P<complaint>(?:(?:my|a|an|the|these|this|sore|bad|achy)\s+)[a-z' ]*?[a-z]+)"
    r"\s*(?=\?|$|\.|!|,\s*(?:please|pls)\b)",
    re.IGNORECASE,
)
_WORD = re.compile(r"[a-z]+")
# how a complaint's ask said with no verb ("anything for a headache?") is asked for one thing
_GOT = "got"
# the words of one thing's purpose or name that may say a problem's matter
_NAMING = frozenset(english.words("prepositions_and_joins"))


@dataclass(frozen=True, slots=True)
class Remedy:
    """The rewrite of the ask (``text``), or the question where no one thing fits, or
    (``none_fits``) that nothing of the office is for the complaint said."""

    text: str
    question: str | None = None
    none_fits: bool = False


class ProblemRemedies:
    """The office's things declared for a use, each with the words of its uses and name."""

    def __init__(self, office: Office) -> None:
        self._plain = english.words("remedy_plain_words") | _NAMING
        self._things: list[tuple[str, str, frozenset[str]]] = []  # id, name, words
        # the same, with each purpose's own verb left out ("cover *cuts*", never "cut")
        self._for: list[tuple[str, str, frozenset[str]]] = []
        for t in office.item_types:
            if not t.purposes or t.kind == "electronic":
                continue
            # what it is for, every word; its names by their head nouns only ("a *roller*",
            # never the "black" of "black umbrella" for a black jacket)
            heads = [n.split()[-1] for n in (t.name, *t.synonyms) if n.split()]
            said = " ".join([*t.purposes, *heads])
            words = frozenset(_forms(_WORD.findall(language.fold(said)))) - self._plain
            self._things.append((t.id, t.name, words))
            objects = [" ".join(_beyond_verb(p.split())) for p in t.purposes]
            said_for = " ".join([*objects, *heads])
            words_for = frozenset(_forms(_WORD.findall(language.fold(said_for)))) - self._plain
            self._for.append((t.id, t.name, words_for))

    def __call__(self, text: str, named: Callable[[str], set[str]]) -> Remedy:
        """``text`` with a remedy asked after a stated problem said as the one thing that
        fits ("got a lint roller?"); ``named``: the item types a phrase names."""
        if not self._things:
            return Remedy(text)
        ask = _ASK.search(text)
        if ask is None:
            return Remedy(text)
        problem = text[: ask.start()]
        words = set(_forms(_WORD.findall(language.fold(problem)))) - self._plain
        if not words:
            return Remedy(text)  # no problem said: "got anything to sort it out?" alone
        about = named(problem)
        fits = [
            (type_id, name)
            for type_id, name, said in self._things
            if type_id not in about and said & words
        ]
        names = list(dict.fromkeys(name for _, name in fits))
        if len(names) == 1:
            thing = _asked_as_question(text, ask.start(), ask.end(), _one(names[0]))
            return Remedy(f"{text[: ask.start()]}{thing}{text[ask.end() :]}")
        if names:
            return Remedy(text, which_question([_one(n) for n in names]))
        return Remedy(
            text,
            "I'm not sure which of the things here would sort that out. What should I bring you?",
        )

    def for_complaint(self, text: str, named: Callable[[str], bool]) -> Remedy:
        """``text`` with a need said by a complaint ("got anything for my cut finger?") said
        as the one thing that fits, or the question which, or ``none_fits``; ``named``:
        whether a phrase names an item, a person or a place of the office."""
        if not self._things:
            return Remedy(text)
        ask = _FOR.search(text)
        if ask is None or named(ask.group("complaint")):
            return Remedy(text)
        said = f"{ask.group('complaint')} {text[ask.end() :]}"
        words = set(_forms(_WORD.findall(language.fold(said)))) - self._plain
        if not words:
            return Remedy(text)
        names = list(dict.fromkeys(name for _, name, w in self._for if w & words))
        if len(names) == 1:
            # still a question ("got anything for my knees?" → "got a plaster?"): answered,
            # and the thing offered; only a yes brings it
            head = ask.start("head")
            thing = _asked_as_question(text, head, ask.end(), _one(names[0]))
            return Remedy(f"{text[:head]}{thing}{text[ask.end() :]}")
        if names:
            return Remedy(text, which_question([_one(n) for n in names]))
        return Remedy(text, none_fits=True)


# the end of a clause before an ask ("my coat is covered in dog hair, anything to ...?")
_CLAUSE_END = re.compile(r"[.,;:!?()\-–—]")
# an ask said as a request ("..., please"), not as a question
_PLEASE = re.compile(r"\s*,?\s*(?:please|pls)\b", re.IGNORECASE)


def _asked_as_question(text: str, start: int, end: int, thing: str) -> str:
    """The one thing that fits, said in place of the ask at ``start``..``end``: after the
    ask's own question words ("got", "do you have") as it is; with none ("anything for a
    headache?", "..., anything to sort it out?") said as "got <thing>", so the message stays
    a question, answered and offered, never a fetch unasked; said with "please", the thing."""
    clause = _CLAUSE_END.split(text[:start])[-1]
    if _WORD.search(clause.lower()) or _PLEASE.match(text[end:]):
        return thing
    return f"{_GOT} {thing}"


def _beyond_verb(words: list[str]) -> list[str]:
    """A purpose's words after its own verb ("cover cuts": "cuts"; "grip": none); a purpose
    that opens with no verb is all its words ("headache relief")."""
    if words and words[0].lower() in language.verb_lemmas(words[0].lower()):
        return words[1:]
    return words


def _one(name: str) -> str:
    """One of a thing, said ("a lint roller", "any wipes")."""
    return f"{language.indefinite(name)} {name}"


def _forms(words: list[str]) -> list[str]:
    """Each word with its singular and its verbs' lemmas ("hairs": hair; "cutting": cut)."""
    out: list[str] = []
    for w in words:
        out.append(w)
        out.extend(language.lemmas(w).get("NOUN", ()))
        out.extend(language.verb_lemmas(w))
    return out
