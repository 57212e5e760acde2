"""What the screen finds in each piece (a ``Finding`` with its verdict), and what it makes of
the whole message (``Screened``)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

from assistantx.agents.symbolic.reading.screen.pieces import Piece
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
