"""Purpose and reason: what a request is for is no request of its own. A purpose clause ("...
so he can book the courier", "... so that I can read it on paper") and an open offer ("my
stapler's on my desk if anyone needs it") are cut from the words before them as pieces of
their own (``pieces``); the need that says why the thing asked for is wanted ("get me Piet's
ruler, need it for the report", "scan my permit, the client wants a pdf of it") points back to
it. All are context: nothing they name (the courier, the paper, the report, the pdf) is an
errand or lends the request an item, and the request before them is read as if they were not
said. Said with no request, they are answered in words."""

from __future__ import annotations

import itertools

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english, language, task_kinds

_NEED = english.words("need_verbs")
_SUBJECTS = english.words("subject_pronouns") - {"you", "u", "ya"}
_SENTENCE_END = frozenset(".!")
# What a request after a statement points back to it with: "heat *it* up", "bring me *one*".
POINTERS = frozenset(
    {"it", "them", "one", "ones", "that", "this", "those", "these", "same", "his", "hers"}
    | {"theirs", "another", "too", "also", "there"}
)
# What points back to the thing just asked for: "need *it* for the report", "a pdf *of it*".
_BACK = frozenset({"it", "them", "that", "this", "those", "these"})
_DETERMINERS = frozenset({"the", "my", "our", "a", "an", "their", "his", "her", "your"})
_SPEAKER = frozenset({"i", "we", "id", "ill", "im", "just", "really", "only", "still"})


def purpose(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """A purpose clause or an open offer after other words: context, never a request; and
    what the offer is of, before it, when that asks nothing ("spare tape on my desk", "my
    stapler's free": no task word, no request wording, no question)."""
    if piece.clause is None:
        return _offered(msg, piece)
    if not any(p.end <= piece.start for p in msg.pieces):
        return None
    if piece.clause == "purpose":
        return Finding("statement", piece, "what the request is for: context only")
    return Finding(
        "statement",
        piece,
        "an offer to whoever needs it: nothing to do",
        message="If anyone asks me for it, I'll tell them.",
    )


def _offered(msg: Message, piece: Piece) -> Finding | None:
    """ "spare tape on my desk" before "if anyone needs it": the thing offered, said."""
    after = [p for p in msg.pieces if p.start >= piece.end]
    if not after or after[0].clause != "open_offer" or "," in msg.text[piece.end : after[0].start]:
        return None
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.question is not None:
        return None
    if any(m.kind == "cue" for m in piece.lexed.mentions):
        return None  # "bring me the tape if anyone needs it": a task word, read as before
    return Finding("statement", piece, "a thing offered to whoever needs it: context only")


def reason(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """ "need it for the report", "the client wants a pdf of it" after a request: why the
    thing is asked for, said of the speaker or of someone outside the office; a colleague's
    need ("Rena needs it") and a need of a thing of its own ("need a ruler too") are read as
    before."""
    acts = piece.acts
    if piece.asks or acts.imperative or acts.question is not None:
        return None
    if not msg.asked_before(piece):
        return None
    words = content(piece.words)
    at = next((n for n, w in enumerate(words) if w in _NEED), None)
    if at is None or not set(words[at + 1 :]) & _BACK:
        return None
    if acts.request and words[at + 1 : at + 2] != ["it"] and words[at + 1 : at + 2] != ["them"]:
        return None  # "need a stapler too": a thing of its own, asked for
    if terms.named(piece.lexed, "person"):
        return None  # "Rena needs it": a colleague who may be the one to get it
    subject = words[:at]
    if subject and not set(subject) <= _SPEAKER and not _outsider(terms, subject):
        return None
    return Finding("statement", piece, "why the request is made: context only")


# The words after "to ..." that still end the piece ("... to stamp, please").
_COURTESY = english.words("courtesy") | {"please", "pls", "thanks"}
# Who the work is said of: the robot ("can you stamp ..."), never the speaker's own doing.
_ADDRESSEE = frozenset({"you", "u", "ya"})


def tool_use(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """ "Siobhan's stamp please, I've a batch of requisitions to stamp": beside a piece that
    asks for a tool (the office's stamp, its seal), the speaker's things to use it on ("a
    pile of letters to seal") say what the tool is borrowed for: context, never the work done
    for them. Asked of the robot ("can you stamp my letters") or of a colleague named, or with
    no tool asked for ("get my letters stamped with Lee's seal"), it is read as before."""
    if piece.acts.imperative:
        return None
    if _thing_needs_the_tools_work(terms, msg, piece):
        return Finding("statement", piece, "what the tool asked for is for: context only")
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    words = [t.word for t in tokens]
    while words and words[-1] in _COURTESY:
        words = words[:-1]
    if len(words) < 3 or words[-2] != "to" or set(words) & _ADDRESSEE:
        return None
    last = len(words) - 1
    cue = next((m for m in mentions if m.start == last and m.kind == "cue"), None)
    if cue is None or terms.named(piece.lexed, "person"):
        return None
    tools = {t for kind in cue.ids if (t := task_kinds.tool_type(kind, terms.office)) is not None}
    if not tools:
        return None
    others = [p for p in msg.pieces if p is not piece]
    if not any(tools & set(terms.named(p.lexed, "item")) for p in others):
        return None
    return Finding("statement", piece, "what the tool asked for is for: context only")


def _thing_needs_the_tools_work(terms: Terms, msg: Message, piece: Piece) -> bool:
    """ "Could someone lend me a bow stringer? A beginner's bow needs stringing.": a thing
    said to need a doing that a tool asked for before is declared for (the stringer's
    purpose "string a bow") is what the tool is borrowed for, the speaker's own doing."""
    if piece.asks or set(piece.words) & _ADDRESSEE or not msg.asked_before(piece):
        return False
    words = piece.words
    at = next((n for n, w in enumerate(words) if w in _NEED), None)
    if at is None or at + 1 >= len(words) or not words[at + 1].endswith("ing"):
        return False
    doing = language.verb_lemmas(words[at + 1])
    asked = {i for p in msg.pieces if p.end <= piece.start for i in terms.named(p.lexed, "item")}
    return any(
        language.verb_lemmas(purpose.split()[0]) & doing or purpose.split()[0] in doing
        for item in asked
        for purpose in terms.office.item_type(item).purposes
    )


def _outsider(terms: Terms, subject: list[str]) -> bool:
    """ "the client", "my landlord": a short subject that names nothing of the office."""
    lex = terms.lex
    known = (*lex.items, *lex.facilities, *lex.places, *lex.people, *lex.name_words)
    return (
        subject[0] in _DETERMINERS
        and len(subject) <= 3
        and not any(w in known or w in _SPEAKER for w in subject[1:])
    )


def preamble(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """ "Long day. Meeting at 3 and I skipped lunch. Can you fetch me a snack ...?": a whole
    sentence before a request, telling what happened to the speaker or someone ("I skipped
    lunch"), that no other rule read and that asks for nothing, lends the request no thing
    when the request names its own and never points back ("heat *it* up", "bring me *one*"
    still take what the sentence named, read as before)."""
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.need or acts.question is not None:
        return None
    if acts.wish or acts.thanks or acts.condition or acts.note is not None or acts.withdrawal:
        return None
    if not _whole_sentence(msg.text, piece) or not _told(piece.words):
        return None
    later = [p for p in msg.pieces if p.start > piece.end and not _same_sentence(msg, piece, p)]
    asks = [p for p in later if p.acts.request or p.acts.imperative]
    if not asks or any(set(p.words) & POINTERS for p in later):
        return None
    return Finding("statement", piece, "what the speaker tells before the request: context only")


def _whole_sentence(text: str, piece: Piece) -> bool:
    """Whether the piece is a sentence of its own, ended by a full stop or "!"."""
    before = text[: piece.start].rstrip()
    after = text[piece.end :].lstrip()
    return (not before or before[-1] in ".!?") and after[:1] in _SENTENCE_END


def _same_sentence(msg: Message, a: Piece, b: Piece) -> bool:
    return not any(c in ".!?" for c in msg.text[a.end : b.start])


def _told(words: list[str]) -> bool:
    """A subject pronoun and a past or present verb after it: "I skipped lunch", "it broke"."""
    return any(a in _SUBJECTS and language.is_finite_verb(b) for a, b in itertools.pairwise(words))
