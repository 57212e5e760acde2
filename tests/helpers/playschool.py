"""A school's drama and science staff for the reader's tests of blind round 17's classes (the
round's own office and sentences were never read): a staff-room urn makes tea (the office's one
hot drink, named only "tea"), milk is kept in the green room fridge, a props bench mixes stage
blood, the prep room's technician (called "Luke" by everyone) makes up practical kits,
reprographics prints script packs, and a cupboard keeps wipes for anyone. Two colleagues have
names that are ordinary words ("Miles", "Penny"); each person's lunch is kept in the green room
fridge; a lab is named "S4"."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_LUNCH = ob.kept("lunch", at="green_room", facility="green_room_fridge")

_PEOPLE = (
    ob.person("ada", "Ada Brook", "stapler", "keyboard", _LUNCH),
    ob.person("rory", "Rory Vance", "keyboard", _LUNCH),
    ob.person("miles", "Miles Cho", "stapler", _LUNCH),
    ob.person("penny", "Penny Ruiz", "keyboard"),
    ob.person("lucas", "Lucas Farrow", aliases=["Luke"]),
    ob.person("thandi", "Thandi Nkosi", "stapler"),
    ob.person("jun", "Jun Park", "keyboard", _LUNCH),
)


def raw_playschool() -> dict[str, Any]:
    return ob.office_file(
        "playschool",
        _PEOPLE,
        everyone_owns=["script"],
        rooms=[
            ob.room("staff_room", "Staff room", 4.0, 20.5),
            ob.room("green_room", "Green room", 14.0, 20.5),
            ob.room("props_room", "Props workshop", 24.0, 20.5),
            ob.room("prep_room", "Prep room", 34.0, 20.5),
            ob.room("repro_room", "Reprographics", 44.0, 20.5),
            ob.room("s4", "S4", 44.0, 6.0, kind="room"),
        ],
        item_types=[
            ob.item("stapler", "stapler"),
            ob.item("keyboard", "keyboard"),
            ob.item("lunch", "lunch", "personal"),
            ob.item("script", "script", "electronic", synonyms=["script file"]),
            ob.item("wipes", "wipes", synonyms=["cleaning wipes"], consumable=True),
            ob.item("milk", "milk", consumable=True),
            ob.item("tea", "tea", "product"),
            ob.item("stage_blood", "stage blood", "product", synonyms=["fake blood"]),
            ob.item("practical_kit", "practical kit", "product", synonyms=["kit"]),
            ob.item("script_pack", "script pack", "product"),
        ],
        operations=[
            ob.operation("tea", name="make tea", product="tea"),
            ob.operation("mix", "mix", name="mix stage blood", product="stage_blood"),
            ob.operation("kit", name="make up a practical kit", product="practical_kit"),
            ob.operation("print", "print", input="script", product="script_pack"),
        ],
        facilities=[
            ob.facility(
                "urn",
                "urn",
                at="staff_room",
                guards=["penny"],
                operations=["tea"],
                products=["tea"],
            ),
            ob.facility(
                "props_bench",
                "props bench",
                at="props_room",
                guards=["jun"],
                operations=["mix"],
                products=["stage_blood"],
            ),
            ob.facility(
                "prep_bench",
                "prep bench",
                at="prep_room",
                guards=["lucas"],
                operations=["kit"],
                products=["practical_kit"],
            ),
            ob.facility(
                "repro",
                "reprographics desk",
                at="repro_room",
                guards=["thandi"],
                operations=["print"],
                products=["script_pack"],
            ),
            ob.facility(
                "green_room_fridge",
                "green room fridge",
                at="green_room",
                guards=["penny"],
                supplies=["milk"],
                synonyms=["fridge"],
            ),
            ob.facility(
                "cupboard",
                "supply cupboard",
                at="staff_room",
                guards=["penny"],
                supplies=["wipes"],
            ),
        ],
        home="staff_room",
    )


playschool = ob.parsed(raw_playschool)


def raw_playschool_with_vat() -> dict[str, Any]:
    """The school with the urn also making coffee and a dye vat in the props workshop that
    dyes costumes (the vat also just "the vat"): a reason clause may name either."""
    raw = raw_playschool()
    raw["item_types"] += [ob.item("coffee", "coffee", "product"), ob.item("costume", "costume")]
    raw["operations"] += [
        ob.operation("coffee", name="make coffee", product="coffee"),
        ob.operation("dye", "dye", input="costume"),
    ]
    urn = next(f for f in raw["facilities"] if f["id"] == "urn")
    urn["operations"].append("coffee")
    urn["products"].append("coffee")
    raw["facilities"].append(
        ob.facility(
            "vat", "dye vat", at="props_room", guards=["jun"], operations=["dye"], synonyms=["vat"]
        )
    )
    return raw


playschool_with_vat = ob.parsed(raw_playschool_with_vat)
