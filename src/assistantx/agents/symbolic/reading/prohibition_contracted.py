"""A prohibition's subject with its "is" contracted: "nobody's to use the microwave till I've
cleaned it", "no one's allowed near my desk" say "nobody is to ...", "no one is allowed ...":
the same wish about other people as the full form, answered in words, nothing moved.

The words come with apostrophes dropped ("nobody's" is "nobodys", "no one's" is "no ones"),
so the contraction looks like a possessive. English tells them apart by what follows: "is to"
(the "be to" of an order) and a past participle ("allowed", "meant", "supposed") follow a
subject's "is"; a noun follows a possessive ("it's nobody's fault", "no one's stapler"), and
a present participle follows an "is" that tells what is going on ("nobody's using it"), a
fact, not a wish: both are left as said.
"""

from __future__ import annotations

from assistantx.core import english, language

_SUBJECTS = tuple(tuple(p.split()) for p in english.entries("prohibition_subjects"))


def _after_is(word: str) -> bool:
    """Whether ``word`` after "'s" makes it "is to" or "is <past participle>"."""
    if word == "to":
        return True
    found = language.lemmas(word)
    if "NOUN" in found or word.endswith("ing"):
        return False
    return any(lemma != word for lemma in found.get("VERB", ()))  # "allowed", "told"


def _contracted_at(words: list[str], k: int) -> tuple[str, ...] | None:
    """The prohibition subject whose "'s" form starts at ``words[k]``, read as "is"."""
    for subject in _SUBJECTS:
        end = k + len(subject)
        if end >= len(words) or words[k : end - 1] != list(subject[:-1]):
            continue
        if words[end - 1] == f"{subject[-1]}s" and _after_is(words[end]):
            return subject
    return None


def with_is(words: list[str]) -> list[str]:
    """``words`` with each contracted prohibition subject written out ("nobodys to" →
    "nobody is to"); anything else as it was."""
    out: list[str] = []
    k = 0
    while k < len(words):
        subject = _contracted_at(words, k)
        if subject is None:
            out.append(words[k])
            k += 1
            continue
        out += [*subject, "is"]
        k += len(subject)
    return out
