"""The simulated office: the world's truth plus simulated messenger, robot base and locker.

It implements the same adapter interfaces as the real messenger, navigator and smart lock,
so the PPDR loop cannot tell it from the real office. People answer after ``reply_delay_s``
and come to the locker ``handover_delay_s`` after the robot stands at their place with a
code for them; both run on the clock (a SimClock makes them instant in real time).
"""

from __future__ import annotations

import asyncio
import functools
import hashlib
import itertools
import logging
import uuid
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from datetime import UTC, datetime
from typing import Any, Protocol, runtime_checkable

from assistantx.adapters.lock.protocol.keys import Keyring
from assistantx.core.clock import Clock, SimClock
from assistantx.core.errors import LockError
from assistantx.core.office import Office
from assistantx.core.ports.lock import Locker, LockEvent
from assistantx.core.ports.messenger import (
    Attachment,
    ChatRef,
    InboundMessage,
    Messenger,
    OutboundMessage,
    SentMessage,
)
from assistantx.core.ports.robot import RobotBase
from assistantx.sim.lent_back import lent_to_requester
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.local import LocalLocker
from assistantx.sim.people import Reply, direct_reply, group_replies, handover_problem
from assistantx.sim.people import perform_handover as do_handover
from assistantx.sim.requester import Wish
from assistantx.sim.requester import answer as requester_answer
from assistantx.sim.robot import DistanceFn, ObservedRobot, SimRobot
from assistantx.sim.world import World

__all__ = ["HandOverDesk", "HeldCode", "SimMessenger", "SimOffice", "SimRobot"]

logger = logging.getLogger(__name__)

# What a long-running simulation keeps of its history (messages, ended instructions): a
# service runs it for months; an evaluation episode never comes near the bound. Small enough
# that a service reaches it within its first few hundred instructions: at 2,000 the messages
# (about 2.9 KB each), the ended ids and their wishes grew for the first 1,500-4,000
# instructions, a tenth of the process's memory (bench/instructions_10k.py).
KEEP = 256


def _trim(history: list[Any], keep: int = KEEP) -> None:
    """Drop the oldest entries once there are twice ``keep`` (amortised O(1) per append)."""
    if len(history) > 2 * keep:
        del history[:-keep]


@runtime_checkable
class HandOverDesk(Protocol):
    """What simulated people do at a locker (``LocalLocker`` and ``TcpLocker`` offer it)."""

    async def simulate_scan(self, payload: str) -> LockEvent: ...

    async def simulate_close(self) -> LockEvent: ...


@dataclass
class HeldCode:
    """A QR code in a simulated person's hands."""

    instruction_id: str
    person: str
    payload: str
    purpose: str
    item: str
    told: str = ""  # the message the code came with: what it asks them to do ("scan it")
    scheduled: bool = False
    done: bool = False
    # They came with it and could not do the hand-over, and said so: they come again only
    # once they can (a person does not walk to the robot to say the same thing twice).
    complained: bool = False


class SimMessenger(Messenger):
    platform = "sim"

    def __init__(self, office_sim: SimOffice) -> None:
        super().__init__()
        self._sim = office_sim
        self._ids = itertools.count(1)
        # A messenger names each message once and for all: a service that restarts or
        # whose office another replica takes over journals what people write by these ids
        # and ignores an id it has seen (a platform's retry). Counted from 1 in each process
        # alone, the replies after a takeover reused the previous process's ids and were
        # dropped as duplicates: the colleague "did not answer" (bench/failover.py).
        self._run = uuid.uuid4().hex[:12]
        self.sent: list[OutboundMessage] = []
        self.received: list[InboundMessage] = []
        self._seen_keys: dict[str, SentMessage] = {}

    async def send(self, message: OutboundMessage) -> SentMessage:
        if message.idempotency_key and message.idempotency_key in self._seen_keys:
            return self._seen_keys[message.idempotency_key]
        self.sent.append(message)
        _trim(self.sent)
        sent = SentMessage(
            platform=self.platform,
            message_id=f"sim-{next(self._ids)}",
            chat=message.chat,
            time=self._sim.timestamp(),
        )
        if message.idempotency_key:
            self._seen_keys[message.idempotency_key] = sent
            if len(self._seen_keys) > 2 * KEEP:  # the oldest keys belong to long-ended runs
                self._seen_keys = dict(list(self._seen_keys.items())[-KEEP:])
        self._sim.on_message(message)
        return sent

    def post(
        self,
        person: str,
        chat: ChatRef,
        text: str,
        *,
        files: Iterable[str] = (),
        in_reply_to: str | None = None,
    ) -> InboundMessage:
        """A simulated person writes to the assistant (used by people and by the CLI)."""
        inbound = InboundMessage(
            platform=self.platform,
            event_id=f"sim-in-{self._run}-{next(self._ids)}",
            chat=chat,
            sender=person,
            text=text,
            attachments=[Attachment(kind="file", name=f"{f}.pdf", item=f) for f in files],
            time=self._sim.timestamp(),
            in_reply_to=in_reply_to,
        )
        self.received.append(inbound)
        _trim(self.received)
        if self._inbox is not None:
            self._inbox.put_nowait(inbound)
        return inbound


class SimOffice:
    """World + simulated adapters. Build one per instruction for evaluation.

    ``robot``: the base that drives (default: a kinematic ``SimRobot``); it is wrapped in an
    ``ObservedRobot`` so hand-overs follow it. ``locker``: any ``Locker`` whose people's acts
    can be simulated (``simulate_scan`` / ``simulate_close``: ``LocalLocker``, ``TcpLocker``).
    Call ``aclose`` when done: hand-overs in flight on a networked locker are tasks.
    """

    def __init__(
        self,
        office: Office,
        *,
        unavailable: Iterable[str] = (),
        clock: Clock | None = None,
        seed: int = 0,
        reply_delay_s: float = 20.0,
        handover_delay_s: float = 30.0,
        distance: DistanceFn | None = None,
        locker: Locker | None = None,
        robot: RobotBase | None = None,
    ) -> None:
        self.office = office
        self.clock = clock or SimClock()
        self.world = World.from_office(office, unavailable)
        self.reply_delay_s = reply_delay_s
        self.handover_delay_s = handover_delay_s
        self.messenger = SimMessenger(self)
        base = robot or SimRobot(
            office, self.clock, distance or office.distance, office.robot.speed_mps
        )
        self.robot = ObservedRobot(base, office.robot.home, self._on_robot_arrived)
        if locker is None:
            key = hashlib.sha256(f"assistantx-sim-{seed}".encode()).digest()
            controller = LockController("sim-locker", Keyring.single("sim", key), self.clock)
            locker = LocalLocker(controller, clock=self.clock, render_png=False)
        if not isinstance(locker, HandOverDesk):
            raise TypeError(
                f"{type(locker).__name__} cannot be used by simulated people: "
                "it needs simulate_scan and simulate_close"
            )
        self.locker: Locker = locker
        self.desk: HandOverDesk = locker
        self.codes: list[HeldCode] = []
        self.told: set[tuple[str | None, str]] = set()  # (instruction id, person)
        # Instructions whose codes and replies are forgotten (insertion-ordered, bounded).
        self.ended: dict[str, None] = {}
        self.requesters: dict[str, str] = {}  # instruction id → who asked for it
        # instruction id → what its requester really wants (evaluation tasks know it): they
        # answer the assistant's questions from it instead of with a generic line
        self.wishes: dict[str, Wish] = {}
        self._visits: set[asyncio.Task[None]] = set()
        # Further robots, each with its locker (a fleet: add_robot), and which robot serves
        # an instruction; people go to that robot for its hand-overs.
        self.fleet: dict[str, tuple[ObservedRobot, Locker]] = {}
        self.robot_of: Callable[[str], str | None] = lambda _instruction: None

    def add_robot(self, name: str, base: RobotBase, locker: Locker, home: str) -> ObservedRobot:
        """Another robot with its own locker in this office (``robot_of`` says which robot
        serves an instruction; an instruction it names no robot for is the first robot's)."""
        if not isinstance(locker, HandOverDesk):
            raise TypeError(f"{type(locker).__name__} cannot be used by simulated people")
        observed = ObservedRobot(base, home, self._on_robot_arrived)
        self.fleet[name] = (observed, locker)
        return observed

    def _body(self, instruction_id: str) -> tuple[ObservedRobot, Locker]:
        """The robot and locker serving ``instruction_id``."""
        name = self.robot_of(instruction_id)
        if name is None or name not in self.fleet:
            return self.robot, self.locker
        return self.fleet[name]

    def timestamp(self) -> datetime:
        return datetime.fromtimestamp(self.clock.now(), tz=UTC)

    def register_instruction(
        self,
        instruction_id: str,
        requester: str,
        wish: Wish | None = None,
        *,
        text: str | None = None,
    ) -> None:
        """The requester asked for it, so they know what the robot comes for; ``wish``: what
        they really want, which their answers to the assistant's questions follow; without
        it, ``text`` (what they wrote): they answer from their own words, as the requester,
        never as a colleague who was asked for something."""
        self.told.add((instruction_id, requester))
        self.requesters[instruction_id] = requester
        if wish is None and text is not None:
            wish = Wish.from_words(self.office, requester, text)
        if wish is not None:
            self.wishes[instruction_id] = wish

    def end_instruction(self, instruction_id: str) -> None:
        """The instruction ended: people drop its codes and forget its questions, so nothing
        they would have written about it arrives afterwards (and starts a new instruction)."""
        self.ended[instruction_id] = None
        if len(self.ended) > 2 * KEEP:
            ended = list(self.ended)
            self.ended = dict.fromkeys(ended[-KEEP:])
            for gone in ended[:-KEEP]:
                self.requesters.pop(gone, None)
                self.wishes.pop(gone, None)
        self.codes = [c for c in self.codes if c.instruction_id != instruction_id]
        self.told = {(i, p) for i, p in self.told if i != instruction_id}

    async def aclose(self) -> None:
        """Wait for the hand-overs under way at a networked locker (cancelled)."""
        for task in list(self._visits):
            task.cancel()
        if self._visits:
            await asyncio.gather(*self._visits, return_exceptions=True)

    # -- messages ------------------------------------------------------------------------
    def on_message(self, message: OutboundMessage) -> None:
        if message.instruction_id is not None and message.instruction_id in self.ended:
            # Sent by an instruction that has ended (a resumed send): read, never acted on.
            self.world.record_message(self.clock.now(), message.chat.id)
            return
        now = self.clock.now()
        if message.chat.kind == "group":
            members = self.office.group(message.chat.id).members
            for person in members:
                self._receive(now, person, message)
            if message.question_id:
                # the requester does not volunteer to help with their own request
                asker = self.requesters.get(message.instruction_id or "")
                helpers = [p for p in members if p != asker]
                # The first who can help offers; the others see the offer and stay quiet, as
                # people do in a group chat (the assistant then asks that person directly).
                replies = group_replies(self.world, helpers, message.text)[:1]
                for n, reply in enumerate(replies):
                    self._schedule_reply(reply, message, n)
            return
        person = message.chat.id
        self._receive(now, person, message)
        if message.question_id:
            answer = self._requester_reply(message, person) or direct_reply(
                self.world, person, message.text
            )
            if answer is not None:
                self._schedule_reply(answer, message, 0)
        self._schedule_handovers()

    def _requester_reply(self, message: OutboundMessage, person: str) -> Reply | None:
        """The requester answering a question about their own request, from what they want."""
        instruction = message.instruction_id or ""
        wish = self.wishes.get(instruction)
        if wish is None or self.requesters.get(instruction) != person:
            return None
        if not self.world.available(person):
            return None
        return Reply(person, requester_answer(self.office, wish, message.text))

    def _receive(self, now: float, person: str, message: OutboundMessage) -> None:
        self.world.record_message(now, person)
        qr = [a for a in message.attachments if a.qr_payload]
        if not qr:
            self.told.add((message.instruction_id, person))
        for a in qr:
            code = HeldCode(
                message.instruction_id or "",
                person,
                a.qr_payload or "",
                a.qr_purpose or "deposit",
                a.item or "",
                told=message.text,
            )
            # A new code for the same hand-over replaces the one they held (a phone shows the
            # latest code; the older one was revoked or is about to be).
            self.codes = [c for c in self.codes if not _same_handover(c, code)]
            self.codes.append(code)
        for a in message.attachments:
            if a.kind == "file" and a.item and self.world.available(person):
                self.world.receive_file(now, person, a.item)

    def _schedule_reply(self, reply: Reply, question: OutboundMessage, n: int) -> None:
        def deliver() -> None:
            if question.instruction_id in self.ended:
                return  # the instruction ended before they answered: they let it be
            if self.world.available(reply.person):
                self.messenger.post(
                    reply.person,
                    question.chat,
                    reply.text,
                    files=reply.files,
                    in_reply_to=question.question_id,
                )

        self.clock.call_later(self.reply_delay_s + 5.0 * n, deliver)

    # -- hand-overs ----------------------------------------------------------------------
    def _on_robot_arrived(self, place: str) -> None:
        self.world.note(self.clock.now(), "robot_arrived", place=place)
        self._schedule_handovers()

    def on_robot_arrived(self) -> None:
        """People with a code for where the robot stands come (again): after a restore."""
        self._schedule_handovers()

    def _schedule_handovers(self) -> None:
        for code in self.codes:
            robot, _ = self._body(code.instruction_id)
            place = robot.place
            if place is None or robot.moving:
                continue
            if code.done or code.scheduled or not self.world.available(code.person):
                continue
            if place not in self.world.places_of(code.person):
                continue
            if (code.instruction_id, code.person) not in self.told:
                continue
            if code.complained and handover_problem(
                self.world, code.person, code.purpose, code.item, place
            ):
                continue  # nothing changed since they said why they cannot
            code.scheduled = True
            self.clock.call_later(
                self.handover_delay_s, functools.partial(self._handover, code, place)
            )

    def _handover(self, code: HeldCode, place: str) -> None:
        """The person comes to the robot and uses every code they hold that works here."""
        code.scheduled = False
        robot, _ = self._body(code.instruction_id)
        if robot.moving or robot.place != place or code.done:
            return  # the robot left before the person came
        mine = [
            c
            for c in self.codes
            if c.person == code.person and c.instruction_id == code.instruction_id and not c.done
        ]
        for held in sorted(mine, key=lambda c: c is not code):
            held.scheduled = False
            self._use_code(held, place)

    def _use_code(self, code: HeldCode, place: str) -> None:
        now = self.clock.now()
        if code.purpose == "deposit":
            self._lent_back(code, now)
        problem = handover_problem(self.world, code.person, code.purpose, code.item, place)
        if problem is not None:
            # They keep the code and come again once the hand-over has become possible.
            if not code.complained:
                code.complained = True
                self.messenger.post(
                    code.person,
                    ChatRef(kind="dm", id=code.person),
                    f"I came to the robot, but: {problem}",
                )
            return
        code.done = True
        _, locker = self._body(code.instruction_id)
        if isinstance(locker, LocalLocker):
            # In-process lock: the whole visit happens at this instant of the clock.
            decision = locker.controller.scan(code.payload).decision
            self._after_scan(code, decision, now, place)
            if decision.kind == "code_accepted":
                locker.controller.close()
            return
        task = asyncio.get_running_loop().create_task(self._visit(code, now, place))
        self._visits.add(task)
        task.add_done_callback(self._visits.discard)

    def _lent_back(self, code: HeldCode, now: float) -> None:
        """The requester putting in a colleague's thing they give back has it (they were lent
        it): the world's record, still with its owner, is brought up to date first."""
        wish = self.wishes.get(code.instruction_id)
        if wish is None or self.requesters.get(code.instruction_id) != code.person:
            return
        if lent_to_requester(self.office, self.world.holder, wish, code.item):
            self.world.holder[code.item] = code.person
            self.world.note(now, "lent_earlier", item=code.item, to=code.person)

    async def _visit(self, code: HeldCode, now: float, place: str) -> None:
        """A hand-over at a networked locker: scan, swap the item, shut the door."""
        _, locker = self._body(code.instruction_id)
        assert isinstance(locker, HandOverDesk)  # checked on the way in
        desk = locker
        try:
            decision = await desk.simulate_scan(code.payload)
        except LockError as exc:
            logger.warning("simulated scan by %s failed: %s", code.person, exc)
            code.done = False  # they try again the next time the robot is here
            return
        self._after_scan(code, decision, now, place)
        if decision.kind == "code_accepted":
            try:
                await desk.simulate_close()
            except LockError as exc:
                logger.warning("simulated door close by %s failed: %s", code.person, exc)

    def _after_scan(self, code: HeldCode, decision: LockEvent, now: float, place: str) -> None:
        if decision.kind != "code_accepted":
            reason = decision.reason or "rejected"
            self.messenger.post(
                code.person,
                ChatRef(kind="dm", id=code.person),
                f"The locker rejected my code ({reason}).",
            )
            return
        do_handover(self.world, now, code.person, code.purpose, code.item, place, told=code.told)

    def check(self, milestones: Iterable[dict[str, object]]) -> list[bool]:
        return [self.world.check(dict(m)) for m in milestones]


def _same_handover(a: HeldCode, b: HeldCode) -> bool:
    return (a.instruction_id, a.person, a.purpose, a.item) == (
        b.instruction_id,
        b.person,
        b.purpose,
        b.item,
    )
