"""A statement of what is under way, its "is"/"are" left out as chat drops it: "two parcels
going out with Otto later", "van leaving at five", "Otto heading home early". One to three
words of a subject that are no verb, then a present participle no errand of the office asks
for: what is happening, the context of a request beside it, never one. A person named in it
("with Otto") is context, not whom the request's thing goes to.

Only where nothing in the piece asks (a modal, a "please", a need are read as before) and its
subject names none of the office's items ("my rota going to Otto" may still say where the
rota goes: read as before, and asked about where unclear), and never where the "-ing" follows
a determiner ("book me the recording studio": a noun's description) or the words before it
hold an object ("book me ..."): an imperative, whatever it asks.
"""

from __future__ import annotations

from collections.abc import Callable, Collection

from assistantx.core import english, language

_SUBJECT_WORDS = 3  # "two parcels", "the late van", "Otto"
_DETERMINERS = english.words("determiners") - {"me"}
# the objects a verb of asking takes ("book me", "get us"): never a word of a subject
_OBJECTS = frozenset({"me", "us", "him", "them"})


def clipped_progressive(
    w: list[str],
    *,
    cue_words: Collection[str],
    asking_words: Collection[str],
    verb_like: Callable[[str], bool],
    names_item: Callable[[list[str]], bool],
) -> bool:
    """Whether the content words ``w`` of a piece are such a statement. ``cue_words``: the
    verbs of the office's errands; ``asking_words``: words that make a piece ask (modals,
    "please", a need); ``verb_like``: whether a word may be a clause's verb;
    ``names_item``: whether words name one of the office's items."""
    if set(w) & set(asking_words):
        return False
    for n in range(1, min(len(w), _SUBJECT_WORDS + 1)):
        word = w[n]
        if not word.endswith("ing") or not language.is_present_participle(word):
            continue
        if language.verb_lemmas(word) & set(cue_words):
            return False  # "someone bringing me a pen": an errand's own verb
        if w[n - 1] in _DETERMINERS:
            # "book me the recording studio", "a parking space": after a determiner the
            # "-ing" describes the noun after it, no verb of a clause under way
            return False
        subject = w[:n]
        if set(subject[1:]) & _OBJECTS:
            return False  # "book me ...": an object after the first word, no subject
        if any(verb_like(x) and not language.is_noun(x) for x in subject):
            return False
        return not names_item(subject)
    return False
