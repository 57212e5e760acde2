"""A small rowing club's boathouse for the reader's tests of blind round 6's classes: people
with names nobody else uses, ordinary belongings (a headlamp, a stopwatch, a radio), a
charging shelf that charges devices (a treat-shape service on a belonging that is neither food
nor paper), a printer and a desk of signable forms."""

from __future__ import annotations

from typing import Any

from helpers.office_builder import (
    ASKS_NAME_AND_ADDRESS,
    desk_row,
    facility,
    item,
    office_file,
    operation,
    parsed,
    person,
    room,
)

_PEOPLE = (
    person("ottilie", "Ottilie Brandt", "headlamp", "form"),
    person("bram", "Bram Okafor", "stopwatch", "headlamp", "form"),
    person("kasia", "Kasia Lind", "radio", "form"),
    person("femi", "Femi Adair", "stopwatch", "form"),
    person("rune", "Rune Solberg", "oar_clamp", "form"),
)


def raw_boathouse() -> dict[str, Any]:
    return office_file(
        "boathouse",
        _PEOPLE,
        everyone_owns=["log"],
        desks=desk_row(len(_PEOPLE), x0=4.0, y=5.0),
        desk_word="bay",
        rooms=[room("tack_room", "Tack room", 4.0, 18.0)],
        item_types=[
            item("headlamp", "headlamp", synonyms=["head torch"]),
            item("stopwatch", "stopwatch"),
            item("radio", "radio", synonyms=["walkie-talkie"]),
            item("oar_clamp", "oar clamp"),
            item("form", "form", "personal", signable=True, synonyms=["waiver", "entry form"]),
            item("log", "log", "electronic", synonyms=["spreadsheet"]),
            item("printout", "printout", "product"),
        ],
        operations=[
            operation("print", "print", input="log", product="printout"),
            operation("charge", "charge", "recharge", input="headlamp"),
            operation(
                "courier",
                "courier",
                "dispatch",
                input="form",
                sends_out=True,
                destination_asked=ASKS_NAME_AND_ADDRESS,
            ),
        ],
        facilities=[
            facility("printer", "printer", at="tack_room", guards=["rune"], operations=["print"]),
            facility(
                "charging_shelf",
                "charging shelf",
                at="tack_room",
                guards=["kasia"],
                operations=["charge"],
            ),
            facility(
                "dispatch_tray",
                "dispatch tray",
                at="tack_room",
                guards=["femi"],
                operations=["courier"],
            ),
        ],
        home="tack_room",
        group=("crew", "Crew"),
    )


boathouse = parsed(raw_boathouse)
