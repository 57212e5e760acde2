"""The PPDR loop: one coroutine per instruction.

perceive → plan → decide → ground and execute → observe ΔM → reflect → apply memory updates,
until Stop, the step limit or the deadline. Fixes what the research code got wrong:

- every action is grounded against memory; an unknown or ambiguous name is refused and the
  error is fed back to the next Decision;
- an action that repeats an earlier one with no new information in between is refused and
  fed back;
- Reflection's verdict and reason reach the next Planning and Decision, and its memory updates
  are applied to the graph with their evidence;
- an action that fails again for the same reason ends the instruction (failures.py) instead
  of a retry loop, and the requester is told where the robot and the locker's contents are;
- the requester is always told the outcome, also on failure, step limit, deadline or cancel,
  in plain words (a model server's failure is described, never its URL or a stack);
- ``deadline_s`` runs on the office clock (simulated time in the simulator), ``wall_s`` on the
  wall clock: a slow model cannot hold an instruction for longer than that;
- every agent call's cost reaches the trace, also when the agent then raised;
- a ``wait`` with nothing new since the last one is refused like any repeated action (a
  different reason or timeout does not make it new);
- locker codes pass the consent guard (``consent.py``, called by the executors): only to a
  party of the item, only to someone who answered, and an owned item leaves its owner only
  with the owner's own yes in their own chat (a model once sent an absent colleague a deposit
  code); a request that claims an authority (someone's agreement, a mode, an identity) is
  told at the start that a message cannot grant it.
"""

from __future__ import annotations

import asyncio
import logging
from dataclasses import dataclass

from assistantx.agents.base import AgentContext, Reasoner
from assistantx.core.actions import Action, Inquire, Move, Outcome, SendQR, Stop, Wait, WaitInPlace
from assistantx.core.errors import (
    AssistantXError,
    GroundingError,
    LLMError,
    LockError,
    MessengerError,
    ModelBehaviorError,
    ReasonerError,
    RobotError,
    UnreachableContactError,
)
from assistantx.core.events import EventKind, EventSink, TraceEvent
from assistantx.core.trace import ActionResult, AgentCall, Observation, TraceStep
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.resolve import Resolver
from assistantx.memory.short_term import ShortTermMemory
from assistantx.memory.updates import (
    AppliedUpdate,
    AvailabilityUpdate,
    MemoryUpdate,
)
from assistantx.runtime import consent
from assistantx.runtime.action_keys import StepKeys
from assistantx.runtime.executors import Executor
from assistantx.runtime.failures import FailureMemory, failure_summary, refusal_summary
from assistantx.runtime.fleet import FleetLease
from assistantx.runtime.lease import BodyLease
from assistantx.runtime.returns import return_note

logger = logging.getLogger(__name__)

_BODY_ACTIONS = (Move, WaitInPlace, SendQR)
END_GRACE_S = 10.0  # wall-clock seconds a cancelled instruction's end may take once cut short


@dataclass(frozen=True)
class LoopLimits:
    max_steps: int = 30
    deadline_s: float = 3600.0  # office clock (simulated time in the simulator)
    wall_s: float | None = 900.0  # wall clock; None: unbounded


def plain_failure(exc: AssistantXError) -> str:
    """What the requester reads when an instruction fails on an error: words, no URL."""
    if isinstance(exc, LLMError):
        cause = getattr(exc, "user_text", None) or "my language model server failed"
        return f"I could not complete this: {cause}, so I stopped."
    if isinstance(exc, ModelBehaviorError):
        return (
            "I could not complete this: my language model kept giving answers I could not "
            "use, so I stopped."
        )
    return f"I could not complete this: {_in_words(exc)}."


class InstructionRunner:
    """Runs one instruction to its end."""

    def __init__(
        self,
        *,
        ltm: LongTermMemory,
        resolver: Resolver,
        executor: Executor,
        reasoner: Reasoner,
        lease: BodyLease | FleetLease,
        limits: LoopLimits = LoopLimits(),
        emit: EventSink | None = None,
    ) -> None:
        self.ltm = ltm
        self.resolver = resolver
        self.executor = executor
        self.reasoner = reasoner
        self.lease = lease
        self.limits = limits
        self._emit_sink = emit
        self._info = 0  # bumped on every new piece of information
        self._last_seen: dict[str, int] = {}  # action signature → info version when executed
        self._failures = FailureMemory()
        # action signature → (info version, result) when the consent guard refused it
        self._guard_refused: dict[str, tuple[int, ActionResult]] = {}

    def _now(self) -> float:
        return self.executor.ctx.clock.now()

    async def _emit(
        self, stm: ShortTermMemory, kind: EventKind, step: int | None, **data: object
    ) -> None:
        if self._emit_sink is None:
            return
        event = TraceEvent(
            instruction_id=stm.instruction_id, kind=kind, time=self._now(), step=step, data=data
        )
        try:
            await self._emit_sink(event)
        except Exception:  # a broken listener must not break the instruction
            logger.exception("trace event sink failed")

    # -- the loop ------------------------------------------------------------------------
    async def run(self, stm: ShortTermMemory) -> ShortTermMemory:
        trace = stm.trace
        if not trace.steps:
            await self._emit(
                stm,
                "instruction_started",
                None,
                requester=stm.requester,
                text=stm.text,
                reasoner=trace.reasoner,
            )
            await self._notice_claims(stm)
        try:
            async with asyncio.timeout(self.limits.wall_s):
                await self._steps(stm)
        except asyncio.CancelledError:
            # (A shutdown cancels too, but then nothing of this end is journaled: it resumes.)
            stm.trace.cancelled = True
            end = asyncio.ensure_future(self._end(stm, "failed", "The instruction was cancelled."))
            try:
                await asyncio.shield(end)
            except asyncio.CancelledError:
                # Cancelled again while ending (a second cancel, a shutdown): the end still
                # comes first, so nothing records this instruction as ended before its
                # ``instruction_ended`` (an event stream opened in between ended without it);
                # bounded, so a messenger that hangs cannot hold a shutdown.
                await asyncio.wait({end}, timeout=END_GRACE_S)
            raise
        except TimeoutError:
            logger.warning("instruction %s ran past its wall-clock bound", stm.instruction_id)
            await self._end(stm, "failed", "I ran out of time for this task.")
        except AssistantXError as exc:
            logger.warning("instruction %s failed: %s", stm.instruction_id, exc)
            await self._end(stm, "failed", plain_failure(exc), detail=str(exc))
        except Exception as exc:
            logger.exception("instruction %s crashed", stm.instruction_id)
            await self._end(stm, "failed", f"I hit an internal error ({type(exc).__name__}).")
        else:
            await self._end(stm, "failed", "The instruction ended without an outcome.")
        return stm

    async def _notice_claims(self, stm: ShortTermMemory) -> None:
        """Tell the requester, once, that what their message claims grants nothing."""
        claims = consent.authority_claims(stm.text, self.executor.ctx.office, stm.requester)
        if not claims:
            return
        try:
            await self.executor.tell_requester(
                stm, consent.no_authority_notice(claims), key="authority"
            )
        except AssistantXError as exc:
            logger.warning("could not tell %s about a claimed authority: %s", stm.requester, exc)

    async def _end(
        self, stm: ShortTermMemory, outcome: Outcome, summary: str, *, detail: str | None = None
    ) -> None:
        try:
            await self._finish(stm, outcome, summary, detail=detail)
            await self._emit(
                stm, "instruction_ended", None, outcome=stm.trace.outcome, summary=stm.trace.summary
            )
        finally:
            self.lease.release(stm.instruction_id)
            self.executor.ctx.replies.close(stm.instruction_id)

    async def _steps(self, stm: ShortTermMemory) -> None:
        trace = stm.trace
        deadline = trace.started_at + self.limits.deadline_s
        feedback: list[str] = []
        while trace.outcome is None:
            index = len(trace.steps)
            if index >= self.limits.max_steps:
                await self._finish(
                    stm,
                    "failed",
                    f"I stopped after {self.limits.max_steps} steps without finishing the task.",
                )
                return
            if self._now() > deadline:
                await self._finish(stm, "failed", "I ran out of time for this task.")
                return
            feedback = await self._step(stm, index, feedback)

    async def _step(self, stm: ShortTermMemory, index: int, feedback: list[str]) -> list[str]:
        step = TraceStep(index=index, started_at=self._now(), feedback=list(feedback))
        stm.trace.steps.append(step)
        await self._emit(stm, "step_started", index)
        dialogue_before = len(stm.dialogue)
        place_before = stm.embodied.robot_place
        locker_before = list(stm.embodied.locker_contents)
        if self.executor.take_messages(stm):
            self._info += 1
        last = stm.trace.steps[-2].reflection if len(stm.trace.steps) > 1 else None
        ctx = AgentContext(
            ltm=self.ltm,
            stm=stm,
            resolver=self.resolver,
            step=index,
            now=self._now(),
            feedback=list(feedback),
            last_reflection=last,
        )

        try:
            step.percept = await self.reasoner.perceive(ctx)
            await self._emit(stm, "percept", index, percept=step.percept.model_dump(mode="json"))
            step.plan = await self.reasoner.plan(ctx, step.percept)
            await self._emit(stm, "plan", index, plan=step.plan.model_dump(mode="json"))
            step.decision = await self.reasoner.decide(ctx, step.percept, step.plan)
            await self._emit(stm, "decision", index, decision=step.decision.model_dump(mode="json"))
        finally:
            # the calls of an agent that raised cost as much as the others: count them
            self._account(stm, step, ctx.calls)
        accounted = len(ctx.calls)

        new_feedback = await self._execute(stm, step, step.decision.actions)

        step.observed = Observation(
            messages=[t for t in stm.dialogue[dialogue_before:] if t.direction == "in"],
            robot_place=stm.embodied.robot_place,
            moved=stm.embodied.robot_place != place_before,
            locker_contents=list(stm.embodied.locker_contents),
            locker_changed=stm.embodied.locker_contents != locker_before,
        )
        if step.observed.messages or step.observed.moved or step.observed.locker_changed:
            self._info += 1
        await self._emit(stm, "observation", index, observed=step.observed.model_dump(mode="json"))

        if stm.trace.outcome is None:
            try:
                step.reflection = await self.reasoner.reflect(
                    ctx, step.percept, step.plan, step.decision, step.results, step.observed
                )
            finally:
                self._account(stm, step, ctx.calls[accounted:])
            await self._emit(
                stm, "reflection", index, reflection=step.reflection.model_dump(mode="json")
            )
            new_feedback += self._apply_updates(stm, step, step.reflection.updates)
            if step.applied:
                await self._emit(
                    stm,
                    "memory_updated",
                    index,
                    updates=[u.model_dump(mode="json") for u in step.applied],
                )
        step.ended_at = self._now()
        if new_feedback:
            await self._emit(stm, "feedback", index, feedback=new_feedback)
        return new_feedback

    @staticmethod
    def _account(stm: ShortTermMemory, step: TraceStep, calls: list[AgentCall]) -> None:
        for call in calls:
            step.calls.append(call)
            stm.trace.usage.add(call)

    async def _execute(
        self, stm: ShortTermMemory, step: TraceStep, actions: list[Action]
    ) -> list[str]:
        feedback: list[str] = []
        keys = StepKeys(step.index)
        for proposed in actions:
            try:
                action = self.resolver.ground(proposed)
            except GroundingError as exc:
                feedback.append(f"Action {proposed.signature()} was refused: {exc}")
                await self._refuse(stm, step, proposed, str(exc))
                break
            signature = action.signature()
            refused_before = self._guard_refused.get(signature)
            if refused_before is not None and refused_before[0] == self._info:
                # The guard already refused exactly this and nothing has changed since: a
                # reasoner that neither replanned nor asked would only loop to the step limit.
                await self._end_on_refusal(stm, step, action, refused_before[1])
                break
            # Waits differ only in wording; what matters is that nothing new came in since.
            seen_key = "wait()" if isinstance(action, Wait) else signature
            if self._last_seen.get(seen_key) == self._info and not isinstance(action, Stop):
                reason = (
                    f"{signature} repeats an earlier action with no new information in "
                    "between; do something else"
                )
                feedback.append(f"Action refused: {reason}.")
                await self._refuse(stm, step, action, reason)
                break
            if isinstance(action, Stop) and action.outcome != "done":
                # Someone's item still aboard goes back (runtime.returns): the requester is
                # told so in the same words as on a cancel or a deadline.
                note = return_note(self.executor.ctx.office, stm)
                if note:
                    action = action.model_copy(update={"summary": action.summary + note})
            if isinstance(action, _BODY_ACTIONS):
                await self._take_body(stm, step, action)
            result = await self.executor.execute(stm, action, key=keys.next(action))
            self._last_seen[seen_key] = self._info
            if result.refused:
                # A refusal changes nothing in the office: it is not news that would make the
                # same action worth trying again.
                self._guard_refused[signature] = (self._info, result)
                feedback.append(
                    f"{signature} was refused: {result.observation}. Do not send it again "
                    "unchanged: ask the person concerned or the requester, choose someone "
                    "else, or stop and say why it cannot be done."
                )
            elif not result.ok:
                self._info += 1  # a failure or a timeout is news
                feedback.append(f"{signature} did not succeed: {result.observation}")
                feedback += self._note_unreachable(stm, step, action, result)
            if isinstance(action, Wait):
                # a wait's own timeout is no reason to wait again: only news from elsewhere is
                self._last_seen[seen_key] = self._info
            elif isinstance(action, Inquire) and result.ok:
                self._last_seen.pop("wait()", None)  # a new question is worth waiting for
            step.results.append(result)
            await self._emit(
                stm, "action_result", step.index, result=result.model_dump(mode="json")
            )
            if isinstance(action, Stop):
                self._close(stm, action.outcome, action.summary)
                break
            if not result.ok and not result.refused and self._failures.repeated(result):
                ctx = self.executor.ctx
                summary = failure_summary(ctx.office, stm, ctx.robot, result)
                await self._finish(stm, "failed", summary)
                break
            if not result.ok:
                break  # the rest of the decision assumed this one worked
        return feedback

    async def _end_on_refusal(
        self, stm: ShortTermMemory, step: TraceStep, action: Action, refused: ActionResult
    ) -> None:
        """End, in words, an instruction whose reasoner chose again an action the guard
        refused with nothing new since (the second try is not sent)."""
        reason = f"{action.signature()} was refused before and nothing has changed since"
        await self._refuse(stm, step, action, reason)
        logger.info("instruction %s: a refused action chosen again; ending", stm.instruction_id)
        await self._finish(
            stm, "failed", refusal_summary(self.executor.ctx.office, refused, stm.requester)
        )

    def _note_unreachable(
        self, stm: ShortTermMemory, step: TraceStep, action: Action, result: ActionResult
    ) -> list[str]:
        """A person the messenger has no way to reach is, for this office, unavailable: memory
        learns it, so planning turns to someone else instead of trying them again."""
        if result.error != UnreachableContactError.__name__:
            return []
        contact = getattr(action, "contact", None) or getattr(action, "target", None)
        if not isinstance(contact, str):
            return []
        try:
            person = self.resolver.person(contact)
        except GroundingError:
            return []  # a group: nothing to record about a person
        update = AvailabilityUpdate(
            person=person, available=False, evidence="cannot be reached by message"
        )
        return self._apply_updates(stm, step, [update])

    async def _take_body(self, stm: ShortTermMemory, step: TraceStep, action: Action) -> None:
        if self.lease.holds(stm.instruction_id):
            return

        def queued(queue: list[str]) -> None:
            step.queue = queue

        toward = action.place if isinstance(action, Move) else None
        await self.lease.acquire(stm.instruction_id, queued, toward)
        if isinstance(self.lease, FleetLease):  # the robot given may stand anywhere
            stm.embodied.robot_place = self.executor.ctx.robot.state().place
        if step.queue:
            await self._emit(stm, "queued", step.index, queue=step.queue)

    async def _refuse(
        self, stm: ShortTermMemory, step: TraceStep, action: Action, reason: str
    ) -> None:
        """Record ``action`` as refused in the step, and tell the event stream."""
        now = self._now()
        result = ActionResult(
            action=action,
            ok=False,
            observation=f"refused: {reason}",
            refused=True,
            error="refused",
            started_at=now,
            ended_at=now,
        )
        step.results.append(result)
        await self._emit(stm, "action_result", step.index, result=result.model_dump(mode="json"))

    def _apply_updates(
        self, stm: ShortTermMemory, step: TraceStep, updates: list[MemoryUpdate]
    ) -> list[str]:
        feedback: list[str] = []
        for update in updates:
            try:
                grounded = self.resolver.ground_update(update)
            except (GroundingError, KeyError) as exc:
                feedback.append(f"Memory update {update.model_dump()} was rejected: {exc}")
                continue
            applied: AppliedUpdate = self.ltm.apply(grounded, self._now(), stm.instruction_id)
            step.applied.append(applied)
            if applied.changed:
                self._info += 1
        return feedback

    # -- ending --------------------------------------------------------------------------
    def _close(self, stm: ShortTermMemory, outcome: Outcome, summary: str) -> None:
        trace = stm.trace
        trace.outcome = outcome
        trace.summary = summary
        trace.ended_at = self._now()

    async def _finish(
        self, stm: ShortTermMemory, outcome: Outcome, summary: str, *, detail: str | None = None
    ) -> None:
        """End without the reasoner's Stop, telling the requester (never raises); ``detail``
        (the technical cause, for the operator) goes in the final step's feedback."""
        if stm.trace.outcome is None:
            if outcome != "done":  # someone's item still aboard goes back (runtime.returns)
                summary += return_note(self.executor.ctx.office, stm)
            stop = Stop(outcome=outcome, summary=summary)
            try:
                result = await self.executor.execute(stm, stop, key="final")
                stm.trace.steps.append(
                    TraceStep(
                        index=len(stm.trace.steps),
                        started_at=result.started_at,
                        ended_at=result.ended_at,
                        results=[result],
                        feedback=[detail] if detail else [],
                    )
                )
            except Exception:
                logger.exception("could not tell %s the outcome", stm.requester)
            self._close(stm, outcome, summary)


def _in_words(exc: AssistantXError) -> str:
    """Why an instruction broke off, for the requester: the details (addresses, ids) are in
    the log, not in the message."""
    match exc:
        case RobotError():
            return "the robot could not get where it had to go"
        case LockError():
            return "the robot's locker did not respond as it should"
        case MessengerError():
            return "I could not send a message I needed to send"
        case LLMError() | ReasonerError():
            return "my reasoning model did not give a usable answer"
        case GroundingError():
            return "I could not tell who or what was meant"
    return f"an internal problem ({type(exc).__name__})"
