"""Executors: turn grounded actions into adapter calls and return typed results.

They update short-term memory (dialogue, embodied state, files received) with what they saw;
long-term memory changes are Reflection's job. Every message carries a stable idempotency key
(instruction, step, the action itself: ``runtime.action_keys``), so a resumed instruction never
sends a message twice, and the code a send minted is journaled under that key before it goes
out (``CodeRecords``), so a replayed send re-uses it instead of handing the person a second.
"""

from __future__ import annotations

import asyncio
import logging
from collections.abc import Awaitable, Callable
from dataclasses import dataclass
from typing import Literal, Protocol

from assistantx.core.actions import (
    Action,
    ForwardFile,
    Inform,
    Inquire,
    Move,
    SendQR,
    Stop,
    Wait,
    WaitInPlace,
)
from assistantx.core.clock import Clock
from assistantx.core.dialogue import DialogueTurn
from assistantx.core.errors import AdapterError, LockCommandError
from assistantx.core.office import Office
from assistantx.core.ports.lock import Locker, LockEvent
from assistantx.core.ports.messenger import (
    Attachment,
    ChatRef,
    InboundMessage,
    Messenger,
    OutboundMessage,
)
from assistantx.core.ports.robot import RobotBase
from assistantx.core.trace import ActionResult
from assistantx.core.wording import item_phrase, person_name, purpose_text
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.short_term import IssuedCode, ShortTermMemory
from assistantx.runtime import consent
from assistantx.runtime.doors import drive_past_closed_doors
from assistantx.runtime.failures import place_name
from assistantx.runtime.received_files import received_files
from assistantx.runtime.replies import ReplyBox

logger = logging.getLogger(__name__)


@dataclass(frozen=True)
class EarlierCode:
    """A code minted under an idempotency key before a restart, and whether its message is
    known to have gone out."""

    code_id: str
    delivered: bool


class CodeRecords(Protocol):
    """Where the code minted under each send's idempotency key is journaled before the send
    (the service's ``CodeLedger``), so a replayed step re-uses it instead of minting another."""

    def earlier(self, key: str) -> EarlierCode | None: ...

    async def minted(self, key: str, code_id: str) -> None: ...


@dataclass
class ExecutionContext:
    office: Office
    ltm: LongTermMemory
    messenger: Messenger
    robot: RobotBase
    locker: Locker
    clock: Clock
    replies: ReplyBox
    # Records codes as revoked before the lock is asked to withdraw them (the service's
    # journal), so a crash in between cannot bring them back; None: nothing to record.
    retire_codes: Callable[[list[str]], Awaitable[None]] | None = None
    # None: nothing journals the codes minted per key (a replayed send mints a new one).
    code_records: CodeRecords | None = None


class Executor:
    def __init__(self, ctx: ExecutionContext) -> None:
        self.ctx = ctx
        # Results journaled before a restart, by "<instruction>:<key>": a resumed step that
        # decides the same action at the same position gets the result, not a second effect.
        self.replay: dict[str, ActionResult] = {}
        # Lock events watched from the moment a code goes out, per instruction: the person may
        # scan it before the instruction reaches its wait_in_place (the loop serves others in
        # between), and that scan must not be missed.
        self._watching: dict[str, tuple[asyncio.Queue[LockEvent], asyncio.Event]] = {}

    def forget(self, instruction_id: str) -> None:
        """The instruction ended: stop watching the lock for it."""
        watched = self._watching.pop(instruction_id, None)
        if watched is not None:
            self.ctx.locker.unsubscribe(watched[0])

    async def execute(self, stm: ShortTermMemory, action: Action, key: str) -> ActionResult:
        """Run one grounded action; ``key`` is its stable id (instruction:step:position)."""
        recorded = self.replay.pop(f"{stm.instruction_id}:{key}", None)
        if recorded is not None and recorded.action.signature() == action.signature():
            return recorded
        started = self.ctx.clock.now()
        refusal = consent.check(self.ctx.office, stm, action)
        if refusal is not None:
            # Refused, whichever reasoner chose it: the agent reads why and what to do instead.
            logger.info("action %s refused (%s): %s", action.type, refusal.rule, refusal.reason)
            return ActionResult(
                action=action,
                ok=False,
                observation=f"refused: {refusal.reason}",
                refused=True,
                error=refusal.rule,
                started_at=started,
                ended_at=started,
            )
        try:
            ok, observation, data = await self._run(stm, action, key)
            error = None
        except AdapterError as exc:
            logger.warning("action %s failed: %s", action.type, exc)
            ok, observation, data, error = False, f"failed: {exc}", {}, type(exc).__name__
        return ActionResult(
            action=action,
            ok=ok,
            observation=observation,
            error=error,
            started_at=started,
            ended_at=self.ctx.clock.now(),
            data=data,
        )

    async def _run(
        self, stm: ShortTermMemory, action: Action, key: str
    ) -> tuple[bool, str, dict[str, object]]:
        match action:
            case Inform():
                await self._send(stm, _chat(self.ctx.office, action.contact), action.content, key)
                return True, f"told {action.contact}", {}
            case Inquire():
                chat = _chat(self.ctx.office, action.contact)
                qid = f"{stm.instruction_id}:{key}"
                self.ctx.replies.ask(qid, stm.instruction_id, chat, self.ctx.clock.now())
                await self._send(stm, chat, action.question, key, question_id=qid)
                return (
                    True,
                    f"asked {action.contact}; the reply will arrive in the dialogue",
                    {"question_id": qid},
                )
            case ForwardFile():
                return await self._forward(stm, action, key)
            case SendQR():
                return await self._send_qr(stm, action, key)
            case Wait():
                return await self._wait(stm, action)
            case Move():

                async def tell(text: str) -> None:
                    await self.tell_requester(stm, text, key=f"{key}:door")

                name = place_name(self.ctx.office, action.place)
                result = await drive_past_closed_doors(
                    self.ctx.robot, action.place, self.ctx.clock, tell, name
                )
                stm.embodied.robot_place = result.place
                return (
                    True,
                    f"arrived at {result.place} ({result.distance_m:.1f} m)",
                    {
                        "distance_m": result.distance_m,
                        "duration_s": result.duration_s,
                    },
                )
            case WaitInPlace():
                return await self._wait_in_place(stm, action)
            case Stop():
                text = f"[{action.outcome}] {action.summary}"
                await self._send(stm, ChatRef(kind="dm", id=stm.requester), text, key)
                return True, f"stopped with {action.outcome}; {stm.requester} was told", {}
        raise TypeError(f"unknown action {action!r}")  # pragma: no cover

    async def tell_requester(self, stm: ShortTermMemory, text: str, key: str) -> None:
        """A note to the requester outside any action (e.g. that a claimed authority does not
        count); it goes into the dialogue like every message."""
        await self._send(stm, ChatRef(kind="dm", id=stm.requester), text, key)

    # -- messaging -----------------------------------------------------------------------
    async def _send(
        self,
        stm: ShortTermMemory,
        chat: ChatRef,
        text: str,
        key: str,
        *,
        question_id: str | None = None,
        attachments: list[Attachment] | None = None,
    ) -> None:
        message = OutboundMessage(
            chat=chat,
            text=text,
            attachments=attachments or [],
            instruction_id=stm.instruction_id,
            question_id=question_id,
            idempotency_key=f"{stm.instruction_id}:{key}",
        )
        await self.ctx.messenger.send(message)
        if chat != ChatRef(kind="dm", id=stm.requester):
            # The requester's unprompted messages are new instructions, not chatter about this.
            self.ctx.replies.engage(stm.instruction_id, chat)
        stm.dialogue.append(
            DialogueTurn(
                time=self.ctx.clock.now(),
                direction="out",
                chat=chat,
                person=chat.id,
                text=text,
                question_id=question_id,
                files=[a.item for a in message.attachments if a.item and a.kind == "file"],
            )
        )

    async def _forward(
        self, stm: ShortTermMemory, action: ForwardFile, key: str
    ) -> tuple[bool, str, dict[str, object]]:
        file = action.file or self.ctx.office.file_of(action.source)
        have = set(stm.files_received.get(action.source, []))
        if action.source == stm.requester:
            # sent along with the instruction: the requester's file, of the type named
            have.add(self.ctx.office.file_of(stm.requester, file.partition(":")[0]))
        if file not in have:
            return (
                False,
                (
                    f"no file {file} received from {action.source}; ask {action.source} to send "
                    "it first"
                ),
                {},
            )
        office = self.ctx.office
        # What the reader sees names people and items; the attachment's ``item`` keeps the id.
        you = action.target
        what = item_phrase(office, file, you=you)
        attachment = Attachment(kind="file", name=f"{_file_name(what)}.pdf", item=file)
        source = person_name(office, action.source, you=you)
        owner = file.partition(":")[2]
        # "Mao Jun's file from Mao Jun" says the name twice: the owner's name is the source.
        text = (
            f"Forwarding {what}." if owner == action.source else f"Forwarding {what} from {source}."
        )
        chat = _chat(office, action.target)
        await self._send(stm, chat, text, key, attachments=[attachment])
        return True, f"forwarded {file} to {action.target}", {"file": file}

    async def _send_qr(
        self, stm: ShortTermMemory, action: SendQR, key: str
    ) -> tuple[bool, str, dict[str, object]]:
        records = self.ctx.code_records
        message_key = f"{stm.instruction_id}:{key}"
        earlier = records.earlier(message_key) if records is not None else None
        todo = purpose_text(
            self.ctx.office,
            action.purpose,
            action.item,
            you=action.contact,
            operation=action.operation,
            destination=action.destination,
            send_to=action.send_to,
        )
        if earlier is not None and earlier.delivered:
            # Sent before a crash cut this step short: the person holds that code, and it is
            # the one to wait for (a new one would be a second code in their hands). Not
            # watched from here: they may have used it already, while no one watched, which
            # the wait reads from what the lock reported (``_used_unseen``).
            self._hold(stm, action, earlier.code_id)
            logger.info("code of %s was sent before; not minted again", message_key)
            return (
                True,
                f"sent {action.contact} a one-time code to {todo}",
                {"code_id": earlier.code_id},
            )
        if earlier is not None:
            # Minted, its message not known to have gone out: withdrawn before a new one goes
            # out under the same key, so at most one code of this send ever opens the locker.
            await self._withdraw([earlier.code_id])
        held = stm.embodied.unused_code(
            action.contact, action.item, action.purpose, self.ctx.locker.code_states
        )
        if held is not None:
            return (
                False,
                (
                    f"{action.contact} already holds an unused QR code for {action.purpose} "
                    f"{action.item}; never resend the same QR code"
                ),
                {},
            )
        taken = self._taken_from(stm, action)
        if taken is not None:
            return False, taken, {"taken": True}
        self._watch(stm)
        qr = await self.ctx.locker.issue_code(
            instruction_id=stm.instruction_id,
            person=action.contact,
            purpose=action.purpose,
            item=action.item,
        )
        if records is not None:
            await records.minted(message_key, qr.code_id)  # journaled before it goes out
        text = (
            f"Here is your one-time code for the robot's locker: scan it at the robot to {todo}. "
            f"It works once and expires in {round((qr.expires_at - qr.issued_at) / 60)} minutes."
        )
        attachment = Attachment(
            kind="image",
            name="locker-code.png",
            mime="image/png",
            data=qr.png,
            item=action.item,
            qr_payload=qr.payload,
            qr_purpose=action.purpose,
        )
        await self._send(
            stm, ChatRef(kind="dm", id=action.contact), text, key, attachments=[attachment]
        )
        self._hold(stm, action, qr.code_id)
        return True, f"sent {action.contact} a one-time code to {todo}", {"code_id": qr.code_id}

    def _taken_from(self, stm: ShortTermMemory, action: SendQR) -> str | None:
        """Why no deposit code goes to the owner of ``action``'s item: memory knows another
        instruction took it after this instruction last heard from them (two instructions
        asked them at nearly the same time, both heard yes, and the other one's hand-over came
        first: a code would ask for an item they no longer have). None: send the code."""
        owner = action.item.partition(":")[2]
        if action.purpose != "deposit" or action.contact != owner:
            return None
        taken = self.ctx.ltm.taken_by_another(action.item, stm.instruction_id)
        if taken is None:
            return None
        heard = [t.time for t in stm.dialogue if t.direction == "in" and t.person == owner]
        if heard and max(heard) > taken.time:
            return None  # they wrote since: what they said is newer than memory
        thing = item_phrase(self.ctx.office, action.item)
        return f"{thing} was taken for another errand; no code sent to {action.contact}"

    def _watch(self, stm: ShortTermMemory) -> None:
        if stm.instruction_id not in self._watching:
            notify = asyncio.Event()
            self._watching[stm.instruction_id] = (self.ctx.locker.subscribe(notify), notify)

    @staticmethod
    def _hold(stm: ShortTermMemory, action: SendQR, code_id: str) -> None:
        stm.embodied.codes.append(
            IssuedCode(
                code_id=code_id, person=action.contact, item=action.item, purpose=action.purpose
            )
        )

    async def revoke_codes(self, stm: ShortTermMemory, *, person: str | None = None) -> int:
        """Withdraw at the lock this instruction's unused codes (only ``person``'s, if given);
        returns how many the lock revoked."""
        revoked = 0
        doomed = [
            code
            for code in stm.embodied.codes
            if code.unused(self.ctx.locker.code_states)
            and (person is None or code.person == person)
        ]
        withdrawn = await self._withdraw([code.code_id for code in doomed])
        for code in doomed:
            if code.code_id in withdrawn:
                code.revoked = True
                revoked += 1
        return revoked

    async def _withdraw(self, code_ids: list[str]) -> set[str]:
        """Journal ``code_ids`` as revoked, then revoke them at the lock; those withdrawn."""
        if code_ids and self.ctx.retire_codes is not None:
            await self.ctx.retire_codes(code_ids)
        withdrawn: set[str] = set()
        for code_id in code_ids:
            try:
                await self.ctx.locker.revoke(code_id)
            except LockCommandError as exc:
                # The lock has no such active code (expired, or forgotten by a lock that
                # restarted): it opens nothing, which is what "revoked" means to the reader.
                logger.info("code %s not active at the lock: %s", code_id, exc)
            except AdapterError as exc:
                # The lock unreachable: still open there (the next start withdraws it).
                logger.info("code %s not revoked: %s", code_id, exc)
                continue
            withdrawn.add(code_id)
        return withdrawn

    # -- waiting -------------------------------------------------------------------------
    def take_messages(self, stm: ShortTermMemory) -> list[InboundMessage]:
        """Move messages that arrived for this instruction into its dialogue."""
        messages = self.ctx.replies.take(stm.instruction_id)
        for m in messages:
            files = received_files(self.ctx.office, m)
            if files:
                stm.files_received.setdefault(m.sender, []).extend(files)
            stm.dialogue.append(
                DialogueTurn(
                    time=m.time.timestamp(),
                    direction="in",
                    chat=m.chat,
                    person=m.sender,
                    text=m.text,
                    in_reply_to=m.in_reply_to,
                    files=files,
                    event_id=m.event_id,
                )
            )
        return messages

    async def _wait(
        self, stm: ShortTermMemory, action: Wait
    ) -> tuple[bool, str, dict[str, object]]:
        event = self.ctx.replies.event(stm.instruction_id)
        got = await self.ctx.clock.wait_event(event, action.timeout_s)
        messages = self.take_messages(stm) if got else []
        if not messages:
            return False, f"no reply within {action.timeout_s:.0f} s", {"timed_out": True}
        said = "; ".join(f"{m.sender} said {m.text!r}" for m in messages)
        return True, said, {"replies": [m.sender for m in messages]}

    async def _wait_in_place(
        self, stm: ShortTermMemory, action: WaitInPlace
    ) -> tuple[bool, str, dict[str, object]]:
        watched = self._watching.pop(stm.instruction_id, None)
        done_unseen = self._used_unseen(stm, action.person) if watched is None else []
        if done_unseen:
            # The lock reported the hand-over while no one watched (before a restart): it
            # happened, and waiting for it again would only time out and send a new code.
            for code in done_unseen:
                code.scanned = code.used = True
                _apply_to_locker(self.ctx.office, stm, code)
            stm.embodied.door = "closed"
            kinds = ["code_accepted", "door_closed"]
            return True, f"{action.person} used the locker ({', '.join(kinds)})", {"events": kinds}
        if watched is None:
            notify = asyncio.Event()
            queue = self.ctx.locker.subscribe(notify)
        else:
            queue, notify = watched
        events: list[LockEvent] = []
        deadline = self.ctx.clock.timer() + action.timeout_s
        try:
            while True:
                while not queue.empty():
                    events.append(queue.get_nowait())
                mine = [e for e in events if e.person == action.person]
                if any(e.kind == "door_closed" for e in mine):
                    break
                opened = any(e.kind == "code_accepted" for e in mine)
                # A rejected scan ends the wait unless the door is already open for them (a
                # second scan of the used code while they put the item in changes nothing).
                if not opened and any(e.kind == "code_rejected" for e in mine):
                    break
                if self.ctx.replies.event(stm.instruction_id).is_set():
                    arrived = self.take_messages(stm)
                    if any(m.sender == action.person for m in arrived):
                        break  # the person wrote instead of coming (e.g. "I don't have it")
                remaining = deadline - self.ctx.clock.timer()
                if remaining <= 0:
                    break
                notify.clear()
                await self.ctx.clock.wait_event(
                    _either(notify, self.ctx.replies.event(stm.instruction_id)), remaining
                )
        finally:
            self.ctx.locker.unsubscribe(queue)
        self.take_messages(stm)
        mine = [e for e in events if e.person == action.person]
        closed = any(e.kind == "door_closed" for e in mine)
        kinds = [e.kind for e in mine]
        accepted = {e.code_id for e in mine if e.kind == "code_accepted"}
        for code in stm.embodied.codes:
            if code.code_id in accepted:
                code.scanned = True
        # On the clock the deadline was set on (simulated seconds): the result's timestamps
        # are wall time, so at a speed-up their difference cannot tell a full wait apart.
        timed_out = not mine and self.ctx.clock.timer() >= deadline
        if timed_out:
            # The person's codes must not open the locker after the robot left.
            await self.revoke_codes(stm, person=action.person)
        if closed:
            for code in stm.embodied.codes:
                if any(e.code_id == code.code_id for e in mine):
                    code.used = True
                    _apply_to_locker(self.ctx.office, stm, code)
            stm.embodied.door = "closed"
            return True, f"{action.person} used the locker ({', '.join(kinds)})", {"events": kinds}
        rejected = [e.reason for e in mine if e.kind == "code_rejected"]
        if rejected:
            return False, f"{action.person}'s code was rejected: {rejected[0]}", {"events": kinds}
        data: dict[str, object] = {"events": kinds}
        if timed_out:
            data["timed_out"] = True
        return False, f"{action.person} did not come to the locker", data

    def _used_unseen(self, stm: ShortTermMemory, person: str) -> list[IssuedCode]:
        """``person``'s codes the lock reported used that this instruction never saw used."""
        reported = self.ctx.locker.code_states
        return [
            code
            for code in stm.embodied.codes
            if code.person == person
            and code.state in ("issued", "scanned")
            and reported.get(code.code_id) == "used"
        ]


class _EitherEvent(asyncio.Event):
    """An event that counts as set when either of two events is set."""

    def __init__(self, a: asyncio.Event, b: asyncio.Event) -> None:
        super().__init__()
        self._a, self._b = a, b

    def is_set(self) -> bool:
        return self._a.is_set() or self._b.is_set()

    async def wait(self) -> Literal[True]:
        waiters = [asyncio.ensure_future(self._a.wait()), asyncio.ensure_future(self._b.wait())]
        try:
            await asyncio.wait(waiters, return_when=asyncio.FIRST_COMPLETED)
        finally:
            for w in waiters:
                w.cancel()
        return True


def _either(a: asyncio.Event, b: asyncio.Event) -> asyncio.Event:
    return _EitherEvent(a, b)


def _apply_to_locker(office: Office, stm: ShortTermMemory, code: IssuedCode) -> None:
    contents = stm.embodied.locker_contents
    if code.purpose in ("deposit", "produce") and code.item not in contents:
        contents.append(code.item)
    elif code.purpose == "collect" and code.item in contents:
        contents.remove(code.item)
    elif code.purpose == "copy":
        item_type, _, owner = code.item.partition(":")
        product = office.made_from(item_type)  # what the office's operation makes of it
        if product is not None and f"{product}:{owner}" not in contents:
            contents.append(f"{product}:{owner}")


def _file_name(phrase: str) -> str:
    """The phrase with anything a file system or chat client may choke on replaced."""
    return "".join(c if c.isalnum() or c in " -'" else "_" for c in phrase).strip() or "file"


def _chat(office: Office, contact: str) -> ChatRef:
    if any(g.id == contact for g in office.groups):
        return ChatRef(kind="group", id=contact)
    return ChatRef(kind="dm", id=contact)
