"""The requester of ``assistantx run`` (no task, only the words they wrote) answers the
question they are asked as the person who asked: never as a colleague who owns the thing."""

from __future__ import annotations

from assistantx.agents.symbolic import InstructionParser, build_factory
from assistantx.core.settings import Settings
from assistantx.sim.requester import NOTHING_TO_ADD, Wish, answer
from assistantx.sim.run import run_in_sim
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
