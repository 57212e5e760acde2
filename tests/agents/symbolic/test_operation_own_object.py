"""An operation whose name carries an object of its own ("restring a guitar", "polish a
trumpet", "patch a tube"): every message that says the operation on the real thing uses the
name's verb with that thing ("could you polish Ines Kowal's trumpet"), never the name and the
thing side by side ("polish a trumpet Ines Kowal's trumpet"), and so does the summary ("your
trumpet was polished", "polish your trumpet"). A name with no object of its own ("print",
"make coffee", "send to the lab") is said as before (``core.wording``)."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.planning import describe
from assistantx.core.goals import Milestone
from assistantx.core.office import Operation
from assistantx.core.task_schema import Task
from assistantx.core.wording import done_words, operation_verb, product_words, with_object
from assistantx.evaluation import metrics
from helpers.music_school import music_school
from helpers.one_episode import ppdr_episode


@pytest.mark.parametrize(
    ("name", "said"),
    [
        ("patch a tube", "patch Miles's inner tube"),
        ("wash the mugs", "wash Miles's inner tube"),
        ("restring a guitar", "restring Miles's inner tube"),
        ("send a parcel to the lab", "send Miles's inner tube to the lab"),
        # must not change: no object of its own
        ("print", "print Miles's inner tube"),
        ("laser print", "laser print Miles's inner tube"),
        ("send off", "send Miles's inner tube off"),
        ("send to the lab", "send Miles's inner tube to the lab"),
    ],
)
def test_the_real_thing_takes_the_names_object_place(name: str, said: str) -> None:
    assert with_object(name, "Miles's inner tube") == said


@pytest.mark.parametrize(
    ("name", "made", "said"),
    [
        # the name's object is what the operation makes: kept, the thing worked on after "from"
        ("print a banner", "banner", "print a banner from Amber's file"),
        ("cut a key", "spare_key", "cut a key from Amber's file"),
        # a bare object, every word of it what the operation makes: kept the same way
        ("print barcode labels", "barcode_labels", "print barcode labels from Amber's file"),
        ("print labels", "label", "print labels from Amber's file"),
        ("grind coffee", "coffee", "grind coffee from Amber's file"),
        # a two-word verb whose first word is also the product's is no verb and object
        ("laser print", "laser_print", "laser print Amber's file"),
        ("print barcodes", "box_label", "print barcodes Amber's file"),
        # what it makes is no word of the name's object: the verb with the thing, as above
        ("patch a tube", "repair_note", "patch Amber's file"),
    ],
)
def test_a_name_whose_object_is_what_it_makes_keeps_it(name: str, made: str, said: str) -> None:
    op = Operation(id="op", name=name, product=made)
    assert with_object(name, "Amber's file", made=product_words(op)) == said


def test_what_it_makes_is_said_in_the_verb_and_the_outcome() -> None:
    op = Operation(id="b", name="print a banner", product="banner")
    assert operation_verb(op.name, product_words(op)) == "print a banner from"
    assert done_words(op) == "printed a banner"


def test_the_verb_and_what_it_did() -> None:
    assert operation_verb("patch a tube") == "patch"
    assert operation_verb("make coffee") == "make coffee"
    assert done_words(Operation(id="p", name="patch a tube")) == "patched"
    assert done_words(Operation(id="r", name="restring a guitar")) == "restrung"
    assert done_words(Operation(id="s", name="shred")) == "shredded"


def test_the_summary_says_the_verb_with_the_thing() -> None:
    office = music_school()
    task = Task(kind="heat", item="trumpet", owner="ines", recipient="ines", operation="polish")
    assert describe(task, office, "ines") == "polish your trumpet for you"


async def test_the_keeper_is_asked_in_english_and_does_it() -> None:
    office = music_school()
    goal: list[Milestone] = [
        {"heated": "trumpet:ines"},
        {"holds": ["ines", "trumpet:ines"]},
        {"informed": "ines"},
    ]
    episode = await ppdr_episode(office, "ines", "can Nell polish my trumpet", goal)
    assert metrics.success(episode), (episode.milestones, episode.trace.summary)
    asked = [str(r.action.question) for r in episode.trace.actions() if r.action.type == "inquire"]
    assert asked and all("polish Ines Kowal's trumpet" in q for q in asked), asked
    assert "a trumpet" not in (episode.trace.summary or ""), episode.trace.summary
