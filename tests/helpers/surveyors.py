"""A land surveyors' practice for the reader's tests of blind round 7's classes (the round's
law firm and sentences were never read): two partners own the chartered stamp (an owned
tool that stamps the practice's papers), one copier in the plan room copies, scans to PDF
and binds (three operations of one machine, two of one shape), a post desk couriers and
faxes papers out of the office, and a colleague is called Bill (a word of the post desk's
trade). Its signable paper is a "plan"; leases, affidavits and wills are papers it never
lists."""

from __future__ import annotations

from typing import Any

from helpers.office_builder import (
    desk_row,
    facility,
    item,
    office_file,
    operation,
    parsed,
    person,
    room,
)

_PEOPLE = (
    person("ines", "Ines Varga", "stamp", "plan", "tape"),
    person("tobias", "Tobias Rehn", "stamp", "plan"),
    person("bill", "Bill Osei", "plan", "tripod"),
    person("noor", "Noor Haddad", "plan", "level"),
    person("callum", "Callum Price", "plan", "tripod", "tape"),
    person("otto", "Otto Lindgren", "plan", "level"),
)


def raw_surveyors() -> dict[str, Any]:
    return office_file(
        "surveyors",
        _PEOPLE,
        everyone_owns=["drawing"],
        desks=desk_row(len(_PEOPLE), x0=4.0),
        rooms=[
            room("plan_room", "Plan room", 4.0, 18.0),
            room("post_room", "Post room", 16.0, 18.0),
        ],
        item_types=[
            item("tape", "measuring tape", synonyms=["tape measure"]),
            item("level", "spirit level", synonyms=["level"]),
            item("tripod", "tripod"),
            item(
                "stamp",
                "chartered stamp",
                seals=True,
                synonyms=["stamp", "embosser", "practice seal"],
            ),
            item(
                "plan",
                "plan",
                "personal",
                signable=True,
                synonyms=["survey plan", "contract", "certificate"],
            ),
            item(
                "drawing", "drawing file", "electronic", synonyms=["drawing", "draft", "cad file"]
            ),
            item("pdf", "PDF", "electronic", synonyms=["pdf file"]),
            item("plot", "plot", "product", synonyms=["printout"]),
            item("copy", "copy", "product", synonyms=["photocopy"]),
        ],
        operations=[
            operation("plot", "print", "plot", name="print", input="drawing", product="plot"),
            operation("copy", "copy", "photocopy", input="plan", product="copy"),
            operation(
                "scan", "scan", "digitise", input="plan", product="pdf", done="scanned to PDF"
            ),
            operation("bind", "bind", input="plan"),
            operation("courier", "courier", input="plan", sends_out=True),
            operation("fax", "fax", input="plan", sends_out=True),
        ],
        facilities=[
            facility(
                "copier",
                "copier",
                at="plan_room",
                guards=["otto"],
                operations=["copy", "scan", "bind"],
                synonyms=["photocopier"],
            ),
            facility("plotter", "plotter", at="plan_room", guards=["otto"], operations=["plot"]),
            facility(
                "post_desk",
                "post desk",
                at="post_room",
                guards=["noor"],
                operations=["courier", "fax"],
            ),
        ],
        home="plan_room",
        group=("practice", "Practice"),
    )


surveyors = parsed(raw_surveyors)
