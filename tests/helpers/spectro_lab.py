"""A small chemistry lab for the reader's tests of blind round 59's classes (the round's own
offices and sentences were never read): one analysis, an IR spectrometer run with the generic
verb "run" (no NMR, no mass spec), a centrifuge that spins samples down, a laminator, a
sealing bay whose service is the two-word verb "heat seal", a diagnostics rig also "run",
a printer that also "runs off" copies, and a coffee machine."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("lee", "Lee Park", "sample", "phone", "banner", "curtain", aliases=["Lee"]),
    ob.person("ana", "Ana Ruiz", "sample", "phone", aliases=["Ana"]),
    ob.person("tom", "Tom Baker", "banner", "curtain", aliases=["Tom"]),
    ob.person("ivy", "Ivy Chen", "parcel", aliases=["Ivy"]),
)


def raw_spectro_lab() -> dict[str, Any]:
    return ob.office_file(
        "spectro lab",
        _PEOPLE,
        rooms=[
            ob.room("instrument_room", "Instrument room", 4.0, 20.0),
            ob.room("centrifuge_room", "Centrifuge room", 12.0, 20.0),
            ob.room("workshop", "Workshop", 20.0, 20.0),
            ob.room("kitchen", "Kitchen", 28.0, 20.0),
        ],
        item_types=[
            ob.item("document", "form", "personal", signable=True, synonyms=["document"]),
            ob.item("file", "file", "electronic"),
            ob.item("sample", "sample", synonyms=["crude product"]),
            ob.item("phone", "phone", "electronic"),
            ob.item("banner", "banner"),
            ob.item("curtain", "curtain", synonyms=["fabric"]),
            ob.item("parcel", "parcel"),
            ob.item("printout", "printout", "product"),
            ob.item("copy", "copy", "product"),
            ob.item("coffee", "coffee", "product"),
        ],
        operations=[
            ob.operation("ir", "run", name="IR scan", input="sample"),
            ob.operation("spin", "spin", "spin down", name="spin down", input="sample"),
            ob.operation("laminate", "laminate", input="banner"),
            ob.operation("seal", "heat seal", name="heat seal", input="curtain"),
            ob.operation("diagnose", "diagnose", "test", name="diagnose", input="phone"),
            ob.operation("print", "print", input="file", product="printout"),
            ob.operation("copy", "copy", "run off", input="document", product="copy"),
            ob.operation("coffee", "brew", name="make coffee", product="coffee"),
        ],
        facilities=[
            ob.facility(
                "spectrometer",
                "IR spectrometer",
                at="instrument_room",
                guards=["ana"],
                operations=["ir"],
                synonyms=["IR", "spectrometer"],
            ),
            ob.facility(
                "centrifuge",
                "centrifuge",
                at="centrifuge_room",
                guards=["ana"],
                operations=["spin"],
            ),
            ob.facility(
                "laminator", "laminator", at="workshop", guards=["tom"], operations=["laminate"]
            ),
            ob.facility(
                "sealing_bay", "sealing bay", at="workshop", guards=["tom"], operations=["seal"]
            ),
            ob.facility(
                "rig", "diagnostics rig", at="workshop", guards=["tom"], operations=["diagnose"]
            ),
            ob.facility(
                "printer",
                "printer",
                at="instrument_room",
                guards=["ivy"],
                operations=["print", "copy"],
                products=["printout", "copy"],
            ),
            ob.facility(
                "coffee_machine",
                "coffee machine",
                at="kitchen",
                guards=["ivy"],
                operations=["coffee"],
                products=["coffee"],
            ),
        ],
        everyone_owns=["document", "file"],
        home="kitchen",
    )


spectro_lab = ob.parsed(raw_spectro_lab)
