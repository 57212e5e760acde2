"""Another service's product in a verb's list of objects: "copy my document and a printout",
"scan my document and a printout". The second thing is what another of the office's services makes
(a printout is what printing makes), so it is no second object of the first verb: it asks for
that service's product, a task of its own. Before, the reader kept one of the two and lost the
other (only the print of "copy my document and a printout" was made). Where the word is also
said in a name of the verb's own product ("print my report and a copy": a "printed copy" is a
printout) the reading is left as it was (one print). It is read as said in a
sentence of its own ("copy my document. and a printout"), as a product asked for alone ("a
printout please") is read: the service's own input, the speaker's.

Only the products of services that make them from a thing of the speaker's (a file printed, a
document copied) are read so; a product made from nothing ("... and a coffee") is left to the
reading that asks whether it is a second request. A second verb said ("copy my document and
print my file") and a product named with its own source ("a printout of my file") read as
before (they already do)."""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.core import english, language
from assistantx.core.office import Office

# words between "and" and the product: "and *also a* printout", "and *two* copies"
_BETWEEN = (
    english.words("determiners")
    | english.words("object_quantifiers")
    | {
        "also",
        "one",
        "another",
    }
)
_SENTENCE = re.compile(r"[^.!?;\n]+[.!?;\n]*|[.!?;\n]+")


class ProductsListed:
    """The office's services that make a product from an input, by their verbs and by the
    names of their products."""

    def __init__(self, office: Office) -> None:
        self._verbs: dict[str, set[str]] = {}  # a verb word → the services it names
        self._products: dict[tuple[str, ...], set[str]] = {}  # a product's name → services
        self._inputs: dict[str, str] = {}
        for op in office.operations:
            if op.input is None or op.product is None:
                continue
            self._inputs[op.id] = op.input
            for verb in op.verbs:
                for w in language.words(verb)[:1]:
                    self._verbs.setdefault(language.fold(w), set()).add(op.id)
            made = office.item_type(op.product)
            for name in (made.name, *made.synonyms):
                said = tuple(language.fold(w) for w in language.words(name))
                for form in {said, (*said[:-1], language.plural(said[-1]))} if said else ():
                    self._products.setdefault(form, set()).add(op.id)
        self._product_ids = {op.id: op.product for op in office.operations}

    def __call__(self, text: str) -> str:
        """``text`` with each "and <another service's product>" after a service's verb and
        its object set in a sentence of its own."""
        if not self._verbs:
            return text
        return "".join(self._split(m.group(0)) for m in _SENTENCE.finditer(text))

    def _split(self, sentence: str) -> str:
        found = list(language.WORD.finditer(sentence))
        words = [language.fold(m.group(0)) for m in found]
        for n, word in enumerate(words):
            if word != "and" or n < 2:
                continue
            verb_at = self._verb_before(words, n)
            if verb_at is None or verb_at >= n - 1:  # no object of the verb before "and"
                continue
            made_by = self._product_at(words, n + 1)
            if made_by is None:
                continue
            own = self._verbs[words[verb_at]]
            other = made_by - own
            if (
                not other
                or self._own_product_said(own, words, n + 1)
                or any(self._inputs.get(o) == self._product_ids.get(x) for o in own for x in other)
            ):
                continue
            at = found[n].start()
            return sentence[:at].rstrip() + ". " + self._split(sentence[at:])
        return sentence

    def _verb_before(self, words: Sequence[str], at: int) -> int | None:
        """The nearest service verb before ``at`` in the sentence; a service's word after a
        determiner or a count ("I need *a copy* of my plan ... and a PDF") is a noun there,
        and then there is no verb."""
        for k in range(at - 1, -1, -1):
            if words[k] in self._verbs:
                return None if k and words[k - 1] in _BETWEEN else k
        return None

    def _own_product_said(self, own: set[str], words: Sequence[str], at: int) -> bool:
        """Whether the product word said from ``at`` on is also a word of a name of the verb's
        own service's product ("print my report and a copy": a "printed copy" is a printout,
        so the copy may be a second print): that reading is left as it was."""
        k = at
        while k < len(words) and words[k] in _BETWEEN:
            k += 1
        said = words[k] if k < len(words) else ""
        return any(said in name for name, ops in self._products.items() if ops & own)

    def _product_at(self, words: Sequence[str], at: int) -> set[str] | None:
        """The services whose product is named from ``at`` on, past the determiners and
        counts, with at least one of those before it where the name is also a verb ("and a
        scan"; "and scan my form" is a second verb)."""
        k = at
        while k < len(words) and words[k] in _BETWEEN:
            k += 1
        for name, ops in sorted(self._products.items(), key=lambda p: -len(p[0])):
            if tuple(words[k : k + len(name)]) != name:
                continue
            if k == at and words[k] in self._verbs:
                continue
            return ops
        return None
