"""Building the Matrix messenger from settings (``ASSISTANTX_MESSENGER=matrix``), its push
router over a real uvicorn server, and the Assistant acknowledging what it handled."""

from __future__ import annotations

import asyncio
from datetime import UTC, datetime
from pathlib import Path

import httpx
import pytest

from adapters.messenger.conftest import PUSH_YAML, ServeRouters
from assistantx.adapters.messenger.matrix import MatrixRuntime, build_matrix_runtime
from assistantx.core.errors import MessengerError
from assistantx.core.office import load_office
from assistantx.core.ports.messenger import ChatRef, InboundMessage
from assistantx.core.settings import Settings
from assistantx.runtime.assistant import Assistant
from assistantx.sim.office import SimOffice
from helpers.office import sim_assistant
from helpers.scripted_reasoner import ScriptedReasoner

PULL_YAML = PUSH_YAML.replace("mode: push", "mode: pull") + (
    'pull_user_id: "@sync:office.test"\npull_access_token: pull-token\n'
)


def settings_for(tmp_path: Path, yaml_text: str | None, **extra: object) -> Settings:
    fields: dict[str, object] = {"messenger": "matrix", "data_dir": tmp_path / "data", **extra}
    if yaml_text is not None:
        path = tmp_path / "matrix.yaml"
        path.write_text(yaml_text, encoding="utf-8")
        fields["matrix_config"] = path
    return Settings(**fields)  # type: ignore[arg-type]


async def test_push_runtime_from_environment_delivers_a_pushed_message(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, serve_routers: ServeRouters
) -> None:
    (tmp_path / "matrix.yaml").write_text(PUSH_YAML, encoding="utf-8")
    monkeypatch.setenv("ASSISTANTX_MESSENGER", "matrix")
    monkeypatch.setenv("ASSISTANTX_MATRIX_CONFIG", str(tmp_path / "matrix.yaml"))
    monkeypatch.setenv("ASSISTANTX_DATA_DIR", str(tmp_path / "data"))
    runtime = build_matrix_runtime(Settings())
    assert runtime.config.mode == "push" and runtime.config.people == {"lee": "@lee:office.test"}
    assert (tmp_path / "data" / "matrix.sqlite3").exists()
    assert runtime.router is not None
    inbox: asyncio.Queue[InboundMessage] = asyncio.Queue()
    runtime.messenger.connect_inbox(inbox)
    # Only a recorded DM room is a DM (a room the bot was merely pulled into is not).
    await runtime.messenger.directory.set_dm("lee", "!dm:office.test")
    event = {
        "type": "m.room.message",
        "event_id": "$e1",
        "room_id": "!dm:office.test",
        "sender": "@lee:office.test",
        "origin_server_ts": 1700000000000,
        "content": {"msgtype": "m.text", "body": "bring me a stapler"},
    }
    try:
        async with serve_routers(runtime.router) as url, httpx.AsyncClient() as http:
            response = await http.put(
                f"{url}/_matrix/app/v1/transactions/t1",
                json={"events": [event]},
                headers={"Authorization": "Bearer hs-token"},
            )
            assert response.status_code == 200
            wrong = await http.put(
                f"{url}/_matrix/app/v1/transactions/t2",
                json={"events": []},
                headers={"Authorization": "Bearer as-token"},
            )
            assert wrong.status_code == 403
        message = inbox.get_nowait()
        assert (str(message.chat), message.sender, message.text) == (
            "dm:lee",
            "lee",
            "bring me a stapler",
        )
        assert [m.event_id for m in await runtime.store.unhandled()] == ["$e1"]
    finally:
        await runtime.aclose()


async def test_pull_runtime_has_no_router_and_an_explicit_store(tmp_path: Path) -> None:
    store_path = tmp_path / "elsewhere" / "events.db"
    runtime = build_matrix_runtime(settings_for(tmp_path, PULL_YAML, matrix_store=store_path))
    try:
        assert runtime.router is None
        assert runtime.config.pull_enabled and not runtime.config.push_enabled
        assert store_path.exists()
        assert not (tmp_path / "data" / "matrix.sqlite3").exists()
    finally:
        await runtime.aclose()
        await runtime.aclose()  # idempotent
    with pytest.raises(MessengerError, match="closed"):
        await runtime.store.unhandled()


def test_wrong_messenger_setting_is_refused(tmp_path: Path) -> None:
    settings = settings_for(tmp_path, PUSH_YAML, messenger="builtin")
    with pytest.raises(MessengerError, match="ASSISTANTX_MESSENGER is 'builtin'"):
        build_matrix_runtime(settings)


def test_missing_config_path_is_named(tmp_path: Path) -> None:
    with pytest.raises(MessengerError, match="ASSISTANTX_MATRIX_CONFIG"):
        build_matrix_runtime(settings_for(tmp_path, None))


def test_bad_config_names_the_file_and_creates_no_store(tmp_path: Path) -> None:
    settings = settings_for(tmp_path, PUSH_YAML.replace("mode: push", "mode: pull"))
    with pytest.raises(MessengerError, match=r"matrix\.yaml.*needs pull_user_id") as caught:
        build_matrix_runtime(settings)
    message = str(caught.value)
    assert "as-token" not in message and "hs-token" not in message  # no secrets echoed
    assert caught.value.__cause__ is None
    assert not (tmp_path / "data" / "matrix.sqlite3").exists()


def test_unknown_messenger_value_fails_at_settings(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ASSISTANTX_MESSENGER", "irc")
    with pytest.raises(ValueError, match="messenger"):
        Settings()


async def test_assistant_acknowledges_replayed_messages_once_handled(tmp_path: Path) -> None:
    """A message accepted before a crash is replayed on start, handled and acknowledged, so
    the next start replays nothing."""
    office = load_office()
    leftover = InboundMessage(
        platform="matrix",
        event_id="$left-over",
        chat=ChatRef(kind="group", id="study_group"),
        sender="zhang",
        text="anyone need a stapler?",
        time=datetime(2025, 1, 1, tzinfo=UTC),
    )
    settings = settings_for(tmp_path, PUSH_YAML)
    first = build_matrix_runtime(settings)
    assert await first.store.accept([leftover]) == [leftover]
    await first.aclose()

    async def run_once(runtime: MatrixRuntime) -> Assistant:
        sim = SimOffice(office)
        assistant = sim_assistant(sim, lambda: ScriptedReasoner([]), messenger=runtime.messenger)
        await assistant.start()
        try:
            await runtime.messenger.start()  # no groups, no pull: no homeserver needed
        finally:
            await assistant.stop()  # handles what is queued before the stop sentinel
            await runtime.aclose()
        return assistant

    replayed = await run_once(build_matrix_runtime(settings))
    assert [m.event_id for m in replayed.unmatched] == ["$left-over"]
    again = await run_once(build_matrix_runtime(settings))
    assert again.unmatched == []
    reopened = build_matrix_runtime(settings)
    try:
        assert await reopened.store.unhandled() == []
    finally:
        await reopened.aclose()
