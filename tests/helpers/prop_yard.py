"""A prop-hire yard for the reader's tests of blind rounds 252, 254 and 255's classes (read from
the rounds' measured offices, never copied): a printer, a label printer making barcode labels
from a stock file, a shredder and a scanner, a stores cage keeping cable ties for anyone, two
drivers and one manager by their titles, and van keys ("van" a word inside a name of them,
"keys to the van")."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ada", "Ada Kerr", "stamp", "van_keys"),
    ob.person("bo", "Bo Lund", aliases=["Driver Lund"]),
    ob.person("cy", "Cy Park", aliases=["Driver Park"]),
    ob.person("di", "Di Moss", aliases=["Manager Moss"]),
    ob.person("ed", "Ed Vale", aliases=["Ed"]),
)


def raw_prop_yard() -> dict[str, Any]:
    return ob.office_file(
        "prop yard",
        _PEOPLE,
        rooms=[
            ob.room("print_corner", "Print corner", 4.0, 20.0),
            ob.room("cage", "Stores cage", 20.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["stock list", "pick list", "form"]),
            ob.item("printout", "printout", "product"),
            ob.item("labels", "barcode labels", "product", synonyms=["barcodes"]),
            ob.item("scan", "scan", "product"),
            ob.item("stamp", "hire stamp", synonyms=["stamp"]),
            ob.item("ties", "cable ties", synonyms=["zip ties"]),
            ob.item("tape", "gaffer tape", consumable=True),
            ob.item("torch", "torch"),
            ob.item("van_keys", "van keys", synonyms=["keys", "keys to the van"]),
        ],
        operations=[
            ob.operation("print", "print", input="file", product="printout"),
            ob.operation(
                "tag", "tag", "label", name="print barcode labels", input="file", product="labels"
            ),
            ob.operation("scan", "scan", input="file", product="scan"),
            ob.operation("shred", "shred", input="file", consumes=True),
        ],
        facilities=[
            ob.facility(
                "printer",
                "printer",
                at="print_corner",
                guards=["ada"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "label_printer",
                "label printer",
                at="print_corner",
                guards=["ed"],
                operations=["tag"],
                products=["labels"],
            ),
            ob.facility(
                "scanner",
                "scanner",
                at="print_corner",
                guards=["ada"],
                operations=["scan"],
                products=["scan"],
            ),
            ob.facility(
                "shredder", "shredder", at="print_corner", guards=["ada"], operations=["shred"]
            ),
            ob.facility("cage", "stores cage", at="cage", guards=["ed"], supplies=["ties", "tape"]),
        ],
        home="print_corner",
        everyone_owns=["file", "torch"],
    )


prop_yard = ob.parsed(raw_prop_yard)
