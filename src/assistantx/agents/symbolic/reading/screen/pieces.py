"""A message cut into pieces (sentences, and the comma parts of one), each with its place in
the original, so what is dropped is removed by its characters and what is left reads as the
person wrote it, and with the lexicon's reading of its words (the stage before the screen:
every rule reads the piece's tokens and mentions from it); and the state the rules keep while
they walk one message's pieces."""

from __future__ import annotations

import itertools
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Literal

from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.agents.symbolic.reading.screen.confirming_tag import confirming_tag
from assistantx.agents.symbolic.reading.screen.english import phrases_pattern, split_words
from assistantx.agents.symbolic.reading.screen.thing_then_need import need_after_thing
from assistantx.agents.symbolic.reading.speech_acts import Acts
from assistantx.core import english

# A spaced dash joins two sentences as a full stop would ("I'm on the ward - print my rota"),
# and so does chat's laugh between two of them ("my badge is peeling lol can it go through
# the laminator"): a laugh is no word of either; one that ends the message stays with it.
_LAUGHS = "|".join(sorted(map(re.escape, english.words("chat_laughs")), key=len, reverse=True))
_SENTENCE_END = re.compile(
    rf"[.!?;\n]+|\s[-–—]+\s|(?<=\w)[\s,]+(?:{_LAUGHS})\b[\s,.!?;]+(?=\w)", re.IGNORECASE
)
# A tag question closing a statement ("Robin's got a spare one hasn't he?", "... isn't it?"):
# a negated auxiliary and a pronoun, said to have the statement confirmed. It asks nothing of
# its own, so its question mark does not make the statement a question: what the statement
# says (who has the thing) stays context for the request beside it.
_TAG_AUXILIARIES = frozenset(
    {"hasnt", "havent", "isnt", "arent", "doesnt", "dont", "didnt", "wasnt", "werent", "wont"}
)
_TAG_PRONOUNS = frozenset({"he", "she", "they", "it", "we", "i", "you"})


def tag_question(words: list[str]) -> bool:
    """Whether a sentence ends in a tag question after a statement of its own."""
    if confirming_tag(words):  # "Zhang has scissors right?": the one-word tag
        return True
    return len(words) > 3 and words[-2] in _TAG_AUXILIARIES and words[-1] in _TAG_PRONOUNS


# A clause that says why the request is made ("... so he can book the courier") or offers a
# thing to whoever wants it ("... on my desk if anyone needs it"): a piece of its own, so what
# it names is never read into the request before it (``purpose``).
_PURPOSE = re.compile(
    rf"(?:{phrases_pattern('purpose_openers')})\s+(?!(?:you|u|ya)\b)[^\W\d_][\w-]*"
    rf"(?:['’](?:ll|d)\b|\s+(?:{phrases_pattern('purpose_modals')})(?:n['’]?t)?\b)",
    re.IGNORECASE,
)
_OPEN_OFFER = re.compile(
    rf"if\s+(?:{phrases_pattern('open_offer_subjects')})\s+(?:\w+\s+)?"
    rf"(?:{phrases_pattern('need_verbs')}|needed|wanted)\b",
    re.IGNORECASE,
)
_CLAUSE_BREAK = re.compile(rf"(?<=\w)\s+(?={_PURPOSE.pattern}|{_OPEN_OFFER.pattern})", re.I)
Clause = Literal["purpose", "open_offer"]


# The speaker's own doing told, then a need of theirs joined by "and" ("I'm covering a class
# after lunch and need a stopwatch"): the need is a request of its own, cut from the account
# before it, which stays context (a need joined to anyone else's doing is not cut: "Gwen and I
# need ...").
_OWN_DOING = re.compile(rf"(?:{phrases_pattern('own_doing_openers')})\s", re.IGNORECASE)
_NEED_JOINED = re.compile(
    rf"(?<=\w)\s+(?=and\s+(?:(?:i|we)\s+)?(?:{phrases_pattern('joined_needs')})\s+"
    rf"(?!(?:{phrases_pattern('nothing_needed')})\b))",
    re.IGNORECASE,
)


def _clauses(chunk: str) -> list[tuple[int, str]]:
    """A comma part cut before its purpose or open-offer clause, and an account of the
    speaker's own doing before a need joined to it: each clause with its offset."""
    breaks = [m.end() for m in _CLAUSE_BREAK.finditer(chunk)]
    if _OWN_DOING.match(chunk.lstrip()):
        breaks += [m.end() for m in _NEED_JOINED.finditer(chunk)]
    breaks += need_after_thing(chunk)  # "my lunch is stuck in the fridge and I need it"
    cuts = [0, *sorted(set(breaks)), len(chunk)]
    return [(a, chunk[a:b]) for a, b in itertools.pairwise(cuts)]


def _clause(text: str) -> Clause | None:
    """Whether a piece is a purpose clause or an open offer, by its opening words."""
    if _PURPOSE.match(text):
        return "purpose"
    return "open_offer" if _OPEN_OFFER.match(text) else None


_PIECE_BREAK = re.compile(r",|\s+(?:and|then|but)\s+", re.IGNORECASE)


@dataclass(frozen=True)
class Part:
    """A part of the request: its text, its place in the original and its words."""

    text: str
    start: int
    end: int
    words: list[str]
    asks: bool = False  # the sentence ends with a question mark

    def verb_at(self, lead_in: frozenset[str]) -> int:
        """Index of the request's verb: the first word that is no lead-in ("could you ...")."""
        return next((n for n, w in enumerate(self.words) if w not in lead_in), len(self.words))


@dataclass(frozen=True, kw_only=True)
class Piece(Part):
    """A piece of a message, as the lexicon and the speech acts read it."""

    lexed: Lexed  # its tokens, typos corrected, and the mentions of the office in them
    acts: Acts  # what it does (a request, a question, thanks ...), read once
    # a purpose ("so he can book the courier") or an open offer ("if anyone needs it"):
    # why or for whom, never what to do (``purpose``)
    clause: Clause | None = None


@dataclass
class Message:
    """One message being screened: its text, its pieces, and what earlier pieces set."""

    text: str
    pieces: list[Piece]
    lexed: Lexed  # the whole message, read once by the lexicon (a rule that looks beyond its piece)
    noting: int | None = None  # where a note began ("note this down: ...")
    withdrawing: bool = False  # a withdrawal was read: what follows may be its reason
    withdrawn_at: int = 0  # where the last withdrawal read begins
    negating: bool = False  # a negated errand was read: what follows may be its reason
    # a wish kept the speaker's own thing from others: "I need it" after it is why
    keeping: bool = False
    # a thing said was corrected to another ("a coffee - sorry, make that a water"): "I've had
    # 3 already" after it is why the first was dropped, not the new one withdrawn
    replaced: bool = False

    def asked_before(self, piece: Part) -> list[Piece]:
        """The pieces before ``piece`` that ask something of the robot (a request or a
        command): what a reason, a count or a topic said after them is about."""
        return [
            p for p in self.pieces if p.end <= piece.start and (p.acts.request or p.acts.imperative)
        ]


def pieces(
    text: str, read: Callable[[str], Lexed], acts: Callable[[list[str], bool], Acts]
) -> list[Piece]:
    """Sentences, and the comma-separated parts of each, each read by ``read`` (the lexicon)
    and by ``acts`` (the speech acts, ``speech_acts.acts_reader``)."""
    out: list[Piece] = []
    pos = 0
    for m in [*_SENTENCE_END.finditer(text), None]:
        end = m.start() if m is not None else len(text)
        sentence_start = pos
        sub = 0
        for b in [*re.finditer(",", text[sentence_start:end]), None]:
            stop = sentence_start + (b.start() if b is not None else end - sentence_start)
            clauses = _clauses(text[sentence_start + sub : stop])
            for n, (offset, chunk) in enumerate(clauses):
                lead = len(chunk) - len(chunk.lstrip())
                piece_text = chunk.strip()
                if not piece_text:
                    continue
                start = sentence_start + sub + offset + lead
                words = split_words(piece_text)
                asks = (  # its last part
                    b is None
                    and n == len(clauses) - 1
                    and m is not None
                    and "?" in m.group(0)
                    and not tag_question(words)
                )
                out.append(
                    Piece(
                        piece_text,
                        start,
                        start + len(piece_text),
                        words,
                        asks,
                        lexed=read(piece_text),
                        acts=acts(words, asks),
                        clause=_clause(piece_text),
                    )
                )
            if b is not None:
                sub = b.end()
        pos = m.end() if m is not None else len(text)
    return out


def sub_pieces(piece: Part) -> list[Part]:
    """The parts of a piece joined by "and"/"then"/"but", for finding each one's verb."""
    out: list[Part] = []
    pos = 0
    for m in [*_PIECE_BREAK.finditer(piece.text), None]:
        end = m.start() if m is not None else len(piece.text)
        chunk = piece.text[pos:end]
        if chunk.strip():
            out.append(Part(chunk, piece.start + pos, piece.start + end, split_words(chunk)))
        pos = m.end() if m is not None else len(piece.text)
    return out


def without(text: str, cut: int, dropped: list[Piece]) -> str:
    """The text from ``cut`` on, with the dropped pieces blanked out."""
    chars = list(text)
    for n in range(min(cut, len(chars))):
        chars[n] = " "
    for p in dropped:
        for n in range(p.start, p.end):
            chars[n] = " "
    left = "".join(chars)
    # punctuation left stranded by a removed piece: ", ," or a leading comma
    left = re.sub(r"(^|[.!?;])[\s,]*,", r"\1", left)
    left = re.sub(r",\s*(?=[.!?;]|$)", "", left)
    return re.sub(r"\s+", " ", left).strip(" ,")
