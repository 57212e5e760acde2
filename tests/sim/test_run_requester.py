"""The requester of ``assistantx run`` (no task, only the words they wrote) answers the
question they are asked as the person who asked: never as a colleague who owns the thing."""

from __future__ import annotations

from assistantx.agents.symbolic import InstructionParser, build_factory
from assistantx.core.settings import Settings
from assistantx.sim.requester import NOTHING_TO_ADD, Wish, answer
from assistantx.sim.run import run_in_sim
from helpers.bindery import bindery
from helpers.clinic import clinic


async def test_a_question_met_with_an_offer_moves_nothing_in_run() -> None:
    # Inés owns a clipboard herself: answered as a colleague, she said "Yes, I have a
    # clipboard. Happy to lend it.", which read as a yes, and Rich's clipboard was fetched.
    office = clinic()
    run = await run_in_sim(
        office, "ines", "does anyone here have a clipboard?", build_factory(office, Settings())
    )
    replies = [m.text for m in run.sim.messenger.received if m.sender == "ines"]
    assert replies == ["No, thanks."]
    assert not run.sim.world.handovers()
    assert run.trace.outcome == "done"


def test_without_a_task_the_requester_picks_the_option_they_wrote() -> None:
    office = clinic()
    wish = Wish.from_words(office, "hal", "print the handout for the dawn feeding round")
    question = "Do you mean Dawn Ellis, or the dawn feeding round?"
    assert answer(office, wish, question) == "the dawn feeding round"
    # nothing they wrote tells the options apart, or the question asks what they did not say
    assert answer(office, wish, "Do you mean Hal Brooks or Rich Adeyemi?") == NOTHING_TO_ADD
    assert answer(office, wish, "Who should get the printout?") == NOTHING_TO_ADD
    assert answer(office, wish, "Shall I bring you a thermometer?") == "No, thanks."


def test_a_reply_that_says_they_have_one_declines_the_offer() -> None:
    parser = InstructionParser(clinic())
    text = "is there a spare thermometer anywhere?"
    assert "Shall I" in (parser.parse(text, "rich").question or "")
    for reply in ("Yes, I have a thermometer. Happy to lend it.", "oh I've got one, thanks"):
        frame = parser.parse_with_answers(text, "rich", [reply])
        assert not frame.tasks, reply
        assert frame.decline is not None, reply
    frame = parser.parse_with_answers(text, "rich", ["yes please"])
    assert [t.item for t in frame.tasks] == ["thermometer"]


def test_without_a_task_an_offer_of_what_they_wrote_is_accepted() -> None:
    """ "robin okonkwo needs to sign my condition report" met with "Shall I get your
    condition report signed by Robin Okonkwo?": what their words ask for, so yes; an offer
    that changes the person, the owner, the item or the work is still declined."""
    office = bindery()
    wrote = "robin okonkwo needs to sign my condition report before it goes back to the lender"
    wish = Wish.from_words(office, "zoe", wrote)
    yes = "Shall I get your condition report signed by Robin Okonkwo?"
    assert answer(office, wish, yes) == "Yes, please."
    for offer in (
        "Shall I get Penny Castellanos's condition report signed by Robin Okonkwo?",
        "Shall I get your condition report signed by Ivy Marchetti?",
        "Shall I bring your condition report to Robin Okonkwo?",
        "Shall I bring you a kick stool?",
        "Shall I bring you one?",
        "Shall I go ahead?",
    ):
        assert answer(office, wish, offer) == "No, thanks.", offer
    others = Wish.from_words(office, "zoe", "Robin needs to sign Penny's condition report")
    assert answer(office, others, yes) == "No, thanks."


async def test_run_signs_the_report_its_owner_asked_to_be_signed() -> None:
    office = bindery()
    text = "robin okonkwo needs to sign my condition report before it goes back to the lender"
    run = await run_in_sim(office, "zoe", text, build_factory(office, Settings()))
    assert run.sim.world.check({"signed": ["report:zoe", "robin"]}), run.trace.outcome
    assert run.sim.world.check({"holds": ["zoe", "report:zoe"]})
