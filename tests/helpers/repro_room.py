"""A small reprographics and chart room for the reader's tests of round 160's classes (the
round's own offices and sentences were never read). A printer prints a file; a large-format
printer prints the same file as a pull-up banner or a poster; a laminator laminates and a
binding machine binds a colleague's report or proofs; a chart table applies corrections to a
chart and a logbook desk updates the register; the QA lab keeps dev kits and the IT desk
spare laptops for anyone."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ana", "Ana Ruiz", "stapler", "report"),
    ob.person("bram", "Bram Visser", "stapler", "report", "chart"),
    ob.person("cleo", "Cleo Hart", "report", "chart"),
    ob.person("dev", "Devika Rao", "report", at="qa_lab"),
    ob.person("ivo", "Ivo Lind", "report", at="it_desk"),
    ob.person("nell", "Nell Quist", "report", "chart"),
)


def raw_repro_room() -> dict[str, Any]:
    return ob.office_file(
        "repro room",
        _PEOPLE,
        everyone_owns=["artwork", "proofs"],
        rooms=[
            ob.room("print_room", "Print room", 4.0, 20.5),
            ob.room("chart_room", "Chart room", 11.0, 20.5),
            ob.room("qa_lab", "QA lab", 18.0, 20.5),
            ob.room("it_desk", "IT desk", 25.0, 20.5),
        ],
        item_types=[
            ob.item("stapler", "stapler"),
            ob.item("report", "report", "personal", signable=True),
            ob.item("proofs", "proofs", "personal", synonyms=["proof"]),
            ob.item("chart", "chart", "personal", synonyms=["sea chart"]),
            ob.item("register", "register", "personal", synonyms=["logbook"]),
            ob.item("artwork", "artwork file", "electronic", synonyms=["artwork", "slides"]),
            ob.item("printout", "printout", "product"),
            ob.item("banner", "pull-up banner", "product", synonyms=["roll-up banner"]),
            ob.item("poster", "poster", "product"),
            ob.item("dev_kit", "dev kit", synonyms=["development kit"]),
            ob.item("laptop", "spare laptop", synonyms=["loan laptop"]),
        ],
        operations=[
            ob.operation("print", "print", input="artwork", product="printout"),
            ob.operation(
                "banner", "plot", name="large-format print", input="artwork", product="banner"
            ),
            ob.operation("poster", "enlarge", name="poster run", input="artwork", product="poster"),
            ob.operation("laminate", "laminate", input="proofs"),
            ob.operation("bind", "bind", input="report"),
            ob.operation("correct", name="apply corrections", input="chart"),
            ob.operation("log", name="update the register", input="register"),
        ],
        facilities=[
            ob.facility(
                "printer",
                "printer",
                at="print_room",
                guards=["ana"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "plotter",
                "large-format printer",
                at="print_room",
                guards=["ana"],
                operations=["banner", "poster"],
                products=["banner", "poster"],
                synonyms=["plotter"],
            ),
            ob.facility(
                "laminator", "laminator", at="print_room", guards=["ana"], operations=["laminate"]
            ),
            ob.facility(
                "binder", "binding machine", at="print_room", guards=["ana"], operations=["bind"]
            ),
            ob.facility(
                "chart_table",
                "chart table",
                at="chart_room",
                guards=["nell"],
                operations=["correct"],
            ),
            ob.facility(
                "log_desk", "logbook desk", at="chart_room", guards=["nell"], operations=["log"]
            ),
            ob.facility(
                "qa_store",
                "QA lab store",
                at="qa_lab",
                guards=["dev"],
                supplies=["dev_kit"],
            ),
            ob.facility(
                "it_cupboard",
                "IT cupboard",
                at="it_desk",
                guards=["ivo"],
                supplies=["laptop"],
            ),
        ],
        home="print_room",
    )


repro_room = ob.parsed(raw_repro_room)
