"""A simulated keeper understands the robot's request for a service by the service's
multi-word name ("could you send to the dry cleaner Ilse's gown ...?"), as a colleague who
runs it would, not only by its declared verbs (``helpers.opera_wardrobe``); and the requester
of ``assistantx run`` never answers "to be dry cleaned" as the place it goes."""

from __future__ import annotations

from assistantx.sim.people import direct_reply
from assistantx.sim.requester import NOTHING_TO_ADD, Wish, answer
from assistantx.sim.understanding import mentioned_requests
from assistantx.sim.world import World
from helpers.opera_wardrobe import opera_wardrobe

_ASKED = (
    "Hi Gwen, could you send to the dry cleaner Ilse Brandt's gown in the goods door "
    "to Harlow Cleaners? The robot will come to you for the hand-over."
)


def test_the_service_s_name_says_the_service() -> None:
    assert [r for r in mentioned_requests(opera_wardrobe(), _ASKED) if r != "send_file"] == [
        "dryclean"
    ]


def test_its_keeper_agrees_and_someone_else_declines() -> None:
    world = World.from_office(opera_wardrobe())
    reply = direct_reply(world, "gwen", _ASKED)
    assert reply is not None and reply.text.startswith("Yes, I can do that (dryclean)")
    other = direct_reply(world, "tomas", _ASKED.replace("Gwen", "Tomás"))
    assert other is not None and not other.text.startswith("Yes")


def test_a_one_word_verb_inside_another_name_is_not_the_service() -> None:
    text = "Hi Kasia, could you bring Ilse Brandt a milkshake?"
    assert "dryclean" not in mentioned_requests(opera_wardrobe(), text)


def test_the_run_requester_names_no_place_for_the_work_asked() -> None:
    office = opera_wardrobe()
    question = (
        "Where should I send to the dry cleaner it to? Please give me the name of the cleaner."
    )
    vague = Wish.from_words(office, "ilse", "could you have my gown sent off to be dry cleaned?")
    assert answer(office, vague, question) == NOTHING_TO_ADD
    named = Wish.from_words(office, "ilse", "send my gown off to Harlow Cleaners, please")
    assert answer(office, named, question) == "To Harlow Cleaners."
