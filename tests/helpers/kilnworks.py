"""A ceramics studio's design office for the reader's tests of blind round 14's classes about
who receives and which parts a request has (the round's own office and sentences were never
read). One person is declared by a title with an article ("the Provost"); hole punches are
only ever someone's own, calculators are someone's or kept in the store cupboard for anyone;
a printer prints an agenda file; a legal desk vets reports; reports go out of the studio by
courier or by fax (two send-out services, neither named by a place)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("kit", "Kit Abara", "hole_punch", "calculator"),
    ob.person("oona", "Oona Pike", "calculator", aliases=["the Provost"]),
    ob.person("sunniva", "Sunniva Holt", "hole_punch"),
    ob.person("teodor", "Teodor Lusk", "hole_punch", "calculator"),
    ob.person("bram", "Bram Okoro", "calculator"),
    ob.person("wen", "Wen Ashby"),
)


def raw_kilnworks() -> dict[str, Any]:
    return ob.office_file(
        "kilnworks",
        _PEOPLE,
        everyone_owns=["report", "agenda"],
        rooms=[
            ob.room("print_bay", "Print bay", 4.0, 20.5),
            ob.room("legal_room", "Legal room", 14.0, 20.5),
            ob.room("post_room", "Post room", 24.0, 20.5),
        ],
        item_types=[
            ob.item("hole_punch", "hole punch", synonyms=["punch"]),
            ob.item("calculator", "calculator"),
            ob.item("report", "report", "personal", signable=True, synonyms=["glaze report"]),
            ob.item("agenda", "agenda", "electronic", synonyms=["agenda file", "minutes"]),
            ob.item("printout", "printout", "product"),
        ],
        operations=[
            ob.operation("print", "print", input="agenda", product="printout"),
            ob.operation("vet", "vet", "clear", name="legal review", input="report", done="vetted"),
            ob.operation(
                "courier",
                "courier",
                input="report",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
            ),
            ob.operation("fax", "fax", input="report", sends_out=True),
        ],
        facilities=[
            ob.facility(
                "printer",
                "printer",
                at="print_bay",
                guards=["bram"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "legal_desk",
                "legal desk",
                at="legal_room",
                guards=["wen"],
                operations=["vet"],
                synonyms=["legal"],
            ),
            ob.facility(
                "post_desk",
                "post desk",
                at="post_room",
                guards=["teodor"],
                operations=["courier", "fax"],
            ),
            ob.facility(
                "store_cupboard",
                "store cupboard",
                at="post_room",
                guards=["teodor"],
                supplies=["calculator"],
            ),
        ],
        home="print_bay",
    )


kilnworks = ob.parsed(raw_kilnworks)
