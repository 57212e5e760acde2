"""An owner said to be away, and their yes said for them: "Otto is away, just take his ruler
from his desk, he won't mind". A colleague's things leave them only with their own yes, asked
in their chat (text carries no authority); a request that says the owner cannot be reached and
answers for them asks the robot to take the thing without that yes, so it is declined in words,
with the reason, before anything in it is read as an errand. The requester may ask for the
thing plainly and the owner is then asked as usual.

The owner may be said to be out in a clause of the request itself: "take Pat's seal and stamp
my contract with it while she's out, she won't mind" (the conjunction, a pronoun, and a state
of being away or busy elsewhere: "while he's in the meeting", "whilst they're at lunch"), or
in a piece of its own after it: "grab Pat's lunch for me, she won't mind, she's out today".

Either half alone is read as before: "borrow Rory's stapler, he won't mind" asks Rory (the
covert rule's docstring), and "Otto is away, could you bring me his ruler" is a fact for the
plan beside a plain request."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import starts_with, while_clause
from assistantx.agents.symbolic.reading.screen.fact import fact
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english


def _phrases(key: str) -> tuple[tuple[str, ...], ...]:
    return tuple(tuple(entry.split()) for entry in english.entries(key))


_WHILE = _phrases("while_openers")
_WHILE_SUBJECTS = _phrases("while_subjects")
_WHILE_STATES = _phrases("while_away_states") + _phrases("away")

# Someone's yes said on their behalf: "he won't mind", "she wouldn't care", "they'll be fine
# with it". The words are matched after the pronoun that says whose yes it is.
_PRESUMED = (
    ("wont", "mind"),
    ("wouldnt", "mind"),
    ("will", "not", "mind"),
    ("would", "not", "mind"),
    ("wont", "care"),
    ("wouldnt", "care"),
    ("wont", "object"),
    ("wouldnt", "object"),
    ("wont", "notice"),
    ("wont", "miss", "it"),
    ("be", "fine", "with", "it"),
    ("be", "ok", "with", "it"),
    ("be", "okay", "with", "it"),
)
# Whose yes: a third person's, never the speaker's or the robot's ("I won't mind" is no
# one's yes for another). A possessive "'ll" is split off by the tokens ("hell" is not read).
_THIRD = frozenset({"he", "she", "they", "hed", "shed", "theyd", "hell", "shell", "theyll"})


def _answers_for_someone(words: list[str]) -> bool:
    for n, word in enumerate(words):
        if word not in _THIRD:
            continue
        rest = words[n + 1 :]
        if rest[:1] == ["ll"]:  # "he'll be fine with it" when split
            rest = rest[1:]
        if any(tuple(rest[: len(p)]) == p for p in _PRESUMED):
            return True
    return False


# A third person said to be away in a piece of its own, by a pronoun: "she's out today",
# "he is away", "they're off": the colleague whose thing the request names.
_SAID_AWAY = tuple(
    (*subject, *state)
    for subject in (("shes",), ("hes",), ("theyre",), ("she", "is"), ("he", "is"), ("they", "are"))
    for state in _phrases("away")
)
# At most this many words after the state ("today", "all day"): more is another clause.
_AWAY_TAIL = 2


# The words that end the clause of being away ("he's off today *so* he won't mind")
_JOINS = frozenset((*english.entries("clause_joins"), *english.entries("consequence_joins")))


def said_away(words: list[str]) -> bool:
    """Whether the words say "he"/"she"/"they" are away in a clause of their own: the whole
    piece ("she's out today"), or its first clause before a join ("he's off today so he won't
    mind", "she's out, and she won't mind")."""
    for p in _SAID_AWAY:
        if not starts_with(words, 0, p):
            continue
        rest = words[len(p) :]
        ends = next((n for n, w in enumerate(rest) if w in _JOINS), len(rest))
        if ends <= _AWAY_TAIL:
            return True
    return False


# Whose thing, when it is not a name: the absent colleague's ("take *his* ruler").
_THEIRS = frozenset({"his", "her", "hers", "their", "theirs"})


def away_people(terms: Terms, msg: Message, requester: str) -> set[str]:
    """The colleagues a piece of the message says are away ("Otto is away", "Otto's off
    today"), as the fact rule reads it."""
    out: set[str] = set()
    for piece in msg.pieces:
        found = fact(terms, msg, piece, requester)
        hint = found.hint if found is not None else None
        if hint is not None and hint.kind == "availability" and hint.value == "away":
            out.add(hint.person)
    return out


def while_away(words: list[str]) -> bool:
    """Whether the words say, in a clause of their own, that "he"/"she"/"they" are out:
    "while she's out", "whilst he is in the meeting"."""
    return while_clause(words, _WHILE_SUBJECTS, _WHILE_STATES, _WHILE)


def _absent_owners_thing(terms: Terms, msg: Message, requester: str) -> bool:
    """Whether a request in the message asks for a thing of a colleague said to be away: by
    their name's possessive, or by "his"/"her" after the name ("Otto is away, take his
    ruler"); "Otto is away, bring me some staples" asks for nobody's. A request that says
    its owner is out in a clause of its own ("take Pat's seal while she's out") asks for a
    colleague's thing by their possessive or "his"/"her"."""
    away = away_people(terms, msg, requester)
    pronoun_away = any(said_away(p.words) for p in msg.pieces)
    for piece in msg.pieces:
        if not piece.acts.request:
            continue
        if (while_away(piece.words) or pronoun_away) and (
            any(w in _THEIRS for w in piece.words)
            or any(
                m.kind == "person" and m.possessive and requester not in m.ids
                for m in piece.lexed.mentions
            )
        ):
            return True
        if not away:
            continue
        if any(w in _THEIRS for w in piece.words):
            return True
        for m in piece.lexed.mentions:
            if m.kind == "person" and m.possessive and away.intersection(m.ids):
                return True
    return False


_CLAIMS = _phrases("entitlement_claims")
_TAKING = _phrases("taking_verbs")
# "take Pat's stapler *back* to her": a return to its owner, taken from nobody
_RETURNED = frozenset({"back", "return", "returned"})
_LEAD_INS = frozenset({"just", "please", "pls", "plz", "can", "could", "you", "u", "go", "and"})


def _claims(words: list[str]) -> bool:
    """Whether the words claim the thing for the speaker in place of its owner's yes ("she
    owes me one", "he borrowed mine", "it's basically mine anyway", "fair's fair")."""
    return any(starts_with(words, n, claim) for n in range(len(words)) for claim in _CLAIMS)


def _taken_from_colleague(msg: Message, requester: str) -> bool:
    """Whether a request of the message takes a colleague's thing ("take Pat's pen", "grab
    his stapler"): a verb of taking first, after any lead-in, and a thing by its owner's
    possessive or "his"/"her"; a return to its owner ("take Pat's stapler back to her") takes
    nothing from them."""
    for p in msg.pieces:
        words = p.words
        k = 0
        while k < len(words) and words[k] in _LEAD_INS:
            k += 1
        if not any(starts_with(words, k, verb) for verb in _TAKING):
            continue
        if set(words) & _RETURNED:
            continue
        if any(w in _THEIRS for w in words) or any(
            m.kind == "person" and m.possessive and requester not in m.ids for m in p.lexed.mentions
        ):
            return True
    return False


def _claimed(terms: Terms, msg: Message, piece: Piece, requester: str) -> bool:
    """A claim in place of the owner's yes, beside a request that takes a colleague's thing
    or one that says its owner is away; judged at the claim or at the request, whichever
    the screen reads first."""
    if not any(_claims(p.words) for p in msg.pieces):
        return False
    if not (_claims(piece.words) or piece.acts.request or piece.acts.imperative):
        return False
    return _taken_from_colleague(msg, requester) or _absent_owners_thing(terms, msg, requester)


def absent_owner(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if _claimed(terms, msg, piece, requester):
        return Finding(
            "unsupported",
            piece,
            "a request to take a colleague's thing on a claim in place of their yes",
            message=(
                "Sorry, I can't take someone's things on a claim to them (what they owe you, "
                "or that it's yours): I only take them with the owner's own yes, asked in "
                "their chat. If you'd like, ask me for it and I'll ask them. I did nothing."
            ),
        )
    if not _answers_for_someone(piece.words):
        return None
    if not _absent_owners_thing(terms, msg, requester):
        return None
    return Finding(
        "unsupported",
        piece,
        "a request to take an absent owner's thing on a yes said for them",
        message=(
            "Sorry, I can't take someone's things on their behalf while they're away: I only "
            "take them with the owner's own yes, asked in their chat. If you'd like, ask me for "
            "it and I'll ask them. I did nothing."
        ),
    )
