"""The simulated requester says yes to an offer of the very thing they asked for, however the
assistant's answer before the offer names it and whoever it says has one (blind rounds 20-22's
class: "As far as I know, A, B and C have a talkback headset. Shall I bring you one?" got
"No, thanks." from a requester who wanted any headset). The people before the offer are who
has one, not whom it is for; an offer of something else, or for someone else, still gets no.
"""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.parser import InstructionParser
from assistantx.core.goals import Milestone
from assistantx.sim.requester import Wish, answer
from helpers.one_episode import ppdr_episode
from helpers.outside_broadcast import outside_broadcast
from helpers.tyre_bay import tyre_bay

ANY_HEADSET: list[Milestone] = [{"holds": ["quill", "camera_headset:*"]}]
RENEES_HEADSET: list[Milestone] = [{"holds": ["quill", "camera_headset:renee"]}]
ANY_BATTERY: list[Milestone] = [{"holds": ["quill", "battery:*"]}]


def _says(goal: list[Milestone], question: str) -> str:
    office = outside_broadcast()
    wish = Wish.from_goal(office, "quill", [*goal, {"informed": "quill"}])
    return answer(office, wish, question)


@pytest.mark.parametrize(
    ("goal", "question"),
    [
        (
            ANY_HEADSET,
            "As far as I know, Renée Falk and Dov Harrow have a headset. Shall I bring you one?",
        ),
        (
            ANY_HEADSET,
            "As far as I know, Renée Falk, Dov Harrow and Anouk Teller have a camera headset. "
            "Shall I bring you one?",
        ),
        (
            ANY_HEADSET,
            "As far as I know, Dov Harrow and Renée Falk have headsets. Want me to get one?",
        ),
        (ANY_HEADSET, "Renée Falk has some cans. Shall I bring you one?"),
        (ANY_BATTERY, "As far as I know, Dov Harrow has spare batteries. Shall I bring you one?"),
        # a wish of someone's own: yes when the one named is theirs
        (RENEES_HEADSET, "As far as I know, Renée Falk has a headset. Shall I bring you one?"),
        (ANY_HEADSET, "Shall I bring you a headset?"),
    ],
)
def test_an_offer_of_the_wanted_thing_gets_a_yes(goal: list[Milestone], question: str) -> None:
    assert _says(goal, question) == "Yes, please."


@pytest.mark.parametrize(
    ("goal", "question"),
    [
        # something else
        (
            ANY_HEADSET,
            "As far as I know, Anouk Teller has some ear defenders. Shall I bring you one?",
        ),
        (ANY_BATTERY, "As far as I know, Renée Falk has a headset. Shall I bring you one?"),
        # for someone else
        (ANY_HEADSET, "Shall I bring Dov Harrow a headset?"),
        # one of several, when a particular colleague's is wanted
        (
            RENEES_HEADSET,
            "As far as I know, Renée Falk and Dov Harrow have a headset. Shall I bring you one?",
        ),
        # a question that asks for nothing
        ([], "As far as I know, Renée Falk and Dov Harrow have a headset. Shall I bring you one?"),
    ],
)
def test_an_offer_of_anything_else_gets_a_no(goal: list[Milestone], question: str) -> None:
    assert _says(goal, question) == "No, thanks."


@pytest.mark.parametrize(
    ("instruction", "offered"),
    [
        # the speaker's own one amiss beside the ask makes it a request: no offer to answer
        # (blind round 59-60 class 3)
        ("anyone got a spare camera headset? mine's crackling", False),
        ("does anyone have a headset?", True),
        ("has anybody got spare batteries", True),
    ],
)
async def test_the_question_offered_on_is_answered_yes_and_the_task_is_done(
    instruction: str, offered: bool
) -> None:
    office = outside_broadcast()
    asked = InstructionParser(office).parse(instruction, "quill").question
    if offered:
        assert asked is not None and asked.endswith("Shall I bring you one?")
    else:
        assert asked is None
    wanted = "battery" if "batter" in instruction else "camera_headset"
    episode = await ppdr_episode(
        office, "quill", instruction, [{"holds": ["quill", f"{wanted}:*"]}, {"informed": "quill"}]
    )
    assert episode.trace.outcome == "done", episode.trace.summary
    assert all(episode.milestones), (episode.milestones, episode.trace.summary)


def test_a_supply_a_facility_keeps_is_anyones_to_the_requester() -> None:
    """Blind round 37's eval class: the goal's charger was the lost-property locker's (a
    facility's supply, anyone's to take), and "As far as I know, C, S and D have a phone
    charger. Shall I bring you one?" got "No, thanks." as if the locker were an owner."""
    office = tyre_bay()
    wish = Wish.from_goal(office, "ines", [{"holds": ["ines", "staples:supply_room"]}])
    assert (wish.own, wish.owners) == ("any", ())
    offer = "As far as I know, Bruno Keel has a box of staples. Shall I bring you one?"
    assert answer(office, wish, offer) == "Yes, please."
    someone_elses = "Shall I bring Tove Lind a box of staples?"
    assert answer(office, wish, someone_elses) == "No, thanks."
