"""A whole instruction through a real Synapse: push, pull, and both at once.

Lee DMs the assistant "Please bring me a stapler". The assistant asks the study group's room,
Zhang answers there, the assistant asks Zhang in a DM, Zhang agrees; the robot drives to
Zhang's desk and Zhang gets a one-time QR code in that DM, reads it off the image and puts the
stapler into the locker; the robot drives to Lee, Lee gets a code in the DM Lee opened, takes
the stapler out, and Lee is told the outcome. Hu, also in the group room, sees the question
and nothing else.

People are real Matrix users driven by plain clients; the robot base and the locker are the
simulated ones on a sped-up wall clock; the decisions come from a scripted reasoner (the
subject here is the messenger, not the reasoning). The Assistant consumes the messenger's
inbound queue and acknowledges each message, so nothing is left to replay.
"""

from __future__ import annotations

import asyncio
import contextlib
import uuid
from collections.abc import AsyncIterator, Callable
from dataclasses import dataclass
from pathlib import Path

import pytest

from assistantx.adapters.messenger.matrix import MatrixConfig, MatrixRuntime, matrix_runtime
from assistantx.adapters.messenger.matrix.config import MatrixMode
from assistantx.agents.base import AgentContext
from assistantx.core.actions import Inquire, Move, SendQR, Stop, Wait, WaitInPlace
from assistantx.core.clock import WallClock
from assistantx.core.office import Office, load_office
from assistantx.core.ports.messenger import ChatRef
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.assistant import Assistant
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.office import SimOffice
from helpers.office import sim_assistant
from helpers.scripted_reasoner import ScriptedReasoner, Step
from synapse.gateway import AppserviceGateway
from synapse.helpers import OfferCountingStore, derive
from synapse.homeserver import Account
from synapse.inbox import Seen
from synapse.people import MatrixPerson
from synapse.physical import ObservedLocker, hand_over_at_robot

pytestmark = [pytest.mark.synapse, pytest.mark.asyncio(loop_scope="session")]

SPEEDUP = 100.0  # a 20 m drive at 0.5 m/s takes 0.4 s; waits end on the reply anyway
REQUEST = "Please bring me a stapler."
GROUP = "study_group"
GROUP_ANSWER = "I have one on my desk."
DM_ANSWER = "Yes, send the robot over."


def stapler_script() -> list[Step]:
    """Ask the group, then whoever answered there; fetch their stapler for Lee."""

    def helper(ctx: AgentContext) -> str:
        group = ChatRef(kind="group", id=GROUP)
        answered = [t.person for t in ctx.stm.dialogue if t.direction == "in" and t.chat == group]
        assert answered, "nobody answered in the group"
        return answered[0]

    def stapler(ctx: AgentContext) -> str:
        return f"stapler:{helper(ctx)}"

    return [
        [
            Inquire(contact=GROUP, question="Does anyone have a stapler for Lee?"),
            Wait(timeout_s=3000),
        ],
        lambda ctx: [
            Inquire(contact=helper(ctx), question="May the robot fetch your stapler now?"),
            Wait(timeout_s=3000),
        ],
        lambda ctx: [Move(place=helper(ctx)), SendQR(contact=helper(ctx), item=stapler(ctx))],
        lambda ctx: [WaitInPlace(person=helper(ctx), timeout_s=3000)],
        lambda ctx: [
            Move(place="lee"),
            SendQR(contact="lee", item=stapler(ctx), purpose="collect"),
        ],
        [WaitInPlace(person="lee", timeout_s=3000)],
        lambda ctx: [Stop(outcome="done", summary=f"{helper(ctx)}'s stapler is in your hands.")],
    ]


@dataclass
class MatrixOffice:
    office: Office
    config: MatrixConfig
    runtime: MatrixRuntime
    store: OfferCountingStore
    assistant: Assistant
    sim: SimOffice
    locker: ObservedLocker
    people: dict[str, MatrixPerson]
    group_room: str

    @property
    def me(self) -> str:
        """Who the assistant writes as: its bot in push/both mode, the pull account in pull."""
        if self.config.push_enabled:
            return self.config.bot_user_id
        assert self.config.pull_user_id is not None
        return self.config.pull_user_id

    def desk(self, person: str) -> str:
        return self.office.person(person).location


@pytest.fixture
def office_on_matrix(
    base_config: MatrixConfig,
    gateway_mounts: AppserviceGateway,
    new_account: Callable[[str], Account],
    tmp_path: Path,
) -> Callable[[MatrixMode], contextlib.AbstractAsyncContextManager[MatrixOffice]]:
    office = load_office()

    @contextlib.asynccontextmanager
    async def build(mode: MatrixMode) -> AsyncIterator[MatrixOffice]:
        accounts = {name: new_account(name) for name in ("lee", "zhang", "hu")}
        people = {n: MatrixPerson(n, a, base_config.homeserver_url) for n, a in accounts.items()}
        async with contextlib.AsyncExitStack() as stack:
            for person in people.values():
                await person.start()
                stack.push_async_callback(person.stop)
            alias = f"study-{uuid.uuid4().hex[:8]}"
            group_room = await people["zhang"].client.create_room(
                preset="public_chat", alias_localpart=alias
            )
            for name in ("lee", "hu"):
                await people[name].client.join(group_room)
            update: dict[str, object] = {
                "mode": mode,
                "people": {name: account.user_id for name, account in accounts.items()},
                "groups": {GROUP: f"#{alias}:{base_config.server_name}"},
            }
            if mode != "push":
                syncbot = new_account("syncbot")
                update |= {
                    "pull_user_id": syncbot.user_id,
                    "pull_access_token": syncbot.access_token,
                    "sync_timeout_s": 5.0,
                }
            config = derive(base_config, **update)
            store = OfferCountingStore(tmp_path / f"matrix-{mode}.sqlite3")
            runtime = matrix_runtime(config, store)
            stack.push_async_callback(runtime.aclose)
            if runtime.router is not None:
                gateway_mounts.mount(runtime.router)
                # Unmounted before the store closes: a push after that is acknowledged and
                # dropped, where a 500 would make Synapse back off from the gateway.
                stack.callback(gateway_mounts.unmount)
            clock = WallClock(SPEEDUP)
            locker = ObservedLocker(clock)
            sim = SimOffice(office, clock=clock, locker=locker)
            assistant = sim_assistant(
                sim,
                lambda: ScriptedReasoner(stapler_script()),
                messenger=runtime.messenger,
                reasoner_name="scripted",
                limits=LoopLimits(max_steps=12),
            )
            await locker.start()
            stack.push_async_callback(locker.stop)
            await assistant.start()  # connects its inbox before the messenger starts
            stack.push_async_callback(assistant.stop)
            await runtime.messenger.start()
            if runtime.messenger.poller is not None:
                async with asyncio.timeout(20):
                    await runtime.messenger.poller.ready.wait()
            yield MatrixOffice(
                office, config, runtime, store, assistant, sim, locker, people, group_room
            )

    return build


@dataclass
class Transcript:
    stm: ShortTermMemory
    inbound: list[str]  # event ids of what people wrote to the assistant
    lee_dm: str
    zhang_dm: str
    group_question: Seen


async def run_stapler_instruction(world: MatrixOffice) -> Transcript:
    lee, zhang, hu = world.people["lee"], world.people["zhang"], world.people["hu"]
    me = world.me
    # In both mode the bot brings its pull account along; Lee waits until both are in.
    extra = (world.config.pull_user_id,) if world.config.mode == "both" else ()
    lee_dm = await lee.open_dm(me, also_wait_for=tuple(u for u in extra if u))
    request = await lee.say(lee_dm, REQUEST)

    question = await zhang.expect(sender=me, room=world.group_room)
    assert "stapler" in question.body
    assert (await hu.expect(sender=me, room=world.group_room)).event_id == question.event_id
    group_answer = await zhang.say(world.group_room, GROUP_ANSWER)

    ask = await zhang.expect(sender=me, not_room=world.group_room)
    zhang_dm = ask.room_id
    assert ask.body == "May the robot fetch your stapler now?"
    dm_answer = await zhang.say(zhang_dm, DM_ANSWER)

    code_text = await zhang.expect(sender=me, msgtype="m.text", not_room=world.group_room)
    code_image = await zhang.expect(sender=me, msgtype="m.image")
    assert (code_text.room_id, code_image.room_id) == (zhang_dm, zhang_dm)
    assert "put your stapler into the locker" in code_text.body
    payload = await zhang.read_qr(code_image)
    events = await hand_over_at_robot(world.sim.robot, world.locker, world.desk("zhang"), payload)
    assert [(e.kind, e.person) for e in events] == [
        ("code_accepted", "zhang"),
        ("door_closed", "zhang"),
    ]

    code_text = await lee.expect(sender=me, msgtype="m.text", not_room=world.group_room)
    code_image = await lee.expect(sender=me, msgtype="m.image")
    assert (code_text.room_id, code_image.room_id) == (lee_dm, lee_dm)  # the DM Lee opened
    assert "take Zhang Wei's stapler out of the locker" in code_text.body
    payload = await lee.read_qr(code_image)
    events = await hand_over_at_robot(world.sim.robot, world.locker, world.desk("lee"), payload)
    assert [e.kind for e in events] == ["code_accepted", "door_closed"]

    outcome = await lee.expect(sender=me, room=lee_dm)
    assert outcome.body == "[done] zhang's stapler is in your hands."

    [instruction_id] = [*world.assistant.running, *world.assistant.finished]
    async with asyncio.timeout(20):
        stm = await world.assistant.wait(instruction_id)
    return Transcript(stm, [request, group_answer, dm_answer], lee_dm, zhang_dm, question)


async def assert_clean_ending(world: MatrixOffice, run: Transcript) -> None:
    """One instruction, done; each message handled once and acknowledged; nothing extra."""
    stm = run.stm
    assert (stm.requester, stm.text, stm.trace.outcome) == ("lee", REQUEST, "done")
    assert len(world.assistant.finished) == 1 and not world.assistant.running
    heard = [(t.chat, t.person, t.text) for t in stm.dialogue if t.direction == "in"]
    assert heard == [
        (ChatRef(kind="group", id=GROUP), "zhang", GROUP_ANSWER),
        (ChatRef(kind="dm", id="zhang"), "zhang", DM_ANSWER),
    ]
    assert world.assistant.unmatched == []
    assert await world.store.unhandled() == []  # acknowledged: a restart replays nothing
    assert world.sim.robot.place == world.desk("lee")
    # Nothing more arrives for anyone: no duplicate sends, no stray messages.
    await asyncio.sleep(0.5)
    lee, zhang, hu = world.people["lee"], world.people["zhang"], world.people["hu"]
    mine = [m for m in lee.messages() if m.sender == world.me]
    assert [(m.room_id, m.msgtype) for m in mine] == [
        (world.group_room, "m.text"),  # Lee is in the study group too
        (run.lee_dm, "m.text"),
        (run.lee_dm, "m.image"),
        (run.lee_dm, "m.text"),
    ]
    assert [(m.room_id, m.msgtype) for m in zhang.messages() if m.sender == world.me] == [
        (world.group_room, "m.text"),
        (run.zhang_dm, "m.text"),
        (run.zhang_dm, "m.text"),
        (run.zhang_dm, "m.image"),
    ]
    assert [m.event_id for m in hu.messages() if m.sender == world.me] == [
        run.group_question.event_id
    ]


async def test_whole_instruction_through_push(
    office_on_matrix: Callable[[MatrixMode], contextlib.AbstractAsyncContextManager[MatrixOffice]],
) -> None:
    async with office_on_matrix("push") as world:
        assert world.runtime.messenger.poller is None
        run = await run_stapler_instruction(world)
        await assert_clean_ending(world, run)
        assert all(world.store.offered[e] == 1 for e in run.inbound)


async def test_whole_instruction_through_pull(
    office_on_matrix: Callable[[MatrixMode], contextlib.AbstractAsyncContextManager[MatrixOffice]],
) -> None:
    async with office_on_matrix("pull") as world:
        assert world.runtime.router is None
        run = await run_stapler_instruction(world)
        await assert_clean_ending(world, run)
        assert all(world.store.offered[e] == 1 for e in run.inbound)
        # The pull account wrote everything; the application service's bot took no part.
        everyone = [m for p in world.people.values() for m in p.messages()]
        assert world.config.bot_user_id not in {m.sender for m in everyone}


async def test_whole_instruction_with_both_handles_each_message_once(
    office_on_matrix: Callable[[MatrixMode], contextlib.AbstractAsyncContextManager[MatrixOffice]],
) -> None:
    async with office_on_matrix("both") as world:
        run = await run_stapler_instruction(world)
        # Both paths saw every message a person wrote (the pull account is in every room)...
        async with asyncio.timeout(20):
            await world.store.wait_offered(run.inbound, times=2)
        # ...and still each was handled once: one instruction, each answer heard once.
        await assert_clean_ending(world, run)
        event_ids = [t.event_id for t in run.stm.dialogue if t.direction == "in"]
        assert len(event_ids) == len(set(event_ids)) == 2
