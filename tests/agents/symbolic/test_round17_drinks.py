"""A hot drink asked for by its everyday name, and how they take it (blind round 17's class,
on a school office no sentence was written for, ``helpers.playschool``, whose urn makes "tea"
and whose fridge keeps milk): "a brew", "a cuppa", "a cup of builder's" are the office's tea;
"milk no sugar", "white, one sugar", "black" say how it is taken and never fetch milk; "been
at the machine all morning" is context. Milk asked for with no drink is still milk, and an
office whose own verb is "brew" keeps it as its verb."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import InstructionParser
from helpers import office_builder as ob
from helpers.playschool import playschool, raw_playschool
from helpers.reading import frame_reader

_frame = frame_reader(playschool, "ada")


@pytest.mark.parametrize(
    "text",
    [
        "could you make me a brew? been at the machine all morning",
        "to be frank I could really do with a brew. milk no sugar",
        "fancy a cuppa",
        "a cup of builder's please",
        "can I get a tea, white, one sugar",
        "tea please, black",
        "could I have a tea with milk and two sugars please",
        "a brew please, milk and one sugar, thanks",
        "I'd love a cuppa. Strong, splash of milk",
    ],
)
def test_the_offices_tea_is_made_and_no_milk_fetched(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "tea", "ada")]
    assert all("milk" not in (e.meaning or "") for e in frame.evidence if e.words == "milk")


def test_how_it_is_taken_is_kept_as_evidence() -> None:
    frame = _frame("to be frank I could really do with a brew. milk no sugar")
    assert any(
        e.words == "milk no sugar" and e.meaning == "how they take their tea"
        for e in frame.evidence
    ), frame.evidence


@pytest.mark.parametrize(
    "text", ["bring me some milk from the fridge", "I need milk", "could you get me the milk"]
)
def test_milk_with_no_drink_is_milk(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "milk", "ada")]


def test_a_tea_and_some_milk_are_two_things() -> None:
    frame = _frame("bring me a tea and some milk")
    assert sorted(t.item for t in frame.tasks) == ["milk", "tea"]


def test_brew_as_a_verb_still_makes_tea() -> None:
    frame = _frame("could you brew me a tea")
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", "tea")]


def test_an_office_machine_named_as_context_is_not_operated() -> None:
    raw = raw_playschool()
    """A microwave also called "the machine": on main "been at the machine all morning" was
    read as heating the tea there, and declined."""
    raw["operations"].append(ob.operation("heat", "heat", "microwave", input="lunch"))
    raw["facilities"].append(
        ob.facility(
            "microwave",
            "microwave",
            at="green_room",
            guards=["penny"],
            operations=["heat"],
            synonyms=["machine"],
        )
    )
    parser = InstructionParser(ob.parsed(lambda: raw)())
    for text in (
        "could you make me a brew? been at the machine all morning",
        "been at the machine since 7. fancy making me a cuppa?",
    ):
        frame = parser.parse(text, "ada")
        assert frame.question is None and frame.decline is None, frame
        assert [(t.kind, t.item) for t in frame.tasks] == [("produce", "tea")]
    frame = parser.parse("been at the machine all morning, heat my lunch please", "ada")
    assert [(t.kind, t.item) for t in frame.tasks] == [("heat", "lunch")]


def test_an_office_whose_verb_is_brew_keeps_it() -> None:
    """A coffee service asked for with "brew": "brew me a coffee" is its coffee, and "a brew"
    names no tea the office does not make."""
    raw = raw_playschool()
    raw["item_types"].append(ob.item("coffee", "coffee", "product"))
    raw["operations"].append(ob.operation("coffee", "brew", name="make coffee", product="coffee"))
    raw["facilities"][0]["operations"].append("coffee")
    raw["facilities"][0]["products"].append("coffee")
    parser = InstructionParser(ob.parsed(lambda: raw)())
    frame = parser.parse("could you brew me a coffee", "ada")
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", "coffee")]
    assert parser.lex.items.get("brew") != "tea"


def _with_tea_named(*teas: tuple[str, str]) -> InstructionParser:
    raw = raw_playschool()
    raw["item_types"] = [t for t in raw["item_types"] if t["id"] != "tea"]
    raw["item_types"] += [ob.item(type_id, name, "product") for type_id, name in teas]
    urn = raw["facilities"][0]
    urn["operations"] = []
    urn["products"] = []
    raw["operations"] = [o for o in raw["operations"] if o["id"] != "tea"]
    for type_id, name in teas:
        raw["operations"].append(
            ob.operation(f"make_{type_id}", name=f"make {name}", product=type_id)
        )
        urn["operations"].append(f"make_{type_id}")
        urn["products"].append(type_id)
    return InstructionParser(ob.parsed(lambda: raw)())


def test_a_tea_named_by_a_longer_name_is_still_the_brew() -> None:
    parser = _with_tea_named(("cuppa_tea", "builder's tea"))
    frame = parser.parse("could you make me a brew? milk no sugar", "ada")
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", "cuppa_tea")], frame


def test_of_two_teas_a_brew_is_neither() -> None:
    parser = _with_tea_named(("green_tea", "green tea"), ("mint_tea", "mint tea"))
    assert "brew" not in parser.lex.items and "cuppa" not in parser.lex.items
    frame = parser.parse("could you make me a brew?", "ada")
    assert frame.tasks == [], frame


def _hot_drink_school() -> InstructionParser:
    """The school with its urn's product called "hot drink", going by "tea", "cuppa" and "cup
    of tea": how the drink is taken is still no milk fetch."""
    raw = raw_playschool()
    for kind in raw["item_types"]:
        if kind["id"] == "tea":
            kind["name"] = "hot drink"
            kind["synonyms"] = ["tea", "cuppa", "cup of tea"]
    return InstructionParser(ob.parsed(lambda: raw)())


@pytest.mark.parametrize(
    "text",
    [
        "could I have a cup of tea? milk no sugar",
        "could I have a cuppa? milk no sugar",
        "tea please, white, one sugar",
    ],
)
def test_a_drink_named_by_a_synonym_is_taken_with_milk_not_fetched_with_it(text: str) -> None:
    frame = _hot_drink_school().parse(text, "ada")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "tea", "ada")]


def test_milk_beside_a_drink_named_by_a_synonym_is_still_milk_when_asked_for() -> None:
    frame = _hot_drink_school().parse("could I have a cup of tea and some milk", "ada")
    assert sorted(t.item for t in frame.tasks) == ["milk", "tea"]
