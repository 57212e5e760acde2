"""Blind round 4's reader classes, by mechanism, on our own offices and sentences (the round's
sentences were never read): a quantity word means what a statement says ran out, not the thing
that only modifies it (A5); "can you <verb> in <manner>?" asks what the assistant can do (A6);
an elliptical negation or "nvm" withdraws what was asked (A7, A8); a requester who will do it
themselves is answered in words (A10); fetching an item out of its keeper to work on it is one
errand (A12); "..., no, a pen" corrects the item just named. Only a request moves the robot."""

from __future__ import annotations

import functools

import pytest
from _offices import parser as office_parser
from _offices import tasks_of

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers.clinic import raw_clinic


@functools.cache
def clinic_with_supplies() -> InstructionParser:
    """The clinic, where Hal keeps probe covers for the thermometers."""
    raw = raw_clinic()
    raw["item_types"].append({"id": "probe_cover", "name": "probe cover"})
    for p in raw["people"]:
        if p["id"] == "hal":
            p["owns"].append({"type": "probe_cover"})
    return InstructionParser(parse_office(raw, "clinic with supplies"))


def _clinic(text: str, who: str = "dawn") -> list[tuple[str, str | None, str | None, str]]:
    frame = clinic_with_supplies().parse(text, who)
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "we're out of probe covers for the thermometers, could you bring me some?",
        "I used the last probe cover for my thermometer. Can you get me some please",
    ],
)
def test_some_means_what_ran_out_not_what_it_was_for(text: str) -> None:
    assert _clinic(text) == [("transfer", "probe_cover", None, "dawn")]


@pytest.mark.parametrize(
    "text", ["can you print in colour?", "could you print double sided?", "can you print?"]
)
def test_a_question_about_what_the_assistant_can_do_moves_nothing(text: str) -> None:
    frame = clinic_with_supplies().parse(text, "dawn")
    assert frame.tasks == [] and frame.decline is not None and frame.decline_outcome == "done"


def test_the_same_verb_with_an_object_is_still_a_request() -> None:
    assert [t[0] for t in _clinic("can you print my rota in colour?")] == ["print"]


@pytest.mark.parametrize(
    "text",
    [
        "could you bring me Hal's thermometer? actually no, don't, I'll walk over",
        "can you print my rota? oh wait, don't. I'll print it later",
        "nvm about the clipboard, thx",
        "nvm the printout",
    ],
)
def test_an_elliptical_negation_or_nvm_withdraws_the_request(text: str) -> None:
    frame = clinic_with_supplies().parse(text, "dawn")
    assert frame.tasks == [] and frame.decline is not None and frame.decline_outcome == "done"


def test_a_bare_no_before_another_item_corrects_it() -> None:
    assert _clinic("bring me a thermometer, no, a clipboard") == [
        ("transfer", "clipboard", None, "dawn")
    ]


@pytest.mark.parametrize(
    "text",
    ["no worries, I'll fetch the clipboard myself", "all good, I'll print it myself"],
)
def test_doing_it_themselves_is_answered_in_words(text: str) -> None:
    frame = clinic_with_supplies().parse(text, "dawn")
    assert frame.tasks == [] and frame.question is None and frame.decline is not None


@pytest.mark.parametrize(
    "text",
    [
        "get my lunch out of the fridge and heat it up",
        "grab my lunch from the fridge and warm it up for me please",
    ],
)
def test_fetching_an_item_to_work_on_it_is_one_errand(text: str) -> None:
    assert tasks_of("default", text, "lee") == [("heat", "lunch", "lee", "lee")]


def test_a_fetch_then_a_delivery_elsewhere_stays_a_delivery() -> None:
    frame = office_parser("default").parse("bring me a stapler and then take it to Wang", "lee")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("transfer", "wang")]


@pytest.mark.parametrize(
    "text",
    [
        "I wish the staff room had a kettle",
        "if only the print corner had a bigger tray",
        "it would be nice if the printer were faster",
        # the speaker's stance first, with or without a comma (round 4 after: one class left)
        "honestly I wish the staff room had a kettle",
        "frankly the print corner should have a bigger tray, I wish it did",
        "to be honest I wish the printer were faster",
        "tbh if only the staff room had a sofa",
    ],
)
def test_a_wish_about_the_place_is_answered_in_words(text: str) -> None:
    frame = clinic_with_supplies().parse(text, "dawn")
    assert frame.tasks == [] and frame.question is None and frame.decline is not None


@pytest.mark.parametrize(
    "text",
    ["honestly, could Hal lend me his thermometer", "seriously can you bring me Hal's thermometer"],
)
def test_a_stance_word_before_a_request_leaves_the_request(text: str) -> None:
    assert _clinic(text) == [("transfer", "thermometer", "hal", "dawn")]


def test_a_wish_that_names_someone_to_act_is_still_read_as_a_request() -> None:
    assert _clinic("if only Rich would lend me his clipboard") == [
        ("transfer", "clipboard", "rich", "dawn")
    ]


@pytest.mark.parametrize(
    "text", ["Hu Jing's scissors please, to my desk", "scissors please", "Gao Min's pen pls"]
)
def test_a_verbless_request_for_an_item_is_a_fetch(text: str) -> None:
    """An item's name that is also a verb form ("scissors") never makes the fragment a
    statement (A11)."""
    assert [(t[0], t[1], t[3]) for t in tasks_of("default", text, "lee")] == [
        ("transfer", "scissors" if "scissors" in text else "pen", "lee")
    ]


def test_an_item_with_a_verb_after_it_is_still_a_statement() -> None:
    frame = clinic_with_supplies().parse("Rich's clipboard snapped yesterday", "dawn")
    assert frame.tasks == [] and frame.decline is not None
