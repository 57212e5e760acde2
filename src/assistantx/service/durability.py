"""What the service journals as instructions run, and how it resumes them after a restart.

Every trace event is journaled; with ``step_started`` and ``action_result`` the instruction's
short-term memory is checkpointed together with the simulated world, in one transaction.
Long-term memory is journaled incrementally: each applied update is one row of
``memory_updates`` (with the event that applied it), and the graph is snapshotted only every
``SNAPSHOT_EVERY`` updates and on shutdown, stamped with the last update row it holds; on
start-up the updates after that stamp are applied again (``restore_memory``). On
start-up an instruction that was running resumes from its checkpoint: the step that was cut
short runs again under the same step index, and an action's idempotency key comes from that
index and the action itself (``runtime.action_keys``), so the same action gets the same key
wherever it stands in the new decision; actions whose results were journaled are replayed (not
executed again), sends whose key is journaled as sent are answered from the journal by the
built-in messenger, and a code whose key is journaled is not minted again (``CodeLedger``).
Questions asked before the restart are registered again, and replies that arrived meanwhile
are delivered.
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from typing import Any

from assistantx.core.events import TraceEvent
from assistantx.core.office import Office
from assistantx.core.ports.messenger import ChatRef, InboundMessage
from assistantx.core.trace import ActionResult
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.short_term import ShortTermMemory
from assistantx.memory.updates import AppliedUpdate
from assistantx.runtime.action_keys import StepKeys
from assistantx.runtime.assistant import Assistant
from assistantx.service.give_back import GiveBacks
from assistantx.service.hub import EventHub
from assistantx.service.telemetry import ServiceMetrics
from assistantx.store.journal import EventRecord, InstructionRecord, Journal, Status

logger = logging.getLogger(__name__)

LTM_STATE = "long_term_memory"
SNAPSHOT_EVERY = 256  # memory updates between two snapshots of the long-term memory graph

_OUTCOME_STATUS: dict[str, Status] = {
    "done": "done",
    "failed": "failed",
    "unachievable": "unachievable",
}


class Durability:
    def __init__(
        self,
        journal: Journal,
        assistant: Assistant,
        hub: EventHub,
        metrics: ServiceMetrics,
        world_state: Callable[[], dict[str, dict[str, Any]]],
    ) -> None:
        self.journal = journal
        self.assistant = assistant
        self.hub = hub
        self.metrics = metrics
        self._world_state = world_state
        self.cancelled: set[str] = set()
        self.give_backs = GiveBacks(journal, assistant.office)
        self.frozen = False  # set on shutdown: what happens after is not journaled
        self._snapshot_at = assistant.ltm.applied_total  # updates held by the last snapshot
        self._world_sent: dict[str, dict[str, Any]] | None = None  # the last world journaled

    def attach(self) -> None:
        self.assistant.subscribe(self.on_event)
        self.assistant.on_instruction_start(self.on_start)
        self.assistant.on_instruction_end(self.on_end)
        self.assistant.on_give_back_end(self.on_given_back)

    # -- recording -----------------------------------------------------------------------
    async def on_start(self, stm: ShortTermMemory) -> None:
        if self.frozen:
            return
        # Started from a message, its first row; else journaled by the REST submit or resumed.
        # The checkpoint only updates a row with the same id and requester: a taken id raises.
        await self.journal.acheckpoint(stm, "running")

    async def on_event(self, event: TraceEvent) -> None:
        if self.frozen:
            return
        stm = self.assistant.get(event.instruction_id)
        status: Status | None = None
        checkpoint: ShortTermMemory | None = None
        states: dict[str, dict[str, Any]] = {}
        updates: list[dict[str, Any]] = []
        match event.kind:
            case "step_started" | "action_result":
                checkpoint, status = stm, "running"
                states = self._world_if_changed()
                if event.kind == "step_started" and stm is not None and len(stm.trace.steps) > 1:
                    self.metrics.step_completed(stm.trace.steps[-2])
                if event.kind == "action_result":
                    self._count_failure(event.data.get("result", {}))
            case "queued":
                status = "queued"
            case "memory_updated":
                updates = list(event.data.get("updates", []))
            case "instruction_ended":
                if stm is not None:
                    # Before the end is journaled: a finished instruction's codes are revoked
                    # in the journal that says it finished, never after it (a crash between
                    # the two would leave them open after a restart).
                    await self._revoke_codes(stm)
                checkpoint, status = stm, self._final_status(event.instruction_id, stm)
                states = self._world_if_changed()
                if stm is not None:  # owing a give-back is journaled with the end
                    states |= self.give_backs.on_end(stm)
                if stm is not None and stm.trace.steps:
                    self.metrics.step_completed(stm.trace.steps[-1])
            case _:
                pass
        try:
            seq = await self.journal.arecord(
                event, stm=checkpoint, status=status, states=states, memory_updates=updates
            )
        except BaseException:
            if states:  # not written: the next checkpoint writes the world again
                self._world_sent = None
            raise
        self.hub.publish(EventRecord(seq=seq, event=event))
        if self.assistant.ltm.applied_total - self._snapshot_at >= SNAPSHOT_EVERY:
            await self.snapshot_memory()

    async def _revoke_codes(self, stm: ShortTermMemory) -> None:
        try:
            await self.assistant.executor.revoke_codes(stm)
        except Exception:  # the lock unreachable: the next start withdraws them (code_recovery)
            logger.exception("could not revoke the codes of %s", stm.instruction_id)

    def _world_if_changed(self) -> dict[str, dict[str, Any]]:
        """The simulated world for this checkpoint, or nothing when it is the one journaled
        last: most checkpoints (a step of an instruction waiting for the robot or a reply)
        change nothing, and encoding and writing the whole world at each of them was a fifth
        of the loop's time with 200 instructions running. The journal keeps the latest state
        per name, so an unchanged world is already there, committed in order before this."""
        world = self._world_state()
        if world == self._world_sent:
            return {}
        self._world_sent = world
        return world

    async def snapshot_memory(self) -> None:
        """Snapshot the graph (bounded: one value per fact, a bounded history)."""
        self._snapshot_at = self.assistant.ltm.applied_total
        await self.journal.aput_memory_snapshot(LTM_STATE, self.assistant.ltm.snapshot())

    async def on_given_back(self, instruction_id: str) -> None:
        """The give-back errand of ``instruction_id`` is over: settled, with the world it left."""
        if not self.frozen:
            await self.journal.aput_states(
                self.give_backs.settle(instruction_id) | self._world_if_changed()
            )

    async def resume_give_backs(self, in_locker: set[str]) -> list[str]:
        """Start again the give-back errands a restart cut short; their ids."""
        resumed = self.give_backs.to_resume(in_locker)
        await self.journal.aput_states(self.give_backs.state())  # the attempts, before acting
        for stm, attempt in resumed:
            self.assistant.give_back(stm, attempt=attempt)
            logger.info("resumed giving back what %s left in the locker", stm.instruction_id)
        return [stm.instruction_id for stm, _ in resumed]

    async def on_end(self, stm: ShortTermMemory) -> None:
        if not self.frozen:
            await self.journal.acheckpoint(stm, self._final_status(stm.instruction_id, stm))

    def _final_status(self, instruction_id: str, stm: ShortTermMemory | None) -> Status:
        if instruction_id in self.cancelled:
            return "cancelled"
        outcome = stm.trace.outcome if stm is not None else None
        return _OUTCOME_STATUS.get(outcome or "failed", "failed")

    def _count_failure(self, result: dict[str, Any]) -> None:
        error = result.get("error")
        if error and not result.get("refused"):
            self.metrics.action_failed(str(error))

    # -- resuming ------------------------------------------------------------------------
    @staticmethod
    def restore_memory(journal: Journal, office: Office) -> LongTermMemory | None:
        """The journaled long-term memory: its last snapshot and the updates after it."""
        snapshot = journal.state(LTM_STATE)
        later = journal.memory_updates_after(int((snapshot or {}).get("through", 0)))
        if snapshot is None and not later:
            return None
        ltm = LongTermMemory.restore(office, snapshot) if snapshot else LongTermMemory(office)
        # A snapshot written before it was stamped already holds every update journaled.
        for body in later if snapshot is None or "through" in snapshot else []:
            ltm.replay(AppliedUpdate.model_validate(body))
        return ltm

    def prepare_resume(self, record: InstructionRecord) -> ShortTermMemory:
        """The checkpointed memory with the cut-short step removed, its results set to replay."""
        assert record.stm is not None
        stm = record.stm.model_copy(deep=True)
        steps = stm.trace.steps
        while steps and steps[-1].ended_at is None:
            cut = steps.pop()
            keys = StepKeys(cut.index)  # the keys the loop gave these actions, in order
            for result in cut.results:
                key = keys.next(result.action)
                if not result.refused:
                    self._replay(stm.instruction_id, key, result)
        replies = self.assistant.replies
        asked: dict[str, float] = {}
        answered = {t.in_reply_to for t in stm.dialogue if t.direction == "in" and t.in_reply_to}
        for turn in stm.dialogue:
            if turn.direction != "out":
                continue
            if turn.question_id:
                replies.ask(
                    turn.question_id,
                    stm.instruction_id,
                    turn.chat,
                    turn.time,
                    answered=turn.question_id in answered,
                )
                asked[turn.question_id] = turn.time
            if turn.chat != ChatRef(kind="dm", id=stm.requester):
                # Where it wrote, in the order it wrote: a word there after the restart goes
                # to the instruction that wrote last, as it did before (``ReplyBox.route``).
                replies.engage(stm.instruction_id, turn.chat, turn.time)
        self._redeliver(stm, asked)
        return stm

    def _replay(self, instruction_id: str, key: str, result: ActionResult) -> None:
        self.assistant.executor.replay[f"{instruction_id}:{key}"] = result

    def _redeliver(self, stm: ShortTermMemory, asked: dict[str, float]) -> None:
        """Replies journaled before the restart that never reached the instruction's memory."""
        seen = {t.event_id for t in stm.dialogue if t.event_id}
        for record in self.journal.messages_of(stm.instruction_id):
            if record.direction != "in" or record.in_reply_to not in asked:
                continue
            message = InboundMessage.model_validate(record.body)
            if message.event_id not in seen:
                self.assistant.replies.deliver(stm.instruction_id, message)
