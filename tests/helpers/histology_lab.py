"""A hospital histology lab for the reader's tests of blind round 18's classes (the round's
office and sentences were never read): three colleagues share the first name Jude and are told
apart by an initial ("Jude A", "Jude C", "Jude O"), a signable paper is a "timesheet" (also a
"COSHH form"), the printer prints files, the reagent store only makes up 70% ethanol, and the
specimen desk sends samples off to an outside lab (asking which lab first) and minipreps for
sequencing (asking which company)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("wren", "Wren Talbot", "timesheet", "pipette"),
    ob.person("ivy", "Ivy Moss", "timesheet", "sample"),
    ob.person("jude_a", "Jude Ashby", "timesheet", "timer", "forceps", aliases=["Jude A"]),
    ob.person("jude_c", "Jude Carver", "timesheet", "forceps", aliases=["Jude C"]),
    ob.person("jude_o", "Jude Okoro", "timesheet", "timer", aliases=["Jude O"]),
    ob.person("bea", "Bea Lund", "timesheet", "sample", "timer", "miniprep"),
)


def raw_histology_lab() -> dict[str, Any]:
    return ob.office_file(
        "histology_lab",
        _PEOPLE,
        everyone_owns=["file"],
        rooms=[
            ob.room("print_bay", "Print bay", 4.0, 18.0),
            ob.room("store_room", "Store room", 12.0, 18.0),
            ob.room("specimen_room", "Specimen room", 20.0, 18.0),
        ],
        item_types=[
            ob.item("pipette", "pipette"),
            ob.item("timer", "timer"),
            ob.item("forceps", "forceps", synonyms=["tweezers"]),
            ob.item(
                "timesheet",
                "timesheet",
                "personal",
                signable=True,
                synonyms=["coshh form", "holiday form"],
            ),
            ob.item("sample", "sample", "personal", synonyms=["biopsy", "slides"]),
            ob.item("miniprep", "miniprep", "personal", synonyms=["plasmid prep"]),
            ob.item("file", "file", "electronic", synonyms=["protocol"]),
            ob.item("printout", "printout", "product", synonyms=["hard copy"]),
            ob.item("ethanol", "70% ethanol", "product", synonyms=["ethanol"]),
        ],
        operations=[
            ob.operation("print", "print", input="file", product="printout"),
            ob.operation("make_ethanol", "make up", name="make up", product="ethanol"),
            ob.operation(
                "send_off",
                "send off",
                name="send off",
                input="sample",
                sends_out=True,
                destination_asked="which lab",
            ),
            ob.operation(
                "sequence",
                "sequence",
                name="sequencing",
                input="miniprep",
                sends_out=True,
                destination_asked="which company",
            ),
        ],
        facilities=[
            ob.facility("printer", "printer", at="print_bay", guards=["bea"], operations=["print"]),
            ob.facility(
                "reagent_store",
                "reagent store",
                at="store_room",
                guards=["ivy"],
                operations=["make_ethanol"],
                products=["ethanol"],
                synonyms=["chem store"],
            ),
            ob.facility(
                "specimen_desk",
                "specimen desk",
                at="specimen_room",
                guards=["wren"],
                operations=["send_off", "sequence"],
            ),
        ],
        home="print_bay",
        group=("lab", "Lab"),
    )


histology_lab = ob.parsed(raw_histology_lab)
