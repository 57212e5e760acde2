"""A product named by its operation's verb, as the object of a rival operation's verb:
"print *labels* for my recipe" asks for labels, made by the label run, not for a printout.

An office may call an operation's product by the operation's own verb form ("label" makes
"labels"). After the verb of another operation on the same input ("print", which makes a
printout from the same file), with only fillers between ("me", "some", "two"), that word is
the thing the verb makes, not a second verb: the lexicon reads it as the product item, and
the operation stage (``operations._verb_objects``) then names the operation that makes it.
Only where two operations take the same input does this apply, so a plain request of one
service ("make a photocopy of my contract", "copy my contract") is read as before.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.asking_forms import asking_forms
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office
from assistantx.memory.names import normalize

# Words between a making verb and what it makes: "print *me some* labels", "print *two* labels".
_FILLERS = english.words("determiners") | {"me", "us", "him", "her", "them", "new", "more"}
# Verbs that ask for a thing to be done or made without naming how: "can you *do* the labels".
_DOING = frozenset({"do", "sort", "make"})
# How many describing words may stand before the product ("print *day* labels").
_DESCRIBING = 2


@dataclass(frozen=True)
class MadeObjects:
    # a verb form that also names its operation's product -> (the product, the verb forms of
    # the other operations on that operation's input)
    rivals: dict[str, tuple[str, frozenset[str]]]

    @classmethod
    def from_office(cls, office: Office) -> MadeObjects:
        forms = {
            op.id: {f for verb in op.verbs for f in asking_forms(normalize(verb))}
            for op in office.operations
        }
        rivals: dict[str, tuple[str, frozenset[str]]] = {}
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
            for form in forms[op.id] & names:
                if others and form not in others:
                    rivals[form] = (op.product, others - forms[op.id])
        return cls(rivals)

    def product_at(
        self, tokens: Sequence[Token], i: int, known: Callable[[str], bool]
    ) -> str | None:
        """The product ``tokens[i]`` names as the object of a rival verb (or a verb of doing)
        before it, if so; ``known``: whether a word is one of the office's."""
        found = self.rivals.get(tokens[i].word)
        if found is None or tokens[i].opens:
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


def _describes(word: str, known: Callable[[str], bool]) -> bool:
    """A word that may describe a product before its noun ("*day* labels", "*new* labels"):
    an English noun or adjective the office does not know as a name or a verb."""
    parts = language.lemmas(word)
    return word.isalpha() and not known(word) and ("NOUN" in parts or "ADJ" in parts)
