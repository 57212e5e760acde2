"""The Surveyor: records each ended instruction's impact and runs its survey over the messenger.

Attached to an Assistant, it

- on every instruction end, stores the instruction's record (kind, outcome, durations, group
  requests, walking saved) and, unless the instruction was cancelled or the requester opted
  out, sends the survey to the requester's direct chat;
- sees every direct message that answers no open question before it would become a new
  instruction, and claims the ones that belong to a survey (answers, a comment, "skip",
  "stop surveys"); a message that reads as a request stays a new instruction;
- on ``tick()`` (run every ``poll_s`` by ``start()``, or called by tests on a simulated clock)
  sends each survey's one reminder when due and expires the unanswered ones.

Messages carry stable idempotency keys (``survey:<instruction>``, ``...:reminder``,
``...:r<n>``), so a messenger that journals sends never sends one twice after a restart.
"""

from __future__ import annotations

import asyncio
import logging
from typing import TYPE_CHECKING

from assistantx.core.clock import Clock
from assistantx.core.errors import AdapterError
from assistantx.core.lifecycle import cancel_and_wait
from assistantx.core.office import Office
from assistantx.core.ports.messenger import ChatRef, InboundMessage, Messenger, OutboundMessage
from assistantx.feedback.answers import ParsedReply, parse_reply
from assistantx.feedback.impact import summarise
from assistantx.feedback.store import FeedbackStore
from assistantx.feedback.survey import Survey, SurveyPolicy, SurveyState
from assistantx.feedback.walking import DistanceFn
from assistantx.memory.short_term import ShortTermMemory

if TYPE_CHECKING:
    from assistantx.runtime.assistant import Assistant

logger = logging.getLogger(__name__)


class Surveyor:
    def __init__(
        self,
        office: Office,
        store: FeedbackStore,
        messenger: Messenger,
        clock: Clock,
        *,
        distance: DistanceFn | None = None,
        policy: SurveyPolicy | None = None,
        poll_s: float = 60.0,
    ) -> None:
        self.office = office
        self.store = store
        self.messenger = messenger
        self.clock = clock
        self.distance = distance
        self.policy = policy or SurveyPolicy()
        self.poll_s = poll_s
        self._task: asyncio.Task[None] | None = None
        self._closed = False
        # The store is awaited (the loop serves others meanwhile); each read-decide-write of
        # survey state holds this, so an end, a reply and a reminder never interleave there.
        # Messages are sent after it is released, as before.
        self._turn = asyncio.Lock()

    def attach(self, assistant: Assistant) -> None:
        assistant.on_instruction_end(self.instruction_ended)
        assistant.intercept_direct_messages(self.handle_message)

    # -- lifecycle (reminders in real time) ------------------------------------------------
    async def start(self) -> None:
        self._closed = False
        if self._task is None:
            self._task = asyncio.create_task(self._remind_forever(), name="survey-reminders")

    async def stop(self) -> None:
        """Stop reminding and stop taking instruction ends and replies (the store may close)."""
        self._closed = True
        await cancel_and_wait(self._task)
        self._task = None
        async with self._turn:
            pass  # an end or a reply taken before is through with the store

    async def _remind_forever(self) -> None:
        failing = False
        while True:
            # Real seconds: the survey's own times come from the clock, so a sped-up clock
            # only makes reminders fall due sooner.
            await asyncio.sleep(self.poll_s)
            try:
                await self.tick()
            except Exception:
                if not failing:
                    logger.exception("survey reminders failed; retrying every %.0f s", self.poll_s)
                failing = True
            else:
                if failing:
                    logger.info("survey reminders work again")
                failing = False

    # -- instruction end -------------------------------------------------------------------
    async def instruction_ended(self, stm: ShortTermMemory) -> None:
        if self._closed:
            return  # shutting down: the instruction resumes (and ends) on the next start
        now = self.clock.now()
        # The walking estimate plans routes on the floor map (seconds on a big floor): off the
        # event loop, so an instruction's end never stalls the service.
        record = await asyncio.to_thread(summarise, self.office, stm.trace, now, self.distance)
        requester = stm.requester
        async with self._turn:
            await self.store.aput_instruction(record)
            if record.outcome == "cancelled":
                return
            if await self.store.aopted_out(requester):
                logger.info("no survey for %s: %s opted out", stm.instruction_id, requester)
                return
            if await self.store.asurvey(stm.instruction_id) is not None:
                return  # already sent (an end hook that ran again after a restart)
            survey = Survey(
                instruction_id=stm.instruction_id,
                person=requester,
                chat=ChatRef(kind="dm", id=requester),
                task_text=stm.text,
                sent_at=now,
            )
            await self.store.aput_survey(survey)
        await self._send(survey, survey.invitation())

    # -- replies ---------------------------------------------------------------------------
    async def handle_message(self, message: InboundMessage) -> bool:
        """Claim a direct message that belongs to a survey (True), else leave it (False)."""
        if self._closed or message.chat.kind != "dm" or not message.text.strip():
            return False
        now = self.clock.now()
        parsed = parse_reply(message.text)
        notice: OutboundMessage | None = None
        answer: str | None = None
        async with self._turn:
            survey = await self._survey_for(message, parsed, now)
            if survey is None:
                notice = await self._standing_command(message, parsed, now)
            elif not survey.claims(message.text, parsed):
                return False
            else:
                answer, replies = await self._take_reply(survey, message, parsed, now)
        if survey is None:
            if notice is None:
                return False
            await self._post(notice)
        elif answer is not None:
            await self._send(survey, answer, suffix=f"r{replies}")
        return True

    async def _take_reply(
        self, survey: Survey, message: InboundMessage, parsed: ParsedReply, now: float
    ) -> tuple[str | None, int]:
        """Apply and store a reply to ``survey``; (the answer to send, replies so far)."""
        invalid_before = survey.invalid_replies
        answer = survey.apply(message.text, parsed, now, self.policy)
        invalid = survey.invalid_replies > invalid_before
        if parsed.opt_out:
            await self._opt_out(message.sender, now, survey)
        elif parsed.opt_in:
            await self.store.aopt_in(message.sender)
        effect = _effect(parsed, survey, invalid=invalid)
        await self.store.arecord_reply(survey, now, message.text, effect)
        replies = 0 if answer is None else len(await self.store.areplies(survey.instruction_id))
        return answer, replies

    async def _survey_for(
        self, message: InboundMessage, parsed: ParsedReply, now: float
    ) -> Survey | None:
        """The survey a reply is for: the one it references, else the latest in that chat."""
        candidates = [
            s
            for s in await self.store.aactive_surveys(message.sender)
            if s.chat == message.chat and s.accepts_replies(now, self.policy)
        ]
        for survey in candidates:
            if message.in_reply_to == survey.question_id:
                return survey
        if parsed.has_answers:
            # Answers go to the latest survey still missing some, not to a comment slot.
            open_ones = [s for s in candidates if s.state is SurveyState.OPEN]
            candidates = open_ones or candidates
        return candidates[-1] if candidates else None

    async def _standing_command(
        self, message: InboundMessage, parsed: ParsedReply, now: float
    ) -> OutboundMessage | None:
        """ "stop surveys" / "start surveys" with no survey running: honoured all the same.

        Returns the confirmation to send, or None for a message that is no such command."""
        if "survey" not in message.text.lower() or not (parsed.opt_out or parsed.opt_in):
            return None
        chat = ChatRef(kind="dm", id=message.sender)
        if parsed.opt_out:
            await self._opt_out(message.sender, now, None)
            text = 'Understood: no more surveys. Write "start surveys" if you change your mind.'
        else:
            await self.store.aopt_in(message.sender)
            text = "Surveys are on. Thank you!"
        return OutboundMessage(chat=chat, text=text)

    async def _opt_out(self, person: str, now: float, current: Survey | None) -> None:
        await self.store.aopt_out(person, now)
        for other in await self.store.aactive_surveys(person):
            if current is None or other.instruction_id != current.instruction_id:
                other.state = SurveyState.OPTED_OUT
                await self.store.aput_survey(other)

    # -- time ------------------------------------------------------------------------------
    async def tick(self) -> int:
        """Send due reminders and expire stale surveys; returns the reminders sent."""
        now = self.clock.now()
        sent = 0
        async with self._turn:
            surveys = await self.store.aactive_surveys()
        for survey in surveys:
            async with self._turn:
                text = None
                if survey.expire_if_due(now, self.policy):
                    await self.store.aput_survey(survey)
                elif survey.reminder_due(now, self.policy) and not await self.store.aopted_out(
                    survey.person
                ):
                    text = survey.remind(now)
                    await self.store.aput_survey(survey)
            if text is not None:
                await self._send(survey, text, suffix="reminder")
                sent += 1
        return sent

    # -- sending ---------------------------------------------------------------------------
    async def _send(self, survey: Survey, text: str, *, suffix: str = "") -> None:
        # No ``question_id``: that marks a question of a running instruction (the simulated
        # colleagues answer those); survey replies are matched by chat, or by ``in_reply_to``
        # where a platform reports the survey message replied to.
        key = survey.question_id + (f":{suffix}" if suffix else "")
        await self._post(
            OutboundMessage(
                chat=survey.chat,
                text=text,
                instruction_id=survey.instruction_id,
                idempotency_key=key,
            )
        )

    async def _post(self, message: OutboundMessage) -> None:
        try:
            await self.messenger.send(message)
        except AdapterError as exc:
            # The survey is stored; a lost invitation is made up for by the reminder.
            logger.warning("could not send survey message to %s: %s", message.chat, exc)


def _effect(parsed: ParsedReply, survey: Survey, *, invalid: bool) -> str:
    """What a reply did, in a few words, stored next to its text."""
    if parsed.opt_out:
        return "opt-out"
    if parsed.opt_in:
        return "opt-in"
    if parsed.skip:
        return "skip"
    if invalid:
        return "invalid"
    comment = ", comment" if survey.comment else ""
    return f"{survey.state.value}: {len(survey.answers)}/4 answered{comment}"
