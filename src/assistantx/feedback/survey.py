"""The after-task survey: its questions, and one survey's state machine.

The survey (as in the paper) asks four multiple-choice questions, Yes / No / Unsure, and
invites an optional free-text comment. A survey moves through these states::

    open ──all four answered──> complete
      │  └─"skip"───────────────> declined
      │  └─"stop surveys"───────> opted_out      (the person is never surveyed again)
      └──no full answer by the deadline──> expired

An open survey gets at most one reminder (``reminder_due``), naming the questions still
open. A reply that carries nothing usable gets one re-ask explaining the accepted forms;
further unusable replies are stored but answered with silence, so an auto-responder cannot
start an endless exchange. Every reply counts once in ``invalid_replies`` when unusable.

Which messages reach a survey at all (a reply to it, or a new request?) is decided by
``claims`` before a direct message would become a new instruction.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum

from pydantic import BaseModel, Field

from assistantx.core.ports.messenger import ChatRef
from assistantx.feedback.answers import (
    Choice,
    ParsedReply,
    looks_like_request,
    says_something,
    word_count,
)


@dataclass(frozen=True)
class Question:
    id: str
    text: str


QUESTIONS: tuple[Question, ...] = (
    Question("success", "Was the task successful?"),
    Question("walking", "Did it save you walking?"),
    Question("satisfied", "Are you satisfied?"),
    Question("productivity", "Did it improve your productivity?"),
)
QUESTION_IDS: tuple[str, ...] = tuple(q.id for q in QUESTIONS)
_ANSWER_HELP = (
    'Answer with yes, no or unsure: all at once ("yes no unsure yes", "1 yes 2 no", "y/n/?/y", '
    '"all yes") or one at a time. Add a comment after your answers or with "comment: ...".'
)
_OPT_OUT_HELP = 'Reply "stop surveys" and I will not ask again.'


class SurveyState(StrEnum):
    OPEN = "open"
    COMPLETE = "complete"
    DECLINED = "declined"
    OPTED_OUT = "opted_out"
    EXPIRED = "expired"


@dataclass(frozen=True)
class SurveyPolicy:
    reminder_after_s: float = 4 * 3600.0
    """No full answer this long after sending: one reminder."""
    expire_after_s: float = 48 * 3600.0
    """After this, the survey takes no more answers (and a missing answer stays missing)."""
    min_comment_words: int = 3
    """Unreadable text this long (in words) is a comment; shorter is nonsense."""


class Survey(BaseModel):
    """One survey, sent to the requester of one instruction."""

    instruction_id: str
    person: str
    chat: ChatRef
    task_text: str = ""
    sent_at: float
    state: SurveyState = SurveyState.OPEN
    answers: dict[str, Choice] = Field(default_factory=dict, description="question id → choice")
    comment: str | None = None
    reminded_at: float | None = None
    completed_at: float | None = None
    invalid_replies: int = 0
    reasked: bool = False

    @property
    def question_id(self) -> str:
        """The id replies may reference (``in_reply_to``) to name this survey."""
        return f"survey:{self.instruction_id}"

    @property
    def pending(self) -> list[str]:
        return [q for q in QUESTION_IDS if q not in self.answers]

    def accepts_replies(self, now: float, policy: SurveyPolicy) -> bool:
        if self.state is SurveyState.OPEN:
            return now < self.sent_at + policy.expire_after_s
        # A comment may still follow complete answers, once, before the deadline.
        return (
            self.state is SurveyState.COMPLETE
            and self.comment is None
            and now < self.sent_at + policy.expire_after_s
        )

    # -- replies -------------------------------------------------------------------------
    def claims(self, text: str, parsed: ParsedReply) -> bool:
        """Whether a direct message belongs to this survey rather than being a new request."""
        if parsed.opt_out or parsed.opt_in or parsed.skip:
            return True
        if looks_like_request(text):
            return False
        if self.state is SurveyState.COMPLETE:
            return bool(text.strip())  # the optional comment
        return True

    def apply(self, text: str, parsed: ParsedReply, now: float, policy: SurveyPolicy) -> str | None:
        """Take a reply this survey claimed; return what to answer (None: stay silent)."""
        if parsed.opt_out:
            self.state = SurveyState.OPTED_OUT
            return 'Understood: no more surveys. Write "start surveys" if you change your mind.'
        if parsed.opt_in:
            return "Surveys are on. Thank you!"
        if parsed.skip:
            if self.state is SurveyState.OPEN:
                self.state = SurveyState.DECLINED
            return "No problem, I will not ask about this one again."
        if self.state is SurveyState.COMPLETE:
            written = (parsed.comment or text).strip()
            if not says_something(written):  # "asdf qwerty" is no comment (answers.py)
                return self._unreadable("Sorry, I could not read that as a comment.")
            self.comment = written
            return "Thank you, I have noted your comment."

        taken = self._take_answers(parsed)
        comment = parsed.comment if parsed.comment and says_something(parsed.comment) else None
        if (
            not taken
            and comment is None
            and word_count(text) >= policy.min_comment_words
            and says_something(text)
        ):
            comment = text.strip()  # free text instead of answers: keep it as the comment
        if comment:
            self.comment = f"{self.comment}\n{comment}" if self.comment else comment
        if not taken and not comment:
            return self._unreadable(
                "Sorry, I could not read that as survey answers. " + self._ask_pending()
            )
        if not self.pending:
            self.state, self.completed_at = SurveyState.COMPLETE, now
            if self.comment is None:
                return "Thank you! If you want to add a comment, just write it."
            return "Thank you for your answers and your comment!"
        got = ", ".join(f"{n}: {taken[q]}" for n, q in enumerate(QUESTION_IDS, 1) if q in taken)
        prefix = f"Got it ({got}). " if got else "Thank you for the comment. "
        return prefix + self._ask_pending()

    def _unreadable(self, answer: str) -> str | None:
        """Count an unusable reply; say ``answer`` the first time only (no loop with an
        auto-responder)."""
        self.invalid_replies += 1
        if self.reasked:
            return None
        self.reasked = True
        return answer

    def _take_answers(self, parsed: ParsedReply) -> dict[str, Choice]:
        """Fill questions from the reply: numbered first, then the rest in order."""
        taken: dict[str, Choice] = {}
        for number, choice in sorted(parsed.numbered.items()):
            qid = QUESTION_IDS[number - 1]
            self.answers[qid] = taken[qid] = choice
        pending = self.pending
        if parsed.to_all is not None:
            for qid in pending:
                self.answers[qid] = taken[qid] = parsed.to_all
        for qid, choice in zip(pending, parsed.ordered, strict=False):
            self.answers[qid] = taken[qid] = choice
        return taken

    # -- messages ------------------------------------------------------------------------
    def invitation(self) -> str:
        about = f' about "{_shorten(self.task_text)}"' if self.task_text else ""
        lines = [f"A short survey{about}, please (yes / no / unsure):"]
        lines += [f"{n}. {q.text}" for n, q in enumerate(QUESTIONS, 1)]
        lines.append("5. Any comment? (optional)")
        lines.append(_ANSWER_HELP + " " + _OPT_OUT_HELP)
        return "\n".join(lines)

    def _ask_pending(self) -> str:
        open_questions = "\n".join(
            f"{n}. {q.text}" for n, q in enumerate(QUESTIONS, 1) if q.id in self.pending
        )
        return f"Still open (yes / no / unsure):\n{open_questions}\n{_ANSWER_HELP}"

    # -- time ----------------------------------------------------------------------------
    def reminder_due(self, now: float, policy: SurveyPolicy) -> bool:
        return (
            self.state is SurveyState.OPEN
            and self.reminded_at is None
            and now >= self.sent_at + policy.reminder_after_s
            and now < self.sent_at + policy.expire_after_s
        )

    def remind(self, now: float) -> str:
        self.reminded_at = now
        about = f' about "{_shorten(self.task_text)}"' if self.task_text else ""
        return f"A reminder of the survey{about}. " + self._ask_pending() + " " + _OPT_OUT_HELP

    def expire_if_due(self, now: float, policy: SurveyPolicy) -> bool:
        if self.state is SurveyState.OPEN and now >= self.sent_at + policy.expire_after_s:
            self.state = SurveyState.EXPIRED
            return True
        return False


def _shorten(text: str, limit: int = 60) -> str:
    text = " ".join(text.split())
    return text if len(text) <= limit else text[: limit - 1] + "…"
