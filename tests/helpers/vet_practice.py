"""A small veterinary practice for the reader's tests of blind round 18's classes (second half):
people with names nobody else uses (one of them, Holly, shares her name with a plant), clinic
belongings (a stethoscope, a thermometer), a lab that runs gels and minipreps, a printer, a
front desk that stamps forms with the practice stamp, a dispensary that makes up medicines and
stores that keep gloves and ice buckets for anyone."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("frank", "Frank Oduya", "stethoscope", "thermometer"),
    ob.person("hazel", "Hazel Pirrie", "stethoscope"),
    ob.person("holly", "Holly Vance", "thermometer"),
    ob.person("jonno", "Jonno Reade", "stethoscope", aliases=["Jon"]),
    ob.person("priya", "Priya Atwal", "thermometer"),
)


def raw_vet_practice() -> dict[str, Any]:
    return ob.office_file(
        "vet practice",
        _PEOPLE,
        everyone_owns=["case_file", "form"],
        rooms=[
            ob.room("lab", "Lab", 4.0, 18.0),
            ob.room("front_desk_room", "Reception", 12.0, 18.0),
            ob.room("pharmacy", "Pharmacy", 20.0, 18.0),
            ob.room("stores_room", "Stores", 28.0, 18.0),
            ob.room("kennels", "Kennels", 36.0, 18.0, kind="room"),
        ],
        item_types=[
            ob.item("stethoscope", "stethoscope"),
            ob.item("thermometer", "thermometer"),
            ob.item("sample", "sample", synonyms=["gel", "miniprep"]),
            ob.item("ice_bucket", "ice bucket"),
            ob.item("gloves", "gloves", consumable=True, synonyms=["glove"]),
            ob.item(
                "form", "form", "personal", signable=True, synonyms=["insurance form", "claim"]
            ),
            ob.item("case_file", "file", "electronic", synonyms=["case notes"]),
            ob.item("printout", "printout", "product"),
            ob.item(
                "meds",
                "prescription",
                "product",
                synonyms=["meds", "medication", "medicine", "tablets"],
            ),
        ],
        operations=[
            ob.operation("print", "print", input="case_file", product="printout"),
            ob.operation("run", "run", name="run samples", input="sample", done="run"),
            ob.operation("stamp", "stamp", name="practice stamp", input="form", done="stamped"),
            ob.operation("dispense", "make up", "dispense", name="make up meds", product="meds"),
        ],
        facilities=[
            ob.facility(
                "printer", "printer", at="front_desk_room", guards=["priya"], operations=["print"]
            ),
            ob.facility("gel_rig", "gel rig", at="lab", guards=["hazel"], operations=["run"]),
            ob.facility(
                "front_desk",
                "front desk",
                at="front_desk_room",
                guards=["priya"],
                operations=["stamp"],
            ),
            ob.facility(
                "dispensary", "dispensary", at="pharmacy", guards=["holly"], operations=["dispense"]
            ),
            ob.facility(
                "stores",
                "stores",
                at="stores_room",
                guards=["frank"],
                supplies=["gloves", "ice_bucket"],
            ),
        ],
        home="front_desk_room",
        group=("team", "Team"),
    )


vet_practice = ob.parsed(raw_vet_practice)
