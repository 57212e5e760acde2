"""A clause told with a modal after its subject: "van run might be off", "franking could be
pricey this month", "the coffee could run out". English never puts a modal right after an
imperative's verb (nobody says "bring might ..."), so one to three nouns and then a modal of
possibility ("might", "could") with a verb after it make those nouns the clause's subject: a
forecast or a remark about the thing, never a request for the service or item they name.
Chat drops the subject's article ("van run might be off"), so no "the" is needed.

A modal with "you" or a helper before it ("you could bring me one", "someone might lend me
one") asks, and a colleague as the subject ("Sun could whip one up") is read by the rules for
colleagues; both are left as before. "may", "will" and "can" are no such modal here: they are
names and nouns too ("take May my letter", "the can")."""

from __future__ import annotations

from collections.abc import Callable

from assistantx.core import english, language

# Modals of possibility only: "should"/"must" say what is wanted ("my stapler should go to
# Lee", "my banner must be fireproofed") and "would" a wish ("a pen would be great"), asked.
_MODALS = frozenset({"might", "could", "mightnt", "couldnt"})
# "could do with a clean", "my poster could use a lamination": a want said of the thing
# (asked), read as before.
_WANTS = (("do", "with"), ("use",))
# Words after the modal that carry its verb on ("might not be", "could well be").
_BETWEEN = frozenset({"not", "well", "also", "still", "really", "easily", "actually"})
_MOST_BEFORE = 3
# What may open the subject ("the coffee could run out"); "me" of the list is no opener.
_OPENERS = english.words("determiners") - {"me"}
# Who is asked or offers: "you could ...", "someone might ...", "I could ..." (the list's
# "the" of "the robot" opens any subject, so it is no sign of one asked).
_ASKEES = (english.words("request_askees") | english.words("subject_pronouns")) - _OPENERS


def told_with_modal(w: list[str], named: Callable[[str], bool]) -> bool:
    """Whether the content words ``w`` open with a subject of one to three words (nouns, a
    determiner, a verb's "-ing") and then a modal and its verb; ``named``: whether a word is
    a colleague's name."""
    at = next((n for n, x in enumerate(w[: _MOST_BEFORE + 1]) if x in _MODALS), None)
    if not at:
        return False  # no modal, or one that opens the clause ("could you ...")
    subject = w[:at]
    if any(x in _ASKEES or named(x) for x in subject):
        return False  # "you could ...", "Sun could whip one up": read as before
    if not all(_subject_word(x) for x in subject):
        return False  # "let it be", a verb before: read as before
    rest = w[at + 1 :]
    while rest and rest[0] in _BETWEEN:
        rest = rest[1:]
    if any(tuple(rest[: len(want)]) == want for want in _WANTS):
        return False
    return bool(rest) and rest[0] in language.verb_lemmas(rest[0])


def _subject_word(word: str) -> bool:
    """A word a subject is made of: a determiner, a noun, or a verb's "-ing" said as one
    ("laminating could take a while")."""
    return word in _OPENERS or language.is_noun(word) or language.is_present_participle(word)


# "can barely see a thing", "could hardly hear you": a modal of ability with its subject
# dropped and an adverb that nearly denies the verb tells the speaker's state; nobody asks
# "can you barely ...?" ("not" left out: "can not" is rare in chat and reads either way)
_ABILITY = frozenset({"can", "could", "cant", "couldnt"})
_NEARLY_DENIED = english.words("negative_adverbs") - {"not", "longer", "nowhere"}


def denied_ability(w: list[str]) -> bool:
    """Whether the content words ``w`` open with "can"/"could" and an adverb that nearly
    denies the verb after it ("can barely see a thing"): the speaker's state, told."""
    return len(w) > 2 and w[0] in _ABILITY and w[1] in _NEARLY_DENIED
