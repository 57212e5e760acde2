"""A veterinary yard for the reader's tests of blind round 55's classes (the round's own office
and sentences were never read): colleagues whose names are also English words (Drew, Bill,
Chase, Min), a mask-testing bench, a printer, a sample courier whose operation's name carries
its own destination ("send to the lab"), and no phone service."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("gwen", "Gwen Ashby", "clippers", "calculator", "mask", "ruler"),
    ob.person("sam", "Sam Ortiz", "clippers", "ruler", aliases=["Sam"]),
    ob.person("ana", "Ana Ruiz", "calculator", "mask"),
    ob.person("drew", "Drew Hale", "rack", aliases=["Drew"]),
    ob.person("bill", "Bill Shaw", "ruler", aliases=["Bill"]),
    ob.person("chase", "Chase Moreno", "mask", aliases=["Chase"]),
    ob.person("min", "Min Park", "calculator", aliases=["Min"]),
)


def raw_vet_yard() -> dict[str, Any]:
    return ob.office_file(
        "vet yard",
        _PEOPLE,
        rooms=[
            ob.room("stores", "Supply room", 4.0, 20.0),
            ob.room("lab_bench", "Lab bench", 20.0, 20.0),
        ],
        item_types=[
            ob.item("file", "file", "electronic", synonyms=["document"]),
            ob.item("clippers", "pair of clippers", synonyms=["clippers"]),
            ob.item("calculator", "calculator"),
            ob.item("mask", "mask"),
            ob.item("ruler", "ruler"),
            ob.item("rack", "sample rack", synonyms=["rack"]),
            ob.item("sample", "blood sample", synonyms=["sample"]),
            ob.item("printout", "printout", "product"),
            ob.item("cable", "charging cable", consumable=True, synonyms=["cable"]),
        ],
        operations=[
            ob.operation("test", "test", input="mask", done="tested"),
            ob.operation("print", "print", input="file", product="printout"),
            ob.operation(
                "lab_send",
                "courier",
                "send off",
                name="send to the lab",
                input="sample",
                sends_out=True,
                destination_asked="the name of the lab",
            ),
        ],
        facilities=[
            ob.facility(
                "supply_room", "supply room", at="stores", guards=["bill"], supplies=["cable"]
            ),
            ob.facility(
                "test_bench", "test bench", at="lab_bench", guards=["drew"], operations=["test"]
            ),
            ob.facility("printer", "printer", at="stores", guards=["bill"], operations=["print"]),
            ob.facility(
                "courier_desk",
                "courier desk",
                at="lab_bench",
                guards=["drew"],
                operations=["lab_send"],
            ),
        ],
        everyone_owns=["file", "sample"],
        home="stores",
    )


vet_yard = ob.parsed(raw_vet_yard)
