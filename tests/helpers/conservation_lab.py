"""A museum's conservation department for the reader's tests of blind rounds 20 to 22's classes
(the rounds' own offices and sentences were never read): a charging shelf charges camera
batteries (its product "charged battery"), a cold store keeps each conservator's sample tray,
modelling clay is kept for anyone in the workshop store and the dry store, and the records
desk prints loan forms. One colleague's name is an ordinary word and also a thing kept here
("Clay"); each person owns a checklist (paper) and a timesheet (a file), and some a phone."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_TRAY = ob.kept("sample_tray", at="cold_room", facility="cold_store")

_PEOPLE = (
    ob.person("nell", "Nell Archer", "battery", "phone", _TRAY),
    ob.person("joss", "Joss Kerr", "battery", "phone", _TRAY),
    ob.person("clay", "Clay Moreno", "phone", _TRAY),
    ob.person("mina", "Mina Sato", "battery"),
    ob.person("otto", "Otto Lind", "phone", _TRAY),
    ob.person("bea", "Bea Quinn", "battery"),
    ob.person("rafi", "Rafi Dunn", "phone"),
)


def raw_conservation_lab() -> dict[str, Any]:
    return ob.office_file(
        "conservation_lab",
        _PEOPLE,
        everyone_owns=["checklist", "timesheet"],
        rooms=[
            ob.room("photo_room", "Photography room", 4.0, 20.5),
            ob.room("cold_room", "Cold room", 14.0, 20.5),
            ob.room("workshop", "Workshop", 24.0, 20.5),
            ob.room("basement", "Basement", 34.0, 20.5),
            ob.room("records", "Records office", 44.0, 20.5),
        ],
        item_types=[
            ob.item("battery", "battery", synonyms=["camera battery"]),
            ob.item("phone", "phone", "personal"),
            ob.item("sample_tray", "sample tray", synonyms=["tray"]),
            ob.item("checklist", "checklist"),
            ob.item("timesheet", "timesheet", "electronic"),
            ob.item("clay", "clay", synonyms=["modelling clay"], consumable=True),
            ob.item("charged_battery", "charged battery", "product"),
            ob.item("loan_form", "loan form", "product"),
        ],
        operations=[
            ob.operation("charge", "charge", name="charge a battery", product="charged_battery"),
            ob.operation("print", "print", input="timesheet", product="loan_form"),
        ],
        facilities=[
            ob.facility(
                "charging_shelf",
                "charging shelf",
                at="photo_room",
                guards=["mina"],
                operations=["charge"],
                products=["charged_battery"],
            ),
            ob.facility(
                "cold_store",
                "cold store",
                at="cold_room",
                guards=["otto"],
                synonyms=["walk-in"],
            ),
            ob.facility(
                "workshop_store",
                "workshop store",
                at="workshop",
                guards=["joss"],
                supplies=["clay"],
            ),
            ob.facility(
                "dry_store",
                "dry store",
                at="basement",
                guards=["bea"],
                supplies=["clay"],
            ),
            ob.facility(
                "records_desk",
                "records desk",
                at="records",
                guards=["rafi"],
                operations=["print"],
                products=["loan_form"],
            ),
        ],
        home="photo_room",
    )


conservation_lab = ob.parsed(raw_conservation_lab)
