"""What a thing of the office needs done to it, told: "the cup needs washing", "my scissors
need sharpening", "the umbrella wants drying", "the stapler needs a refill", "the kettle needs
to be descaled".

English says a thing's state with "need" and a gerund (the gerund is passive: "needs washing"
is "needs to be washed"), "need" and a noun of work ("a wash", "a refill"), or "need to be"
and a participle. Its subject is the thing, never a person: nobody asks for the thing. Only
work the office does asks for something ("my document needs printing": a print, read by the
rules for the office's operations); work that no operation or task of the office names is how
the thing is, a statement, never the thing fetched for the speaker. The reader had read "the
cup needs washing" as "I need the cup" and fetched a colleague's cup; "the mug needs washing"
said "Noted" only because that office has no mug."""

from __future__ import annotations

from collections.abc import Container

from assistantx.core import language

# what may open the thing's phrase: an article, a demonstrative, a possessive pronoun
_OPENERS = frozenset(
    {"the", "this", "that", "these", "those", "my", "our", "your", "his", "her", "their"}
)
_NEEDS = frozenset({"needs", "need", "wants", "want"})
# "could do with a wash", "could use a clean": a need said with a helping verb
_MODAL_NEEDS = (("could", "do", "with"), ("could", "use"))
_ARTICLES = frozenset({"a", "an", "some", "another", "new", "good", "proper", "quick"})
_MOST_WORDS = 3  # the longest name of a thing looked for ("laptop charger stand")
# "new batteries", "more staples", "fresh ink": words before the part or supply needed
_SUPPLY_OPENERS = _ARTICLES | frozenset({"fresh", "more", "spare", "replacement", "its"})
_SUPPLY_WORDS = 2  # "new batteries", "ink cartridge": the longest part or supply read


def work_told(w: list[str], items: Container[str], asked: Container[str]) -> bool:
    """Whether ``w`` says a thing of ``items`` needs work that nothing in ``asked`` (the
    office's operation words and the task words that ask for work) names: "the cup needs
    washing", "my pen could do with a refill"."""
    at = 1 if w[:1] and w[0] in _OPENERS else 0
    size = next((k for k in range(_MOST_WORDS, 0, -1) if " ".join(w[at : at + k]) in items), 0)
    if not size:
        return False
    rest = w[at + size :]
    if rest[:1] and rest[0] in _NEEDS:
        rest = rest[1:]
    else:
        modal = next((m for m in _MODAL_NEEDS if tuple(rest[: len(m)]) == m), None)
        if modal is None:
            return False
        rest = rest[len(modal) :]
    work = _work(rest, items)
    if work is None:
        return False
    return not any(form in asked for form in {work, *language.verb_lemmas(work)})


def part_told(w: list[str], items: Container[str], asked: Container[str]) -> bool:
    """Whether ``w`` says a thing of ``items`` needs a part or supply the office does not
    keep: "the calculator needs new batteries", "the stapler needs staples", "my pen needs
    fresh ink". The thing is the subject, so it is not what is asked for; the part is no
    item of the office, so there is nothing to fetch either: how the thing is, a statement.
    Left as it was, the thing itself was fetched for the speaker (a wrong physical action).
    A part the office keeps ("the printer needs paper"), work ("needs a signature") or a
    person ("needs Mark") is left to the rules for things and work."""
    at = 1 if w[:1] and w[0] in _OPENERS else 0
    size = next((k for k in range(_MOST_WORDS, 0, -1) if " ".join(w[at : at + k]) in items), 0)
    if not size:
        return False
    rest = w[at + size :]
    if not rest or rest[0] not in _NEEDS:
        return False
    rest = rest[1:]
    k = 0
    while k < len(rest) and rest[k] in _SUPPLY_OPENERS:
        k += 1
    part = rest[k:]
    if not part or len(part) > _SUPPLY_WORDS or not all(p.isalpha() for p in part):
        return False  # "needs to go back", "needs new batteries before Friday": read as before
    if part[0] in _NOT_PARTS or any(language.is_present_participle(p) for p in part):
        return False  # "needs flame-proofing": work, said with a gerund
    said = {*part, " ".join(part)}
    lemmas = {lemma for p in part for lemma in language.verb_lemmas(p)}
    return not any(x in items or x in asked for x in said | lemmas)


# what follows "needs" and is no part: a pronoun, an infinitive's "to", a doer
_NOT_PARTS = frozenset({"to", "it", "me", "us", "you", "him", "her", "them", "someone"})


def _work(rest: list[str], items: Container[str]) -> str | None:
    """The word of the work needed, from the words after "needs": a gerund ("washing"), a
    participle after "to be" ("to be washed") or a noun that is also a verb after an article
    ("a wash", "a good clean"); None where a thing is named instead ("needs a stapler")."""
    if not rest:
        return None
    first = rest[0]
    if rest[:2] == ["to", "be"] and rest[2:3] and language.is_past_participle(rest[2]):
        return rest[2]  # "needs to be washed"
    if first.endswith("ing") and language.is_present_participle(first):
        return None if first in items else first  # "needs washing", not "needs a lining"
    k = 0
    while k < len(rest) and rest[k] in _ARTICLES:
        k += 1
    if k == 0 or k >= len(rest) or rest[k] in items:
        return None
    noun = rest[k]
    # "a wash", "a refill": a noun that is also the verb of the work; "new batteries", "a
    # plug" name a thing the office does not keep, no work: left to the rules for things
    if noun in language.verb_lemmas(noun) and language.is_noun(noun):
        return noun
    return None
