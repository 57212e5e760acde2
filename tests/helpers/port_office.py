"""A harbour operations office for the tests of a rank of one word: colleagues called by a
single title before their surname ("Director Okafor", "Captain Reyes"), a one-word title two
people hold ("Sister"), an adjective before a surname ("Young Park": a nickname, no rank),
a colleague whose given name is also a title's word ("Marshal Kowal"), and a paper type
named otherwise in a request ("permit" of "document")."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ada", "Ada Okafor", "timesheet", aliases=["Director Okafor"]),
    ob.person("luis", "Luis Reyes", "radio", "timesheet", aliases=["Captain Reyes"]),
    ob.person("mae", "Mae Dunn", "timesheet", aliases=["Sister Dunn"]),
    ob.person("ines", "Ines Holt", "timesheet", aliases=["Sister Holt"]),
    ob.person("jin", "Jin Park", "radio", "timesheet", aliases=["Young Park"]),
    ob.person("marshal", "Marshal Kowal", "timesheet", aliases=["Deputy Kowal"]),
    ob.person("otto", "Otto Berg", "radio", "timesheet", aliases=["Marshal Berg"]),
    ob.person("tom", "Tom Lund", "radio", "timesheet", "document"),
    ob.person("kit", "Kit Moss", "radio"),
    ob.person("drew", "Drew Fenn", "radio", aliases=["Drew"]),
)


def raw_port_office() -> dict[str, Any]:
    return ob.office_file(
        "port office",
        _PEOPLE,
        rooms=[ob.room("quay", "Quay office", 4.0, 20.0)],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["spreadsheet"]),
            ob.item("radio", "radio"),
            ob.item("timesheet", "timesheet", "personal", signable=True),
            ob.item("document", "document", "personal", synonyms=["permit", "waiver"]),
        ],
        operations=[],
        facilities=[],
        everyone_owns=["file"],
        home="quay",
    )


port_office = ob.parsed(raw_port_office)
