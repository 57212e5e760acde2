"""An operation named by a noun: "my poster needs a lamination", "this contract could use a
legal review", "my draft should get a proofread": after words that say the thing needs
something ("needs", "wants", "could use", "should get"), a noun that names one of the office's
operations asks for that operation on the thing, as its verb would ("laminate my poster").

The nouns come from the office file only, never from a list of services here:

* a nominalization of a declared verb that the morphology library knows as a noun
  ("laminate" → "lamination", "inspect" → "inspection", "approve" → "approval"); the plain
  verb used as a noun ("a proofread") and its gerund ("proofreading") are its own forms
  already, read as the verb by the lexicon;
* the head noun of the operation's display name where the office declares verbs of its own
  ("legal review" for an operation asked for by "vet"), with the name's other words.

A noun two operations share, or one that is already a word of the office (an item, a name, a
task verb), is left alone as a bare noun; said with the rest of an operation's display name
("a *legal* read" where a "style read" also exists, or where "read" is an office word), the
whole name names that operation and is read as it. The rewrite is the lexicon's, like a
typo's correction: the token is read as the operation's verb, its typed text kept.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office
from assistantx.memory.names import normalize

# The endings a verb takes to name its act: "laminat-ion", "inspect-ion", "approv-al".
_NOMINAL_ENDINGS = ("ion", "ation", "ment", "al")
# What says its subject needs something done: "needs", "wants", "requires", "is due".
NEEDING = english.words("need_verbs") | {"needed", "wanted", "requires", "require", "due"}
# Two words that say the same: "could use a", "could do with a", "should get a".
_NEEDING_PAIRS = frozenset(
    {("could", "use"), ("do", "with"), ("should", "get"), ("should", "have"), ("to", "get")}
)
_ARTICLES = frozenset({"a", "an", "another", "some", "one", "its"})
_MAX_MODIFIERS = 2  # "a quick final proofread"


def _nominals(verb: str) -> set[str]:
    """The nouns the dictionary knows that name the act of ``verb``."""
    stems = {verb, verb[:-1]} if verb.endswith("e") else {verb}
    found = {stem + ending for stem in stems for ending in _NOMINAL_ENDINGS}
    return {n for n in found if n != verb and "NOUN" in language.lemmas(n)}


def operation_nouns(office: Office, taken: Callable[[str], bool]) -> dict[str, str]:
    """Each noun that names exactly one of ``office``'s operations, with the operation's
    first verb it is read as; ``taken``: whether a word already means something in the office
    (an item, a person, a task verb)."""
    named: dict[str, set[str]] = {}
    things = _thing_names(office)
    for op in office.operations:
        if not op.verbs:
            continue  # an operation without verbs is asked for by its name's words already
        verb = normalize(op.verbs[0]).split()[0]
        nouns: set[str] = set()
        for declared in op.verbs:
            words = normalize(declared).split()
            if len(words) == 1:
                nouns |= _nominals(words[0])
        name = normalize(op.name).split()
        if _is_a_declared_phrase(name, op.verbs):
            pass  # "a bump test": the declared phrase itself, joined as the verb later
        elif name and language.is_noun(name[-1]) and not _ends_with_thing(name, things):
            nouns.add(name[-1])  # "legal review": its head noun
        for noun in nouns:
            named.setdefault(noun, set()).add(verb)
    return {
        noun: next(iter(verbs))
        for noun, verbs in named.items()
        if len(verbs) == 1 and not taken(noun)
    }


def _is_a_declared_phrase(name: list[str], verbs: Sequence[str]) -> bool:
    """Whether an operation's display name of several words is one of its own declared verb
    phrases ("bump test" asked for by "bump test"): the lexicon joins that phrase into one
    verb token wherever it is said ("needs a bump test"), so reading its head noun as the
    phrase's first word alone would leave "bump bump", no operation at all."""
    return len(name) > 1 and " ".join(name) in {" ".join(normalize(v).split()) for v in verbs}


def _thing_names(office: Office) -> set[tuple[str, ...]]:
    """The office's item names, as word tuples ("cool", "box")."""
    return {
        tuple(normalize(n).split())
        for t in office.item_types
        for n in (t.name, *t.synonyms)
        if normalize(n)
    }


def _ends_with_thing(name: list[str], things: set[tuple[str, ...]]) -> bool:
    """Whether an operation's display name ends with an item's name: "pack a cool box" names
    the verb and the thing it makes, whose noun ("box") is that thing, not the act."""
    return any(len(t) <= len(name) and tuple(name[-len(t) :]) == t for t in things)


def operation_names(office: Office) -> dict[tuple[str, ...], str]:
    """Each operation's display name of two words or more, as its words ("legal", "read"),
    with the operation's first verb: the whole name names one operation even where its head
    noun alone is shared or means something else in the office. A name two operations share
    is left out."""
    named: dict[tuple[str, ...], set[str]] = {}
    for op in office.operations:
        if not op.verbs:
            continue
        name = tuple(normalize(op.name).split())
        if _is_a_declared_phrase(list(name), op.verbs):
            continue  # the name is the operation's own verb phrase ("bump test")
        if len(name) >= 2 and language.is_noun(name[-1]):
            named.setdefault(name, set()).add(normalize(op.verbs[0]).split()[0])
    return {name: next(iter(verbs)) for name, verbs in named.items() if len(verbs) == 1}


def _needed_before(words: Sequence[str], at: int, skippable: Callable[[str], bool]) -> bool:
    """Whether the noun at ``at`` follows the words of a need: "needs (a) (quick) ___",
    "could use a ___"; at most two modifiers between the article and the noun."""
    k = at - 1
    skipped = 0
    while k >= 0 and skipped < _MAX_MODIFIERS and skippable(words[k]):
        k -= 1
        skipped += 1
    if k >= 0 and words[k] in _ARTICLES:
        k -= 1
    if k < 0:
        return False
    return words[k] in NEEDING or (k >= 1 and (words[k - 1], words[k]) in _NEEDING_PAIRS)


def read_as_verbs(
    tokens: Sequence[Token],
    nouns: dict[str, str],
    skippable: Callable[[str], bool],
    names: dict[tuple[str, ...], str] | None = None,
) -> list[Token]:
    """``tokens`` with each noun of ``nouns`` said after a need read as its operation's verb
    ("needs a lamination" → "needs a laminate"); ``skippable``: whether a word may stand as a
    modifier between the article and the noun ("a *legal* review"); ``names``: operations'
    whole display names (``operation_names``), whose head noun after a need is read as the
    verb whatever the noun alone means ("needs a legal read" → "needs a legal vet")."""
    words = [t.word for t in tokens]
    out = list(tokens)
    for n, t in enumerate(tokens):
        if t.possessive:
            continue
        verb = _by_whole_name(words, n, names or {})
        if verb is None:
            verb = nouns.get(t.word)
            if verb is not None and not _needed_before(words, n, skippable):
                verb = None
        if verb is not None:
            out[n] = t.corrected_to(verb)
    return out


def _by_whole_name(words: Sequence[str], n: int, names: dict[tuple[str, ...], str]) -> str | None:
    """The verb of the operation whose whole name ends at word ``n`` after a need, if any.
    The whole name is specific, so any plain word may describe it ("a *quick* legal read")."""
    for name, verb in names.items():
        start = n - len(name) + 1
        if start < 0 or tuple(words[start : n + 1]) != name:
            continue
        if _needed_before(words, start, _describing):
            return verb
    return None


def _describing(word: str) -> bool:
    return word.isalpha() and word not in _ARTICLES and word not in NEEDING
