"""The service with ``ASSISTANTX_MESSENGER=matrix``: a person DMs the bot on a real Synapse,
the service's assistant runs the instruction and answers there, and the REST API shows it."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import httpx
import pytest
import yaml

from assistantx.adapters.messenger.matrix import MatrixConfig
from assistantx.core.actions import Inform, Stop
from assistantx.core.office import Office
from assistantx.core.settings import Settings
from assistantx.runtime.assistant import ReasonerFactory
from assistantx.service.app import create_app
from helpers.scripted_reasoner import ScriptedReasoner
from synapse.gateway import AppserviceGateway
from synapse.homeserver import Account
from synapse.people import MatrixPerson

pytestmark = [pytest.mark.synapse, pytest.mark.asyncio(loop_scope="session")]

OPERATOR = "operator-token-for-the-matrix-test"


def acknowledge_builder(office: Office, settings: object) -> ReasonerFactory:
    """``ASSISTANTX_REASONER_BUILDER`` target: tell the requester, then stop."""
    del office, settings
    return lambda: ScriptedReasoner(
        [
            [Inform(contact="lee", content="On it.")],
            [Stop(outcome="done", summary="Your note is filed.")],
        ]
    )


async def test_service_runs_an_instruction_sent_on_matrix(
    base_config: MatrixConfig,
    gateway_mounts: AppserviceGateway,
    new_account: Callable[[str], Account],
    tmp_path: Path,
) -> None:
    lee_account = new_account("lee")
    config_path = tmp_path / "matrix.yaml"
    config_path.write_text(
        yaml.safe_dump(
            {
                "homeserver_url": base_config.homeserver_url,
                "server_name": base_config.server_name,
                "as_token": base_config.as_token.get_secret_value(),
                "hs_token": base_config.hs_token.get_secret_value(),
                "appservice_id": base_config.appservice_id,
                "sender_localpart": base_config.sender_localpart,
                "mode": "push",
                "people": {"lee": lee_account.user_id},
            }
        ),
        encoding="utf-8",
    )
    settings = Settings(
        messenger="matrix",
        matrix_config=config_path,
        data_dir=tmp_path / "data",
        people="human",
        operator_token=OPERATOR,  # type: ignore[arg-type]
        reasoner_builder=f"{__name__}:acknowledge_builder",
        speedup=100.0,
    )
    app = create_app(settings)
    lee = MatrixPerson("lee", lee_account, base_config.homeserver_url)
    await lee.start()
    try:
        async with app.router.lifespan_context(app):
            gateway_mounts.mount_app(app)
            bot = base_config.bot_user_id
            room = await lee.open_dm(bot)
            await lee.say(room, "Please file my note.")
            assert (await lee.expect(sender=bot, room=room)).body == "On it."
            done = await lee.expect(sender=bot, room=room)
            assert done.body == "[done] Your note is filed."
            runtime = app.state.runtime
            for running in list(runtime.assistant.running.values()):
                await running.task  # the last message is sent just before the run ends
            [(instruction_id, stm)] = runtime.assistant.finished.items()
            assert (stm.requester, stm.text) == ("lee", "Please file my note.")
            assert await runtime.matrix.store.unhandled() == []
            assert base_config.appservice_url is not None
            async with httpx.AsyncClient(base_url=base_config.appservice_url) as http:
                response = await http.get(
                    f"/v1/instructions/{instruction_id}",
                    headers={"Authorization": f"Bearer {OPERATOR}"},
                )
            assert response.status_code == 200, response.text
            assert response.json()["outcome"] == "done"
            gateway_mounts.unmount()
    finally:
        await lee.stop()
