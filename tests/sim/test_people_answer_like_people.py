"""Simulated people answer like people: the requester from what they really want, colleagues
from the office's own tables (a "label printer" is a thing to lend, not a request to print)."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import build_factory
from assistantx.core.office import DEFAULT_OFFICE, Office, load_office, parse_office
from assistantx.core.settings import Settings
from assistantx.sim.people import direct_reply
from assistantx.sim.requester import Wish, answer
from assistantx.sim.run import run_in_sim
from assistantx.sim.understanding import mentioned_requests
from assistantx.sim.world import World
from helpers.yaml_files import raw_yaml


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


def _wish(office: Office, requester: str, *goal: dict[str, object]) -> Wish:
    return Wish.from_goal(office, requester, [*goal, {"informed": requester}])


def test_the_option_that_fits_the_truth_is_chosen(harbour: Office) -> None:
    grace = harbour.person("grace").name
    question = f"Do you mean {grace}, or the grace period talk?"
    for_me = _wish(harbour, "bill", {"holds": ["bill", "printout:bill"]}, {"printed": "file:bill"})
    assert answer(harbour, for_me, question) == "the grace period talk"
    for_her = _wish(harbour, "bill", {"holds": ["grace", "printout:bill"]})
    assert answer(harbour, for_her, question) == grace


def test_an_offer_is_accepted_only_when_it_is_what_they_want(office: Office) -> None:
    stapler = _wish(office, "lee", {"holds": ["lee", "stapler:*"]})
    nothing = Wish.from_goal(office, "lee", [{"informed": "lee"}])
    zhangs = _wish(office, "lee", {"holds": ["lee", "stapler:zhang"]})
    assert answer(office, stapler, "Shall I bring you a stapler?") == "Yes, please."
    assert answer(office, nothing, "Shall I bring you a stapler?") == "No, thanks."
    assert answer(office, zhangs, "Shall I bring you Wang Fang's stapler?") == "No, thanks."
    assert answer(office, zhangs, "Shall I bring you Zhang Wei's stapler?") == "Yes, please."
    assert answer(office, stapler, "Shall I bring you some scissors?") == "No, thanks."
    assert answer(office, stapler, "Shall I go ahead?") == "Yes, please."
    assert answer(office, nothing, "Shall I go ahead?") == "No, thanks."


def test_missing_recipient_owner_signer_and_item_are_told(office: Office) -> None:
    wish = _wish(office, "lee", {"holds": ["zhou", "book:zhang"]})
    zhou, zhang = office.person("zhou").name, office.person("zhang").name
    assert answer(office, wish, "Who should get Zhang Wei's book?") == f"{zhou}."
    assert answer(office, wish, "Whose book do you mean?") == f"{zhang}'s."
    assert answer(office, wish, "Which item do you mean? Please tell me what it is.") == "The book."
    signed = _wish(office, "lee", {"signed": ["document:lee", "wang"]})
    who = "Who should do that with your document? Please tell me their name."
    assert answer(office, signed, who) == f"{office.person('wang').name}."
    two = f"Which do you mean: {zhang}, {office.person('wang').name}?"
    assert answer(office, _wish(office, "lee", {"holds": ["lee", "book:zhang"]}), two) == zhang
    assert answer(office, wish, "Sorry?") == f"I mean {zhang}'s book, for {zhou}."


async def test_the_requester_answers_a_clarifying_question_from_the_task(office: Office) -> None:
    # "forward my file" names nobody: the assistant asks, Lee names Zhou (the task's truth),
    # and the file goes to Zhou. Before, Lee answered "Yes, I'm here. What do you need?".
    goal = [{"received": ["zhou", "file:lee"]}, {"informed": "lee"}]
    run = await run_in_sim(
        office,
        "lee",
        "Please forward my file.",
        build_factory(office, Settings()),
        wish=Wish.from_goal(office, "lee", goal),
    )
    asked = [t for t in run.trace.actions() if t.action.type == "inquire"]
    assert asked, "the assistant should have asked who gets the file"
    replies = [m.text for m in run.sim.messenger.received if m.sender == "lee"]
    assert replies == [f"{office.person('zhou').name}."]
    assert run.trace.outcome == "done"
    assert run.sim.check(goal) == [True, True]


def _office_with_a_label_printer() -> Office:
    raw = {
        "name": "labels",
        "locations": [
            {"id": "desk_a", "kind": "workstation", "name": "a", "x": 0, "y": 0},
            {"id": "desk_b", "kind": "workstation", "name": "b", "x": 1, "y": 0},
            {"id": "print_room", "kind": "facility", "name": "print room", "x": 5, "y": 5},
        ],
        "item_types": [
            {"id": "label_printer", "name": "label printer"},
            {"id": "file", "name": "file", "kind": "electronic"},
            {"id": "printout", "name": "printout", "kind": "product"},
        ],
        "operations": [
            {
                "id": "print",
                "name": "print",
                "verbs": ["print"],
                "input": "file",
                "product": "printout",
            },
        ],
        "people": [
            {"id": "ann", "name": "Ann Lee", "location": "desk_a", "handle": "@ann"},
            {
                "id": "bo",
                "name": "Bo Kim",
                "location": "desk_b",
                "handle": "@bo",
                "owns": [{"type": "label_printer"}],
            },
        ],
        "facilities": [
            {
                "id": "printer",
                "name": "printer",
                "location": "print_room",
                "operations": ["print"],
                "guards": ["ann"],
            },
        ],
        "groups": [{"id": "all", "name": "All", "members": ["ann", "bo"]}],
        "robot": {"home": "print_room"},
    }
    return parse_office(raw)


def test_a_label_printer_is_a_thing_to_lend_not_a_request_to_print() -> None:
    labels = _office_with_a_label_printer()
    ask = "Hi Bo, could you lend Ann your label printer? The robot will come to you."
    assert mentioned_requests(labels, ask) == []
    reply = direct_reply(World.from_office(labels), "bo", ask)
    assert reply is not None and reply.text == "Yes, I have a label printer. Happy to lend it."
    # the operation itself, in any of its forms, is still read
    for said in ("could you print Bo's file?", "Could you get it printed?", "printing, please"):
        assert mentioned_requests(labels, said) == ["print"], said


def test_a_keeper_is_asked_about_someone_elses_kept_item(office: Office) -> None:
    # Chen looks after the fridge and has a lunch of his own: asked for Zhang's, he takes it out
    world = World.from_office(office)
    text = "Hi Chen, could you take Zhang Wei's lunch out of the fridge for the robot?"
    reply = direct_reply(world, "chen", text)
    assert reply is not None
    assert reply.text == "Yes, I can take Zhang Wei's lunch out for the robot."
    owner = direct_reply(world, "zhang", "Hi Zhang, could you let Lee have your lunch?")
    assert owner is not None and owner.text.startswith("Yes, you can have my lunch.")
    assert "fridge" in owner.text  # where it really is (tests/sim/test_kept_items_answers.py)


def test_asked_to_receive_a_delivery_they_say_whether_they_are_there() -> None:
    """In an office whose item is called a "delivery" (a parcel), the robot's question "could
    you be at your desk to receive a delivery?" is about being there, not about lending one."""
    parcels = parse_office(
        {
            "name": "parcels",
            "locations": [
                {"id": "desk_a", "kind": "workstation", "name": "a", "x": 0, "y": 0},
                {"id": "desk_b", "kind": "workstation", "name": "b", "x": 1, "y": 0},
            ],
            "item_types": [{"id": "parcel", "name": "parcel", "synonyms": ["delivery"]}],
            "people": [
                {"id": "ann", "name": "Ann Lee", "location": "desk_a", "handle": "@ann"},
                {"id": "bo", "name": "Bo Kim", "location": "desk_b", "handle": "@bo"},
            ],
            "facilities": [],
            "groups": [{"id": "all", "name": "All", "members": ["ann", "bo"]}],
            "robot": {"home": "desk_a"},
        }
    )
    ask = "Hi Bo, could you be at your desk soon to receive a delivery from Ann Lee?"
    reply = direct_reply(World.from_office(parcels), "bo", ask)
    assert reply is not None and reply.text.startswith("Yes, I'm here")


def test_a_keeper_reads_whose_item_by_the_full_name_not_a_colleagues_given_name(
    office: Office,
) -> None:
    """Round 4 (b1): "Anna Mao's lunch" is Anna Mao's, though Mao is a colleague's given name;
    the fridge's keeper takes it out instead of saying they do not have Mao's lunch."""
    with_anna = _with_anna_mao({"type": "lunch", "at": "fridge_corner"})
    keeper = with_anna.facility("fridge").guards[0]
    text = "Hi, could you take Anna Mao's lunch out of the fridge for the robot?"
    reply = direct_reply(World.from_office(with_anna), keeper, text)
    assert reply is not None and reply.text == "Yes, I can take Anna Mao's lunch out for the robot."


def _with_anna_mao(owned: dict[str, str]) -> Office:
    """The default office with Anna Mao, whose family name is a colleague's given name (Mao
    Jun), owning ``owned``."""
    raw = raw_yaml(DEFAULT_OFFICE)
    raw["people"].append(
        {
            "id": "anna",
            "name": "Anna Mao",
            "location": "desk_01",
            "handle": "@anna",
            "owns": [owned],
        }
    )
    return parse_office(raw)


def test_the_requester_names_whom_they_meant_of_two_overlapping_names() -> None:
    """Round 4 (b5): asked "who do you mean: Anna Mao or Mao Jun?" for a file they want from
    Anna Mao, the requester names her (not "Me."), and each option names one person."""
    office = _with_anna_mao({"type": "file"})
    wish = _wish(office, "lee", {"received": ["lee", "file:anna"]})
    assert answer(office, wish, "Who do you mean: Anna Mao or Mao Jun?") == "Anna Mao"
    assert answer(office, wish, "Sorry, who do you mean?") == "Anna Mao."
    mao = _wish(office, "lee", {"received": ["lee", "file:mao"]})
    assert answer(office, mao, "Who do you mean: Anna Mao or Mao Jun?") == "Mao Jun"


def test_a_requester_whose_task_cannot_be_done_still_says_what_they_asked_for() -> None:
    office = load_office()
    wish = Wish.from_goal(office, "lee", [{"informed": "lee"}, {"holds": ["lee", "stapler:zhang"]}])
    assert answer(office, wish, "Sorry, whose stapler do you mean?") == "Zhang Wei's."
