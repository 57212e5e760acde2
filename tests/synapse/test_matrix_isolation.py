"""No event stops the bridge (issue 24), played by matrix-nio people against a real Synapse with
the service running as deployed: a stranger's invite the bot declines (it leaves the room), a
stranger leaving a room the bot shares, and a poison transaction, in push and in pull mode."""

from __future__ import annotations

from collections.abc import Callable

import httpx
import pytest

from assistantx.adapters.messenger.matrix.normalize import STRANGER_TEXT
from synapse.homeserver import Account
from synapse.nio_office import OPERATOR, QUESTION, Office, borrow, running

pytestmark = [pytest.mark.synapse, pytest.mark.asyncio(loop_scope="session")]

REQUEST = "Please ask Zhang if I can borrow her stapler."


async def skipped_on_metrics(office: Office, path: str) -> float:
    assert office.config.appservice_url is not None
    async with httpx.AsyncClient(base_url=office.config.appservice_url) as http:
        response = await http.get("/metrics", headers={"Authorization": f"Bearer {OPERATOR}"})
    assert response.status_code == 200, response.text
    prefix = f'assistantx_inbound_events_skipped_total{{path="{path}"}} '
    lines = [line for line in response.text.splitlines() if line.startswith(prefix)]
    return float(lines[0].removeprefix(prefix)) if lines else 0.0


async def test_push_a_declined_strangers_invite_blocks_nothing(office: Office) -> None:
    """The stranger invites the bot, which says why it cannot help and leaves. The leave
    event once answered 500 for ever and queued every later push behind it: Lee's request
    after it was never seen."""
    bot = office.config.bot_user_id
    service = office.service_for(borrow)
    async with running(service):
        room = await office.stranger.create_room([bot], is_direct=True)
        notice = await office.stranger.expect(sender=bot, room=room)
        assert notice.body == STRANGER_TEXT
        await office.stranger.wait_member(room, bot, present=False)
        group = await office.stranger.create_room([bot, office.lee.user_id])
        await office.stranger.expect(sender=bot, room=group)
        await office.stranger.wait_member(group, bot, present=False)

        lee_dm = await office.lee.open_dm(bot)
        await office.lee.say(lee_dm, REQUEST)
        question = await office.zhang.expect(sender=bot)
        assert question.body == QUESTION
        await office.zhang.say(question.room_id, "Yes.")
        outcome = await office.lee.expect(sender=bot, room=lee_dm)
        assert outcome.body == "[done] Zhang answered: Yes."
        assert await skipped_on_metrics(office, "matrix_push") == 0


async def test_push_a_poison_transaction_is_acknowledged_and_counted(office: Office) -> None:
    """A pushed event whose text is not valid Unicode is skipped and counted on /metrics; the
    transaction is acknowledged, and the next message is handled."""
    bot = office.config.bot_user_id
    service = office.service_for(borrow)
    assert office.config.appservice_url is not None
    async with running(service):
        lee_dm = await office.lee.open_dm(bot)
        poison = (
            '{"events": [{"type": "m.room.message", "event_id": "$poison", "room_id": "'
            + lee_dm
            + '", "sender": "'
            + office.lee.user_id
            + '", "content": {"msgtype": "m.text", "body": "\\ud800"}}]}'
        )
        token = office.config.hs_token.get_secret_value()
        async with httpx.AsyncClient(base_url=office.config.appservice_url) as http:
            pushed = await http.put(
                "/_matrix/app/v1/transactions/poison-1",
                content=poison.encode(),
                headers={"Authorization": f"Bearer {token}", "Content-Type": "application/json"},
            )
        assert (pushed.status_code, pushed.json()) == (200, {})
        assert await skipped_on_metrics(office, "matrix_push") == 1
        await office.lee.say(lee_dm, REQUEST)
        assert (await office.zhang.expect(sender=bot)).body == QUESTION


async def test_pull_strangers_coming_and_going_block_nothing(
    office: Office, new_account: Callable[[str], Account]
) -> None:
    """Pull mode: a stranger's invite is declined (the pull account leaves), and a stranger
    leaves Lee's lunch room the pull account is in. That leave once made every /sync round
    fail, so nothing was received again."""
    syncbot = new_account("syncbot")
    service = office.service_for(borrow)
    service.use_pull_account(syncbot, "pull")
    async with running(service):
        room = await office.stranger.create_room([syncbot.user_id], is_direct=True)
        notice = await office.stranger.expect(sender=syncbot.user_id, room=room)
        assert notice.body == STRANGER_TEXT
        await office.stranger.wait_member(room, syncbot.user_id, present=False)

        lunch = await office.lee.create_room([syncbot.user_id, office.stranger.user_id])
        for member in (syncbot.user_id, office.stranger.user_id):
            await office.lee.wait_member(lunch, member)
        await office.lee.say(lunch, "Lunch at noon?")
        await office.stranger.client.room_leave(lunch)
        await office.lee.wait_member(lunch, office.stranger.user_id, present=False)

        lee_dm = await office.lee.open_dm(syncbot.user_id)
        await office.lee.say(lee_dm, REQUEST)
        question = await office.zhang.expect(sender=syncbot.user_id)
        assert question.body == QUESTION
        assert await skipped_on_metrics(office, "matrix_sync") == 0
