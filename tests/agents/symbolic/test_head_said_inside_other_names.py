"""A head noun of one type's names is no name of it where the office says that word inside
another name, before that name's head (``reading.head_names``): with "band-aid" plasters, a
"first aid room" and a "first aid bag", "an ice pack from first aid" had fetched plasters too
(blind round 193). A head said nowhere else still names its type."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.head_names import head_names


def _known(word: str) -> bool:
    return False


def test_a_head_said_inside_a_place_name_is_no_name() -> None:
    items = [("band aid", "plasters"), ("band aids", "plasters"), ("plaster", "plasters")]
    one, shared = head_names(items, ["first aid room"], _known)
    assert "aid" not in one and "aids" not in one and "aid" not in shared


def test_a_head_said_inside_another_things_name_is_no_name() -> None:
    items = [("band aid", "plasters"), ("band aids", "plasters"), ("first aid bag", "bag")]
    one, _ = head_names(items, [], _known)
    assert "aid" not in one


def test_a_head_said_nowhere_else_names_its_type() -> None:
    items = [("hand gel", "sanitiser"), ("alcohol gel", "sanitiser"), ("first aid bag", "bag")]
    one, _ = head_names(items, ["first aid room"], _known)
    assert one["gel"] == "sanitiser" and one["gels"] == "sanitiser"
