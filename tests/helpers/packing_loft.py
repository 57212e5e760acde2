"""A packing loft for the reader's tests of blind round 28's classes on items, operations and
places (the round's own office and sentences were never read): a cool-box service that packs a
sample (its verb also the last word of an item's name, "ice pack"), a copier that prints a
file (also "run off") and photocopies a paper, a van that sends a parcel out, an office stamp
Robin keeps, a binder that comb-binds a manuscript, supplies kept in the stores; two people
called Sam, and one person who owns a register kept in a cabinet."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("lena", "Lena Brandt", "sample", "invoice", "manuscript", "stapler"),
    ob.person(
        "otto",
        "Otto Pike",
        "ruler",
        "stapler",
        ob.kept("register", at="back_office", facility="cabinet"),
    ),
    ob.person("sam_r", "Sam Reyes", "ruler"),
    ob.person("sam_k", "Sam Kowal"),
    ob.person("robin", "Robin Hale", "office_stamp"),
)


def raw_packing_loft() -> dict[str, Any]:
    return ob.office_file(
        "packing loft",
        _PEOPLE,
        rooms=[
            ob.room("back_office", "Back office", 4.0, 20.0),
            ob.room("stores", "Stores", 12.0, 20.0),
            ob.room("bench", "Packing bench", 20.0, 20.0),
            ob.room("yard", "Yard", 28.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["labels"]),
            ob.item("printout", "printout", "product", synonyms=["copies"]),
            ob.item("photocopy", "photocopy", "product", synonyms=["duplicate"]),
            ob.item("sample", "sample", synonyms=["vial"]),
            ob.item("ice_pack", "ice pack", synonyms=["cold pack"], consumable=True),
            ob.item("cable_tie", "cable tie", consumable=True),
            ob.item("padded_bag", "padded bag", synonyms=["jiffy bag"], consumable=True),
            ob.item("ruler", "ruler"),
            ob.item("stapler", "stapler"),
            ob.item("register", "register", "personal"),
            ob.item("invoice", "invoice", "personal"),
            ob.item("manuscript", "manuscript", "personal", synonyms=["ms"]),
            ob.item("parcel", "parcel"),
            ob.item("office_stamp", "office stamp", synonyms=["stamp"], seals=True),
        ],
        operations=[
            ob.operation("print", "print", "run off", input="file", product="printout"),
            ob.operation("photocopy", "photocopy", input="invoice", product="photocopy"),
            ob.operation("pack", "pack", name="cool-box packing", input="sample"),
            ob.operation(
                "send_out",
                "send out",
                "dispatch",
                name="van run",
                input="parcel",
                sends_out=True,
            ),
            ob.operation("bind", "comb-bind", "bind", input="manuscript"),
        ],
        facilities=[
            ob.facility(
                "copier",
                "copier",
                synonyms=["printer"],
                at="back_office",
                guards=["robin"],
                operations=["print", "photocopy"],
                products=["printout", "photocopy"],
            ),
            ob.facility("cool_box", "cool box", at="bench", guards=["robin"], operations=["pack"]),
            ob.facility("van", "van", at="yard", guards=["robin"], operations=["send_out"]),
            ob.facility(
                "binder", "binder", at="back_office", guards=["robin"], operations=["bind"]
            ),
            ob.facility(
                "stores",
                "stores",
                at="stores",
                guards=["robin"],
                supplies=["ice_pack", "cable_tie", "padded_bag", "stapler"],
            ),
            ob.facility("cabinet", "cabinet", at="back_office", guards=["otto"]),
        ],
        everyone_owns=["file"],
        home="back_office",
    )


packing_loft = ob.parsed(raw_packing_loft)
