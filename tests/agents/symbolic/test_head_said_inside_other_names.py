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


def test_a_head_of_two_types_inside_a_machines_name_is_still_asked_about() -> None:
    # blind round 211: a "protector cutter" (a machine) beside a glass and a hydrogel
    # protector: "a protector" was "no protector in this office"; it is which of the two
    items = [
        ("tempered glass protector", "glass"),
        ("screen protector", "glass"),
        ("hydrogel protector", "film"),
        ("custom protector", "film"),
    ]
    one, shared = head_names(items, ["protector cutter"], _known)
    assert shared["protector"] == ("glass", "film") and "protector" not in one


def test_a_head_of_one_type_inside_a_machines_name_stays_no_name() -> None:
    items = [("tempered glass protector", "glass"), ("screen protector", "glass")]
    one, shared = head_names(items, ["protector cutter"], _known)
    assert "protector" not in one and "protector" not in shared


def test_a_head_of_several_types_inside_another_things_name_is_still_asked_about() -> None:
    # round 207 (read): three mics beside a "mic cable" (a cable's name): "a mic" was "no mic
    # in this office"; the longer name is still read whole by the lexicon ("a mic cable")
    items = [
        ("ribbon mic", "ribbon"),
        ("dynamic mic", "dynamic"),
        ("condenser mic", "condenser"),
        ("mic cable", "xlr"),
        ("xlr", "xlr"),
    ]
    one, shared = head_names(items, ["mic locker"], _known)
    assert shared["mic"] == ("ribbon", "dynamic", "condenser") and "mic" not in one
