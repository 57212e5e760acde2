"""A made thing the office cannot make: "make a copy of my document for Mark", "make Mark a
copy of my document", "run off two copies of my report", "Mark needs a copy of my document"
where nothing in the office copies.

"Make (someone) a <product>" asks for a new thing to be made; the thing it is made from is
only the input. Where no operation of the office makes a thing called by that word, the
request is declined, naming the service it needs and what the office can do: handing over
the input instead ("Mark now has your document") would be a wrong physical action.

The product words are those of the standard services (``data/standard_services.yaml``: "copy",
"photocopy", "printout", "coffee", ...) and English's ``service_products``. A word such as
"copy" that is only part of one of the office's product names ("scanned copy", "printed
copy") is not that product: a copy is not a scan, and the office makes no plain copy.
"""

from __future__ import annotations

import functools

from assistantx.agents.symbolic.reading.screen.english import DETERMINERS, split_words
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english
from assistantx.core.office import Office
from assistantx.core.office_upgrade import standard

# Verbs that ask for a new thing to be made ("make me a copy", "do two copies", "produce a
# copy"); "run" and "knock" only with "off" after them ("run off a copy").
_MAKING = frozenset({"make", "do", "produce", "create"})
_MAKING_WITH_OFF = frozenset({"run", "knock"})
# Words between the verb and what it makes: who it is for ("me", "Mark") and how many.
_FOR_WHOM = frozenset({"me", "us", "him", "her", "them", "you"})
_HOW_MANY = frozenset({"another", "extra", "spare", "quick", "new", "more", "few", "couple", "of"})
# Verbs whose object is wanted ("needs a copy of ..."): made, where it is made "of" a thing.
_WANTING = frozenset({"needs", "need", "wants", "want", "get", "gets", "like"})
# "I'll make a copy myself": the speaker's own doing, no request.
_SPEAKER = frozenset({"i", "we", "ill", "id", "well", "im"})
_NUMBERS = english.words("number_words")


@functools.cache
def _standard_products() -> dict[str, str]:
    """A one-word product name or synonym of the standard services, singular or plural → the
    name of the standard service that makes it ("copy" → "copy", "coffee" → "make coffee")."""
    services = standard()
    out: dict[str, str] = {}
    for op in services["operations"].values():
        product = services["item_types"].get(op.get("product") or "")
        if product is None:
            continue
        for phrase in (product["name"], *product.get("synonyms", ())):
            words = split_words(phrase)
            if len(words) == 1:
                out.setdefault(words[0], op["name"])
                out.setdefault(words[0] + "s", op["name"])
    return out


def _made_here(office: Office) -> frozenset[str]:
    """The one-word names (singular and plural) of the things the office's operations make."""
    made: set[str] = set()
    for op in office.operations:
        if op.product is None or not office.runnable(op.id):
            continue
        product = office.item_type(op.product)
        for phrase in (product.name, *product.synonyms):
            words = split_words(phrase)
            if len(words) == 1:
                made |= {words[0], words[0] + "s", words[0].removesuffix("s")}
    return frozenset(made)


def made_product(terms: Terms, words: list[str]) -> tuple[int, str] | None:
    """Where ``words`` ask for a product to be made ("make Mark a copy"): the product word's
    index and the word; None when no making verb is followed by a product word."""
    products = set(_standard_products()) | set(terms.en.service_products)
    for at, w in enumerate(words):
        if w in _MAKING:
            n = at + 1
        elif w in _MAKING_WITH_OFF and at + 1 < len(words) and words[at + 1] == "off":
            n = at + 2
        elif _wants_one_made_of(words, at, products):
            return at + 2, words[at + 2]
        else:
            continue
        if _SPEAKER & set(words[max(0, at - 2) : at]):
            continue  # "I'll make a copy myself": the speaker's own doing
        while n < len(words) and (
            words[n] in DETERMINERS
            or words[n] in _FOR_WHOM
            or words[n] in _HOW_MANY
            or words[n].isdigit()
            or words[n] in _NUMBERS
            or (words[n] not in products and _names_someone(terms, words[n]))
        ):
            n += 1
        if n < len(words) and words[n] in products:
            return n, words[n]
    return None


def _wants_one_made_of(words: list[str], at: int, products: set[str]) -> bool:
    """ "Hope needs a copy of my report", "Ray wants a printout of my notes", "Ray should get
    a copy of it": a product made *of* a thing, wanted or to be got, asks for it to be made
    as "make Hope a copy of my report" does; the thing it is made of is only the input."""
    return (
        words[at] in _WANTING
        and at + 3 < len(words)
        and words[at + 1] in ("a", "an")
        and words[at + 2] in products
        and words[at + 3] == "of"
    )


def _names_someone(terms: Terms, word: str) -> bool:
    """Whether ``word`` is one of the office's people's names or aliases ("mark", "will"),
    even where it is also an English word: between a making verb and its product it is the
    one the product is for ("make Mark a copy")."""
    return word in terms.lex.people or word in terms.lex.name_words


def unmade_product(terms: Terms, piece: Piece) -> Finding | None:
    """The decline of a product the piece asks to be made that nothing here makes."""
    found = made_product(terms, piece.words)
    if found is None:
        return None
    _, word = found
    if word in _made_here(terms.office):
        return None  # the office makes it: the operation stage reads the request
    service = _standard_products().get(word)
    what = service if service is not None else f"make {word}"
    said = [
        f"Sorry, I can't {what}: nothing in this office makes {_plural(word)}, so I won't hand "
        "over anything else in their place.",
        terms.capabilities(),
    ]
    return Finding(
        "unsupported", piece, f"not made here: {word}", message=" ".join(s for s in said if s)
    )


def _plural(word: str) -> str:
    if word.endswith("s"):
        return word
    if word.endswith("y") and word[-2:-1] not in ("a", "e", "o", "u"):
        return word[:-1] + "ies"
    return word + "s"
