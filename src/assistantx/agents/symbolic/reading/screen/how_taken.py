"""How someone takes the drink they ask for ("a brew. milk no sugar", "tea, white, one sugar",
"a coffee with milk and two sugars", "black"): words about the drink, never a second thing to
fetch. Set aside before the pieces are judged when the message names a hot drink of the office
(on main "milk no sugar" had the robot bring milk from the fridge instead of the tea). With no
drink named, "bring me some milk" is milk."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.categories import category_named, is_member
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language
from assistantx.core.task_schema import Evidence

# What a drink is taken with, and the small words between them ("milk and two sugars").
_HOW = frozenset(
    {
        "milk", "milky", "sugar", "sugars", "white", "black", "sweetener", "sweeteners",
        "honey", "lemon", "strong", "weak", "decaf", "oat", "soy", "soya", "almond",
        "skimmed", "semi", "skim", "lump", "lumps", "spoon", "spoons", "teaspoon", "teaspoons",
    }
)  # fmt: skip
_BETWEEN = frozenset(
    {
        "no", "one", "two", "three", "1", "2", "3", "a", "splash", "dash", "drop", "of",
        "with", "and", "but", "just", "bit", "little", "lots", "extra", "half", "please",
        "pls", "plz", "thanks", "thx", "ta", "cheers", "x", "nice", "not", "too",
    }
)  # fmt: skip
_CLAUSE = re.compile(r"[^.,;!?\n]+")
# "tea with milk and one sugar": the taking words after "with", to the clause's end
_WITH_TAIL = re.compile(r"\s+with\s+([^.,;!?\n]+)$", re.IGNORECASE)


def how_taken(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """``text`` without how its hot drink is taken, which is kept as evidence."""
    drink = _drink_named(terms, text)
    if drink is None:
        return text, []
    found: list[Evidence] = []
    kept: list[str] = []
    last = 0
    for clause in _CLAUSE.finditer(text):
        said = clause.group(0)
        kept.append(text[last : clause.start()])
        last = clause.end()
        if _only_how(said):
            found.append(Evidence(words=said.strip(), meaning=f"how they take their {drink}"))
            continue
        tail = _WITH_TAIL.search(said)
        if tail is not None and _only_how(tail.group(1)):
            found.append(
                Evidence(words=tail.group(0).strip(), meaning=f"how they take their {drink}")
            )
            said = said[: tail.start()]
        kept.append(said)
    kept.append(text[last:])
    if not found:
        return text, []
    left = re.sub(r"([.,;!?])(?:\s*[.,;!?])+", r"\1", "".join(kept))
    return re.sub(r"\s{2,}", " ", left).strip(" ,;"), found


def _only_how(said: str) -> bool:
    words = language.words(said)
    return bool(words) and bool(set(words) & _HOW) and set(words) <= _HOW | _BETWEEN


def _drink_named(terms: Terms, text: str) -> str | None:
    """The name of the office's hot drink the text names (the first), if any."""
    hot = category_named("hot drink")
    if hot is None:
        return None
    lexed = terms.lex.read(text)
    for item_id in terms.named(lexed, "item"):
        kind = terms.office.item_type(item_id)
        # an office may call its urn's product "hot drink" and list "tea" and "brew" among
        # its synonyms: the thing is a hot drink if its name, or any name it goes by, is one
        names = (kind.name, *kind.synonyms)
        if category_named(kind.name) is hot or any(is_member(hot, n) for n in names):
            return kind.name
    # "Brew please. Milk, no sugar.": the verb of the office's service that makes a hot drink
    # from nothing, said for the drink it makes
    words = set(language.words(text))
    for op in terms.office.operations:
        if op.product is None or op.input is not None or not words & set(op.verbs):
            continue
        kind = terms.office.item_type(op.product)
        names = (kind.name, *kind.synonyms)
        if category_named(kind.name) is hot or any(is_member(hot, n) for n in names):
            return kind.name
    return None
