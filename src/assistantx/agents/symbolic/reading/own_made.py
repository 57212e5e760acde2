"""A thing named by the speaker's own doing: "print the meeting note I just saved", "the
slides that I made this morning", "the draft I sent you", "I finished the seating chart, can
you print it". A relative clause whose subject is the speaker and whose verb makes or sends
the thing (english.yaml ``own_making_verbs``), or a clause of the speaker's own making with
the thing as its object ("I drew up the floor plan", "just wrote up the minutes" with the "I"
left out), says whose it is as "my" does: "the" is read as "my" before the lexicon, so the
later stages read "my meeting note" (the requester's own file or paper), and an "it" after it
points back at it rather than at nothing. Another's doing ("the file Zhang sent me", "Tam
finished the chart"), a verb of getting ("the stapler I borrowed"), a phrase with a name or a
preposition in it, and a thing of the office that is no file ("I made the coffee") are read
as before.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english

_VERBS = english.words("own_making_verbs")
_FILLERS = english.words("own_making_fillers")
_SPEAKER = frozenset({"i", "ive", "id"})
_RELATIVE = frozenset({"that", "which"})
_PARTICLES = english.words("own_making_particles")
_WORDS = 3  # the words of the thing's name between "the" and the clause ("the meeting note")
# words that end the thing's name: another phrase, not a noun of it
_NOT_NAME = frozenset(
    {"a", "an", "the", "this", "that", "my", "your", "of", "for", "to", "from", "on", "in", "at"}
    | {"with", "and", "or", "but", "me", "you", "it", "them", "i", "we", "please", "one"}
)


def read_own_made(
    tokens: Sequence[Token],
    named: Callable[[str], bool],
    physical: Callable[[str], bool] = lambda _word: False,
) -> list[Token]:
    """``tokens`` with "the" read as "my" where the phrase it opens is followed by the
    speaker's own making or sending, or is the object of it ("I finished the seating chart",
    "just wrote up the minutes": the speaker's dropped "I"); ``named`` says whether a word
    names one of the office's people (then the phrase is left as it was), ``physical``
    whether it opens the name of one of the office's things that is no file ("I made the
    coffee": a thing the office has, not a file of the speaker's)."""
    out = list(tokens)
    for n, t in enumerate(tokens):
        if t.word != "the" or t.possessive:
            continue
        if _own_clause_after(tokens, n, named) or _own_making_before(tokens, n, named, physical):
            out[n] = t.corrected_to("my")
    return out


def _own_making_before(
    tokens: Sequence[Token],
    n: int,
    named: Callable[[str], bool],
    physical: Callable[[str], bool],
) -> bool:
    """ "I finished the seating chart", "I've just drawn up the plan", "wrote up the minutes"
    (opening the sentence, the speaker's "I" left out): "the" opens the object of the
    speaker's own making. Another's making ("Tam finished the chart") is not the speaker's."""
    if n + 1 >= len(tokens) or tokens[n].after_pause:
        return False
    thing = tokens[n + 1]
    if thing.opens or thing.after_pause or not thing.word.isalpha():
        return False
    if thing.word in _NOT_NAME or named(thing.word) or physical(thing.word):
        return False
    k = n - 1
    if k > 0 and tokens[k].word in _PARTICLES and not tokens[k].opens:
        if tokens[k].after_pause:
            return False
        k -= 1  # "wrote up", "put together"
    if k < 0 or tokens[k].word not in _VERBS or tokens[k].possessive:
        return False
    while k > 0 and not _starts(tokens[k]) and tokens[k - 1].word in _FILLERS:
        k -= 1
    if _starts(tokens[k]):
        return True  # "just wrote up the minutes": the speaker's own, "I" left out
    return tokens[k - 1].word in _SPEAKER and not tokens[k].after_pause


def _starts(token: Token) -> bool:
    """Whether a clause starts at ``token``: a sentence's first word, or after a pause."""
    return token.opens or token.after_pause


def _own_clause_after(tokens: Sequence[Token], n: int, named: Callable[[str], bool]) -> bool:
    k = n + 1
    while k < len(tokens) and k - n <= _WORDS:
        t = tokens[k]
        if t.opens or t.after_pause or not t.word.isalpha():
            return False
        if t.word in _SPEAKER or t.word in _RELATIVE:
            break
        if t.possessive or t.word in _NOT_NAME or named(t.word):
            return False
        k += 1
    else:
        return False
    if k == n + 1:
        return False  # "the I ...": no thing named
    if tokens[k].word in _RELATIVE:
        k += 1
    if k >= len(tokens) or tokens[k].word not in _SPEAKER or tokens[k].after_pause:
        return False
    k += 1
    while k < len(tokens) and tokens[k].word in _FILLERS and not tokens[k].after_pause:
        k += 1
    return k < len(tokens) and tokens[k].word in _VERBS and not tokens[k].after_pause
