"""Configuration, registration, the event store, normalization and outbound helpers."""

from __future__ import annotations

import sqlite3
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

import pytest
import yaml

from assistantx.adapters.messenger.matrix import (
    EventNormalizer,
    MatrixConfig,
    SqliteEventStore,
    load_matrix_config,
    transaction_id,
    write_registration,
)
from assistantx.adapters.messenger.matrix.adapter import png_size
from assistantx.core.errors import MessengerError
from assistantx.core.ports.messenger import ChatRef, InboundMessage

CONFIG_YAML = """
homeserver_url: http://127.0.0.1:8008
server_name: office.test
as_token: as-token
hs_token: hs-token
appservice_url: http://127.0.0.1:8000
mode: both
pull_user_id: "@assistant-sync:office.test"
pull_access_token: pull-token
people: {lee: "@lee:office.test", zhang: "@zhang:office.test"}
groups: {printing: "#printing:office.test"}
"""


def config(**update: Any) -> MatrixConfig:
    base: dict[str, Any] = yaml.safe_load(CONFIG_YAML)
    return MatrixConfig.model_validate({**base, **update})


def message(event_id: str, text: str = "hi") -> InboundMessage:
    return InboundMessage(
        platform="matrix",
        event_id=event_id,
        chat=ChatRef(kind="dm", id="lee"),
        sender="lee",
        text=text,
        time=datetime(2026, 1, 1, tzinfo=UTC),
    )


def test_config_loads_from_yaml_and_masks_secrets(tmp_path: Path) -> None:
    path = tmp_path / "matrix.yaml"
    path.write_text(CONFIG_YAML)
    loaded = load_matrix_config(path)
    assert loaded.bot_user_id == "@assistant:office.test"
    assert loaded.person_of("@zhang:office.test") == "zhang"
    assert loaded.own_user_ids() == {"@assistant:office.test", "@assistant-sync:office.test"}
    assert "hs-token" not in repr(loaded)


@pytest.mark.parametrize(
    ("update", "problem"),
    [
        ({"mode": "pull", "pull_access_token": None}, "pull_user_id and pull_access_token"),
        ({"people": {"lee": "lee@office"}}, "not a Matrix user id"),
        ({"groups": {"g": "printing"}}, "not a room id or alias"),
        ({"people": {"a": "@x:o", "b": "@x:o"}}, "share"),
        ({"colour": "blue"}, "Extra inputs"),
    ],
)
def test_bad_config_names_the_problem(tmp_path: Path, update: dict[str, Any], problem: str) -> None:
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump({**yaml.safe_load(CONFIG_YAML), **update}))
    with pytest.raises(MessengerError, match=problem):
        load_matrix_config(path)


def test_unreadable_config_is_a_clear_error(tmp_path: Path) -> None:
    with pytest.raises(MessengerError, match="cannot read"):
        load_matrix_config(tmp_path / "missing.yaml")
    (tmp_path / "list.yaml").write_text("- a\n")
    with pytest.raises(MessengerError, match="mapping"):
        load_matrix_config(tmp_path / "list.yaml")


def test_registration_claims_only_the_bot_exclusively(tmp_path: Path) -> None:
    path = write_registration(config(), tmp_path / "reg.yaml")
    reg = yaml.safe_load(path.read_text())
    assert reg["url"] == "http://127.0.0.1:8000"
    assert (reg["as_token"], reg["hs_token"], reg["sender_localpart"]) == (
        "as-token",
        "hs-token",
        "assistant",
    )
    assert reg["namespaces"]["users"] == [
        {"exclusive": True, "regex": r"^@assistant:office\.test$"}
    ]
    assert path.stat().st_mode & 0o777 == 0o600
    with pytest.raises(MessengerError, match="appservice_url"):
        write_registration(config(appservice_url=None), tmp_path / "none.yaml")


async def test_store_dedups_durably_and_replays_unhandled(
    tmp_path: Path, database_url: str | None
) -> None:
    path = tmp_path / "events.db"
    store = SqliteEventStore(path, database_url=database_url)
    assert await store.accept([message("$1"), message("$2")], txn_id="t1") == [
        message("$1"),
        message("$2"),
    ]
    assert await store.accept([message("$2"), message("$3")], sync_key="s", sync_token="n1") == [
        message("$3")
    ]
    await store.mark_handled("matrix", "$1")
    await store.close()
    with pytest.raises(MessengerError, match="closed"):
        await store.sync_token("s")

    reopened = SqliteEventStore(path, database_url=database_url)
    assert await reopened.transaction_seen("t1") and not await reopened.transaction_seen("t2")
    assert await reopened.sync_token("s") == "n1"
    assert [m.event_id for m in await reopened.unhandled()] == ["$2", "$3"]
    assert await reopened.event_seen("matrix", "$3") and not await reopened.event_seen(
        "slack", "$3"
    )
    await reopened.close()
    if database_url is None:
        with sqlite3.connect(path) as db:
            assert db.execute("PRAGMA journal_mode").fetchone()[0] == "wal"


async def test_store_write_is_atomic(tmp_path: Path, database_url: str | None) -> None:
    store = SqliteEventStore(tmp_path / "events.db", database_url=database_url)
    with pytest.raises(ValueError, match="together"):
        await store.accept([message("$1")], sync_key="s")
    assert not await store.event_seen("matrix", "$1")
    await store.close()


def test_normalize_media_and_filters() -> None:
    normalizer = EventNormalizer(config(), {"!group:office.test": "printing"})

    def event(
        sender: str, content: dict[str, Any], room: str = "!dm:office.test"
    ) -> InboundMessage | None:
        return normalizer.normalize(
            room,
            {
                "type": "m.room.message",
                "event_id": "$e",
                "sender": sender,
                "origin_server_ts": 1700000000000,
                "content": content,
            },
        )

    captioned = event(
        "@zhang:office.test",
        {
            "msgtype": "m.image",
            "body": "here it is",
            "filename": "scan.png",
            "url": "mxc://office.test/abc",
            "info": {"mimetype": "image/png"},
        },
        room="!group:office.test",
    )
    assert captioned is not None
    assert (str(captioned.chat), captioned.sender, captioned.text) == (
        "group:printing",
        "zhang",
        "here it is",
    )
    assert [(a.kind, a.name, a.mime, a.ref) for a in captioned.attachments] == [
        ("image", "scan.png", "image/png", "mxc://office.test/abc")
    ]
    assert event("@assistant:office.test", {"msgtype": "m.text", "body": "own"}) is None
    assert event("@stranger:office.test", {"msgtype": "m.text", "body": "hi"}) is None
    assert (
        event(
            "@lee:office.test",
            {
                "msgtype": "m.text",
                "body": "* fix",
                "m.relates_to": {"rel_type": "m.replace", "event_id": "$x"},
            },
        )
        is None
    )
    assert (
        event("@lee:office.test", {"msgtype": "m.file", "body": "secret.pdf", "file": {}}) is None
    )
    open_door = EventNormalizer(config(accept_unknown_senders=True), {})
    stranger = open_door.normalize(
        "!r:o",
        {
            "type": "m.room.message",
            "event_id": "$s",
            "sender": "@guest:elsewhere",
            "content": {"msgtype": "m.text", "body": "hi"},
        },
    )
    assert stranger is not None and str(stranger.chat) == "dm:@guest:elsewhere"


def test_transaction_ids_are_stable_and_distinct() -> None:
    assert transaction_id("k", 0) == transaction_id("k", 0)
    assert len({transaction_id("k", 0), transaction_id("k", 1), transaction_id("j", 0)}) == 3


def test_png_size_reads_the_header() -> None:
    import io

    import segno

    buffer = io.BytesIO()
    segno.make("x", micro=False).save(buffer, kind="png", scale=2, border=0)
    size = png_size(buffer.getvalue())
    assert size is not None and size[0] == size[1] == 42
    assert png_size(b"GIF89a....") is None
