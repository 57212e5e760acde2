"""A noun's "'s" before a participle or a preposition is "has" or "is", no possessive: "the
visitor's gone home", "Wang's gone to lunch with the scissors", "Zhang's at lunch", "Wang's
off today". English writes the same "'s" for the possessive and for the contracted auxiliary;
the possessive owns a noun after it, and no noun is "gone", "been", "off" or "at". Read as a
possessive, "Wang's gone to lunch" makes lunch Wang's and "the visitor's gone home" is no
sentence at all; spelled out ("Wang has gone", "Zhang is at lunch") the reader reads them as
statements, context for the request after them.

Which words: "been", said only as a verb, always ("has"); "gone" and the particles and
prepositions that say where someone is ("off", "out", "away", "on", "at", "in") always ("is":
"Wang is gone" is the state the reader already reads as away, as it reads "Wang's gone"); a
participle that is also an adjective before a noun ("lost", "left", "taken", "got": "Wang's
lost stapler") only when what follows is no noun of its own: a determiner or pronoun ("lost
his tie", "taken the stapler"), an adverb of time or place ("left already"), a preposition,
or the clause's end. A hyphened compound ("Wang's gone-off milk", "Wang's on-call phone") is
one word describing the owned thing and stays a possessive."""

from __future__ import annotations

import re

# a participle no noun is: the "'s" before it is always "has"
_HAS_ALWAYS = ("been",)
# participles that also describe a noun ("Wang's lost stapler"): "has" only before no noun
_HAS_BEFORE_NO_NOUN = ("lost", "left", "taken", "got", "gotten")
# where someone is: "Zhang's at lunch", "Wang's off today", "Wang's gone" (a state, "is gone")
_IS = ("gone", "off", "out", "away", "on", "at", "in")
# what follows a verb and is no noun the participle could describe
_NO_NOUN = (
    "the|a|an|his|her|their|my|your|our|its|it|them|him|me|us|this|that|these|those|some"
    "|already|early|home|just|now|today|yet|again|for|to|with|without|from|off|out|away"
    "|on|at|in|up|down|back"
)
# the words whose "'s" is no noun's: "let's", and the pronouns' own contractions, which the
# reader already reads as "is"/"has"
_NOT_A_NOUN = frozenset({"let"})

# a subject opens its clause: at the text's start, after a stop or a comma, after a joining
# word or a verb of saying ("says his son's lost ..."), at most a determiner before it, and
# after one up to two words that describe the noun ("my phone cable's at home"); "put it on
# Wang's in the morning" is a possessive after a preposition, no subject
_SUBJECT_OPENING = re.compile(
    r"(?:^|[,.;:!?(–—-]|\b(?:and|but|because|cos|since|as|so|then|when|while|though|says|said|thinks|reckons|that)\b)"
    r"\s*(?:(?:the|a|an|this|that|my|our|your|his|her|their)\s+(?:(?!(?:on|in|at|to|for|from|with|of|by|off|and|or)\b)[^\W\d_][\w-]*\s+){0,2})?$",
    re.IGNORECASE,
)

_CONTRACTED = re.compile(
    r"\b(?P<noun>[A-Za-z][\w-]*)['’]s\s+"
    r"(?:"
    rf"(?P<has>{'|'.join(_HAS_ALWAYS)})(?![\w'’-])"
    rf"|(?P<has_verb>{'|'.join(_HAS_BEFORE_NO_NOUN)})(?=\s*(?:[,.;:!?)]|$|\s(?:{_NO_NOUN})\b))"
    rf"|(?P<is>{'|'.join(_IS)})(?![\w'’-])"
    r")",
    re.IGNORECASE,
)


def spelled_has_is(text: str) -> str:
    """``text`` with each noun's contracted "has"/"is" spelled out before a participle or a
    preposition ("Wang's gone" -> "Wang has gone", "Zhang's at" -> "Zhang is at"), where
    the noun is its clause's subject."""

    def spelled(m: re.Match[str]) -> str:
        noun = m.group("noun")
        if noun.lower() in _NOT_A_NOUN or not _SUBJECT_OPENING.search(text[: m.start()]):
            return m.group(0)
        if m.group("is"):
            return f"{noun} is {m.group('is')}"
        return f"{noun} has {m.group('has') or m.group('has_verb')}"

    return _CONTRACTED.sub(spelled, text)
