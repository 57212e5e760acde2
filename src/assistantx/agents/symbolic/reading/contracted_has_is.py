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
one word describing the owned thing and stays a possessive.

A thing of the office's "'s" before a verb's -ing form is "is" too, where the -ing word opens
no name of the office ("my drill's eating batteries", "my recorder's playing up": the drill is
eating them; "my drill's charging lead" names the lead, and stays the drill's) and no verb of
its own follows a word or two on ("my drill's cutting disc is worn": the -ing word describes
the subject's noun). Read as a possessive, the thing doing it was the thing asked about
("Where is your drill?") and the request beside it was never read."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import language

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


# a thing's "'s", then an -ing word and the words after it up to the clause's end
_DOING = re.compile(
    r"\b(?P<noun>[A-Za-z][\w-]*)['’]s\s+(?P<doing>[A-Za-z]+ing)\b(?![\w'’-])(?P<rest>[^,.;:!?]*)",
    re.IGNORECASE,
)
# a verb of the subject's own after the -ing word: that word describes the subject's noun
_OWN_VERB = frozenset({"is", "was", "are", "were", "has", "had", "isnt", "wasnt", "hasnt", "s"})


def spelled_has_is(
    text: str,
    thing: Callable[[str], bool] = lambda phrase: False,
    opens_name: Callable[[str], bool] = lambda phrase: False,
) -> str:
    """``text`` with each noun's contracted "has"/"is" spelled out before a participle or a
    preposition ("Wang's gone" -> "Wang has gone", "Zhang's at" -> "Zhang is at"), where
    the noun is its clause's subject; and a thing's before a verb's -ing form ("my drill's
    eating batteries" -> "my drill is eating batteries") where ``thing`` says the noun names
    one of the office's things and ``opens_name`` says the -ing word and the words after it
    open no name of the office."""

    def spelled(m: re.Match[str]) -> str:
        noun = m.group("noun")
        if noun.lower() in _NOT_A_NOUN or not _SUBJECT_OPENING.search(text[: m.start()]):
            return m.group(0)
        if m.group("is"):
            return f"{noun} is {m.group('is')}"
        return f"{noun} has {m.group('has') or m.group('has_verb')}"

    def doing(m: re.Match[str]) -> str:
        noun, ing, rest = m.group("noun"), m.group("doing"), m.group("rest")
        after = re.findall(r"[\w'’]+", rest)[:3]
        if (
            noun.lower() in _NOT_A_NOUN
            or not _SUBJECT_OPENING.search(text[: m.start()])
            or not language.is_present_participle(ing.lower())
            or not thing(noun)
            or opens_name(" ".join([ing, *after[:2]]))
            or any(re.sub(r"['’]", "", w).lower() in _OWN_VERB for w in after)
        ):
            return m.group(0)
        return f"{noun} is {ing}{rest}"

    return _DOING.sub(doing, _CONTRACTED.sub(spelled, text))
