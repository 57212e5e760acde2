"""Blind round 6's reader classes, by mechanism, on sentences of our own against a boathouse
no sentence was written for (the round's office and sentences were never read). Only what is
asked for moves, and only whose it was said to be."""

from __future__ import annotations

import functools

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers.boathouse import boathouse, raw_boathouse
from helpers.reading import parser_for

_parser = functools.partial(parser_for, boathouse)


def _tasks(text: str, who: str) -> list[tuple[str, str | None, str | None, str]]:
    frame = _parser().parse(text, who)
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("who", "text", "owner", "item"),
    [
        ("ottilie", "Bram has a stopwatch on his bay. Can I borrow it?", "bram", "stopwatch"),
        ("ottilie", "Femi has a stopwatch. could you get it for me", "femi", "stopwatch"),
        (
            "bram",
            "Ottilie has a headlamp at her bay, can you get it for me?",
            "ottilie",
            "headlamp",
        ),
        ("bram", "Kasia's got a radio. I'd like to borrow it", "kasia", "radio"),
    ],
)
def test_it_after_a_person_who_has_the_item_is_that_persons_item(
    who: str, text: str, owner: str, item: str
) -> None:
    """E: "it" is the item the statement said the person has, never another of its kind (so
    its owner is the one asked)."""
    assert _tasks(text, who) == [("transfer", item, owner, who)]


@pytest.mark.parametrize(
    "text",
    [
        "please bring me a radio because there's no money for new stopwatches",
        "please bring me a radio, because there's no money for new stopwatches",
        "can I get a radio since we can't afford new headlamps",
        "bring me a radio cause the club won't buy new stopwatches",
    ],
)
def test_an_item_in_a_reason_clause_is_not_fetched(text: str) -> None:
    """F: a reason clause's items explain the request; only the radio is fetched."""
    assert _tasks(text, "femi") == [("transfer", "radio", None, "femi")]


def test_a_reason_clause_keeps_the_owner_of_the_requested_item() -> None:
    text = "get me Bram's stopwatch because we have no budget for new stopwatches"
    assert _tasks(text, "femi") == [("transfer", "stopwatch", "bram", "femi")]


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        ("take my signed form to Kasia", ("transfer", "form", "bram", "kasia")),
        ("please bring Femi my signed waiver", ("transfer", "form", "bram", "femi")),
        ("print the signed log for Kasia", ("print", "log", "bram", "kasia")),
    ],
)
def test_a_participle_before_the_item_describes_it(
    text: str, wanted: tuple[str, str, str, str]
) -> None:
    """C: "the signed form" is a form that was signed; the request is the sentence's verb."""
    assert _tasks(text, "bram") == [wanted]


@pytest.mark.parametrize("text", ["bring me the printed log", "bring me my printed spreadsheet"])
def test_an_office_service_participle_still_asks_for_its_product(text: str) -> None:
    """Only a person's service (a signature) is an adjective there; "the printed log" is
    still the print of the requester's log."""
    assert _tasks(text, "femi") == [("print", "log", "femi", "femi")]


@pytest.mark.parametrize(
    "text",
    [
        "courier my signed waiver to the regional federation in York",
        "please courier the signed form to the county rowing office",
    ],
)
def test_a_send_out_of_a_signed_paper_is_the_send_out(text: str) -> None:
    frame = _parser().parse(text, "bram")
    assert [(t.item, t.operation) for t in frame.tasks] == [("form", "courier")]
    assert frame.tasks[0].destination


@pytest.mark.parametrize("text", ["can you get my form signed by Rune", "get Rune to sign my form"])
def test_the_verb_itself_still_asks_for_the_signature(text: str) -> None:
    assert _tasks(text, "bram") == [("sign", "form", "bram", "bram")]
    assert _parser().parse(text, "bram").tasks[0].actor == "rune"


@pytest.mark.parametrize(
    "text",
    [
        "can you print my log? I need the spreadsheet for the regatta meeting",
        "please print my log. I need the log for tomorrow's briefing",
    ],
)
def test_the_file_named_again_as_what_is_needed_is_the_purpose(text: str) -> None:
    """D: a second sentence that says what the file is needed for keeps the print."""
    assert _tasks(text, "ottilie") == [("print", "log", "ottilie", "ottilie")]


def test_a_signed_paper_needed_for_something_is_still_the_signature() -> None:
    text = "get Rune to sign my form. I need the waiver for the race on Saturday"
    assert _tasks(text, "bram") == [("sign", "form", "bram", "bram")]


@pytest.mark.parametrize(
    ("text", "to"),
    [
        ("print my log and email it to Kasia", "kasia"),
        ("print my log. send the spreadsheet to Rune too", "rune"),
    ],
)
def test_a_file_passed_on_to_someone_else_is_a_second_task(text: str, to: str) -> None:
    assert _tasks(text, "ottilie") == [
        ("print", "log", "ottilie", "ottilie"),
        ("send_file", "log", "ottilie", to),
    ]


@pytest.mark.parametrize(
    "text",
    [
        "could you get me a radio as my headlamp is dying",
        "I'd like a radio please, my headlamp is dying",
        "can you bring a radio to me since my headlamp is dying",
    ],
)
def test_an_owned_item_in_a_trailing_reason_is_not_the_object(text: str) -> None:
    """H: "my headlamp is dying" explains the request; the radio is what is fetched."""
    assert _tasks(text, "ottilie") == [("transfer", "radio", None, "ottilie")]


@pytest.mark.parametrize(
    ("text", "thing"),
    [
        ("could I get a power bank, my headlamp is dying", "power bank"),
        ("can you bring me a spare battery because my headlamp is dying", "spare battery"),
        ("bring me a power bank as my headlamp is dying", "power bank"),
    ],
)
def test_an_unknown_thing_with_a_reason_is_declined_not_swapped(text: str, thing: str) -> None:
    """H: the item of the reason is never fetched in place of a thing the office lacks."""
    frame = _parser().parse(text, "ottilie")
    assert frame.tasks == [] and frame.decline and f"no {thing} in this office" in frame.decline


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I'm out of stopwatches for the race. could you get me a few?", "stopwatch"),
        ("we're short of radios, can you fetch a few", "radio"),
        ("the crew needs radios. can you bring a couple?", "radio"),
        ("we need stopwatches for the regatta. grab some more please", "stopwatch"),
    ],
)
def test_a_quantity_word_refers_back_to_the_item_named_before(text: str, item: str) -> None:
    """G: "a few", "a couple", "some more" are how many of the item just named."""
    assert _tasks(text, "femi") == [("transfer", item, None, "femi")]


@pytest.mark.parametrize("text", ["can you bring me a few", "bring me a couple more"])
def test_a_quantity_with_nothing_named_is_asked_about(text: str) -> None:
    frame = _parser().parse(text, "femi")
    assert frame.tasks == [] and frame.decline is None and frame.question


@pytest.mark.parametrize(
    ("who", "text", "owner"),
    [
        ("ottilie", "charge my headlamp", "ottilie"),
        ("ottilie", "please recharge my head torch", "ottilie"),
        ("ottilie", "put my headlamp on the charging shelf", "ottilie"),
        ("ottilie", "take my headlamp to the charging shelf", "ottilie"),
        ("bram", "could you put Ottilie's headlamp on the charging shelf for her", "ottilie"),
    ],
)
def test_a_declared_service_on_a_belonging_is_reached_by_verb_and_by_facility(
    who: str, text: str, owner: str
) -> None:
    """A: the office's own treat service on an ordinary belonging, by its declared verbs and
    by putting the item at the facility that offers it."""
    frame = _parser().parse(text, who)
    assert [(t.item, t.owner, t.operation) for t in frame.tasks] == [("headlamp", owner, "charge")]


def test_an_item_taken_from_a_service_facility_is_only_fetched() -> None:
    assert _tasks("bring me Bram's headlamp from the charging shelf", "ottilie") == [
        ("transfer", "headlamp", "bram", "ottilie")
    ]


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("charge my radio", "charge a radio"),
        ("put my radio on the charging shelf", "charge a radio"),
        ("courier my headlamp to the federation", "courier a headlamp"),
    ],
)
def test_a_service_on_an_item_it_does_not_take_is_unachievable(text: str, said: str) -> None:
    frame = _parser().parse(text, "ottilie")
    assert frame.tasks == [] and frame.decline_outcome == "unachievable"
    assert frame.decline and said in frame.decline


async def test_a_declared_service_on_a_belonging_runs_to_done() -> None:
    run = await run_instruction(boathouse(), "ottilie", "Please charge my headlamp.")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    handed = {e.detail["to"] for e in run.sim.world.handovers() if e.detail.get("to") != "locker"}
    assert handed <= {"ottilie", "kasia"}


async def test_a_service_on_an_item_it_does_not_take_ends_unachievable() -> None:
    run = await run_instruction(boathouse(), "ottilie", "charge my radio please")
    assert run.stm.trace.outcome == "unachievable"
    assert run.actions == ["stop"]


@pytest.mark.parametrize(
    ("text", "thing"),
    [
        ("can you bring me a recharger", "recharger"),
        ("I need a courier bag", "courier bag"),
        ("get me a dispatcher please", "dispatcher"),
        ("could you fetch a printer cable", "printer cable"),
        ("bring me a charge cable", "charge cable"),
    ],
)
def test_a_noun_made_from_a_service_word_is_a_thing_the_office_lacks(text: str, thing: str) -> None:
    """B: a device named after a service ("recharger"), or a service word as the first noun
    of a compound, is a thing asked for: declined by name, never a question about the
    service's item."""
    frame = _parser().parse(text, "ottilie")
    assert frame.tasks == [] and frame.question is None
    assert frame.decline and f"no {thing} in this office" in frame.decline


def test_a_service_noun_with_its_object_still_asks_for_the_service() -> None:
    assert _tasks("can I have a print of my log please", "femi") == [
        ("print", "log", "femi", "femi")
    ]


def _with_a_duplicator() -> InstructionParser:
    """The boathouse with a light box that traces forms (a product from a physical item)."""
    raw = raw_boathouse()
    raw["item_types"].append({"id": "tracing", "name": "tracing", "kind": "product"})
    raw["operations"].append(
        {"id": "trace", "name": "trace", "verbs": ["trace"], "input": "form", "product": "tracing"}
    )
    raw["facilities"].append(
        {
            "id": "light_box",
            "name": "light box",
            "location": "tack_room",
            "operations": ["trace"],
            "guards": ["rune"],
        }
    )
    return InstructionParser(parse_office(raw, "boathouse with a light box"))


@pytest.mark.parametrize(
    "text", ["put my waiver in the light box", "take my form to the light box", "trace my form"]
)
def test_an_item_taken_to_a_facility_that_makes_something_from_it_asks_for_that(
    text: str,
) -> None:
    frame = _with_a_duplicator().parse(text, "bram")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("copy", "form", "bram", "bram")
    ]
