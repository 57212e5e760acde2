"""The Matrix bot's own state and its reading of events, case by case (no homeserver)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml

from adapters.messenger.test_matrix_units import CONFIG_YAML
from assistantx.adapters.messenger.matrix import EventNormalizer, MatrixConfig, SqliteEventStore
from assistantx.adapters.messenger.matrix.normalize import (
    EDIT_TEXT,
    ENCRYPTED_TEXT,
    STRANGER_TEXT,
    AutoReply,
    strip_reply_fallback,
)
from assistantx.core.ports.messenger import InboundMessage

DM, GROUP = "!dm:office.test", "!group:office.test"


def strict_normalizer() -> EventNormalizer:
    normalizer = EventNormalizer(MatrixConfig.model_validate(yaml.safe_load(CONFIG_YAML)), {})
    normalizer.rooms.strict = True
    normalizer.rooms.groups[GROUP] = "printing"
    normalizer.rooms.dms[DM] = "lee"
    normalizer.rooms.questions["$q"] = "ins-7:s0a0"
    normalizer.rooms.questions["$told"] = ""
    return normalizer


def event(
    content: dict[str, Any],
    *,
    sender: str = "@lee:office.test",
    kind: str = "m.room.message",
    event_id: str = "$e",
) -> dict[str, Any]:
    return {
        "type": kind,
        "event_id": event_id,
        "sender": sender,
        "origin_server_ts": 1700000000000,
        "content": content,
    }


def text(body: str, **extra: Any) -> dict[str, Any]:
    return {"msgtype": "m.text", "body": body, **extra}


def test_only_recorded_dms_and_configured_groups_are_chats() -> None:
    n = strict_normalizer()
    [dm] = n.interpret(DM, event(text("bring me a stapler")))
    assert isinstance(dm, InboundMessage) and str(dm.chat) == "dm:lee"
    [group] = n.interpret(GROUP, event(text("I have one")))
    assert isinstance(group, InboundMessage) and str(group.chat) == "group:printing"
    assert n.interpret("!lunch:office.test", event(text("anyone up for lunch?"))) == []
    # Zhang writing in Lee's DM room does not make it hers.
    assert n.interpret(DM, event(text("hi"), sender="@zhang:office.test")) == []


def test_notices_and_own_messages_are_ignored() -> None:
    n = strict_normalizer()
    assert n.interpret(DM, event({"msgtype": "m.notice", "body": "build passed"})) == []
    assert n.interpret(DM, event(text("mine"), sender="@assistant:office.test")) == []
    assert n.interpret(DM, event(text("mine"), sender="@assistant-sync:office.test")) == []


def test_edits_encrypted_and_strangers_are_answered() -> None:
    n = strict_normalizer()
    edit = text("* fix", **{"m.relates_to": {"rel_type": "m.replace", "event_id": "$x"}})
    assert n.interpret(DM, event(edit)) == [AutoReply(DM, "$e", EDIT_TEXT)]
    encrypted = event({"algorithm": "m.megolm.v1.aes-sha2"}, kind="m.room.encrypted")
    assert n.interpret(DM, encrypted) == [AutoReply(DM, "$e", ENCRYPTED_TEXT)]
    stranger = event(text("hi"), sender="@guest:elsewhere")
    assert n.interpret("!x:elsewhere", stranger) == [AutoReply("!x:elsewhere", "$e", STRANGER_TEXT)]
    assert n.interpret(GROUP, stranger) == []  # not answered in a group


def test_long_text_gets_a_clear_reply() -> None:
    [reply] = strict_normalizer().interpret(DM, event(text("x" * 43_000)))
    assert isinstance(reply, AutoReply) and "43,000 characters" in reply.text
    [fits] = strict_normalizer().interpret(DM, event(text("x" * 4000)))
    assert isinstance(fits, InboundMessage)


def test_reactions_to_questions_are_answers() -> None:
    n = strict_normalizer()

    def react(target: str, key: str) -> list[Any]:
        relates = {"rel_type": "m.annotation", "event_id": target, "key": key}
        return n.interpret(DM, event({"m.relates_to": relates}, kind="m.reaction"))

    [yes] = react("$q", "👍🏽")
    assert isinstance(yes, InboundMessage)
    assert (yes.text, yes.in_reply_to, str(yes.chat)) == ("Yes", "ins-7:s0a0", "dm:lee")
    [no] = react("$q", "👎")
    assert isinstance(no, InboundMessage) and no.text == "No"
    [other] = react("$q", "🎉")
    assert isinstance(other, AutoReply) and "🎉" in other.text
    [plain] = react("$told", "👍")
    assert isinstance(plain, AutoReply)  # a reaction to a message that asked nothing
    assert react("$someone-elses", "👍") == []


def test_reply_fallback_is_stripped_and_the_reply_answers_its_question() -> None:
    body = "> <@assistant:office.test> May the robot come?\n> second line\n\nYes, come."
    relates = {"m.in_reply_to": {"event_id": "$q"}}
    [message] = strict_normalizer().interpret(DM, event(text(body, **{"m.relates_to": relates})))
    assert isinstance(message, InboundMessage)
    assert (message.text, message.in_reply_to) == ("Yes, come.", "ins-7:s0a0")
    assert strip_reply_fallback("> quoted only") == ""
    assert strip_reply_fallback("no quote\n> later") == "no quote\n> later"


def test_files_carry_the_office_item_and_a_captionless_one_is_acknowledged() -> None:
    content = {
        "msgtype": "m.file",
        "body": "report.pdf",
        "url": "mxc://office.test/r",
        "info": {"mimetype": "application/pdf"},
    }
    message, note = strict_normalizer().interpret(DM, event(content))
    assert isinstance(message, InboundMessage) and message.text == ""
    assert [(a.item, a.ref) for a in message.attachments] == [("file:lee", "mxc://office.test/r")]
    assert isinstance(note, AutoReply) and "report.pdf" in note.text
    captioned = {**content, "filename": "report.pdf", "body": "print this"}
    [only] = strict_normalizer().interpret(DM, event(captioned))
    assert isinstance(only, InboundMessage) and only.text == "print this"


async def test_transaction_ids_are_reused_for_a_retry_only(
    tmp_path: Path, database_url: str | None
) -> None:
    store = SqliteEventStore(tmp_path / "m.db", database_url=database_url)
    first = await store.outbound_part("ins-1:s0a0", 0, "d1", room_id="!r", instruction_id="ins-1")
    retry = await store.outbound_part("ins-1:s0a0", 0, "d1", room_id="!r", instruction_id="ins-1")
    assert retry == first and first.event_id is None
    await store.part_sent(first.txn_id, "$sent", "ins-1:s0a0")
    assert (
        await store.outbound_part("ins-1:s0a0", 0, "d1", room_id="!r", instruction_id="ins-1")
    ).event_id == "$sent"
    assert await store.question_of("$sent") == "ins-1:s0a0"
    # The same key for other content (an instruction id used again) gets a new id...
    other = await store.outbound_part("ins-1:s0a0", 0, "d2", room_id="!r", instruction_id="ins-1")
    assert other.txn_id != first.txn_id and other.event_id is None
    # ...and so does the same content once its instruction ended.
    await store.close_instruction("ins-1")
    again = await store.outbound_part("ins-1:s0a0", 0, "d2", room_id="!r", instruction_id="ins-1")
    assert again.txn_id not in (first.txn_id, other.txn_id)
    await store.close()


async def test_rooms_media_and_claims_survive_reopening(
    tmp_path: Path, database_url: str | None
) -> None:
    store = SqliteEventStore(tmp_path / "m.db", database_url=database_url)
    await store.set_dm_room("lee", "!a")
    await store.set_dm_room("lee", "!b")
    await store.set_dm_room("zhang", "!z")
    await store.set_dm_room("zhang", None)
    await store.remember_media("file:lee", "mxc://o/1", "report.pdf", "application/pdf")
    assert await store.claim("matrix", ["$x", "$y"]) == ["$x", "$y"]
    await store.close()
    reopened = SqliteEventStore(tmp_path / "m.db", database_url=database_url)
    assert await reopened.dm_rooms() == {"lee": "!b"}
    assert await reopened.media("file:lee") == ("mxc://o/1", "report.pdf", "application/pdf")
    assert await reopened.claim("matrix", ["$x", "$z"]) == ["$z"]
    assert await reopened.unhandled() == []  # claimed events are never replayed
    await reopened.close()
