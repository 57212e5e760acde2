"""A fire station's kit rooms for the reader's tests of blind round 154's classes (the round's
own offices and sentences were never read): facilities named after what they do (a drying room
that dries kit, a packing store that packs a lot for collection and keeps bubble wrap for
anyone, a copy room that copies a form and keeps tape, a binding room that binds a manual and
keeps bags), a rack that charges radios, people who own a tunic, a helmet, a coat or a radio,
and everyone's pre-plan files to print."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("eilidh", "Eilidh Ross", "tunic", "helmet", "radio"),
    ob.person("callum", "Callum Reid", "tunic", "coat", "lot"),
    ob.person("morag", "Morag Bain", "helmet", "stapler"),
    ob.person("fraser", "Fraser Muir", "coat", "manual"),
)


def raw_kit_station() -> dict[str, Any]:
    return ob.office_file(
        "kit station",
        _PEOPLE,
        rooms=[
            ob.room("drying_room", "Drying room", 4.0, 20.0),
            ob.room("packing_store", "Packing store", 12.0, 20.0),
            ob.room("copy_room", "Copy room", 20.0, 20.0),
            ob.room("binding_room", "Binding room", 28.0, 20.0),
            ob.room("mess", "Mess", 34.0, 12.0, kind="room"),
        ],
        item_types=[
            ob.item("tunic", "tunic", synonyms=["fire tunic"]),
            ob.item("helmet", "helmet"),
            ob.item("coat", "coat", synonyms=["jacket"]),
            ob.item("radio", "radio"),
            ob.item("stapler", "stapler"),
            ob.item("lot", "lot", synonyms=["lots"]),
            ob.item("manual", "manual", "personal"),
            ob.item("form", "form", "personal", synonyms=["invoice"]),
            ob.item("plan_file", "file", "electronic", synonyms=["pre-plan", "quote"]),
            ob.item("printout", "printout", "product"),
            ob.item("bubble_wrap", "bubble wrap", consumable=True),
            ob.item("tape", "tape", synonyms=["parcel tape"], consumable=True),
            ob.item("bag", "bag", synonyms=["bags"], consumable=True),
            ob.item("photocopy", "photocopy", "product", synonyms=["copy", "copies"]),
        ],
        operations=[
            ob.operation("dry", "dry", name="dry kit", input="tunic"),
            ob.operation("pack", "pack", name="pack for collection", input="lot"),
            ob.operation("copy", "copy", input="form", product="photocopy"),
            ob.operation("print", "print", input="plan_file", product="printout"),
            ob.operation("bind", "bind", input="manual"),
            ob.operation("charge", "charge", "recharge", input="radio"),
        ],
        facilities=[
            ob.facility(
                "drying_room", "drying room", at="drying_room", guards=["morag"], operations=["dry"]
            ),
            ob.facility(
                "packing_store",
                "packing store",
                at="packing_store",
                guards=["morag"],
                operations=["pack"],
                supplies=["bubble_wrap"],
            ),
            ob.facility(
                "copy_room",
                "copy room",
                at="copy_room",
                guards=["fraser"],
                operations=["copy", "print"],
                products=["photocopy", "printout"],
                supplies=["tape"],
            ),
            ob.facility(
                "binding_room",
                "binding room",
                at="binding_room",
                guards=["fraser"],
                operations=["bind"],
                supplies=["bag"],
            ),
            ob.facility(
                "charging_rack",
                "charging rack",
                at="mess",
                guards=["eilidh"],
                operations=["charge"],
            ),
        ],
        everyone_owns=["form", "plan_file"],
        home="mess",
    )


kit_station = ob.parsed(raw_kit_station)
