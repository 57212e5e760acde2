"""Replies reach the instruction that asked; unprompted messages are routed with care."""

from __future__ import annotations

from datetime import UTC, datetime

import pytest

from assistantx.core.ports.messenger import ChatRef, InboundMessage
from assistantx.runtime.replies import ReplyBox


def _msg(
    sender: str, chat: ChatRef, text: str = "hi", reply_to: str | None = None
) -> InboundMessage:
    return InboundMessage(
        platform="t",
        event_id=f"e-{sender}-{text}",
        chat=chat,
        sender=sender,
        text=text,
        time=datetime.now(tz=UTC),
        in_reply_to=reply_to,
    )


def test_explicit_reference_beats_recency() -> None:
    box = ReplyBox()
    zhang = ChatRef(kind="dm", id="zhang")
    box.ask("q1", "ins-1", zhang, 0)
    box.ask("q2", "ins-2", zhang, 1)
    assert box.route(_msg("zhang", zhang, reply_to="q1")) == "ins-1"
    assert box.route(_msg("zhang", zhang, "later")) == "ins-2"
    assert [m.in_reply_to for m in box.take("ins-2")] == ["q2"]


def test_unprompted_message_goes_to_the_instruction_that_wrote_there() -> None:
    box = ReplyBox()
    zhang = ChatRef(kind="dm", id="zhang")
    box.engage("ins-1", zhang)
    assert box.route(_msg("zhang", zhang, "I can't come")) == "ins-1"
    box.close("ins-1")
    assert box.route(_msg("zhang", zhang, "bring me a coffee")) is None


def test_group_answers_are_filed_under_the_asking_instruction() -> None:
    box = ReplyBox()
    group = ChatRef(kind="group", id="office_work")
    box.ask("q9", "ins-3", group, 0)
    assert box.route(_msg("hu", group, "I have one")) == "ins-3"
    assert box.route(_msg("gao", group, "me too")) == "ins-3"
    assert [m.sender for m in box.take("ins-3")] == ["hu", "gao"]
    assert box.route(_msg("lin", ChatRef(kind="group", id="study_group"))) is None


def test_a_reference_to_a_question_asked_in_another_dm_is_not_an_answer() -> None:
    box = ReplyBox()
    wang, zhang = ChatRef(kind="dm", id="wang"), ChatRef(kind="dm", id="zhang")
    box.ask("q-wang", "ins-1", wang, 0)
    # Zhang quotes, in his own DM, the question sent to Wang: it answers nothing.
    assert box.route(_msg("zhang", zhang, "yes, I have one", reply_to="q-wang")) is None
    assert box.take("ins-1") == []
    # Wang, in his DM, does answer it.
    assert box.route(_msg("wang", wang, "yes", reply_to="q-wang")) == "ins-1"
    assert [m.sender for m in box.take("ins-1")] == ["wang"]


def test_a_foreign_reference_is_dropped_not_kept_as_an_answer() -> None:
    box = ReplyBox()
    wang, zhang = ChatRef(kind="dm", id="wang"), ChatRef(kind="dm", id="zhang")
    box.ask("q-wang", "ins-1", wang, 0)
    box.ask("q-zhang", "ins-2", zhang, 1)
    # Zhang names Wang's question; he may still answer the one asked in his own DM.
    assert box.route(_msg("zhang", zhang, "I have one", reply_to="q-wang")) == "ins-2"
    assert [m.in_reply_to for m in box.take("ins-2")] == ["q-zhang"]
    assert box.take("ins-1") == []


def test_a_group_question_is_answered_only_in_the_group_by_members() -> None:
    members = {"office_work": {"hu", "gao"}}
    box = ReplyBox(is_member=lambda person, group: person in members.get(group, set()))
    group = ChatRef(kind="group", id="office_work")
    box.ask("q9", "ins-3", group, 0)
    assert box.route(_msg("hu", ChatRef(kind="dm", id="hu"), "me", reply_to="q9")) is None
    other = ChatRef(kind="group", id="study_group")
    assert box.route(_msg("lin", other, "me", reply_to="q9")) is None
    assert box.route(_msg("lin", group, "me", reply_to="q9")) is None  # not a member
    assert box.route(_msg("gao", group, "me", reply_to="q9")) == "ins-3"
    assert [m.sender for m in box.take("ins-3")] == ["gao"]


def test_a_word_after_an_answered_question_follows_the_chats_last_writer() -> None:
    """Three instructions asked Wang, he said yes to each; one then sent him a locker code.
    "I came to the robot, but I don't have it" is about that code: it goes to the one that
    wrote last, not to the newest question (seen: it went to another instruction, and the
    one waiting at the locker sent Wang 29 codes, never told why he did not come)."""
    box = ReplyBox()
    wang = ChatRef(kind="dm", id="wang")
    for n in (1, 2, 3):
        box.ask(f"q{n}", f"ins-{n}", wang, n)
        box.engage(f"ins-{n}", wang)
    for n in (1, 2, 3):
        assert box.route(_msg("wang", wang, f"yes {n}", reply_to=f"q{n}")) == f"ins-{n}"
    box.engage("ins-2", wang)  # the code
    assert box.route(_msg("wang", wang, "I came to the robot, but I don't have it")) == "ins-2"
    assert [m.in_reply_to for m in box.take("ins-2")] == ["q2", "q2"]


def test_an_unanswered_question_still_takes_the_next_word() -> None:
    box = ReplyBox()
    wang = ChatRef(kind="dm", id="wang")
    box.ask("q1", "ins-1", wang, 1)
    box.engage("ins-1", wang)
    box.engage("ins-2", wang)  # a code sent while Wang's answer to ins-1 is pending
    assert box.route(_msg("wang", wang, "yes, I have one")) == "ins-1"


def test_writers_registered_again_after_a_restart_keep_the_order_they_wrote_in() -> None:
    box = ReplyBox()
    wang = ChatRef(kind="dm", id="wang")
    box.ask("q1", "ins-1", wang, 1, answered=True)
    box.engage("ins-1", wang, 5.0)  # resumed first, though it wrote earlier
    box.engage("ins-2", wang, 3.0)
    assert box.route(_msg("wang", wang, "I don't have it")) == "ins-1"
    box.engage("ins-2", wang)  # a write after the restart comes after every journaled one
    assert box.route(_msg("wang", wang, "still don't")) == "ins-2"


def _ended_after(box: ReplyBox, question: str, chat: ChatRef) -> str | None:
    """The ended instruction a late reply to ``question`` in ``chat`` is about."""
    return box.ended_instruction(_msg(chat.id, chat, "late", reply_to=question))


def test_only_the_latest_ended_instructions_are_remembered() -> None:
    box = ReplyBox(ended_kept=2)
    chats = [ChatRef(kind="dm", id=p) for p in ("zhang", "wang", "lee")]
    for i, chat in enumerate(chats, start=1):
        box.ask(f"q{i}", f"ins-{i}", chat, i)
        box.close(f"ins-{i}")
    assert _ended_after(box, "q1", chats[0]) is None  # forgotten with its chat
    assert box.ended_instruction(_msg("zhang", chats[0], "hello again")) is None
    assert _ended_after(box, "q2", chats[1]) == "ins-2"
    assert _ended_after(box, "q3", chats[2]) == "ins-3"
    assert box.ended_instruction(_msg("lee", chats[2], "hello again")) == "ins-3"


def test_forgetting_an_instruction_keeps_a_chat_a_later_one_ended_in() -> None:
    box = ReplyBox(ended_kept=1)
    zhang = ChatRef(kind="dm", id="zhang")
    box.ask("q1", "ins-1", zhang, 0)
    box.close("ins-1")
    box.ask("q2", "ins-2", zhang, 1)
    box.close("ins-2")  # ins-1 is forgotten; the chat now names ins-2
    assert _ended_after(box, "q1", zhang) == "ins-2"  # q1 unknown: the chat's last one
    assert box.ended_instruction(_msg("zhang", zhang, "one more thing")) == "ins-2"


def test_what_is_remembered_of_ended_instructions_stays_bounded() -> None:
    box = ReplyBox(ended_kept=4)
    for i in range(1000):
        chat = ChatRef(kind="dm", id=f"person-{i % 7}")
        box.ask(f"q{i}a", f"ins-{i}", chat, i)
        box.ask(f"q{i}b", f"ins-{i}", chat, i)
        box.engage(f"ins-{i}", chat, i)
        box.close(f"ins-{i}")
    remembered = [
        i
        for i in range(1000)
        if _ended_after(box, f"q{i}a", ChatRef(kind="group", id="elsewhere")) is not None
    ]
    assert remembered == [996, 997, 998, 999]
    assert all(
        _ended_after(box, f"q{i}b", ChatRef(kind="group", id="elsewhere")) == f"ins-{i}"
        for i in remembered
    )


def test_ended_kept_must_be_positive() -> None:
    with pytest.raises(ValueError, match="ended_kept"):
        ReplyBox(ended_kept=0)
