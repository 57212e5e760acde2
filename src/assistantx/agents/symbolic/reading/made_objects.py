"""A product named by its operation's verb, as the object of a rival operation's verb:
"print *labels* for my recipe" asks for labels, made by the label run, not for a printout.

An office may call an operation's product by the operation's own verb form ("label" makes
"labels"). After the verb of another operation on the same input ("print", which makes a
printout from the same file), with only fillers between ("me", "some", "two"), that word is
the thing the verb makes, not a second verb: the lexicon reads it as the product item, and
the operation stage (``operations._verb_objects``) then names the operation that makes it.
Only where two operations take the same input does this apply, so a plain request of one
service ("make a photocopy of my contract", "copy my contract") is read as before.

A product called by its own operation's verb ("copy", "copies", "photocopy" where the copy
operation makes copies) after a word that counts a thing ("a copy", "two copies", "another
photocopy") is that product too: after "a" or a number English has a noun, never a verb, so
"make me a copy" asks for a copy as "make me a printout" asks for a printout.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

from assistantx.agents.symbolic.reading.asking_forms import asking_forms
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office
from assistantx.memory.names import normalize

# Words between a making verb and what it makes: "print *me some* labels", "print *two* labels".
_FILLERS = english.words("determiners") | {"me", "us", "him", "her", "them", "new", "more"}
# Verbs that ask for a thing to be done or made without naming how: "can you *do* the labels".
_DOING = frozenset({"do", "sort", "make"})
# Words after which a noun is counted: "a copy", "another copy", "two copies", "few copies".
_COUNTING = english.words("number_words") | {
    "a",
    "an",
    "another",
    "some",
    "few",
    "couple",
    "extra",
    "spare",
    "more",
    "several",
}
# Whose paper it is, after "of": "of my report", "of his contract".
_POSSESSIVE = frozenset({"my", "our", "your", "his", "her", "their", "its"})
# What "of" may point back to: "a copy of it".
_POINTERS = frozenset({"it", "them", "this", "that", "these", "those", "mine", "yours"})
# How many describing words may stand before the product ("print *day* labels").
_DESCRIBING = 2


@dataclass(frozen=True)
class MadeObjects:
    # a verb form that also names its operation's product -> (the product, the verb forms of
    # the other operations on that operation's input)
    rivals: dict[str, tuple[str, frozenset[str]]]
    # a verb form that also names its own operation's product -> that product, and the verb
    # forms of the other operations (after one of them, "a copy" is that one's product)
    counted: dict[str, tuple[str, frozenset[str]]] = field(default_factory=dict)

    @classmethod
    def from_office(cls, office: Office) -> MadeObjects:
        forms = {
            op.id: {f for verb in op.verbs for f in asking_forms(normalize(verb))}
            for op in office.operations
        }
        rivals: dict[str, tuple[str, frozenset[str]]] = {}
        counted: dict[str, tuple[str, frozenset[str]]] = {}
        for op in office.operations:
            if op.product is None or op.input is None:
                continue
            product = office.item_type(op.product)
            names = {normalize(n) for n in (product.name, *product.synonyms)}
            others = frozenset(
                f
                for other in office.operations
                if other.id != op.id and other.input == op.input
                for f in forms[other.id]
            )
            plurals = {language.plural(n) for n in names if " " not in n}
            rest = frozenset(f for other, fs in forms.items() if other != op.id for f in fs)
            for form in forms[op.id] & (names | plurals):
                counted.setdefault(form, (op.product, rest - forms[op.id]))
            for form in forms[op.id] & names:
                if others and form not in others:
                    rivals[form] = (op.product, others - forms[op.id])
        return cls(rivals, counted)

    def product_at(
        self, tokens: Sequence[Token], i: int, known: Callable[[str], bool]
    ) -> str | None:
        """The product ``tokens[i]`` names as the object of a rival verb (or a verb of doing)
        before it, if so; ``known``: whether a word is one of the office's."""
        if tokens[i].opens:
            return None
        counted = self.counted.get(tokens[i].word)
        if (
            counted is not None
            and i > 0
            and _counts(tokens[i - 1].word)
            # "a copy of the agenda", "print Chen a copy": not read so here
            and not _of_unknown(tokens, i, known)
            and not _after_other_work(tokens, i, counted[1])
        ):
            return counted[0]  # "make me a copy", "two copies": the thing, never the verb
        found = self.rivals.get(tokens[i].word)
        if found is None:
            return None
        product, verbs = found
        k, described = i - 1, 0
        while k >= 0 and not tokens[k].opens:
            word = tokens[k].word
            if word in _FILLERS or word.isdigit():
                k -= 1
            elif described < _DESCRIBING and _describes(word, known) and word not in verbs:
                described += 1
                k -= 1
            else:
                break
        return product if k >= 0 and tokens[k].word in verbs | _DOING else None


def _of_unknown(tokens: Sequence[Token], i: int, known: Callable[[str], bool]) -> bool:
    """Whether the product at ``i`` is said "of" a thing the office does not know ("a copy of
    the agenda"): a copy of the requester's own paper would be a guess, so it is not read."""
    if i + 1 >= len(tokens) or tokens[i + 1].word != "of" or tokens[i + 1].opens:
        return False
    for t in tokens[i + 2 :]:
        if t.word in _FILLERS or t.word in _POSSESSIVE:
            continue
        return not (known(t.word) or t.possessive or t.word in _POINTERS)
    return False


def _after_other_work(tokens: Sequence[Token], i: int, others: frozenset[str]) -> bool:
    """Whether the sentence asks another operation's work before the product at ``i``, with
    no verb of making since ("print Chen a copy of my file", "print my report and a copy for
    Zhang": the printout is the copy meant)."""
    k = i - 1
    while k >= 0:
        word = tokens[k].word
        if word in _DOING:
            return False  # "print my file and make me a copy": the copy is made
        if word in others:
            return True
        if tokens[k].opens:
            return False
        k -= 1
    return False


def _counts(word: str) -> bool:
    """A word that counts the thing after it ("a", "another", "two", "2", "few", "extra"):
    "the" is none ("the copy" may be one somebody already holds)."""
    return word in _COUNTING or word.isdigit()


def _describes(word: str, known: Callable[[str], bool]) -> bool:
    """A word that may describe a product before its noun ("*day* labels", "*new* labels"):
    an English noun or adjective the office does not know as a name or a verb."""
    parts = language.lemmas(word)
    return word.isalpha() and not known(word) and ("NOUN" in parts or "ADJ" in parts)
