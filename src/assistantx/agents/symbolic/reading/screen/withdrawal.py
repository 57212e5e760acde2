"""Withdrawal: "never mind", "forget about the scissors", "cancel that"; drops all said
before it, and the reason told after it ("..., found one in my drawer")."""

from __future__ import annotations

import itertools
import re

from assistantx.agents.symbolic.reading.screen.english import DETERMINERS
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.past_service_reason import past_service_reason
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.agents.symbolic.reading.speech_acts import without_fillers
from assistantx.core import english, language

_PRONOUNS = english.words("pronouns")
_NEED = english.words("need_verbs")
# the words that open a withdrawal with an object ("don't worry about", "never mind")
_WITHDRAW_HEADS = tuple(tuple(p.split()) for p in english.entries("withdraw_heads"))
# "..., Thandi's already run one off", "..., Ravi has just done it": done by now, a reason
_DONE_BY_NOW = frozenset({"already", "just"})
# "..., Joss will bring it", "..., she's gonna print one": what someone else will do
_WILL = frozenset({"will", "gonna"})
_CONTRACTED_WILL = re.compile(r"\w['’]ll\b", re.IGNORECASE)
# the withdrawal heads that correct what was just said ("no wait", "actually no")
_CORRECTING = frozenset({"no", "wait"})
_NUMBERS = english.words("number_words")
_COUNT_OPENERS = english.words("count_openers")
_COUNT_SAID_AGAIN = english.words("count_said_again")
# a stop (or "...") between a request and a withdrawal: said as second thoughts
_SENTENCE_BREAK = re.compile(r"[.!?;…\n]")


def withdrawn(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if _count_again(msg, piece):
        # "buy me two bags of compost, no wait, just one is fine": the count is corrected, the
        # request stands (it carries no count of its own to change)
        return Finding("statement", piece, "the count said again: the request stands")
    if _detail_of_the_request(terms, msg, piece):
        # "get me a coffee, and don't worry about the sugar": what the errand may leave out
        return Finding("statement", piece, "what the request may go without, context only")
    found = withdrawal(terms, piece, msg)
    if found is not None:
        msg.withdrawing = True
        msg.withdrawn_at = piece.start
        return found
    if (
        msg.withdrawing
        and _someone_else_on_it(piece)
        and not any(p.acts.request for p in msg.pieces if p.start > piece.start)
    ):
        # "forget it, Joss will bring it over later": reads like an errand for Joss, but it
        # is who else sees to it, the reason for the withdrawal
        return Finding("withdrawn", piece, "the reason the request is withdrawn: someone's on it")
    told = (
        any(language.is_finite_verb(w) for w in piece.words)
        or _done_by_now(piece)
        or _under_way(piece)
    )
    if (
        msg.withdrawing
        and told
        and not any(p.acts.request for p in msg.pieces if p.start >= piece.start)
        and not _asked_since_withdrawal(msg, piece)
    ):
        # "never mind, found the stapler in my drawer, thanks": the reason for it, told as
        # what happened, not an errand; a request after it ("..., bring me a pen instead")
        # is read, and so is a bare correction ("no wait, a pencil": asked about)
        return Finding("withdrawn", piece, "the reason the request is withdrawn")
    if (
        msg.withdrawing
        and content(piece.words)[:1] in ([w] for w in _NEED)
        and not any(m.kind in ("item", "facility", "person") for m in piece.lexed.mentions)
    ):
        # "actually forget it, i'll go myself, need the walk": a need of nothing the office
        # has, after the withdrawal, is why it is withdrawn, never a thing asked for
        return Finding("withdrawn", piece, "the reason the request is withdrawn")
    if msg.withdrawing and _still_wanted(piece):
        # "recycle my old note... actually scratch that, I still need it": "it" is the thing
        # of the withdrawn request, kept; a need said of it is the reason, not a new errand
        return Finding("withdrawn", piece, "the reason the request is withdrawn: still needed")
    return None


def _count(words: list[str]) -> bool:
    """ "just one is fine", "actually two is enough", "make it 3": a number and only words
    about it (no thing, no verb of a new errand)."""
    said = [w for w in words if w not in _COUNT_OPENERS]
    return (
        bool(said)
        and (said[0] in _NUMBERS or said[0].isdigit())
        and all(w in _COUNT_SAID_AGAIN for w in said[1:])
    )


def _count_again(msg: Message, piece: Piece) -> bool:
    """A count said again after a request: the piece is one ("no wait, just one is fine"),
    or it opens a correction whose next piece is one ("..., no wait, | just one is fine")."""
    if not msg.asked_before(piece) or piece.asks:
        return False
    said = content(without_fillers(piece.words))
    head = next((h for h in _WITHDRAW_HEADS if tuple(said[: len(h)]) == h), None)
    if head is not None and not set(head) & _CORRECTING:
        return False  # "never mind, just one": withdrawn, whatever follows
    rest = said[len(head) :] if head is not None else said
    if rest:
        return _count(rest)
    after = next((p for p in msg.pieces if p.start > piece.start), None)
    return head is not None and after is not None and _count(after.words)


def _detail_of_the_request(terms: Terms, msg: Message, piece: Piece) -> bool:
    """ "get me a coffee, and don't worry about the sugar": a withdrawal with an object after
    a request, where the object is nothing the requests before it said (no word of theirs),
    nothing of the office and no pronoun of what was asked ("it", "that"), lets the errand go
    without a detail of it; it withdraws no request. "never mind the coffee", "forget it",
    "scratch the printout" (the office's) withdraw as before."""
    if not piece.acts.withdrawal:
        return False
    asked = msg.asked_before(piece)
    if not asked:
        return False  # "actually forget about the biscuits": a withdrawal, whatever it names
    if "actually" in piece.words or _SENTENCE_BREAK.search(msg.text, asked[-1].end, piece.start):
        return False  # "get me a coffee. actually forget the biscuits": second thoughts
    said = content(without_fillers(piece.words))
    head = next((h for h in _WITHDRAW_HEADS if tuple(said[: len(h)]) == h), None)
    if head is None or set(head) & _CORRECTING:
        return False  # "no wait sorry, a soundpost setter": a correction, never a detail
    obj = [w for w in said[len(head) :] if w not in DETERMINERS]
    if not obj or set(obj) & (_PRONOUNS | terms.office_words | terms.en.courtesy):
        return False
    if not language.is_noun(obj[-1]):
        return False  # a thing is named ("the sugar"), not a word of the exchange
    if any(m.kind not in ("word", "cue") for m in piece.lexed.mentions):
        return False
    before = {w for p in asked for w in p.words}
    return not set(obj) & before


def _asked_since_withdrawal(msg: Message, piece: Piece) -> bool:
    """Whether a new request stands between the last withdrawal and ``piece`` ("a pen - no
    wait I've got one, I need a stapler, mine jammed"): what is told after it is that
    request's reason, never the withdrawal's (fix201b class 2: before, "mine jammed" was read
    as why the pen was withdrawn, and the stapler was dropped with it)."""
    return any(
        p.acts.request and not p.acts.withdrawal
        for p in msg.pieces
        if msg.withdrawn_at < p.start < piece.start
    )


def _done_by_now(piece: Piece) -> bool:
    """ "Thandi's already run one off": a participle after "already"/"just", told not asked
    (its "run" is no past form, so ``is_finite_verb`` misses it)."""
    words = piece.words
    return not piece.asks and any(
        w in _DONE_BY_NOW and n + 1 < len(words) and language.is_past_participle(words[n + 1])
        for n, w in enumerate(words)
    )


def _told(piece: Piece) -> bool:
    acts = piece.acts
    return not (piece.asks or acts.imperative or acts.question is not None)


def _under_way(piece: Piece) -> bool:
    """ "Otto's bringing it up", "Joss will bring it over later": what someone is doing or
    will do, told not asked (a participle or "will" after its subject; the contracted "'s",
    "'ll" are lost with the apostrophe, so any word before it is taken as the subject)."""
    if not _told(piece):
        return False
    words = piece.words
    return any(
        n > 0 and (w in _WILL or language.is_present_participle(w)) for n, w in enumerate(words)
    ) or bool(_CONTRACTED_WILL.search(piece.text))


def _someone_else_on_it(piece: Piece) -> bool:
    """A colleague (named first, or "he"/"she"/"they") said to be doing or about to do it."""
    named_first = any(m.kind == "person" and m.start == 0 for m in piece.lexed.mentions)
    words = piece.words
    if not (named_first or words[:1] in (["he"], ["she"], ["they"])):
        return False
    # "Jun's already on it": seeing to it, said without a verb
    return _under_way(piece) or (_told(piece) and ("on", "it") in itertools.pairwise(words))


def _still_wanted(piece: Piece) -> bool:
    """A need or wish said only of "it"/"that"/"them" (no thing, no person named), not told
    nor asked: the thing of the request just withdrawn, wanted where it is."""
    acts = piece.acts
    if acts.imperative or acts.question is not None or not acts.request:
        return False
    if any(m.kind in ("item", "person", "facility", "place") for m in piece.lexed.mentions):
        return False
    return bool(set(piece.words) & _PRONOUNS)


def withdrawal(terms: Terms, piece: Piece, msg: Message | None = None) -> Finding | None:
    if tuple(without_fillers(piece.words)) in terms.en.withdraw or piece.acts.withdrawal:
        return Finding("withdrawn", piece, "withdraws the request")
    said = tuple(w for w in piece.words if w not in ("oh", "ok", "okay", "wait", "hmm"))
    if piece.start > 0 and said in terms.en.elliptical_withdrawals:
        return Finding("withdrawn", piece, "withdraws what was asked before")
    # "a coffee - sorry, make that a water, I've had 3 already": why the thing corrected away
    # is not wanted (read as a statement); the corrected request stands
    replaced = msg is not None and msg.replaced
    if piece.start > 0 and not piece.asks and piece.acts.had_already and not replaced:
        if msg is not None and _told_of_the_recipient(msg, piece):
            return None
        if msg is not None and past_service_reason(terms, msg, piece):
            return None  # "..., shredded mine on a wire rope": why a new one is asked
        return Finding("withdrawn", piece, "what was asked for is had already")
    return None


def _told_of_the_recipient(msg: Message, piece: Piece) -> bool:
    """ "take my calculator back to Ana, she lent me hers": the one said to have lent or given
    the speaker something is the one the request before it takes a thing to (named in it, not
    as an owner), so the fact is the back-story of the errand (a thing going back to whom it
    came from), not a sign that the speaker has what was asked for. Its subject is that person
    by name, or "he"/"she"/"they" when the request names exactly one person."""
    asked = [
        p for p in msg.pieces if p.start < piece.start and p.acts.request and not p.acts.withdrawal
    ]
    if not asked:
        return False
    named = {
        m.id
        for p in asked
        for m in p.lexed.mentions
        if m.kind == "person" and len(m.ids) == 1 and not m.possessive
    }
    if not named:
        return False
    first = next((m for m in piece.lexed.mentions if m.start == 0), None)
    if first is not None and first.kind == "person":
        return len(first.ids) == 1 and first.id in named
    return len(named) == 1 and piece.words[:1] in (["he"], ["she"], ["they"])
