"""Office-declared operations: what they are, and loading refuses an inconsistent office
naming the file, the entry and the problem (runs: tests/agents/symbolic/test_new_operations.py)."""

from __future__ import annotations

import copy
from typing import Any

import pytest

from assistantx.core.errors import OfficeError
from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import HARBOUR_FILE as HARBOUR
from helpers.yaml_files import raw_yaml


@pytest.fixture
def raw() -> dict[str, Any]:
    data: dict[str, Any] = raw_yaml(HARBOUR)
    return copy.deepcopy(data)


def test_operations_and_their_shapes(harbour: Office) -> None:
    shapes = {o.id: o.shape(harbour) for o in harbour.operations}
    assert shapes == {
        "print": "render",
        "scan": "transform",
        "boil": "make",
        "supply": "make",
        "laminate": "treat",
        "frank": "make",
        "relax": "use",
    }
    assert [f.id for f in harbour.offering("scan")] == ["scanner"]
    assert harbour.making("tea") is not None and harbour.making("tea").id == "boil"  # type: ignore[union-attr]
    # two facilities at one location, and which one keeps an item
    assert {f.id for f in harbour.facilities if f.location == "kitchen"} == {"kettle", "fridge"}
    assert harbour.keeper("will", "lunch").id == "fridge"  # type: ignore[union-attr]
    assert harbour.keeper("may", "label_maker").id == "cupboard"  # type: ignore[union-attr]
    assert harbour.keeper("mark", "ruler") is None


@pytest.mark.parametrize(
    ("change", "entry", "problem"),
    [
        (
            lambda r: r["facilities"][0]["operations"].append("teleport"),
            "facilities (printer).operations",
            "unknown operation 'teleport'",
        ),
        (
            lambda r: r["operations"][2].update(product="unicorn"),
            "operations (boil).product",
            "unknown item type 'unicorn'",
        ),
        (
            lambda r: r["operations"][2].update(product="ruler"),
            "operations (boil).product",
            "'ruler' is not a product",
        ),
        (
            lambda r: r["operations"].append({"id": "juggle", "name": "juggle"}),
            "operations (juggle)",
            "no facility offers it",
        ),
        (
            lambda r: (
                r["operations"].append({"id": "brew2", "name": "brew", "product": "tea"})
                or r["facilities"][2]["operations"].append("brew2")
            ),
            "operations (product tea)",
            "2 operations make 'tea'",
        ),
        (
            lambda r: r["people"][2]["owns"][3].update(facility="cupboard"),
            "people (will).owns (lunch).facility",
            "'cupboard' is not at 'kitchen'",
        ),
        (
            lambda r: r["facilities"][0].update(products=["tea"]),
            "facilities (printer).products",
            "no operation here makes 'tea'",
        ),
    ],
)
def test_inconsistent_office_is_refused_naming_file_entry_and_problem(
    raw: dict[str, Any], change: Any, entry: str, problem: str
) -> None:
    change(raw)
    with pytest.raises(OfficeError) as info:
        parse_office(raw, "harbour.yaml")
    message = str(info.value)
    assert "harbour.yaml" in message and entry in message and problem in message


def test_an_item_kept_where_several_facilities_stand_goes_to_the_one_with_no_service() -> None:
    """The previous format named no keeper: the fridge beside the kettle keeps the lunch
    (office_upgrade; the loader says so in a warning)."""
    raw = raw_yaml(HARBOUR)
    raw["people"][2]["owns"][3].pop("facility")
    office = parse_office(raw, "harbour")
    keeper = office.keeper("will", "lunch")
    assert keeper is not None and keeper.id == "fridge"
