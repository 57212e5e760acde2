"""A theatre's costume shop for the reader's tests of fixer 175d's classes (written without the
testers' names): aprons and coats owned by people (an apron also called "my whites"), electronic
files, a laundry room whose sewing bench stitches and washes people's clothes, a print desk, a
post room that ships papers out, and a lint roller kept in the laundry whose declared purpose
is taking hair and fluff off clothes."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("wang", "Wang Fang", "apron", "coat", "file", "document"),
    ob.person("tomas", "Tomás Reyes", "apron", "coat", "file", "document"),
    ob.person("lee", "Lee Ming", "apron", "coat", "file", "document"),
    ob.person("nia", "Nia Cole", "apron", "file", "document"),
)


def raw_costume_shop() -> dict[str, Any]:
    return ob.office_file(
        "costume_shop",
        _PEOPLE,
        desks=ob.desk_row(len(_PEOPLE), x0=4.0, y=5.0),
        rooms=[
            ob.room("laundry", "Laundry", 24.0, 18.0),
            ob.room("print_desk", "Print desk", 8.0, 18.0),
            ob.room("post_room", "Post room", 16.0, 18.0),
        ],
        item_types=[
            ob.item("apron", "apron", "personal", synonyms=["whites", "pinny"]),
            ob.item("coat", "coat", "personal", synonyms=["jacket"]),
            ob.item("document", "document", "personal", synonyms=["report", "form"], signable=True),
            ob.item(
                "file", "electronic file", "electronic", synonyms=["file", "spreadsheet", "pdf"]
            ),
            ob.item("printout", "printout", "product", synonyms=["printed copy"]),
            ob.item("cake", "cake", "product", synonyms=["sponge"]),
            ob.item("lint_roller", "lint roller", synonyms=["fluff roller"])
            | {"purposes": ["remove hair", "remove lint", "remove fluff"]},
            ob.item("scissors", "scissors") | {"purposes": ["cut"]},
        ],
        operations=[
            ob.operation("stitch", "stitch", "sew", "mend", name="stitch", input="apron"),
            ob.operation("print", "print", name="print", input="file", product="printout"),
            ob.operation("ship", "ship", "post", name="ship", input="document"),
            ob.operation("bake", "bake", name="bake a cake", product="cake"),
        ],
        facilities=[
            ob.facility(
                "sewing_bench",
                "sewing bench",
                at="laundry",
                guards=["nia"],
                operations=["stitch"],
                supplies=["lint_roller", "scissors"],
            ),
            ob.facility(
                "printer",
                "printer",
                at="print_desk",
                guards=["tomas"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility("post", "post desk", at="post_room", guards=["wang"], operations=["ship"]),
            ob.facility(
                "oven", "oven", at="laundry", guards=["nia"], operations=["bake"], products=["cake"]
            ),
        ],
        home="laundry",
        group=("crew", "Crew"),
    )


costume_shop = ob.parsed(raw_costume_shop)
