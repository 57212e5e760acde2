"""A full hand-over driven by hand through the simulator, and the ways it goes wrong."""

from __future__ import annotations

import pytest

from assistantx.core.actions import Inform, Inquire, Move, SendQR, Stop, Wait, WaitInPlace
from assistantx.core.errors import AmbiguousNameError, UnknownNameError
from assistantx.core.office import Office, load_office
from assistantx.sim.session import SimSession

STAPLER_TO_LEE = [{"holds": ["lee", "stapler:zhang"]}, {"informed": "lee"}]


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


async def test_full_handover_reaches_the_goal(office: Office) -> None:
    async with SimSession(office, requester="lee") as s:
        r = await s.do(Inquire(contact="Dr. Zhang", question="Do you have a stapler?"))
        assert r.ok
        r = await s.do(Wait(timeout_s=60))
        assert r.ok and "Yes, I have a stapler" in r.observation
        await s.do(Inform(contact="zhang", content="The robot is coming for your stapler."))
        assert (await s.do(Move(place="Zhang"))).data["distance_m"] > 0
        await s.do(SendQR(contact="zhang", item="Zhang's stapler", purpose="deposit"))
        r = await s.do(WaitInPlace(person="zhang"))
        assert r.ok, r.observation
        assert s.stm.embodied.locker_contents == ["stapler:zhang"]
        assert s.sim.world.holder["stapler:zhang"] == "locker"
        await s.do(Move(place="lee"))
        await s.do(SendQR(contact="lee", item="stapler:zhang", purpose="collect"))
        r = await s.do(WaitInPlace(person="lee"))
        assert r.ok, r.observation
        await s.do(Stop(outcome="done", summary="Zhang's stapler is on your desk."))
        assert s.sim.check(STAPLER_TO_LEE) == [True, True]
        moves = [(e.detail["item"], e.detail["to"]) for e in s.sim.world.handovers()]
        assert moves == [("stapler:zhang", "locker"), ("stapler:zhang", "lee")]


async def test_skipping_the_qr_code_leaves_the_goal_unmet(office: Office) -> None:
    async with SimSession(office, requester="lee") as s:
        await s.do(Inform(contact="zhang", content="The robot is coming for your stapler."))
        await s.do(Move(place="zhang"))
        r = await s.do(WaitInPlace(person="zhang", timeout_s=120))  # no QR code sent
        assert not r.ok and "did not come" in r.observation
        await s.do(Move(place="lee"))
        assert s.sim.check(STAPLER_TO_LEE) == [False, False]


async def test_person_not_told_what_to_do_does_not_come(office: Office) -> None:
    async with SimSession(office, requester="lee") as s:
        await s.do(Move(place="zhang"))
        await s.do(SendQR(contact="zhang", item="stapler:zhang"))
        r = await s.do(WaitInPlace(person="zhang", timeout_s=120))
        assert not r.ok
        assert s.sim.world.holder["stapler:zhang"] == "zhang"


async def test_unavailable_person_never_answers_nor_hands_over(office: Office) -> None:
    async with SimSession(office, requester="lee", unavailable=("zhang",)) as s:
        await s.do(Inquire(contact="zhang", question="Do you have a stapler?"))
        r = await s.do(Wait(timeout_s=90))
        assert not r.ok and r.data["timed_out"]
        assert s.sim.clock.now() >= 90
        await s.do(Move(place="zhang"))
        await s.do(SendQR(contact="zhang", item="stapler:zhang"))
        assert not (await s.do(WaitInPlace(person="zhang", timeout_s=60))).ok
        assert s.sim.world.holder["stapler:zhang"] == "zhang"


async def test_group_chat_finds_an_unknown_owner(office: Office) -> None:
    # hu and gao own staplers but the assistant does not know it; zhang and wang are away.
    async with SimSession(office, requester="lee", unavailable=("zhang", "wang")) as s:
        assert "hu" not in s.ltm.owners("stapler")
        await s.do(Inquire(contact="Office Work", question="Does anyone have a stapler?"))
        r = await s.do(Wait(timeout_s=60))
        assert r.ok
        helpers = {t.person for t in s.stm.dialogue if t.direction == "in"}
        assert helpers <= {"hu", "gao"} and helpers
        assert all(t.chat.kind == "group" for t in s.stm.dialogue if t.direction == "in")


async def test_replies_are_matched_to_the_question(office: Office) -> None:
    async with SimSession(office, requester="lee") as s:
        first = await s.do(Inquire(contact="chen", question="Do you have scissors?"))
        await s.do(Inquire(contact="wang", question="Do you have a stapler?"))
        await s.do(Wait(timeout_s=60))
        await s.do(Wait(timeout_s=60))
        answers = {t.person: t for t in s.stm.dialogue if t.direction == "in"}
        assert answers["chen"].in_reply_to == first.data["question_id"]
        assert "scissors" in answers["chen"].text


async def test_same_qr_code_is_never_sent_twice(office: Office) -> None:
    async with SimSession(office, requester="lee") as s:
        await s.do(Inquire(contact="zhang", question="Could you lend Lee your stapler?"))
        assert (await s.do(Wait(timeout_s=60))).ok
        assert (await s.do(SendQR(contact="zhang", item="stapler:zhang"))).ok
        again = await s.do(SendQR(contact="zhang", item="stapler:zhang"))
        assert not again.ok and "never resend" in again.observation
        qr_messages = [m for m in s.sim.messenger.sent if m.attachments]
        assert len(qr_messages) == 1


async def test_ambiguous_and_unknown_names_are_errors(office: Office) -> None:
    wang_li = office.person("sun").model_copy(
        update={"id": "wang_li", "name": "Wang Li", "aliases": (), "handle": "@wangli"}
    )
    two_lis = office.model_copy(update={"people": (*office.people, wang_li)})
    async with SimSession(two_lis, requester="lee") as s:
        with pytest.raises(UnknownNameError, match="Unknown contact 'Smith'"):
            await s.do(Inform(contact="Smith", content="hi"))
        with pytest.raises(AmbiguousNameError, match="matches sun, wang_li"):
            await s.do(Inform(contact="Li", content="hi"))
        with pytest.raises(UnknownNameError, match="Did you mean"):
            await s.do(Move(place="desk"))
        assert s.sim.messenger.sent == []


async def test_printing_needs_the_file_first(office: Office) -> None:
    from assistantx.core.actions import ForwardFile

    async with SimSession(office, requester="lee") as s:
        await s.do(Inquire(contact="xu", question="Could you print Lee's file for me?"))
        assert "Yes" in (await s.do(Wait(timeout_s=60))).observation
        await s.do(Move(place="printer"))
        await s.do(SendQR(contact="xu", item="printout:lee", purpose="produce"))
        r = await s.do(WaitInPlace(person="xu"))
        assert not r.ok  # xu has no file to print and says so
        assert any("haven't received the file" in t.text for t in s.stm.dialogue)
        await s.do(ForwardFile(source="lee", target="xu"))
        resent = await s.do(SendQR(contact="xu", item="printout:lee", purpose="produce"))
        assert not resent.ok  # xu still holds the first, unused code
        await s.do(Move(place="lee"))
        await s.do(Move(place="printer"))
        assert (await s.do(WaitInPlace(person="xu"))).ok
        assert s.sim.check([{"printed": "file:lee"}]) == [True]


def _complaints(s: SimSession, person: str) -> list[str]:
    return [
        m.text
        for m in s.sim.messenger.received
        if m.sender == person and m.text.startswith("I came to the robot, but")
    ]


async def test_a_person_who_cannot_hand_over_says_so_once(office: Office) -> None:
    """Zhang agrees to lend her stapler, but it is gone from her desk by the time the robot
    comes (Wang took it): she comes, says so, and does not walk to the robot to say it again
    each time it comes back."""
    async with SimSession(office, requester="lee") as s:
        await s.do(Inquire(contact="zhang", question="Could you lend Lee your stapler?"))
        assert (await s.do(Wait(timeout_s=60))).ok
        s.sim.world.holder["stapler:zhang"] = "wang"
        await s.do(Move(place="zhang"))
        assert (await s.do(SendQR(contact="zhang", item="stapler:zhang", purpose="deposit"))).ok
        r = await s.do(WaitInPlace(person="zhang", timeout_s=120))
        assert not r.ok
        assert _complaints(s, "zhang") == ["I came to the robot, but: I don't have my stapler."]
        for _ in range(3):
            await s.do(Move(place="lee"))
            await s.do(Move(place="zhang"))
            await s.do(Inform(contact="zhang", content="The robot is back at your desk."))
            await s.do(WaitInPlace(person="zhang", timeout_s=120))
        assert len(_complaints(s, "zhang")) == 1


async def test_a_new_code_replaces_the_one_a_person_held(office: Office) -> None:
    async with SimSession(office, requester="lee") as s:
        await s.do(Inquire(contact="zhang", question="Could you lend Lee your stapler?"))
        assert (await s.do(Wait(timeout_s=60))).ok
        assert (await s.do(SendQR(contact="zhang", item="stapler:zhang", purpose="deposit"))).ok
        await s.executor.revoke_codes(s.stm, person="zhang")
        await s.do(SendQR(contact="zhang", item="stapler:zhang", purpose="deposit"))
        held = [c for c in s.sim.codes if c.person == "zhang"]
        assert len(held) == 1
        assert held[0].payload == s.sim.messenger.sent[-1].attachments[0].qr_payload
