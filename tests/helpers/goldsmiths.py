"""A goldsmiths' workshop for the reader's tests of places outside said by their proper names
(fix61b): an XRF bench in the workshop assays a job (also "xrf"), a printer prints a report,
and a dispatch desk sends a job out two ways, to be hallmarked ("send for hallmarking", asked
which assay office) or by courier; so a place outside may hold the office's words ("the
Birmingham *Assay* Office", "the Leeds *Print* Works"), a colleague's surname ("the *Baker*
Street office") or a thing's name ("*Stapler* House")."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("lee", "Lee Park", "ring", "stapler"),
    ob.person("sam", "Sam Baker", "ring"),
    ob.person("ada", "Ada Stone", "stapler"),
    ob.person("tom", "Tom Reed"),
)


def raw_goldsmiths() -> dict[str, Any]:
    return ob.office_file(
        "goldsmiths",
        _PEOPLE,
        everyone_owns=["job", "report"],
        rooms=[
            ob.room("workshop", "Workshop", 4.0, 20.0),
            ob.room("front_desk", "Front desk", 12.0, 20.0),
        ],
        item_types=[
            ob.item("job", "job", "personal", synonyms=["piece"]),
            ob.item("ring", "ring"),
            ob.item("stapler", "stapler"),
            ob.item("report", "report", "electronic"),
            ob.item("printout", "printout", "product"),
        ],
        operations=[
            ob.operation("assay", "assay", "xrf", input="job", done="assayed"),
            ob.operation(
                "hallmark",
                "hallmark",
                name="send for hallmarking",
                input="job",
                sends_out=True,
                destination_asked="which assay office",
            ),
            ob.operation("print", "print", input="report", product="printout"),
            ob.operation(
                "courier",
                "courier",
                input="job",
                sends_out=True,
                destination_asked=ob.ASKS_NAME_AND_ADDRESS,
            ),
        ],
        facilities=[
            ob.facility(
                "xrf_bench", "XRF bench", at="workshop", guards=["tom"], operations=["assay"]
            ),
            ob.facility(
                "printer",
                "printer",
                at="workshop",
                guards=["tom"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "dispatch_desk",
                "dispatch desk",
                at="front_desk",
                guards=["ada"],
                operations=["hallmark", "courier"],
            ),
        ],
        home="workshop",
    )


goldsmiths = ob.parsed(raw_goldsmiths)
