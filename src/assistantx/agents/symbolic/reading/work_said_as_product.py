"""A service's product said by its verb as a noun, after the service was asked: "print my file
and take *the print-out* to Mao", "... *the print out*", "... *the print*", "scan my letter and
bring *the scans* to Sue". The noun is what that service makes, the product of the work just
asked (fix180a class 3: read as the verb again, a second printout was made for the speaker
besides Mao's). It is said again by the product's name ("the printout"), which the readings
already take as the work's own product: one printout, handed to whom it is taken to.

Only after a determiner ("the", "this", "that", ...), and only where a verb of the same service
was said before it in the message, and never as the modifier of a noun after it ("the print
room", "the 3D printer"); "out of" after it ("take the print out of the tray") says
where the noun is taken from, no part of it."""

from __future__ import annotations

import re

from assistantx.core import language
from assistantx.core.office import Office

# the words that open the noun ("*the* print-out", "*this* scan")
_OPENERS = frozenset({"the", "this", "that", "these", "those"})
_PARTICLES = frozenset({"out", "off"})  # "print-out", "print off"
_WORD = re.compile(r"[\w']+")


class WorkSaidAsProduct:
    """The office's services that make a product, by the first words of their verbs."""

    def __init__(self, office: Office) -> None:
        self._products: dict[str, tuple[str, set[str]]] = {}  # verb word → (product, forms)
        for op in office.operations:
            if op.product is None:
                continue
            product = office.item_type(op.product).name
            forms = {language.fold(w) for v in op.verbs for w in language.words(v)[:1]}
            for verb in forms:
                self._products.setdefault(verb, (product, forms))

    def __call__(self, text: str) -> str:
        if not self._products:
            return text
        words = [(m.start(), m.end(), language.fold(m.group())) for m in _WORD.finditer(text)]
        said: set[str] = set()  # the verbs of the services said so far
        spans: list[tuple[int, int, str]] = []  # where a noun is said again, and as what
        for n, (start, _end, word) in enumerate(words):
            lemmas = language.verb_lemmas(word) or frozenset({word})
            known = next((w for w in (word, *lemmas) if w in self._products), None)
            if known is None or not language.lemmas(word).get("VERB"):
                continue
            product, forms = self._products[known]
            if not (n > 0 and words[n - 1][2] in _OPENERS):
                said.update(forms)
                continue
            if not said & forms:
                continue  # "take the print to Mao" alone: no work asked before it
            last = n
            # "the print out of the tray": the noun, then where it is taken out of
            out_of = n + 2 < len(words) and words[n + 2][2] == "of"
            if n + 1 < len(words) and words[n + 1][2] in _PARTICLES and not out_of:
                last = n + 1
            plural = word not in forms and word.endswith("s")
            name = language.plural(product) if plural else product
            if last == n and language.fold(name) == word:
                continue  # "the scan" where the product is a scan: said so already
            after = words[last + 1][2] if last + 1 < len(words) else ""
            if (
                after not in _PARTICLES
                and language.is_noun(after)
                and not _gap(text, words[last][1])
            ):
                continue  # "the print room", "the 3D printer": a compound's modifier
            spans.append((start, words[last][1], name))
        for start, end, name in reversed(spans):
            text = text[:start] + name + text[end:]
        return text


def _gap(text: str, end: int) -> bool:
    """Whether a pause follows the word ending at ``end`` (a comma, a stop, a dash)."""
    rest = text[end:].lstrip(" ")
    return bool(rest) and rest[0] in ",.;:!?-–—"
