"""A small newsroom for the tests of blind round 16's classes (the round's own office and
sentences were never read). People named with diacritics (Åsa, Ramón, Łukasz, Zoë) who each
own a long lens and a camera; people whose first names are ordinary English words (Mark,
Will, Sunny, Frank); an editor with a role alias ("the Publisher"); a standards desk named by an
adjective ("standards", "compliance") that reads page proofs and gives them back; a courier
whose verbs include "run"; a printer whose input is the running sheet; a trimmer whose verbs
include "cut" beside a cutting mat; a light meter and a magnifying glass to borrow; negative
strips (synonym "negatives") that people hold."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ines", "Ines Duarte", "page_proof", "running_sheet", "file"),
    ob.person("asa", "Åsa Lindgren", "long_lens", "camera", "negative_strip"),
    ob.person("ramon", "Ramón Ibáñez", "long_lens", "camera"),
    ob.person("lukasz", "Łukasz Nowak", "long_lens", "light_meter"),
    ob.person("zoe", "Zoë Marchetti", "camera", "page_proof"),
    ob.person("mark", "Mark Ellison", "cutting_mat", "magnifying_glass"),
    ob.person("will", "Will Tanner", "light_meter", "page_proof"),
    ob.person("sunny", "Sunny Rao", "magnifying_glass"),
    ob.person("bjorn", "Bjørn Haugen", "long_lens", "camera"),
    ob.person("frank", "Frank Osei", "cutting_mat"),
    ob.person("bea", "Beatrix Holm", "running_sheet", aliases=["Bea", "the Publisher"]),
)


def raw_newsroom() -> dict[str, Any]:
    return ob.office_file(
        "newsroom",
        _PEOPLE,
        rooms=[
            ob.room("print_room", "Print room", 4.0, 20.5),
            ob.room("back_office", "Back office", 20.0, 20.5),
            ob.room("post_room", "Post room", 30.0, 20.5),
        ],
        item_types=[
            ob.item("long_lens", "long lens", synonyms=["telephoto"]),
            ob.item("camera", "camera"),
            ob.item("light_meter", "light meter", synonyms=["exposure meter"]),
            ob.item("magnifying_glass", "magnifying glass", synonyms=["eyeglass"]),
            ob.item("cutting_mat", "cutting mat"),
            ob.item("negative_strip", "negative strip", "personal", synonyms=["negatives"]),
            ob.item("page_proof", "page proof", "personal", synonyms=["proof"]),
            ob.item("running_sheet", "running sheet", "personal", synonyms=["rundown"]),
            ob.item("file", "electronic file", "electronic", synonyms=["file", "draft"]),
            ob.item("printout", "printout", "product", synonyms=["hard copy"]),
        ],
        operations=[
            ob.operation("vet", "vet", name="standards read", input="page_proof"),
            ob.operation(
                "courier",
                "courier",
                "run",
                "dispatch",
                input="page_proof",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
            ),
            ob.operation("print", "print", input="file", product="printout"),
            ob.operation("shred", "shred", input="page_proof", consumes=True),
            ob.operation("trim", "trim", "cut", input="printout"),
        ],
        facilities=[
            ob.facility(
                "standards_desk",
                "standards desk",
                synonyms=["standards", "the standards team", "compliance", "editorial"],
                at="back_office",
                guards=["mark"],
                operations=["vet"],
            ),
            ob.facility(
                "courier_desk",
                "courier desk",
                at="post_room",
                guards=["sunny"],
                operations=["courier", "shred"],
            ),
            ob.facility(
                "printer",
                "printer",
                at="print_room",
                guards=["will"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "trimmer", "trimmer", at="print_room", guards=["will"], operations=["trim"]
            ),
        ],
        home="print_room",
    )


newsroom = ob.parsed(raw_newsroom)
