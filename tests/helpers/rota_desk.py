"""A ferry terminal's rota desk for the reader's tests of blind round 28's name classes (the
round's own office and sentences were never read): colleagues whose given names are ordinary
verbs ("Mark", "Bill", "Chase"), one called Otto who keeps a ruler and a tin of soup in the
crew-room fridge, a printer that prints a rota, and a kettle that brews a tea."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person(
        "ada",
        "Ada Brennan",
        "ruler",
        ob.kept("soup", at="crew_room", facility="fridge"),
        aliases=["Bren"],
    ),
    ob.person("mark", "Mark Tiller", "ruler"),
    ob.person("bill", "Bill Okoro", "ruler", aliases=["Mr Okoro"]),
    ob.person("chase", "Chase Munro"),
    ob.person(
        "otto",
        "Otto Lindqvist",
        "ruler",
        ob.kept("soup", at="crew_room", facility="fridge"),
    ),
    ob.person("rhiannon", "Rhiannon Pryce", "ruler", aliases=["Mrs Okafor"]),
    ob.person("alexandra", "Alexandra Petrov", "ruler"),
    ob.person("alexei", "Alexei Marr", "ruler"),
)


def raw_rota_desk() -> dict[str, Any]:
    return ob.office_file(
        "rota desk",
        _PEOPLE,
        rooms=[
            ob.room("crew_room", "Crew room", 4.0, 20.0),
            ob.room("print_bay", "Print bay", 14.0, 20.0),
        ],
        item_types=[
            ob.item("rota", "rota", "electronic", synonyms=["shift plan"]),
            ob.item("printout", "printout", "product", synonyms=["hard copy"]),
            ob.item("tea", "tea", "product", synonyms=["brew"]),
            ob.item("ruler", "ruler", synonyms=["steel rule"]),
            ob.item("soup", "soup", "personal"),
        ],
        operations=[
            ob.operation("print", "print", input="rota", product="printout"),
            ob.operation("brew", "brew", "make", product="tea"),
        ],
        facilities=[
            ob.facility(
                "printer",
                "rota printer",
                at="print_bay",
                guards=["chase"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "kettle",
                "crew kettle",
                at="crew_room",
                guards=["chase"],
                operations=["brew"],
                products=["tea"],
            ),
            ob.facility("fridge", "crew-room fridge", at="crew_room", guards=["chase"]),
        ],
        everyone_owns=["rota"],
        home="crew_room",
    )


rota_desk = ob.parsed(raw_rota_desk)
