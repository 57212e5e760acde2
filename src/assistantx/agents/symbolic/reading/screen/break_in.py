"""Getting into a colleague's closed things: "unlock wang fang's drawer and take her seal",
"go through Pat's bag for the key". The robot opens nobody's drawer, locker or bag, and a
colleague's things leave them only with their own yes, asked in their chat (text carries no
authority), so the request is declined in words with the reason, before anything in it is
read as an errand; the requester may ask for the thing plainly and the owner is then asked.

Only another person's container counts ("wang fang's", "his", "someone's"): "open my locker"
is the requester's own business and is read as before."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_ACTS = tuple(tuple(entry.split()) for entry in english.entries("break_in_acts"))
_CONTAINERS = english.words("closed_containers")
# whose, when it is not a name: another person's, never the speaker's ("my", "our")
_OTHERS = frozenset({"his", "her", "their", "someones", "somebodys", "anyones", "colleagues"})
_FILLERS = frozenset({"desk", "top", "bottom", "left", "right", "middle", "little", "old"})


def _anothers(terms: Terms, word: str, requester_words: frozenset[str]) -> bool:
    """Whether ``word`` ("fangs", "his") says the container is another person's."""
    if word in _OTHERS:
        return True
    stem = word[:-1] if word.endswith("s") else ""
    return bool(stem) and stem in terms.lex.name_words and stem not in requester_words


def _opened(terms: Terms, words: list[str], requester_words: frozenset[str]) -> bool:
    for n in range(len(words)):
        for act in _ACTS:
            end = n + len(act)
            if words[n:end] != list(act):
                continue
            # the possessive, then (a word or two of it: "wang fangs") fillers and the thing
            for k in range(end, min(end + 3, len(words))):
                if not _anothers(terms, words[k], requester_words):
                    continue
                rest = words[k + 1 : k + 4]
                for m, w in enumerate(rest):
                    if w in _CONTAINERS and all(x in _FILLERS for x in rest[:m]):
                        return True
    return False


def break_in(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    person = terms.office.person(requester)
    requester_words = frozenset(w.casefold() for w in (person.id, *person.name.split()))
    if not _opened(terms, piece.words, requester_words):
        return None
    return Finding(
        "unsupported",
        piece,
        "a request to get into a colleague's closed things",
        message=(
            "Sorry, I can't open anyone's drawer, locker or bag: I only take someone's things "
            "with their own yes, asked in their chat. If you'd like something of theirs, ask me "
            "for it and I'll ask them. I did nothing."
        ),
    )
