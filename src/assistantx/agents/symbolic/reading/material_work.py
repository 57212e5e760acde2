"""A need said by the work the speaker will do to a material: "need to cut some string for the
parcel, got anything?", "have to staple these pages, anything around?".

Needing to cut string is needing something to cut it with: where the work's verb is what an
item of the office is declared for (its ``purposes``: scissors "cut") and the material it is
done to names no item of the office, the material is the object of the speaker's own work,
never a thing to fetch. The rewrite says the need of the instrument ("need something to cut
some string with") and the reader's purpose rule picks the item. Where the material is an
item of the office ("need to cut some paper") the words may ask for it, and are left as said;
a verb of the office's own services ("need to print the report") is a service asked, and a
message that names a thing of the office ("..., bring me a stapler") says what it wants.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Collection

from assistantx.core import language

# "(I) need to cut some string", "have to staple these pages", "gotta wipe the bench down"
_NEED = re.compile(
    r"\b(?P<need>need|needs|have|has|got|gotta)\s+(?:to\s+)?(?P<verb>[a-z]+)"
    r"\s+(?P<object>(?:(?:the|my|our|this|that|these|those|a|an|some|more)\s+)?"
    r"[a-z]+(?:\s+[a-z]+)?)",
    re.IGNORECASE,
)
# words that end a material's phrase: "some string *for* the parcel"
_END = frozenset({"for", "with", "to", "on", "before", "after", "and", "but", "so", "then"})


def material_work(
    text: str,
    declared: Collection[str],
    services: Collection[str],
    names_something: Callable[[str], bool],
    items_named: Callable[[str], set[str]],
) -> str:
    """``text`` with each need of work on a material the office lacks said as the need of the
    instrument for it ("need to cut some string" -> "need something to cut some string
    with"). ``declared``: what the office's items are for, in lower case; ``services``: the
    office's operation words; ``names_something``: whether a phrase names an item, a person
    or a place of the office; ``items_named``: the item types a text names."""
    if _NEED.search(text) is None or items_named(text):
        return text  # "need to cut some string, bring me a stapler": the thing is said

    def need(match: re.Match[str]) -> str:
        said_need = match.group("need").lower()
        to_said = match.group(0)[len(match.group("need")) :].lstrip().lower().startswith("to ")
        if said_need != "gotta" and not to_said:
            return match.group(0)  # "I need some string": the thing itself
        verb = match.group("verb").lower()
        lemmas = language.verb_lemmas(verb) | {verb}
        if lemmas & set(services) or not lemmas & {d.split()[0] for d in declared if d}:
            return match.group(0)
        words = match.group("object").split()
        for n, w in enumerate(words):
            if w.lower() in _END:
                words = words[:n]
                break
        material = " ".join(words)
        if not words or names_something(material) or words[-1].lower() in _DEMONSTRATIVES:
            return match.group(0)
        needs = "needs" if said_need in ("needs", "has") else "need"
        rest = match.group("object")[len(material) :]
        return f"{needs} something to {match.group('verb')} {material} with{rest}"

    return _NEED.sub(need, text)


_DEMONSTRATIVES = frozenset({"it", "them", "this", "that", "these", "those", "one"})
