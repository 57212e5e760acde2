"""Matching inbound messages to the instruction and question that asked for them.

Every question the assistant sends gets a question id. A reply is matched by, in order:
the platform's explicit reply reference (``in_reply_to``), the most recent question still
unanswered in the same chat (a DM with that person, or that group), else the open instruction
that wrote to that chat last (its question there, or the instruction itself: a colleague sent
a locker code writes back "I came, but I don't have it").
Anything unmatched goes back to the caller (a new instruction, or chatter to ignore).
Replies are kept per instruction, so two instructions asking the same person never see
each other's answers. Once an instruction ends, its questions and the chats it wrote to are
remembered as ended (``ended_instruction``): a late reply there is about that instruction,
not a new request. Only the latest ``ended_kept`` ended instructions are remembered so: the
assistant looks a late reply's instruction up among the ended instructions it still holds
(as many, ``FINISHED_KEPT``) and treats one it no longer holds as unknown, so remembering
more (the last 10,000 questions, as once) changed no answer and grew the service by one entry
per question for its first 10,000 questions.

A question is answered only from the chat it was asked in: a DM question by that person in
that DM, a group question by a member in that group. An ``in_reply_to`` naming a question
asked elsewhere (Zhang quoting, in his own DM, the question sent to Wang) is not an answer to
it; the reference is dropped and the message is routed as if it named no question.
"""

from __future__ import annotations

import asyncio
from collections import defaultdict
from collections.abc import Callable
from dataclasses import dataclass

from assistantx.core.ports.messenger import ChatRef, InboundMessage

ENDED_KEPT = 256  # ended instructions whose questions and chats are remembered (by default)


@dataclass
class OpenQuestion:
    question_id: str
    instruction_id: str
    chat: ChatRef
    asked_at: float
    answered: bool = False  # an answer arrived (a later unreferenced word may be for another)


# Whether a person belongs to a group (person id, group id); None: trust the chat alone.
MembershipCheck = Callable[[str, str], bool]


class ReplyBox:
    def __init__(
        self, is_member: MembershipCheck | None = None, *, ended_kept: int = ENDED_KEPT
    ) -> None:
        if ended_kept < 1:
            raise ValueError("ended_kept must be at least 1")
        self._is_member = is_member
        self._ended_kept = ended_kept
        self._questions: dict[str, OpenQuestion] = {}
        self._by_chat: dict[ChatRef, list[str]] = defaultdict(list)
        self._events: dict[str, asyncio.Event] = defaultdict(asyncio.Event)
        self._inbox: dict[str, list[InboundMessage]] = defaultdict(list)
        self._engaged: dict[ChatRef, list[str]] = defaultdict(list)
        self._written_at: dict[ChatRef, dict[str, float]] = defaultdict(dict)
        self._ended_questions: dict[str, str] = {}  # question id → its ended instruction
        self._ended_chats: dict[ChatRef, str] = {}  # chat → the ended instruction last in it
        # The ended instructions remembered, oldest first, each with its ended questions.
        self._ended: dict[str, list[str]] = {}

    def ask(
        self,
        question_id: str,
        instruction_id: str,
        chat: ChatRef,
        time: float,
        *,
        answered: bool = False,
    ) -> None:
        """Register an open question; ``answered``: asked and answered before a restart."""
        self._questions[question_id] = OpenQuestion(
            question_id, instruction_id, chat, time, answered=answered
        )
        self._by_chat[chat].append(question_id)
        self._ended_chats.pop(chat, None)

    def engage(self, instruction_id: str, chat: ChatRef, at: float | None = None) -> None:
        """``instruction_id`` wrote to ``chat`` (at ``at``; None: now, after every other
        write): unprompted messages there may concern it. The chat's writers stay in the
        order of their last writes, also when a restart registers them again out of order."""
        self._ended_chats.pop(chat, None)
        engaged = self._engaged[chat]
        if instruction_id in engaged:
            engaged.remove(instruction_id)
        written = self._written_at[chat]
        written[instruction_id] = at if at is not None else max(written.values(), default=0.0)
        engaged.append(instruction_id)
        engaged.sort(key=lambda i: written.get(i, 0.0))

    def event(self, instruction_id: str) -> asyncio.Event:
        """Set whenever a message for ``instruction_id`` arrives."""
        return self._events[instruction_id]

    def route(self, message: InboundMessage) -> str | None:
        """File ``message`` under its instruction; return the instruction id (None: unmatched)."""
        question = self._questions.get(message.in_reply_to or "")
        if question is not None and not self.may_answer(question, message):
            message = message.model_copy(update={"in_reply_to": None})
            question = None
        if question is None:
            question = self._in_context(message)
        if question is None:
            engaged = self._engaged.get(message.chat)
            if not engaged:
                return None
            self.deliver(engaged[-1], message)
            return engaged[-1]
        if message.in_reply_to is None:
            message = message.model_copy(update={"in_reply_to": question.question_id})
        question.answered = True
        self._inbox[question.instruction_id].append(message)
        self._events[question.instruction_id].set()
        return question.instruction_id

    def _in_context(self, message: InboundMessage) -> OpenQuestion | None:
        """The open question an unreferenced ``message`` answers; None: it is unprompted.

        A question nobody has answered yet comes first (the newest). Once every question here
        has its answer, the message follows the chat's last writer: the instruction that wrote
        there last (its newest question, else none: an unprompted word to it), so "I came to
        the robot, but I don't have it" reaches the instruction that just sent the code, not
        another one whose question was answered earlier. With no writer known, the newest
        question."""
        here = [self._questions[q] for q in self._by_chat.get(message.chat, [])]
        here = [q for q in here if self.may_answer(q, message)]
        waiting = [q for q in here if not q.answered]
        if waiting:
            return waiting[-1]
        engaged = self._engaged.get(message.chat)
        if engaged:
            mine = [q for q in here if q.instruction_id == engaged[-1]]
            return mine[-1] if mine else None
        return here[-1] if here else None

    def may_answer(self, question: OpenQuestion, message: InboundMessage) -> bool:
        """Whether ``message`` comes from the chat ``question`` was asked in."""
        if message.chat != question.chat:
            return False
        if question.chat.kind == "dm":
            return message.sender == question.chat.id
        return self._is_member is None or self._is_member(message.sender, question.chat.id)

    def deliver(self, instruction_id: str, message: InboundMessage) -> None:
        """File a message known to belong to ``instruction_id`` (e.g. a requester's answer)."""
        self._inbox[instruction_id].append(message)
        self._events[instruction_id].set()

    def take(self, instruction_id: str) -> list[InboundMessage]:
        """The messages for ``instruction_id`` not yet taken."""
        messages = self._inbox.pop(instruction_id, [])
        self._events[instruction_id].clear()
        return messages

    def close(self, instruction_id: str) -> None:
        """Forget an ended instruction's questions; later replies go unmatched, and
        ``ended_instruction`` names it for them (while it is one of the latest ``ended_kept``
        ended)."""
        asked = [q for q, o in self._questions.items() if o.instruction_id == instruction_id]
        for qid in asked:
            question = self._questions.pop(qid)
            self._by_chat[question.chat].remove(qid)
            self._ended_questions[qid] = instruction_id
            if not self._engaged.get(question.chat):
                self._ended_chats[question.chat] = instruction_id
        for chat, engaged in self._engaged.items():
            self._written_at[chat].pop(instruction_id, None)
            if instruction_id in engaged:
                engaged.remove(instruction_id)
                if not engaged and not self._by_chat.get(chat):
                    self._ended_chats[chat] = instruction_id
        self._inbox.pop(instruction_id, None)
        self._events.pop(instruction_id, None)
        self._ended.pop(instruction_id, None)
        self._ended[instruction_id] = asked
        while len(self._ended) > self._ended_kept:  # oldest first: dicts keep insertion order
            self._forget(next(iter(self._ended)))

    def ended_instruction(self, message: InboundMessage) -> str | None:
        """The ended instruction an unmatched ``message`` answers (its ``in_reply_to``) or
        writes back to (the last instruction in its chat has ended); None: none known."""
        if message.in_reply_to is not None and message.in_reply_to in self._ended_questions:
            return self._ended_questions[message.in_reply_to]
        return self._ended_chats.get(message.chat)

    def _forget(self, instruction_id: str) -> None:
        """An ended instruction no longer remembered: its questions and the chats it was
        the last in (unless a later one took them) name no instruction any more."""
        for qid in self._ended.pop(instruction_id):
            if self._ended_questions.get(qid) == instruction_id:
                del self._ended_questions[qid]
        for chat in [c for c, i in self._ended_chats.items() if i == instruction_id]:
            del self._ended_chats[chat]
