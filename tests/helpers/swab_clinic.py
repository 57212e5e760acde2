"""A small occupational-health clinic for the reader's tests of fixer fix180c's classes (the
testers' own offices and sentences were never read): a lab that tests a person's sample into a
lab report (the sample has no other name, so "my swab" is a guess from the work asked), a first
aid kit called "kit" that one person keeps, stopwatches (which the lab calibrates, "audit",
"review") and staplers several people own, a
store cupboard that keeps lanyards for anyone, and a print room whose printer prints a file and
whose laminator makes a laminated copy from the same file."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ines", "Ines Duarte", "stapler", "kit", aliases=["Ines"]),
    ob.person("bram", "Bram de Vries", "stapler", aliases=["Bram"]),
    ob.person("kemi", "Kemi Adebayo", "stopwatch", aliases=["Kemi"], at="lab"),
    ob.person("tariq", "Tariq Aziz", "stopwatch", aliases=["Tariq"]),
)


def raw_swab_clinic() -> dict[str, Any]:
    return ob.office_file(
        "swab clinic",
        _PEOPLE,
        rooms=[ob.room("lab", "Lab", 4.0, 20.0), ob.room("office", "Print room", 12.0, 20.0)],
        item_types=[
            ob.item("sample", "test sample", "personal", synonyms=["sample"]),
            ob.item("kit", "first aid kit", synonyms=["kit"]),
            ob.item("stapler", "stapler"),
            ob.item("stopwatch", "stopwatch"),
            ob.item("lanyard", "lanyard", consumable=True),
            ob.item("document", "document", "personal", signable=True, synonyms=["form"]),
            ob.item("file", "electronic file", "electronic", synonyms=["file", "report"]),
            ob.item("printout", "printout", "product"),
            ob.item("sheet", "laminated copy", "product", synonyms=["laminated sheet"]),
            ob.item("lab_report", "lab report", "product"),
        ],
        operations=[
            ob.operation("test", "test", input="sample", product="lab_report"),
            ob.operation("print", "print", input="file", product="printout"),
            ob.operation("laminate", "laminate", input="file", product="sheet"),
            ob.operation(
                "calibrate", "calibrate", "audit", "review", name="calibration", input="stopwatch"
            ),
        ],
        facilities=[
            ob.facility("lab", "lab", at="lab", guards=["kemi"], operations=["test", "calibrate"]),
            ob.facility(
                "printer",
                "printer",
                at="office",
                guards=["bram"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "laminator",
                "laminator",
                at="office",
                guards=["bram"],
                operations=["laminate"],
                products=["sheet"],
            ),
            ob.facility(
                "store", "store cupboard", at="office", guards=["bram"], supplies=["lanyard"]
            ),
        ],
        everyone_owns=["sample", "document", "file"],
        home="office",
    )


swab_clinic = ob.parsed(raw_swab_clinic)
