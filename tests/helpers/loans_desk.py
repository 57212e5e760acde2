"""A museum's loans office for the reader's tests of a service's timing said beside a request
(fix154a class 1; the measured office and sentence were never read): a courier desk that
sends papers out, a shredder and a photography bench (three services that take a paper), an
accession stamp two colleagues own (a sealing tool), and loan papers everyone has, which a
colleague may sign."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ines", "Ines Alvarez", "accession_stamp"),
    ob.person("tobi", "Tobi Adeyemi", "accession_stamp"),
    ob.person("marek", "Marek Nowak"),
    ob.person("gwen", "Gwen Price"),
)


def raw_loans_desk() -> dict[str, Any]:
    return ob.office_file(
        "loans desk",
        _PEOPLE,
        rooms=[
            ob.room("dispatch", "Dispatch", 4.0, 20.0),
            ob.room("studio", "Photo studio", 12.0, 20.0),
            ob.room("back_office", "Back office", 20.0, 20.0),
        ],
        item_types=[
            ob.item(
                "paper",
                "loan paper",
                "personal",
                signable=True,
                synonyms=["loan agreement", "condition report", "form", "contract"],
            ),
            ob.item("accession_stamp", "accession stamp", synonyms=["stamp"], seals=True),
            ob.item("photograph", "photograph", "product", synonyms=["photo"]),
        ],
        operations=[
            ob.operation(
                "courier",
                "courier",
                "dispatch",
                name="send by courier",
                input="paper",
                sends_out=True,
            ),
            ob.operation("shred", "shred", input="paper", consumes=True),
            ob.operation("photograph", "photograph", "photo", input="paper", product="photograph"),
        ],
        facilities=[
            ob.facility(
                "courier_desk",
                "courier desk",
                at="dispatch",
                guards=["marek"],
                operations=["courier"],
            ),
            ob.facility(
                "shredder", "shredder", at="back_office", guards=["gwen"], operations=["shred"]
            ),
            ob.facility(
                "photo_bench",
                "photography bench",
                at="studio",
                guards=["gwen"],
                operations=["photograph"],
                products=["photograph"],
            ),
        ],
        everyone_owns=["paper"],
        home="dispatch",
    )


loans_desk = ob.parsed(raw_loans_desk)
