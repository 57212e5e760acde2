"""A statement closed by a one-word confirming tag ("Zhang has scissors right?", "Mark's got
a ruler yeah?"): the speaker says what they believe and asks only to have it confirmed, as
"..., hasn't he?" does. The question mark asks nothing of its own, so the sentence stays a
statement (who has the thing is context for the request beside it), never a question that
the reader answers or reads as a request of its own.

Only a sentence that opens as a statement counts: one opening with an auxiliary or a wh-word
("is this right?", "which one is right?") is a question whatever its last word. And "right"
after a preposition or a determiner ("on the right?", "turn to the right?") is a direction,
not a tag."""

from __future__ import annotations

from assistantx.core import english

# The words said after a statement to have it confirmed (chat and speech alike).
_TAGS = frozenset({"right", "yeah", "yea", "yes", "innit", "correct", "eh"})
_QUESTION_OPENERS = english.words("question_auxiliaries") | english.words("wh_words")
# words after which "right" is a direction or a judgement, not a tag ("to the right",
# "all right", "turn right", "is it right")
_NOT_BEFORE_TAG = (
    english.words("prepositions_and_joins")
    | english.words("determiners")
    | frozenset({"all", "turn", "go", "is", "its", "it", "that", "thats", "not", "quite"})
)
# "X has Y right": a statement says at least a subject and a verb before its tag
_SHORTEST_STATEMENT = 2


def confirming_tag(words: list[str]) -> bool:
    """Whether a sentence's words (lower-cased, as split) are a statement and a one-word
    confirming tag after it."""
    if len(words) <= _SHORTEST_STATEMENT or words[-1] not in _TAGS:
        return False
    if words[0] in _QUESTION_OPENERS or words[0] in english.words("request_modals"):
        return False  # "is this right?", "can you do it right?"
    return words[-2] not in _NOT_BEFORE_TAG
