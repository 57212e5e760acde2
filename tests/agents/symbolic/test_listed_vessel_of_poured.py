"""A vessel the office lists as an item, said of or from a facility that makes one poured
product ("a cup of the urn", "a mug from the coffee machine please"), asks for that product,
never the cup (fixer fix59e, class 4). A cup alone, a cup from a room, a cup of a named
drink, the cup standing at the machine and a machine of printouts read as before."""

from __future__ import annotations

import pytest

from helpers import office_builder as ob
from helpers.reading import frame_reader


def _raw() -> ob.Row:
    return ob.office_file(
        "tea room",
        (ob.person("lee", "Lee Park", aliases=["Lee"]), ob.person("ana", "Ana Ruiz")),
        rooms=[
            ob.room("kitchenette", "Kitchenette", 4.0, 20.0),
            ob.room("print_room", "Print room", 20.0, 20.0),
        ],
        item_types=[
            ob.item("cup", "cup", synonyms=["mug"]),
            ob.item("tea", "tea", "product"),
            ob.item("coffee", "coffee", "product"),
            ob.item("file", "file", "electronic"),
            ob.item("printout", "printout", "product"),
        ],
        operations=[
            ob.operation("boil", "brew", name="make tea", product="tea"),
            ob.operation("coffee", "make", name="make coffee", product="coffee"),
            ob.operation("print", "print", input="file", product="printout"),
        ],
        facilities=[
            ob.facility(
                "urn",
                "urn",
                at="kitchenette",
                guards=["ana"],
                operations=["boil"],
                products=["tea"],
            ),
            ob.facility(
                "coffee_machine",
                "coffee machine",
                at="kitchenette",
                guards=["ana"],
                operations=["coffee"],
                products=["coffee"],
            ),
            ob.facility(
                "printer",
                "printer",
                at="print_room",
                guards=["ana"],
                operations=["print"],
                products=["printout"],
            ),
        ],
        everyone_owns=["cup", "file"],
        home="kitchenette",
    )


_lee = frame_reader(ob.parsed(_raw), "lee")


@pytest.mark.parametrize(
    ("text", "product"),
    [
        ("a cup of the urn", "tea"),
        ("a mug from the coffee machine please", "coffee"),
        ("could you get me a cup from the urn", "tea"),
        ("a cup of coffee", "coffee"),  # named, as before
    ],
)
def test_a_listed_vessel_of_a_poured_product_is_that_product(text: str, product: str) -> None:
    frame = _lee(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", product)], frame


@pytest.mark.parametrize(
    "text",
    [
        "bring me a cup",
        "a cup from the kitchenette",  # a room, no facility's product
    ],
)
def test_the_cup_itself_reads_as_before(text: str) -> None:
    frame = _lee(text)
    assert [t.item for t in frame.tasks] == ["cup"], frame


@pytest.mark.parametrize(
    "text", ["bring me the mug from the coffee machine", "a cup from the printer"]
)
def test_no_product_is_made_of_the_cup_there_or_of_printouts(text: str) -> None:
    frame = _lee(text)
    assert not any(t.kind == "produce" for t in frame.tasks), frame
