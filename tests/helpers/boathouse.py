"""A small rowing club's boathouse for the reader's tests of blind round 6's classes: people
with names nobody else uses, ordinary belongings (a headlamp, a stopwatch, a radio), a
charging shelf that charges devices (a treat-shape service on a belonging that is neither food
nor paper), a printer and a desk of signable forms."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ottilie", "Ottilie Brandt", "headlamp", "form"),
    ob.person("bram", "Bram Okafor", "stopwatch", "headlamp", "form"),
    ob.person("kasia", "Kasia Lind", "radio", "form"),
    ob.person("femi", "Femi Adair", "stopwatch", "form"),
    ob.person("rune", "Rune Solberg", "oar_clamp", "form"),
)


def raw_boathouse() -> dict[str, Any]:
    return ob.office_file(
        "boathouse",
        _PEOPLE,
        everyone_owns=["log"],
        desks=ob.desk_row(len(_PEOPLE), x0=4.0, y=5.0),
        desk_word="bay",
        rooms=[ob.room("tack_room", "Tack room", 4.0, 18.0)],
        item_types=[
            ob.item("headlamp", "headlamp", synonyms=["head torch"]),
            ob.item("stopwatch", "stopwatch"),
            ob.item("radio", "radio", synonyms=["walkie-talkie"]),
            ob.item("oar_clamp", "oar clamp"),
            ob.item("form", "form", "personal", signable=True, synonyms=["waiver", "entry form"]),
            ob.item("log", "log", "electronic", synonyms=["spreadsheet"]),
            ob.item("printout", "printout", "product"),
        ],
        operations=[
            ob.operation("print", "print", input="log", product="printout"),
            ob.operation("charge", "charge", "recharge", input="headlamp"),
            ob.operation(
                "courier",
                "courier",
                "dispatch",
                input="form",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
            ),
        ],
        facilities=[
            ob.facility(
                "printer", "printer", at="tack_room", guards=["rune"], operations=["print"]
            ),
            ob.facility(
                "charging_shelf",
                "charging shelf",
                at="tack_room",
                guards=["kasia"],
                operations=["charge"],
            ),
            ob.facility(
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


boathouse = ob.parsed(raw_boathouse)
