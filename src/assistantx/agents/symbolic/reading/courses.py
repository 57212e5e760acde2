"""A course of a product (the lexicon stage, once typos are corrected): "make up 14 days of
meloxicam", "dispense a course of amoxicillin": a measure of supply ("days", "a course",
"doses"; English data ``course_measures``) then "of" and a word the office does not know,
said beside the verb of a service that makes one product from nothing given, names that
product: what the service makes, in the kind the speaker named (the office lists medicines
by what they are, "meds", not by each drug).

Only where exactly one such service's verb is said, and only a word that names nothing of the
office; anything else is read as before (an unknown thing is asked about or declined)."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english
from assistantx.core.office import Office
from assistantx.memory.names import normalize

_MEASURES = english.words("course_measures")


@dataclass(frozen=True)
class Courses:
    """The services that make one product from nothing given: each verb phrase's words → the
    product's one-word name, as the lexicon reads it."""

    makers: dict[tuple[str, ...], str]

    @classmethod
    def from_office(cls, office: Office) -> Courses:
        items = {t.id: t for t in office.item_types}
        makers: dict[tuple[str, ...], str] = {}
        for op in office.operations:
            product = items.get(op.product) if op.product is not None else None
            if product is None or op.input is not None:
                continue
            names = [normalize(n) for n in (product.name, *product.synonyms)]
            one_word = [n for n in names if n.isalpha()]
            if not one_word:
                continue
            for verb in op.verbs:
                makers[tuple(normalize(verb).split())] = one_word[0]
        return cls(makers)

    def read(self, tokens: Sequence[Token], known: Callable[[str], bool]) -> list[Token]:
        """``tokens`` with an unknown word after "<measure> of" read as the product named."""
        out = list(tokens)
        product = self._said_product([t.word for t in out])
        if product is None:
            return out
        for n in range(1, len(out) - 1):
            if out[n].word != "of" or out[n - 1].word not in _MEASURES:
                continue
            said = out[n + 1].word
            if said.isalpha() and not known(said):
                out[n + 1] = out[n + 1].corrected_to(product)
        return out

    def _said_product(self, words: list[str]) -> str | None:
        """The product of the one making service whose verb the words say, if just one."""
        said = {
            product
            for verb, product in self.makers.items()
            if any(tuple(words[n : n + len(verb)]) == verb for n in range(len(words)))
        }
        return next(iter(said)) if len(said) == 1 else None
