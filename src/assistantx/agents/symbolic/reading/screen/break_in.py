"""Getting into a colleague's closed things: "unlock wang fang's drawer and take her seal",
"go through Pat's bag for the key". The robot opens nobody's drawer, locker or bag, and a
colleague's things leave them only with their own yes, asked in their chat (text carries no
authority), so the request is declined in words with the reason, before anything in it is
read as an errand; the requester may ask for the thing plainly and the owner is then asked.

A tool's name said as the verb ("drill out the lock on Maria's desk drawer", "hammer open
his locker", where the office has a drill or a hammer) is the same forcing: declined the same
way, never read as the tool fetched for the colleague. The tool said as a thing ("bring me a
drill", "bring Maria the drill") is read as before.

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
# "drill out", "hammer open": the particle after a tool's name said as the verb
_FORCING = english.words("forcing_particles")
# "the lock on": a fitting of the closed thing, and what joins it to the thing
_FITTINGS = english.words("container_fittings")
_FITTING_JOINS = english.words("fitting_joins")
_ARTICLES = frozenset({"the", "a", "an", "that", "this"})
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


def _anothers_container(terms: Terms, words: list[str], requester_words: frozenset[str]) -> bool:
    """Whether ``words`` open with another person's closed thing, said plainly ("marias desk
    drawer") or by a fitting of it ("the lock on marias desk drawer")."""
    n = 0
    while n < len(words) and words[n] in _ARTICLES:
        n += 1
    if n < len(words) and words[n] in _FITTINGS:
        n += 1
        if n >= len(words) or words[n] not in _FITTING_JOINS:
            return False
        n += 1
    if n >= len(words) or not _anothers(terms, words[n], requester_words):
        return False
    rest = words[n + 1 : n + 4]
    return any(
        w in _CONTAINERS and all(x in _FILLERS for x in rest[:m]) for m, w in enumerate(rest)
    )


def _forced_with_tool(terms: Terms, piece: Piece, requester_words: frozenset[str]) -> bool:
    """A tool of the office's said as the request's verb, with a forcing particle, on a
    colleague's closed thing: "drill out the lock on Maria's desk drawer"."""
    words = piece.words
    verb = piece.verb_at(terms.en.lead_in)
    if verb + 1 >= len(words) or words[verb + 1] not in _FORCING:
        return False
    if words[verb] not in terms.lex.items:
        return False  # no tool of the office's: "clear out ...", "open up ..." are read above
    return _anothers_container(terms, words[verb + 2 :], requester_words)


def break_in(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    person = terms.office.person(requester)
    requester_words = frozenset(w.casefold() for w in (person.id, *person.name.split()))
    if not (
        _opened(terms, piece.words, requester_words)
        or _forced_with_tool(terms, piece, requester_words)
    ):
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
