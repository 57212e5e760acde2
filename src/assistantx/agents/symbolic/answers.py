"""Reading a colleague's reply: yes, no, or unclear, by tolerant rules.

Real people write "yep, got one", "nope", "sorry, not today", "no problem!"; the simulator
writes "Yes, I have a stapler…". Both are read by the same word rules, not by matching the
simulator's sentences. A negative marker wins over a positive one ("yes, but I can't"),
except in the fixed phrases that are positive despite a "no" ("no problem").
"""

from __future__ import annotations

import re
from typing import Literal

from assistantx.core.language import fold

Stance = Literal["yes", "no", "unclear"]

_POSITIVE_PHRASES = (
    "no problem",
    "no worries",
    "not a problem",
    "why not",
    "of course",
    "no prob",
)
_NEGATIVE = re.compile(
    r"\b(no|nope|nah|sorry|cant|cannot|dont|do not|doesnt|unable|not available|havent|"
    r"have not|wont|will not|busy|away|not me|negative|unfortunately|afraid not|out of office|"
    r"not here|not at my desk|lost|none)\b"
)
_POSITIVE = re.compile(
    r"\b(yes|yeah|yep|yup|ya|sure|ok|okay|certainly|absolutely|definitely|will do|i have|"
    r"i can|ive got|got one|got it|here is|heres|here you go|happy to|on my way|coming|fine|"
    r"alright|i do|go ahead|can do|no problem|i am here|im here|count me in|ill do it|"
    r"help with that)\b"
)


def _clean(text: str) -> str:
    # folded first: "Noémie" is one word "noemie", never "no" and "mie" (a yes naming her
    # was read as a no, and the consent guard refused the owner's own yes)
    text = fold(text).replace("'", "")
    return re.sub(r"\s+", " ", re.sub(r"[^a-z0-9 ]+", " ", text)).strip()


# "it is kept in the negative vault", "in the lost property box", "over the busy season": a
# refusing word said after a determiner and before another word describes a thing, a place's
# or a time's name, and refuses nothing
_NAMING = re.compile(
    r"\b(?:the|a|an|my|our|your|his|her|their|this|that)\s+(?:negative|lost|busy|away|none)"
    r"(?=\s+(?!and\b|or\b|but\b)[a-z])"
)


def stance(text: str) -> Stance:
    """Whether a reply agrees, refuses, or says neither."""
    t = _NAMING.sub(" ", _clean(text))
    for phrase in _POSITIVE_PHRASES:
        t = t.replace(phrase, "no problem_ok")
    positive = bool(_POSITIVE.search(t)) or "problem_ok" in t
    negative = bool(_NEGATIVE.search(t.replace("no problem_ok", "")))
    if negative:
        return "no"
    if positive:
        return "yes"
    return "unclear"


# "I have one", "I've got a stapler", "I found mine": to an offer of a thing, saying that one
# has it is a no, however it starts ("Yes, I have a stapler" answers "Shall I bring you one?"
# as a colleague would, and means they need none).
_HAVE_ONE = re.compile(
    r"\b(i have|ive got|i got|i found|i already|got one|got mine|happy to lend|you can borrow|"
    r"you can have)\b"
)


def offer_stance(text: str) -> Stance:
    """Whether a reply to an offer ("Shall I bring you one?") accepts it."""
    t = _clean(text)
    if _HAVE_ONE.search(t) and not re.search(r"\b(please|need|want)\b", t):
        return "no"
    return stance(text)


# "Sorry, I don't know.", "no idea", "not sure": a reply to a clarifying question that names
# nothing; read as the answer, its words would become the answer ("fax it to Sorry").
_NOT_KNOWN = re.compile(
    r"^(sorry )?(i )?(dont know|do not know|have no idea|no idea|am not sure|im not sure|"
    r"not sure)\b"
)


def says_not_known(text: str) -> bool:
    """Whether a reply to a clarifying question only says that they do not know."""
    return bool(_NOT_KNOWN.search(_clean(text)))
