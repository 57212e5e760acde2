"""What the screen finds in each piece (a ``Finding`` with its verdict), and what it makes of
the whole message (``Screened``)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece, without
from assistantx.core.task_schema import DeclineOutcome, Evidence, Hint

Verdict = Literal[
    "withdrawn",
    "note",
    "condition",
    "exclusion",
    "wish",
    "thanks",
    "negated",
    "destructive",
    "unplaced",
    "which",
    "instead",
    "fact",
    "question",
    "statement",
    "unsupported",
]


@dataclass(frozen=True)
class Finding:
    verdict: Verdict
    piece: Piece
    meaning: str  # in words, for the evidence
    hint: Hint | None = None
    message: str = ""  # for a decline, or the reply to a non-request
    offer: str = ""  # the request a "Shall I ...?" would carry out on a yes
    shall: str = ""  # the "Shall I ...?" question itself
    context: tuple[str, ...] = ()  # item types and people a statement named


@dataclass(frozen=True)
class Spoken:
    """A message's pieces with the verdict of each that a rule matched, before anything is
    made of the whole (``RequestScreen.verdicts``)."""

    msg: Message
    findings: list[Finding]
    fixes: list[Evidence]  # the corrections read first ("no, I meant a pencil")

    @property
    def hints(self) -> list[Hint]:
        return [f.hint for f in self.findings if f.hint is not None]

    @property
    def withdrawn(self) -> list[Finding]:
        return [f for f in self.findings if f.verdict == "withdrawn"]

    @property
    def cut(self) -> int:
        """Where what still counts begins: after the last withdrawal."""
        withdrawn = self.withdrawn
        return withdrawn[-1].piece.end if withdrawn else 0

    @property
    def live(self) -> list[Finding]:
        """The verdicts on the pieces after the last withdrawal."""
        return [f for f in self.findings if f.piece.start >= self.cut]

    @property
    def dropped(self) -> list[Piece]:
        return [f.piece for f in self.findings if f.verdict in DROPPED]

    @property
    def left(self) -> str:
        """The text with what was withdrawn and the dropped pieces taken out."""
        return without(self.msg.text, self.cut, self.dropped)

    @property
    def kept(self) -> list[Piece]:
        """The pieces still counted and not dropped: the request's."""
        dropped = self.dropped
        return [
            p for p in self.msg.pieces if p.start >= self.cut and not any(p is d for d in dropped)
        ]


@dataclass(frozen=True)
class Request:
    """What is left of a message for the later stages to read, rewritten so they can."""

    text: str
    evidence: list[Evidence]  # the rewrites made, in words


@dataclass
class Screened:
    """What the screen made of a request."""

    text: str  # what is left for the frame parser
    decline: str | None = None
    outcome: DeclineOutcome = "unachievable"
    hints: list[Hint] = field(default_factory=list)
    evidence: list[Evidence] = field(default_factory=list)
    question: str | None = None  # "... Shall I bring you one?": asked before anything moves
    offer: str | None = None  # the request carried out when the answer is yes
    confirm: bool = False  # a third person's need only: restate the reading and ask

    @property
    def answered(self) -> bool:
        """The screen answered the message itself: no request is left to read."""
        return self.decline is not None or self.question is not None


UNANSWERED = "a question I cannot answer"
# What asks nothing of the assistant: an aside beside it ("..., all sorted") is no request.
SAYS_NOTHING_TO_DO = frozenset(
    {"thanks", "wish", "withdrawn", "note", "condition", "fact", "statement"}
)
# What is taken out of the text before the request is read.
DROPPED = frozenset(
    {
        "note",
        "condition",
        "negated",
        "fact",
        "withdrawn",
        "exclusion",
        "wish",
        "thanks",
        "question",
        "statement",
    }
)
