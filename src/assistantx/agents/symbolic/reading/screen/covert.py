"""Behind someone's back: "borrow Zhang's stapler without telling him", "grab Pat's charger,
don't tell her", "take Min's mug on the quiet". An owner's yes is asked in their own chat
before any of their things moves, whatever the request says (text carries no authority), so a
request to skip that is declined in words, with the reason; the requester may ask again
plainly and the owner is then asked as usual. A request that only says the owner will not
mind ("he won't mind") is read as before: the owner is still asked.

A request to skip asking the owner ("grab his tape while he's at lunch, no need to ask", "take
Pat's seal, don't ask her") is declined the same way, saying their own yes is needed: only
where the message asks for a colleague's thing ("Pat's", "his"), so "print my report, no need
to ask" is read as before, and a colleague named after the mark is its owner ("don't ask
Pat" beside a request for Kim's stapler is a choice of whom to ask, read as before). Skipping
telling the owner ("no need to tell her", "you don't need to tell him", "she won't need to
know") is the same mark ("unasked_marks"); "no need to tell me" is the speaker's own say. Leaving
the owner undisturbed ("grab Pat's seal, she's out so don't bother her", "no need to trouble
him") skips asking them the same way, only where whom to leave alone follows the mark
("unasked_person_marks"): "don't bother bringing it back" is a negation of its own.

Taken where the owner cannot see ("grab his mug while he's not looking", "when she isn't
watching", "before he notices") is kept in the dark the same way; so is a colleague's thing
taken before they are back or see ("grab Pat's stapler before she's back", "take his seal and
stamp my invoices before he gets back", "before Pat notices"), only where a request of the
message names a colleague's thing ("bring me a coffee before the boss gets back" and "bring
me Pat's report before the meeting" are read as before); a colleague's thing asked
for as a joke on them ("take Pat's mug to prank her", "... I want to wind him up") is declined
only where a request of the message names a colleague's thing ("Pat's", "his").

A colleague's seal asked for while they are out, to stamp or sign with ("take Pat's seal from
her desk while she's out, I only need to stamp one thing", "use his stamp whilst he's at
lunch to seal my form") is their tool used behind their back, not a transfer nor their own
stamping: it is declined the same way. "can Pat stamp my form while she's at her desk?" asks
for Pat's own work, and "take Pat's stapler while she's out" asks Pat as usual.

A yes the requester reports ("Zhang said I could have his stapler, just bring it, no need to
ask him") makes a mark that skips asking a reason, not a request to keep the owner out: the
request is read and the owner asked as always (reported_leave.py)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.absent_owner import (
    away_people,
    said_away,
    while_away,
)
from assistantx.agents.symbolic.reading.screen.destructive import commanded
from assistantx.agents.symbolic.reading.screen.english import starts_with, while_clause
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.reported_leave import reported_leave
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_COVERT = tuple(tuple(entry.split()) for entry in english.entries("covert_marks"))
_UNASKED = tuple(tuple(entry.split()) for entry in english.entries("unasked_marks"))
_BOTHER = tuple(tuple(entry.split()) for entry in english.entries("unasked_person_marks"))
_OBJECTS = frozenset(english.entries("object_pronouns"))
_PRANKS = tuple(tuple(entry.split()) for entry in english.entries("prank_marks"))
_WHILE = tuple(tuple(entry.split()) for entry in english.entries("while_openers"))
_UNSEEN_SUBJECTS = tuple(
    tuple(entry.split())
    for key in ("while_subjects", "unseen_subjects")
    for entry in english.entries(key)
)
_UNSEEN = tuple(tuple(entry.split()) for entry in english.entries("unseen_states"))
_BEFORE_WHO = tuple(tuple(entry.split()) for entry in english.entries("covert_before_subjects"))
_BEFORE_STATES = tuple(tuple(entry.split()) for entry in english.entries("covert_before_states"))
# Whose thing, when it is not a name: a colleague's ("grab *his* tape")
_THEIRS = frozenset({"his", "her", "hers", "their", "theirs"})
# "use Pat's seal on my contract": a colleague's seal put to use by the one who asks
_USING = english.words("seal_using_verbs")
# The words of stamping or signing a paper ("I only need to *stamp* one thing")
_STAMPING = frozenset(
    w for kind in ("seal", "sign") for w in english.word_table("cues").get(kind, ())
)


# "print it without asking me again": the speaker's own say, nobody kept in the dark
_SPEAKER = frozenset({"me", "us", "i", "we", "anyone", "anybody"})
_TELLING = frozenset({"without", "dont", "do"})  # the marks a speaker's "me"/"us" may follow


def _unseen(words: list[str]) -> bool:
    """Whether the words say, in a clause of their own, that the owner cannot see: "while
    he's not looking", "when she isn't watching"."""
    return while_clause(words, _UNSEEN_SUBJECTS, _UNSEEN, _WHILE)


def _before_back(piece: Piece, requester: str) -> bool:
    """Whether the piece says a thing is to be taken before its owner is back or sees:
    "before she's back", "before he gets back", "before Pat notices", "before anyone sees".
    "before the meeting", "before 3pm", "before I get back" are times, not the owner's."""
    words, tokens = piece.words, piece.lexed.tokens
    for n, word in enumerate(words):
        if word != "before":
            continue
        ends = [n + 1 + len(who) for who in _BEFORE_WHO if starts_with(words, n + 1, who)]
        ends += [
            m.end
            for m in piece.lexed.mentions
            if m.kind == "person"
            and requester not in m.ids
            and m.start == n + 1
            and len(tokens) == len(words)
        ]
        if any(starts_with(words, end, state) for end in ends for state in _BEFORE_STATES):
            return True
    return False


def _pranked(msg: Message, requester: str) -> bool:
    """Whether a piece of the message says a colleague's thing is asked for as a joke on
    them (``prank_marks``), beside a request that names a colleague's thing."""
    said = any(
        starts_with(p.words, n, mark)
        for p in msg.pieces
        for n in range(len(p.words))
        for mark in _PRANKS
    )
    if not said:
        return False
    owners, pronoun = colleagues_things(msg, requester)
    return bool(owners) or pronoun


def kept_in_the_dark(words: list[str]) -> bool:
    """Whether ``words`` say the owner is to be kept in the dark (``covert_marks``, or a
    clause that says they cannot see: ``unseen_states``)."""
    if _unseen(words):
        return True
    for n in range(len(words)):
        for mark in _COVERT:
            end = n + len(mark)
            if words[n:end] != list(mark):
                continue
            # "without asking me", "don't tell us": the speaker's own say; "she'll never
            # notice we took it" keeps the owner in the dark whoever follows
            spoken_to = mark[0] in _TELLING and end < len(words) and words[end] in _SPEAKER
            if not spoken_to:
                return True
    return False


def _unasked_at(words: list[str], names: frozenset[str] = frozenset()) -> int | None:
    """Where a mark that skips asking ends ("no need to ask| him"), or None; "don't ask me
    again" is the speaker's own say. A mark of leaving someone undisturbed ("don't bother|
    her") counts only with whom to leave so after it: "him", "her", "them", or a word of
    ``names`` (the first words of the colleagues the piece names): "don't bother bringing it
    back" skips nobody's yes."""
    for n in range(len(words)):
        for mark in _UNASKED:
            end = n + len(mark)
            if words[n:end] != list(mark):
                continue
            if end < len(words) and words[end] in _SPEAKER:
                continue
            return end
        for mark in _BOTHER:
            end = n + len(mark)
            if words[n:end] == list(mark) and end < len(words):
                if words[end] in _OBJECTS or words[end] in names:
                    return end
    return None


def _unasked_in(piece: Piece) -> int | None:
    """Where a mark that skips asking ends in the piece (``_unasked_at``), with the names of
    the colleagues it mentions."""
    tokens = piece.lexed.tokens
    names = frozenset(tokens[m.start].word for m in piece.lexed.mentions if m.kind == "person")
    return _unasked_at(piece.words, names)


def colleagues_things(
    msg: Message, requester: str, terms: Terms | None = None
) -> tuple[set[str], bool]:
    """The colleagues whose things a request of the message names by their possessive, and
    whether one names a thing by "his"/"her"/"their"; with ``terms``, a piece that tells the
    robot to do something by a plain verb first ("use Pat's stamp on my form") is a request."""
    owners: set[str] = set()
    pronoun = False
    for p in msg.pieces:
        told = terms is not None and commanded(terms, p)
        if not (p.acts.request or p.acts.imperative or told):
            continue
        pronoun = pronoun or any(w in _THEIRS for w in p.words)
        for m in p.lexed.mentions:
            if m.kind == "person" and m.possessive and requester not in m.ids:
                owners.update(m.ids)
    return owners, pronoun


def _skips_asking(msg: Message, requester: str, terms: Terms) -> bool:
    """Whether a piece of the message (its own, or one beside it that another rule reads as
    a negation: "you don't need to ask him") asks that a colleague's thing be taken
    without asking them."""
    return any(_skips_asking_in(msg, p, requester, terms) for p in msg.pieces)


def _skips_asking_in(msg: Message, piece: Piece, requester: str, terms: Terms) -> bool:
    end = _unasked_in(piece)
    if end is None:
        return False
    owners, pronoun = colleagues_things(msg, requester, terms)
    named = piece.words[end : end + 1]  # the word after the mark: whom not to ask
    tokens = piece.lexed.tokens
    asked = [
        m for m in piece.lexed.mentions if m.kind == "person" and [tokens[m.start].word] == named
    ]
    if asked:  # "don't ask Pat": only about Pat's own thing
        return any(owners.intersection(m.ids) for m in asked)
    return bool(owners) or pronoun


def _their_seal_used(terms: Terms, msg: Message, requester: str) -> bool:
    """Whether a request of the message asks for a colleague's seal (their possessive, or
    "his"/"her" before it) while they are said to be out, beside words of stamping or signing
    outside the seal's own name ("take Pat's seal while she's out, I need to stamp my form")
    or the seal put to use ("use Pat's seal on my contract"). Out is said in a clause of the
    request ("while she's out") or in a piece of its own, by a pronoun ("take Pat's seal and
    stamp my form, she's at lunch") or by the owner's name ("..., Pat's on holiday")."""
    tool = terms.office.seal_tool()
    if tool is None:
        return False
    asked = False
    stamping = False
    owners: set[str] = set()
    for p in msg.pieces:
        tokens, mentions = p.lexed.tokens, p.lexed.mentions
        # the seal by its item's name, or "seal"/"stamp" said as a noun after its owner
        # ("Wang's seal": the lexicon reads the word as the task's cue)
        seals = [
            (n, m)
            for n, m in enumerate(mentions)
            if (m.kind == "item" and tool in m.ids) or (m.kind == "cue" and m.ids == ("seal",))
        ]
        theirs = []
        for n, m in seals:
            if n == 0:
                continue
            owner = mentions[n - 1]
            possessed = owner.kind == "person" and owner.possessive and requester not in owner.ids
            if not (possessed or tokens[m.start - 1].word in _THEIRS):
                continue
            theirs.append(m)
            if possessed:
                owners.update(owner.ids)
            # "use Pat's seal on my contract", "use her seal": the seal put to use
            said = owner.start if possessed else m.start - 1
            stamping = stamping or (said > 0 and tokens[said - 1].word in _USING)
        named = {n for m in theirs for n in range(m.start, m.end)}
        stamping = stamping or any(
            t.word in _STAMPING for n, t in enumerate(tokens) if n not in named
        )
        if theirs and (p.acts.imperative or commanded(terms, p)):
            asked = True
    if not (asked and stamping):
        return False
    if any(while_away(p.words) or said_away(p.words) for p in msg.pieces):
        return True
    return bool(owners & away_people(terms, msg, requester))


def covert(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    asks = piece.acts.request or piece.acts.imperative
    if (asks or commanded(terms, piece)) and _their_seal_used(terms, msg, requester):
        return Finding(
            "unsupported",
            piece,
            "a request to use an absent colleague's seal",
            message=(
                "Sorry, I can't take someone's seal to use while they're away: it is used "
                "only with their own yes, asked in their chat. If you'd like, ask me again "
                "and I'll ask them to stamp it for you. I did nothing."
            ),
        )
    # "Zhang said I could have it, no need to ask him": why asking seems needless to the
    # requester, not a request to keep Zhang out; Zhang is asked as always
    skipped = not reported_leave(msg) and _skips_asking(msg, requester, terms)
    if (asks or _unasked_in(piece) is not None) and skipped:
        if not (piece.acts.request or any(commanded(terms, p) for p in msg.pieces)):
            return None
        return Finding(
            "unsupported",
            piece,
            "a request to take a colleague's thing without asking them",
            message=(
                "Sorry, I can't take someone's things without asking them: I only take them "
                "with the owner's own yes, asked in their chat. If you'd like, ask me again "
                "and I'll ask them. I did nothing."
            ),
        )
    if not (
        kept_in_the_dark(piece.words)
        or (asks and _pranked(msg, requester))
        or (_before_back(piece, requester) and any(colleagues_things(msg, requester, terms)))
    ):
        return None
    if not (piece.acts.request or any(commanded(terms, p) for p in msg.pieces)):
        return None
    return Finding(
        "unsupported",
        piece,
        "a request to act without the owner's knowledge",
        message=(
            "Sorry, I can't do that without the owner knowing: I only take someone's things "
            "with their own yes, asked in their chat. If you'd like, ask me again and I'll ask "
            "them. I did nothing."
        ),
    )
