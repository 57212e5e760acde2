"""Classes of the rounds written on stop 62's final build and read after their measure (a
hospital pharmacy's dispensary, a car rental branch), by mechanism, on small offices here and
the default office:

- a colleague's possessive before a place word the office also names a place by ("drop it
  on Mercy's bench" where a workstation is the "Checking bench") is that colleague's place,
  so they receive it (the printout had been handed to the speaker: a wrong physical action);
- a machine the speaker would like the place to have some day ("I'd love a proper espresso
  machine in here someday") is a wish about the place, never its product made now (a coffee
  had been made: a wrong physical action)."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, load_office, parse_office
from helpers import office_builder as ob


@functools.cache
def _dispensary() -> Office:
    people = (
        ob.person("rob", "Rob Baker", "calculator", at="bench_one"),
        ob.person("mercy", "Mercy Owusu", "calculator", at="checking_bench"),
        ob.person("lucy", "Lucy Page", "calculator", at="bench_two"),
    )
    raw = ob.office_file(
        "dispensary",
        people,
        everyone_owns=["rota"],
        rooms=[
            ob.room("print_bay", "Print bay", 4.0, 20.5),
            ob.room("checking_bench", "Checking bench", 13.0, 6.0, kind="workstation"),
            ob.room("bench_one", "Dispensing bench 1", 17.0, 6.0, kind="workstation"),
            ob.room("bench_two", "Dispensing bench 2", 21.0, 6.0, kind="workstation"),
        ],
        item_types=[
            ob.item("calculator", "calculator"),
            ob.item("rota", "file", "electronic", synonyms=["rota"]),
            ob.item("printout", "printout", "product"),
        ],
        operations=[ob.operation("print", "print", input="rota", product="printout")],
        facilities=[
            ob.facility(
                "printer",
                "printer",
                at="print_bay",
                guards=["lucy"],
                operations=["print"],
                products=["printout"],
            )
        ],
        home="print_bay",
        desk_for_everyone=False,
    )
    return parse_office(raw, raw["name"])


@functools.cache
def _parser(name: str) -> InstructionParser:
    return InstructionParser(_dispensary() if name == "dispensary" else load_office())


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("print my rota and drop it on Mercy's bench please", "print"),
        ("bring my calculator to Mercy's bench", "transfer"),
    ],
)
def test_a_colleagues_bench_is_where_they_receive_it(text: str, kind: str) -> None:
    frame = _parser("dispensary").parse(text, "rob")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [(kind, "mercy")]


def test_a_thing_from_a_colleagues_bench_is_not_theirs_to_receive() -> None:
    """Near-miss: "from Mercy's bench" is where it comes from; the speaker receives it."""
    frame = _parser("dispensary").parse("bring me the calculator from Mercy's bench", "rob")
    assert all(t.recipient == "rob" for t in frame.tasks)


@pytest.mark.parametrize(
    "text",
    [
        "I'd love a proper espresso machine in here someday",
        "would like a microwave up here one day",
    ],
)
def test_a_machine_wished_for_some_day_is_told(text: str) -> None:
    frame = _parser("default").parse(text, "liu")
    assert frame.tasks == [] and frame.question is None and frame.decline is not None


@pytest.mark.parametrize(
    "text",
    ["I'd love a coffee", "id love a coffee from the coffee machine at some point today"],
)
def test_a_drink_wished_for_is_still_made(text: str) -> None:
    """Near-miss: the machine's product asked for, later or not, is made."""
    frame = _parser("default").parse(text, "liu")
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", "coffee")]


@functools.cache
def _model_shop() -> InstructionParser:
    """An architects' model shop: drawings to stamp, also called a "planning set" (a name
    whose last word is also a past verb), and the registration stamp that seals them."""
    people = (
        ob.person("sam", "Sam Okonkwo", "drawings"),
        ob.person("fern", "Fern Wood", "drawings", "stamp"),
    )
    raw = ob.office_file(
        "model shop",
        people,
        rooms=[ob.room("front_desk", "Front desk", 4.0, 20.5)],
        item_types=[
            ob.item(
                "drawings",
                "drawing set",
                "personal",
                synonyms=["planning set", "drawings"],
                signable=True,
            ),
            ob.item("stamp", "registration stamp", synonyms=["stamp"], seals=True),
        ],
        operations=[],
        facilities=[],
        home="front_desk",
    )
    return InstructionParser(parse_office(raw, raw["name"]))


@pytest.mark.parametrize(
    "text",
    [
        "My planning set needs the registration stamp before it goes out.",
        "my planning set needs stamping",
    ],
)
def test_a_things_name_ending_in_a_past_verb_is_no_event(text: str) -> None:
    """ "set" ends the thing's name here, no past verb: the stamp is asked for (it was read
    as what had happened to the speaker's own thing, and nothing was done)."""
    frame = _model_shop().parse(text, "sam")
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("seal", "drawings", "sam")]
