"""Acting as a colleague: "take Summer's smartcard and log into her EDMS account for me",
"grab Wang's badge and sign in as her on the portal", "use Zhang's login to book the room",
"get me Mao's key card so I can get into his email". Getting into a colleague's account with
their login, password or card is acting as them, whatever the thing that opens it: declined in
words with the reason, before any of it is read as an errand (fix61f class 1: the card was
fetched, its owner asked).

The mark is a verb of getting in (``account_entry_verbs``) followed by whose account it is (a
colleague's name said as theirs, or "his", "her", "their") and an account noun
(``account_nouns``) within a few words ("log into her EDMS account"), or a verb of signing on
(``account_as_verbs``) followed by whom ("sign in as her", "log on as Pat"). It counts in the
request or in a clause beside it whose doer is the speaker or unsaid ("so I can get into his
email"); "... so he can log into his email" is the colleague's own doing. "log my hours", "log
into my account" and "bring me Wang's badge" are read as before."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.destructive import commanded
from assistantx.agents.symbolic.reading.screen.english import starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_ENTRY = tuple(tuple(e.split()) for e in english.entries("account_entry_verbs"))
_AS = tuple(tuple(e.split()) for e in english.entries("account_as_verbs"))
_ACCOUNTS = english.words("account_nouns")
_SUBJECTS = frozenset(english.entries("kept_out_subjects"))
# whose account, when it is not a name; whom one signs in as
_THEIRS = frozenset({"his", "her", "their"})
_THEM = frozenset({"him", "her", "them"})
# how far after whose it is the account noun may stand ("her *EDMS* account")
_NOUN_SPAN = 3
# what joins a second command to the first ("bring Wang the badge and log into her account")
_JOINS = frozenset({"and", "then", "&"})


def _acted_as(piece: Piece, requester: str) -> bool:
    """Whether the piece says getting into a colleague's account, by the speaker or unsaid."""
    words = piece.words
    aligned = len(piece.lexed.tokens) == len(words)
    theirs: dict[int, int] = {}
    named: dict[int, int] = {}
    for m in piece.lexed.mentions if aligned else ():
        if m.kind != "person" or requester in m.ids:
            continue
        (theirs if m.possessive else named)[m.start] = m.end
    clause = 0  # where the clause the verb is in begins
    for n in range(len(words)):
        if words[n] in _JOINS:
            clause = n + 1  # "bring Wang the stapler *and* log into her account": a new verb
        # "... so he can log into his email": the colleague's own doing; "tell Pat to log
        # into her account": Pat's, said in the same clause
        if set(words[:n]) & _SUBJECTS:
            break
        if any(clause <= start < n for start in named):
            continue
        for verb in _AS:
            if starts_with(words, n, verb):
                at = n + len(verb)
                if at < len(words) and (words[at] in _THEM or at in named):
                    return True
        for verb in _ENTRY:
            if not starts_with(words, n, verb):
                continue
            at = n + len(verb)
            if at < len(words) and words[at] in _THEIRS:
                end = at + 1
            elif at in theirs:
                end = theirs[at]
            else:
                continue
            if any(w in _ACCOUNTS for w in words[end : end + _NOUN_SPAN]):
                return True
    return False


def impersonation(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if not (piece.acts.request or piece.acts.imperative or commanded(terms, piece)):
        return None
    if not any(_acted_as(p, requester) for p in msg.pieces):
        return None
    return Finding(
        "unsupported",
        piece,
        "a request to get into a colleague's account as them",
        message=(
            "Sorry, I won't do that: getting into a colleague's account with their login, "
            "password or card is acting as them, and only they may do that. If your own "
            "login is locked, IT can reset it; if you need something from their account, "
            "please ask them. I did nothing."
        ),
    )
