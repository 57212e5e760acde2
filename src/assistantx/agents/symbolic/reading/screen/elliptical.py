"""Elliptical asks: "got a light meter anywhere? want to check the light before the run",
"anyone got an eyeglass? want to look at the negatives". A question whether anyone has one
thing of a kind of the office, followed by the speaker's own reason, asks for one for the
speaker: the question rule leaves it in the request (``elliptical_ask``), and the reason is
set aside as context (``elliptical_reason``), so the things it names (the negatives the
speaker looks at) are never errands of their own. A question about the one thing ("got the
light meter back from Will yet?", "who's got the light meter?"), a bare "got a light
meter?" and a reason that asks for work of its own ("want to print my draft") keep their
readings."""

from __future__ import annotations

import itertools

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.said_of import without_states
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.supply_going import supply_going
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

# "(anyone) got a light meter (anywhere)?": who may be asked before the verb of having.
_ASKED = english.words("request_askees") - {"i", "we", "the", "robot"}
_HAVING = frozenset({"got", "have", "has"})
_AUXILIARIES = frozenset({"have", "has", "do", "does"})
_ANYWHERE = frozenset({"anywhere", "around", "about", "handy"})
_INDEFINITE = frozenset({"a", "an", "any", "some", "another", "one"})
# The speaker's reason after it: "want to check ...", "need it for ...", "to check ...".
_REASON_OPENERS = english.words("need_verbs") | {"wanna", "gotta", "to", "for"}
_REASON_LEAD = frozenset({"i", "just", "so", "only", "id", "ill"})
# "... I can nab", "... we could use": the speaker, then a modal of possibility.
_SPEAKER = frozenset({"i", "we"})
_MODALS = frozenset({"can", "could", "may", "might"})
_SPARE = "spare"
# The speaker's own one of the kind ("mine's dead", "my one is broken", "my own died").
_MINE = frozenset({"mine", "mines"})
_ONE = frozenset({"one", "own", "ones"})


def elliptical_ask(terms: Terms, msg: Message, piece: Piece) -> bool:
    """ "got a light meter anywhere? want to check the flash", "anyone got a light meter?
    need it for the shoot", "light meter anywhere? ...": a question whether anyone has a
    thing of the office (one of a kind, never "the" one), then the speaker's own reason, asks
    for one for the speaker; it is left in the request. "got the light meter back from Will
    yet?", "who's got the light meter?" and a bare "got a light meter?" stay questions
    (answered, an offer at most)."""
    if terms.named(piece.lexed, "person"):
        return False
    if supply_going(terms, piece):
        return True  # "is there any paper going?": the office's supply, wanted
    if not _things(piece):
        return _spare_after_complaint(msg, piece)
    if len(_things(piece)) != 1:
        return False
    if not (_having_one(piece) or _one_anywhere(piece)):
        return False
    if _wanted_by_the_asker(piece) and not piece.acts.later:
        return True  # "anyone got a stopwatch I can nab?", "... going spare?"
    later = [p for p in msg.pieces if p.start > piece.end]
    if later and _gives_a_reason(terms, later[0]) and later[0].acts.question is None:
        return True
    # "anyone got a spare charger? mine's dead", "mine's dead - anyone got a charger?"; a
    # request of its own beside them ("..., take it to Jory") may be about the speaker's own
    if any(p.acts.request or p.acts.imperative for p in msg.pieces if p is not piece):
        return False
    before = [p for p in msg.pieces if p.end < piece.start]
    asked = _things(piece)[0].ids
    return any(_own_one_amiss(p, asked) for p in [*before[-1:], *later[:1]])


# What an ask for "a spare" may say besides it: "anyone got *a spare one anywhere*?", "does
# anybody have *one I could use*?", "anyone have *some*?"
_SPARE_WORDS = (
    _INDEFINITE
    | _ANYWHERE
    | _SPEAKER
    | _MODALS
    | frozenset(
        {"spare", "extra", "ones", "more", "few", "couple", "of", "going", "lying", "please", "pls"}
        | {"use", "borrow", "have", "nab", "pinch", "grab", "take", "here", "me", "lend", "to"}
    )
)


def _spare_after_complaint(msg: Message, piece: Piece) -> bool:
    """ "my charger is dead. anyone got a spare?", "ran out of tape, anyone have some?": an
    ask whether anyone has one, naming no thing, right after the speaker's own thing of a kind
    said amiss asks for one of that kind for the speaker (another's, or the office's supply),
    left in the request, where the rewrites read "a spare"/"one" as the thing said amiss. A
    bare "anyone got a spare?" and one after a request of its own keep their readings."""
    if not spare_asked(piece):
        return False
    if any(p.acts.request or p.acts.imperative for p in msg.pieces if p is not piece):
        return False
    # the complaint just before the ask, or just after it ("anyone got a spare? mine ... my
    # charger just died")
    before = [p for p in msg.pieces if p.end < piece.start]
    later = [p for p in msg.pieces if p.start > piece.end]
    return any(_kind_amiss(p) for p in [*before[-1:], *later[:1]])


def spare_asked(piece: Piece) -> bool:
    """ "anyone got a spare?", "does anybody have one I could use?", "anyone have some?": an
    ask whether anyone has one of something, with no thing named."""
    if _things(piece):
        return False
    w = piece.words
    k = 2 if w[:2] == ["any", "chance"] else 0
    k += 1 if w[k : k + 1] and w[k] in _AUXILIARIES else 0
    k += 1 if w[k : k + 1] and w[k] in _ASKED else 0
    if not (len(w) > k + 1 and w[k] in _HAVING and w[k + 1] in _INDEFINITE | {"spare"}):
        return False
    return all(x in _SPARE_WORDS for x in w[k + 1 :])


# What may open a complaint before its subject ("ugh, my charger has died").
_INTERJECTIONS = frozenset(
    {"ugh", "argh", "oh", "no", "great", "so", "well", "damn", "sigh", "welp"}
)


def _tells_of_things_only(piece: Piece) -> bool:
    """A piece that only tells (no request, command, question, withdrawal or thanks) and
    names no person or facility: what a statement of a thing amiss must be."""
    a = piece.acts
    if a.request or a.imperative or a.question is not None or a.withdrawal or a.thanks:
        return False
    return not any(m.kind in ("person", "facility") for m in piece.lexed.mentions)


def _kind_amiss(piece: Piece) -> bool:
    """ "my charger is dead", "charger's dead", "my mouse died", "ran out of tape": a statement
    of one thing of a kind, its subject (the speaker's own, or said bare) or used up ("out
    of"), naming no one."""
    if not _tells_of_things_only(piece):
        return False
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    items = [m for m in mentions if m.kind == "item"]
    if len({m.ids for m in items}) != 1:
        return False
    at = items[0].start
    before = [t.word for t in tokens[max(0, at - 2) : at]]
    if before == ["out", "of"]:
        return True  # "ran out of tape"
    # the thing as the statement's subject: "my charger is dead", "charger's dead"
    lead = [t.word for t in tokens[:at] if t.word not in _INTERJECTIONS]
    return before[-1:] in (["my"], ["our"]) or lead in ([], ["the"])  # "I lost my charger"


def _wanted_by_the_asker(piece: Piece) -> bool:
    """The ask itself says the thing is for the speaker: the thing said to be spare, to be
    given away ("anyone got a stopwatch *going spare*?", "... a stopwatch spare?"), or the
    speaker as the subject of a modal after the thing ("... a stopwatch *I can* nab?", "...
    I could pinch"), whatever verb of taking follows. "a spare stopwatch" before the thing
    only says which kind: the question stays a question."""
    items = _things(piece)
    if len(items) != 1:
        return False
    w = [t.word for t in piece.lexed.tokens]
    after = w[items[0].end :]
    if _SPARE in after:
        return True
    return any(a in _SPEAKER and b in _MODALS for a, b in itertools.pairwise(after))


def _things(piece: Piece) -> list[Mention]:
    """The items the piece asks about, less a word said of one of them ("a torque wrench
    *going spare*", ``said_of``)."""
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    return [m for m in without_states(tokens, mentions) if m.kind == "item"]


def _having_one(piece: Piece) -> bool:
    """ "(have you / has anyone / anyone) got a ...", "(does anyone) have a ...", "(any
    chance someone) has a ...", "anyone got earphones" (a plural with no article)."""
    w = piece.words
    k = 2 if w[:2] == ["any", "chance"] else 0
    k += 1 if w[k : k + 1] and w[k] in _AUXILIARIES else 0
    k += 1 if w[k : k + 1] and w[k] in _ASKED else 0
    if not (len(w) > k + 1 and w[k] in _HAVING):
        return False
    if len(w) > k + 2 and w[k + 1] in _INDEFINITE:
        return True
    # the thing right after the verb, with no article ("anyone got earphones?")
    tokens = piece.lexed.tokens
    return len(tokens) == len(w) and any(
        m.kind == "item" and m.start == k + 1 for m in piece.lexed.mentions
    )


def _one_anywhere(piece: Piece) -> bool:
    """ "light meter anywhere?", "a light meter around?": only the thing and where."""
    w = piece.words
    if len(w) < 2 or w[-1] not in _ANYWHERE:
        return False
    items = [m for m in piece.lexed.mentions if m.kind == "item"]
    return len(items) == 1 and all(
        k in range(items[0].start, items[0].end) or w[k] in _INDEFINITE for k in range(len(w) - 1)
    )


def elliptical_reason(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """The speaker's reason after an elliptical ask ("got an eyeglass anywhere? *want to look
    at the negatives*"): context for the thing asked for, never an errand of its own on the
    things it names (the negatives are what the speaker already has in hand)."""
    before = [p for p in msg.pieces if p.end < piece.start]
    later = [p for p in msg.pieces if p.start > piece.end]
    for p in [*before[-1:], *later[:1]]:
        # "mine just crackles", "I left mine at home", said before or after the ask
        asked = _things(p)
        if len(asked) == 1 and _own_one_amiss(piece, asked[0].ids):
            if elliptical_ask(terms, msg, p):
                return Finding("statement", piece, "the speaker's reason for the thing asked for")
    if not before or not _gives_a_reason(terms, piece):
        return None
    if not elliptical_ask(terms, msg, before[-1]):
        return None
    return Finding("statement", piece, "the speaker's reason for the thing asked for")


def _own_one_amiss(piece: Piece, asked: tuple[str, ...]) -> bool:
    """ "mine just crackles on one side", "mine's dead", "I left mine at home", "my one is
    broken", "my charger is dead": the speaker's own thing of the kind ``asked`` said in a
    statement beside an ask for one is why they ask, never the thing asked for. A piece that
    asks for anything itself, names a person or another thing ("want to print my draft"), or
    asks a question is not."""
    if not _tells_of_things_only(piece):
        return False
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    items = [n for n, m in enumerate(mentions) if m.kind == "item"]
    if items:  # "my charger is dead": the speaker's own, said by its name
        return all(
            n and tokens[mentions[n - 1].start].word == "my" and mentions[n].ids == asked
            for n in items
        )
    w = piece.words
    return any(x in _MINE for x in w) or any(
        a == "my" and b in _ONE for a, b in itertools.pairwise(w)
    )


def _gives_a_reason(terms: Terms, piece: Piece) -> bool:
    """Whether ``piece`` is the speaker's own reason for wanting something ("want to check
    the light before the run"), naming no person of the office (a thing it names is what
    the speaker works on: "want to look at the negatives")."""
    w = piece.words
    k = 0
    while k < len(w) and w[k] in _REASON_LEAD:
        k += 1
    if k >= len(w) or w[k] not in _REASON_OPENERS:
        return False
    # "want to print my draft" asks for a task of its own; "want to check ..." does not
    return not any(
        m.kind == "person" or (m.kind == "cue" and m.start != k) for m in piece.lexed.mentions
    )
