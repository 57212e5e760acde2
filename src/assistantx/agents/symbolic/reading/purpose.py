"""What someone else will do with the item once it is handed over: "take my drive to Dot *so
it can be couriered* to the lab", "... so she can post it". The verbs of such a purpose are
not asked of the robot: its errand is the hand-over; the colleague runs the service.

A purpose opens with "so" (or "so that") and a subject other than the one spoken to ("it",
"she", "Dot") with a modal after it ("can", "will", "could be"); every task word after it in
the clause only modifies.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english

_MODALS = english.words("request_modals") | {"shall", "should", "must"}
_SPOKEN_TO = frozenset({"you", "u", "ya", "ye"})
_SUBJECT_WORDS = frozenset({"it", "they", "she", "he", "we", "i", "them", "someone"})


def others_purpose(tokens: Sequence[Token], mentions: Sequence[Mention]) -> set[int]:
    """The starts of the task words in ``mentions`` that say what another will do once the
    errand is done ("so it can be couriered"), none when no such purpose is said."""
    words = [t.word for t in tokens]
    for m in mentions:
        at = m.start
        if words[at] != "so":
            continue
        k = at + 1 + (at + 1 < len(words) and words[at + 1] == "that")
        subject = next((x for x in mentions if x.start == k), None)
        if k >= len(words) or words[k] in _SPOKEN_TO:
            continue
        said = words[k] in _SUBJECT_WORDS or (subject is not None and subject.kind == "person")
        end = subject.end if subject is not None else k + 1
        if said and end < len(words) and words[end] in _MODALS:
            return {x.start for x in mentions if x.start > end and x.kind == "cue"}
    return set()


# what opens the thing wanted after "after" ("Kit's after *a* torch")
_WANTED_STARTS = r"(?:a|an|the|some|one|another|any|his|her|their|my|your)\b"


def _need_phrases_after(first: str) -> str:
    """The ``need_phrases`` that open with ``first`` ("s", "is"), less that word, as one
    alternation; "after" only before what is wanted."""
    return "|".join(
        r"\s+".join(re.escape(w) for w in p.split()[1:])
        + (r"(?=\s+" + _WANTED_STARTS + ")" if p.split()[1:] == ["after"] else r"\b")
        for p in english.entries("need_phrases")
        if p.split()[0] == first and len(p.split()) > 1
    )


# "Kit's after a torch", "Kit's looking for one": the need phrases said with "'s" for "is"
# ("s after", "s looking for" of ``need_phrases``); "after" only before what is wanted ("Kit's
# after a torch", never "Kit's after-school club")
_CONTRACTED_NEEDS = re.compile(
    r"(?<=\w)['’]s\s+(?P<phrase>" + _need_phrases_after("s") + ")", re.IGNORECASE
)


# "Gwen has been after the key all morning", "Kit has been looking for one" (the "'s been" of
# "Gwen's been after" is spelled "has been" before this, ``contracted_has_is``): the want said
# as going on till now is the want now, "is after" of ``need_phrases``; "after" only before
# what is wanted ("has been after lunch" is a time). "I have been after" is the speaker's own
# and left as said; "has been broken" is no need phrase.
_LASTING_NEEDS = re.compile(
    r"\bhas\s+been\s+(?P<phrase>" + _need_phrases_after("is") + ")", re.IGNORECASE
)


def contracted_needs(text: str) -> str:
    """ "Kit's after a torch" said as "Kit is after a torch": the "'s" of a need phrase is
    "is", not a possessive, so the need is read as any other ("Kit is after a torch": whom
    it is for); "Kit has been after a torch" is the same want, said as lasting till now."""
    text = _CONTRACTED_NEEDS.sub(lambda m: f" is {m.group('phrase')}", text)
    return _LASTING_NEEDS.sub(lambda m: f"is {m.group('phrase')}", text)


# "I'd murder a coffee", "we could kill for some tea", "I'm dying for a snack", "I could
# really go for a muffin": the speaker's idiom of wanting (``wanting_idioms``), after a helping
# verb ("'d", "could", "'m") and any degree words, before what is wanted
def _any_of(key: str) -> str:
    phrases = sorted(english.entries(key), key=len, reverse=True)
    return "|".join(r"\s+".join(re.escape(w) for w in p.split()) for p in phrases)


# an additive ("also", "still") among the degrees adds this want to the one before: the same
# want, a second request ("bring me plasters? I'm also desperate for a tea")
_DEGREES = rf"(?:\s+(?:{_any_of('wanting_degrees')}|{_any_of('wanting_additives')}))*\s+"
_WANTING = re.compile(
    rf"\b(?P<subject>i|we)(?:(?:\s*['’]\s*|\s+|)(?:{_any_of('wanting_helpers')}){_DEGREES}"
    rf"(?:{_any_of('wanting_idioms')}|{_any_of('wanting_verbs')})"
    rf"|{_DEGREES}(?:{_any_of('wanting_verbs')}))"
    r"\s+(?=(?:a|an|some|another|one|more|a\s+few|a\s+couple)\b)",
    re.IGNORECASE,
)


def wanting_idioms(text: str) -> str:
    """ "I'd murder a coffee", "... and I could kill for a snack" said as "I need a coffee":
    the speaker's idiom of wanting is their need of the thing, read as any need of theirs (a
    request for them, also as the second part of a message). Only before what is wanted (an
    article or a quantity): "I'd murder whoever took my pen" and "I'm dying to know who ..."
    keep their readings."""
    return _WANTING.sub(lambda m: f"{m.group('subject')} need ", text)
