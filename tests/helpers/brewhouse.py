"""A small brewery for the reader's tests of a colleague asked to run an office service for
the requester (fixer fix143b's class 2; the round's own office and sentences were never read):
a quality lab that tests a beer sample into a lab report, looked after by a colleague called by
a nickname (Zosia) and a second one; a label printer that prints labels from a file; a
laminator. Everyone has a beer sample, a document and a file of their own."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("zofia", "Zofia Wiśniewska", aliases=["Zosia", "Zofia"], at="lab"),
    ob.person("tomek", "Tomasz Nowak", aliases=["Tomek", "Tomasz"], at="lab"),
    ob.person("ines", "Ines Duarte", aliases=["Ines"]),
    ob.person("bram", "Bram de Vries", aliases=["Bram"]),
    ob.person("kemi", "Kemi Adebayo", aliases=["Kemi"]),
)


def raw_brewhouse() -> dict[str, Any]:
    return ob.office_file(
        "brewhouse",
        _PEOPLE,
        rooms=[
            ob.room("lab", "Quality lab", 4.0, 20.0),
            ob.room("packing", "Packing hall", 20.0, 20.0),
            ob.room("office", "Back office", 12.0, 20.0),
        ],
        item_types=[
            ob.item("sample", "beer sample", "personal", synonyms=["sample"]),
            ob.item("document", "document", "personal", signable=True, synonyms=["form"]),
            ob.item("file", "electronic file", "electronic", synonyms=["file", "artwork"]),
            ob.item("lab_report", "lab report", "product", synonyms=["report", "results"]),
            ob.item("label", "label", "product", synonyms=["labels", "can labels"]),
            ob.item("laminated_sheet", "laminated sheet", "product"),
        ],
        operations=[
            ob.operation("test", "test", "analyse", input="sample", product="lab_report"),
            ob.operation("print_labels", "print", input="file", product="label"),
            ob.operation("laminate", "laminate", input="document", product="laminated_sheet"),
        ],
        facilities=[
            ob.facility(
                "lab", "quality lab", at="lab", guards=["zofia", "tomek"], operations=["test"]
            ),
            ob.facility(
                "label_printer",
                "label printer",
                at="packing",
                guards=["bram"],
                operations=["print_labels"],
                products=["label"],
            ),
            ob.facility(
                "laminator", "laminator", at="office", guards=["kemi"], operations=["laminate"]
            ),
        ],
        everyone_owns=["sample", "document", "file"],
        home="office",
    )


brewhouse = ob.parsed(raw_brewhouse)


def raw_brewhouse_that_couriers() -> dict[str, Any]:
    """The brewery whose back office also couriers a document out ("send", "courier"), so a
    past "sent" may be taken for that service."""
    raw = raw_brewhouse()
    raw["operations"].append(
        ob.operation(
            "courier",
            "send",
            "courier",
            input="document",
            sends_out=True,
            destination_asked="the address",
        )
    )
    next(f for f in raw["facilities"] if f["id"] == "laminator")["operations"].append("courier")
    return raw


brewhouse_that_couriers = ob.parsed(raw_brewhouse_that_couriers)
