"""What a Matrix requester sees (issue 24, item 6), played by matrix-nio people against a real
Synapse: their message read, the bot typing and "On it: ..." at once; an encrypted DM left
for a plain one; and in ``both`` mode the pull account in the group rooms, so a group answer
arrives while pushes fail."""

from __future__ import annotations

import uuid
from collections.abc import Callable

import pytest

from assistantx.adapters.messenger.matrix.normalize import ENCRYPTED_ROOM_TEXT
from helpers.eventually import eventually
from synapse.homeserver import Account
from synapse.nio_office import QUESTION, Office, ask_zhang_through, borrow, running

pytestmark = [pytest.mark.synapse, pytest.mark.asyncio(loop_scope="session")]

REQUEST = "Please ask Zhang if I can borrow her stapler."


async def test_a_request_is_read_typed_and_acknowledged_at_once(office: Office) -> None:
    bot = office.config.bot_user_id
    service = office.service_for(borrow)
    async with running(service):
        lee_dm = await office.lee.open_dm(bot)
        request = await office.lee.say(lee_dm, REQUEST)
        [ack] = await eventually(
            office.lee.acknowledgements, what="Lee's acknowledgement", timeout_s=20
        )
        assert (ack.room_id, ack.sender, ack.body) == (lee_dm, bot, f"On it: {REQUEST}")
        await eventually(
            lambda: ("read", lee_dm, bot, request) in office.lee.signals,
            what="the bot's read receipt",
            timeout_s=20,
        )
        assert ("typing", lee_dm, bot) in office.lee.signals
        # Only then does the instruction's own conversation go on.
        question = await office.zhang.expect(sender=bot)
        await office.zhang.say(question.room_id, "Yes.")
        outcome = await office.lee.expect(sender=bot, room=lee_dm)
        assert outcome.body == "[done] Zhang answered: Yes."
        assert len(office.lee.acknowledgements()) == 1


async def test_an_encrypted_dm_is_left_and_the_person_told_in_a_plain_one(
    office: Office,
) -> None:
    """Element opens DMs encrypted by default. The bot cannot encrypt: it once took that room
    as Lee's DM and wrote his answers (and codes) there in plain text."""
    bot = office.config.bot_user_id
    service = office.service_for(borrow)
    async with running(service):
        secret = await office.lee.create_room([bot], is_direct=True, encrypted=True)
        told = await office.lee.expect(sender=bot)
        assert told.body == ENCRYPTED_ROOM_TEXT
        assert told.room_id != secret
        await office.lee.wait_member(secret, bot, present=False)
        await office.lee.say(told.room_id, REQUEST)
        question = await office.zhang.expect(sender=bot)
        await office.zhang.say(question.room_id, "Yes.")
        outcome = await office.lee.expect(sender=bot)
        assert (outcome.room_id, outcome.body) == (told.room_id, "[done] Zhang answered: Yes.")
        assert [m for m in office.lee.seen if m.room_id == secret] == []


async def test_both_mode_the_pull_account_is_in_the_group_rooms(
    office: Office, new_account: Callable[[str], Account]
) -> None:
    """The bot joined the group room in push mode. In ``both`` mode the pull account joins it
    too (it never did), so Zhang's answer in the group arrives while pushes fail."""
    bot = office.config.bot_user_id
    syncbot = new_account("syncbot")
    alias = f"work-{uuid.uuid4().hex[:8]}"
    group_question = "Who can lend Lee a stapler?"

    ask_group = ask_zhang_through("office_work", group_question, "an answer in the group")
    service = office.service_for(ask_group)
    service.write_config(groups={"office_work": f"#{alias}:{office.config.server_name}"})
    response = await office.hu.client.room_create(
        alias=alias, invite=[bot, office.zhang.user_id, office.lee.user_id]
    )
    room = str(getattr(response, "room_id"))  # noqa: B009 - nio's union type
    async with running(service):  # push: the bot joins its configured group
        await office.hu.wait_member(room, bot)
    service.use_pull_account(syncbot, "both")
    async with running(service):
        await office.hu.wait_member(room, syncbot.user_id)
        lee_dm = await office.lee.open_dm(bot, also=(syncbot.user_id,))
        await office.lee.say(lee_dm, "Please find me a stapler.")
        asked_there = await office.zhang.expect(sender=bot, room=room)
        assert asked_there.body == group_question
        service.gateway.go_down()  # pushes fail from now on: only /sync hears the group
        await office.zhang.say(room, "I can, come by.")
        outcome = await office.lee.expect(sender=bot, room=lee_dm)
        assert outcome.body == "[done] Zhang answered: I can, come by."
    assert QUESTION not in [m.body for m in office.zhang.seen]
