"""Matrix as its users expect (issue 17), played by Lee, Zhang, Mao, Hu and a stranger at
matrix-nio clients against a real Synapse, with the service running as deployed
(``ASSISTANTX_MESSENGER=matrix``) and restarted the way SIGTERM and a new start do it.

Wang is in the office but has no Matrix account in the configuration.
"""

from __future__ import annotations

import asyncio
import uuid
from collections.abc import Callable

import httpx
import pytest

from assistantx.adapters.messenger.matrix.normalize import (
    EDIT_TEXT,
    ENCRYPTED_TEXT,
    STRANGER_TEXT,
)
from assistantx.agents.base import AgentContext
from assistantx.core.actions import Action, ForwardFile, Inform, SendQR, Stop, Wait
from helpers.eventually import eventually
from synapse.homeserver import Account
from synapse.nio_office import OPERATOR, QUESTION, Office, borrow, lee_asks_to_borrow, running

pytestmark = [pytest.mark.synapse, pytest.mark.asyncio(loop_scope="session")]


async def locker_codes(office: Office) -> list[dict[str, object]]:
    assert office.config.appservice_url is not None
    async with httpx.AsyncClient(base_url=office.config.appservice_url) as http:
        response = await http.get(
            "/v1/locker/codes", headers={"Authorization": f"Bearer {OPERATOR}"}
        )
    assert response.status_code == 200, response.text
    codes: list[dict[str, object]] = response.json()
    return codes


async def quiet(seconds: float = 1.0) -> None:
    """Let anything that would still arrive arrive (asserting on nothing more)."""
    await asyncio.sleep(seconds)


# -- 1, 4, 5: restarts ---------------------------------------------------------------------


async def test_restart_mid_instruction_loses_and_repeats_nothing(office: Office) -> None:
    """SIGTERM while the assistant waits for Zhang; Zhang answers while it is down. After the
    restart the instruction carries on: Zhang was asked once, Lee hears the outcome once, in
    the DM he opened, and nobody was told it failed."""
    service = office.service_for(borrow)
    bot = office.config.bot_user_id
    await service.start()
    lee_dm, question = await lee_asks_to_borrow(office)
    assert question.body == QUESTION

    await service.stop(down=True)  # SIGTERM: pushes fail until the restart
    await office.zhang.say(question.room_id, "Sure, take it.")
    await service.start()

    outcome = await office.lee.expect(sender=bot)
    assert (outcome.room_id, outcome.body) == (lee_dm, "[done] Zhang answered: Sure, take it.")
    await quiet()
    assert [(m.room_id, m.body) for m in office.lee.from_(bot)] == [(lee_dm, outcome.body)]
    assert [m.body for m in office.zhang.from_(bot)] == [QUESTION]
    [stm] = await service.wait_ended()
    assert stm.trace.outcome == "done"
    await service.stop()


async def test_an_instruction_after_a_restart_gets_its_own_messages(office: Office) -> None:
    """The instruction ids of a new process start again, yet the homeserver never takes the
    new question for a repeat of the old one (transaction ids are never reused)."""
    service = office.service_for(borrow)
    bot = office.config.bot_user_id
    async with running(service):
        lee_dm, first = await lee_asks_to_borrow(office)
        await office.zhang.say(first.room_id, "Yes.")
        assert (await office.lee.expect(sender=bot)).body == "[done] Zhang answered: Yes."
        await service.wait_ended()
    async with running(service):
        await office.lee.say(lee_dm, "Please ask Zhang if I can borrow her stapler.")
        second = await office.zhang.expect(sender=bot)
        assert second.event_id != first.event_id and second.body == QUESTION
        assert second.room_id == first.room_id  # the same DM, also after the restart
        await office.zhang.say(second.room_id, "Yes, again.")
        outcome = await office.lee.expect(sender=bot)
        assert (outcome.room_id, outcome.body) == (lee_dm, "[done] Zhang answered: Yes, again.")


async def test_a_person_who_left_the_dm_gets_a_new_one(office: Office) -> None:
    service = office.service_for(borrow)
    bot = office.config.bot_user_id
    async with running(service):
        lee_dm, question = await lee_asks_to_borrow(office)
        await office.lee.client.room_leave(lee_dm)
        await office.zhang.say(question.room_id, "Yes.")
        outcome = await office.lee.expect(sender=bot)  # Lee accepts the new DM's invite
        assert outcome.body == "[done] Zhang answered: Yes."
        assert outcome.room_id != lee_dm
        assert await office.lee.members(outcome.room_id) == {office.lee.user_id, bot}


# -- 2: private content stays in the DM; invites --------------------------------------------


async def test_a_collect_code_never_leaves_the_dm(office: Office) -> None:
    """Lee pulls the bot into "Lunch Club" with Mao and Hu and chats there while his
    instruction runs; his one-time code still goes to his DM only."""
    bot = office.config.bot_user_id

    def collect(ctx: AgentContext) -> list[Action]:
        if ctx.step == 0:
            return [Wait(reason="let Lee chat", timeout_s=150)]
        if ctx.step == 1:
            # Lee's own stapler (no owner's yes to wait for: runtime/consent.py)
            return [SendQR(contact="lee", item="stapler:lee", purpose="collect")]
        return [Stop(outcome="done", summary="Your code is in this chat.")]

    service = office.service_for(collect)
    async with running(service):
        lunch = await office.lee.create_room([bot, office.mao.user_id, office.hu.user_id])
        for member in (office.mao.user_id, office.hu.user_id):
            await office.lee.wait_member(lunch, member)
        lee_dm = await office.lee.open_dm(bot)
        assert await locker_codes(office) == []  # the operator's locker panel is open
        await office.lee.say(lee_dm, "Please bring me my stapler.")
        await office.lee.say(lunch, "Anyone up for lunch?")
        code = await office.lee.expect(sender=bot, msgtype="m.image")
        assert code.room_id == lee_dm
        assert await office.lee.read_qr(code)  # a real, readable code
        # The operator can scan a code sent over Matrix from the locker panel.
        # The runtime records a code as held once its message has gone out, so Lee's client
        # can show the message a moment before the panel lists it.
        [held] = await eventually(
            lambda: locker_codes(office), what="the code on the operator's locker panel"
        )
        assert (held["person"], held["purpose"], held["scannable"]) == ("lee", "collect", True)
        about = await office.lee.expect(sender=bot, msgtype="m.text", room=lee_dm)
        assert "one-time code" in about.body
        done = await office.lee.expect(sender=bot, msgtype="m.text", room=lee_dm)
        assert done.body == "[done] Your code is in this chat."
        await quiet()
        assert office.mao.from_(bot) == [] and office.hu.from_(bot) == []
        assert [m.room_id for m in office.lee.from_(bot)] == [lee_dm] * len(office.lee.from_(bot))
        assert len(service.instructions()) == 1  # the lunch chatter started nothing


async def test_a_strangers_invite_is_declined_politely(office: Office) -> None:
    bot = office.config.bot_user_id
    service = office.service_for(borrow)
    async with running(service):
        room = await office.stranger.create_room([bot], is_direct=True)
        notice = await office.stranger.expect(sender=bot, room=room)
        assert (notice.msgtype, notice.body) == ("m.notice", STRANGER_TEXT)
        await office.stranger.wait_member(room, bot, present=False)
        await office.stranger.say(room, "Please bring me a stapler.")
        await quiet()
        assert service.instructions() == {}


# -- 3: rooms joined later, history ---------------------------------------------------------


async def test_a_group_created_after_start_is_a_group(office: Office) -> None:
    bot = office.config.bot_user_id
    alias = f"work-{uuid.uuid4().hex[:8]}"
    service = office.service_for(borrow)
    service.write_config(groups={"office_work": f"#{alias}:{office.config.server_name}"})
    async with running(service):  # the room does not exist yet
        response = await office.hu.client.room_create(alias=alias, invite=[bot])
        room = str(getattr(response, "room_id"))  # noqa: B009 - nio's union type
        await office.hu.wait_member(room, bot)
        await office.hu.say(room, "Anyone up for lunch?")
        await quiet()
        assert service.instructions() == {}
        assert office.hu.from_(bot) == []
        unmatched = service.runtime.assistant.unmatched
        assert [(str(m.chat), m.text) for m in unmatched] == [
            ("group:office_work", "Anyone up for lunch?")
        ]


async def test_pull_mode_takes_no_history_as_new(
    office: Office, new_account: Callable[[str], Account]
) -> None:
    syncbot = new_account("syncbot")
    service = office.service_for(borrow)
    service.use_pull_account(syncbot, "pull")
    async with running(service):
        room = await office.lee.create_room([], is_direct=True)
        await office.lee.say(room, "Old news: bring me a cup.")
        await office.lee.client.room_invite(room, syncbot.user_id)
        await office.lee.wait_member(room, syncbot.user_id)
        await quiet(2.0)
        assert service.instructions() == {}
        await office.lee.say(room, "Please ask Zhang if I can borrow her stapler.")
        await office.zhang.expect(sender=syncbot.user_id)
        [stm] = service.instructions().values()
        assert stm.text == "Please ask Zhang if I can borrow her stapler."


# -- 6: files and unmapped people -----------------------------------------------------------


async def test_a_file_is_forwarded_by_reference_and_an_unmapped_person_fails_once(
    office: Office,
) -> None:
    bot = office.config.bot_user_id

    def forward(ctx: AgentContext) -> list[Action]:
        if ctx.step == 0:
            return [ForwardFile(source="lee", target="zhang")]
        if ctx.step == 1:
            return [Inform(contact="wang", content="Lee's report is with Zhang.")]
        return [Stop(outcome="done", summary="Zhang has your report.")]

    service = office.service_for(forward)
    async with running(service):
        lee_dm = await office.lee.open_dm(bot)
        data = b"%PDF-1.4 quarterly report"
        mxc = await office.lee.upload_file(lee_dm, "report.pdf", data)
        note = await office.lee.expect(sender=bot, room=lee_dm)
        assert "report.pdf" in note.body  # a captionless file is acknowledged, not dropped
        assert service.instructions() == {}
        await office.lee.say(lee_dm, "Please forward my report to Zhang.")
        forwarded = await office.zhang.expect(sender=bot, msgtype="m.file")
        assert forwarded.content["url"] == mxc  # by reference, no copy
        assert await office.zhang.download(mxc) == data
        assert (await office.lee.expect(sender=bot, room=lee_dm)).body.startswith("[done]")
        [stm] = await service.wait_ended()
        wang = [r for s in stm.trace.steps for r in s.results if r.action.type == "inform"]
        assert len(wang) == 1 and not wang[0].ok
        assert "cannot be reached on Matrix" in wang[0].observation
        assert "@" not in wang[0].observation and "!" not in wang[0].observation


# -- 7: every message handled or answered ---------------------------------------------------


async def test_each_kind_of_message_is_handled_or_answered(office: Office) -> None:
    bot = office.config.bot_user_id
    service = office.service_for(borrow)
    async with running(service):
        lee_dm = await office.lee.open_dm(bot)
        mao_dm = await office.mao.open_dm(bot)
        # A notice is another bot talking: ignored.
        await office.mao.send(mao_dm, {"msgtype": "m.notice", "body": "Build passed."})
        # An encrypted message cannot be read: say so.
        await office.mao.send(
            mao_dm,
            {"algorithm": "m.megolm.v1.aes-sha2", "ciphertext": "AwgA", "session_id": "s"},
            kind="m.room.encrypted",
        )
        answer = await office.mao.expect(sender=bot, room=mao_dm)
        assert answer.body == ENCRYPTED_TEXT
        # Too long for a request: a clear reply, no instruction.
        await office.mao.say(mao_dm, "x" * 43_000)
        too_long = await office.mao.expect(sender=bot, room=mao_dm)
        assert "43,000 characters" in too_long.body
        assert service.instructions() == {}

        request = await office.lee.say(lee_dm, "Please ask Zhang if I can borrow her stapler.")
        question = await office.zhang.expect(sender=bot)
        # Lee edits his request: told what the assistant does about it.
        await office.lee.say(
            lee_dm,
            "* Please ask Zhang for scissors.",
            **{
                "m.new_content": {"msgtype": "m.text", "body": "Please ask Zhang for scissors."},
                "m.relates_to": {"rel_type": "m.replace", "event_id": request},
            },
        )
        assert (await office.lee.expect(sender=bot, room=lee_dm)).body == EDIT_TEXT
        # Zhang answers the question with a thumbs-up.
        await office.zhang.react(question.room_id, question.event_id, "👍")
        outcome = await office.lee.expect(sender=bot, room=lee_dm)
        assert outcome.body == "[done] Zhang answered: Yes"
        # A rich reply to the outcome: the quoted fallback is not part of the new request.
        await office.lee.say(
            lee_dm,
            f"> <{bot}> {outcome.body}\n\nPlease ask Zhang if I can borrow her stapler.",
            **{"m.relates_to": {"m.in_reply_to": {"event_id": outcome.event_id}}},
        )
        await office.zhang.expect(sender=bot)
        texts = sorted(stm.text for stm in service.instructions().values())
        assert texts == ["Please ask Zhang if I can borrow her stapler."] * 2
        assert office.mao.from_(bot)[2:] == []  # nothing for the notice


# -- 8: switching modes ---------------------------------------------------------------------


async def test_switching_modes(office: Office, new_account: Callable[[str], Account]) -> None:
    bot = office.config.bot_user_id
    syncbot = new_account("syncbot")
    service = office.service_for(borrow)
    async with running(service):  # push
        lee_dm = await office.lee.open_dm(bot)
    # both: the DM made in push mode gets the pull account too
    service.use_pull_account(syncbot, "both")
    async with running(service):
        await office.lee.wait_member(lee_dm, syncbot.user_id)
    # pull: a registration left in place still gets an answer, not 405
    service.write_config(mode="pull")
    async with running(service):
        assert office.config.appservice_url is not None
        async with httpx.AsyncClient(base_url=office.config.appservice_url) as http:
            response = await http.put(
                "/_matrix/app/v1/transactions/left-over",
                json={"events": []},
                headers={"Authorization": f"Bearer {office.config.hs_token.get_secret_value()}"},
            )
        assert response.status_code == 200, response.text


# -- 9: the journal -------------------------------------------------------------------------


async def test_matrix_traffic_is_in_the_journal_and_chats(office: Office) -> None:
    bot = office.config.bot_user_id
    service = office.service_for(borrow)
    async with running(service):
        lee_dm, question = await lee_asks_to_borrow(office)
        await office.zhang.say(question.room_id, "Yes.")
        await office.lee.expect(sender=bot)
        await service.wait_ended()
        # The survey follows the outcome.
        await eventually(office.lee.set_aside, what="the survey to Lee", timeout_s=20)
        assert office.config.appservice_url is not None
        auth = {"Authorization": f"Bearer {OPERATOR}"}
        async with httpx.AsyncClient(base_url=office.config.appservice_url) as http:
            chats = (await http.get("/v1/chats", headers=auth)).json()
            lee = (await http.get("/v1/chats/dm/lee", headers=auth)).json()
            zhang = (await http.get("/v1/chats/dm/zhang", headers=auth)).json()
    assert {(c["kind"], c["id"]) for c in chats} >= {("dm", "lee"), ("dm", "zhang")}
    assert [(m["direction"], m["text"]) for m in lee][:3] == [
        ("in", "Please ask Zhang if I can borrow her stapler."),
        ("out", "On it: Please ask Zhang if I can borrow her stapler."),
        ("out", "[done] Zhang answered: Yes."),
    ]
    # The survey reaches Lee where he talks to the assistant, and is journaled like the rest.
    [survey] = office.lee.set_aside()
    assert survey.room_id == lee_dm
    assert [(m["direction"], m["text"]) for m in lee][3:] == [("out", survey.body)]
    assert [(m["direction"], m["text"]) for m in zhang] == [("out", QUESTION), ("in", "Yes.")]
