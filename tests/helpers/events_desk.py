"""An events office for the reader's tests of blind round 59's classes (the round's own office
and sentences were never read): colleagues whose given names are also English words (Tam, Drew,
Wren) and who are written in lower case; a printer that prints a person's electronic file; a
badge desk that issues visitor badges from nothing (a credential the office makes); a door key
a colleague owns (a credential of someone's); ordinary belongings (a stapler, a tape measure)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ines", "Ines Varga", "stapler"),
    ob.person("tam", "Tam Okafor", "stapler", "tape_measure"),
    ob.person("drew", "Drew Pell", "stapler"),
    ob.person("wren", "Wren Holt", "tape_measure"),
    ob.person("sam", "Sam Ruiz", "door_key"),
    ob.person("bo", "Bo Lind"),
)


def raw_events_desk() -> dict[str, Any]:
    return ob.office_file(
        "events desk",
        _PEOPLE,
        everyone_owns=["file"],
        rooms=[
            ob.room("print_room", "Print room", 4.0, 20.0),
            ob.room("reception", "Reception", 20.0, 20.0),
        ],
        item_types=[
            ob.item("stapler", "stapler"),
            ob.item("tape_measure", "tape measure"),
            ob.item("door_key", "door key", "personal"),
            ob.item("file", "electronic file", "electronic", synonyms=["file"]),
            ob.item("printout", "printout", "product"),
            ob.item("visitor_badge", "visitor badge", "product"),
        ],
        operations=[
            ob.operation("print", "print", input="file", product="printout"),
            ob.operation("issue_badge", "issue", name="issue badges", product="visitor_badge"),
        ],
        facilities=[
            ob.facility(
                "printer",
                "printer",
                at="print_room",
                guards=["bo"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "badge_desk",
                "badge desk",
                at="reception",
                guards=["bo"],
                operations=["issue_badge"],
                products=["visitor_badge"],
            ),
        ],
        home="print_room",
    )


events_desk = ob.parsed(raw_events_desk)
