"""A land surveyors' practice for the reader's tests of blind round 7's classes (the round's
law firm and sentences were never read): two partners own the chartered stamp (an owned
tool that stamps the practice's papers), one copier in the plan room copies, scans to PDF
and binds (three operations of one machine, two of one shape), a post desk couriers and
faxes papers out of the office, and a colleague is called Bill (a word of the post desk's
trade). Its signable paper is a "plan"; leases, affidavits and wills are papers it never
lists."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ines", "Ines Varga", "stamp", "plan", "tape"),
    ob.person("tobias", "Tobias Rehn", "stamp", "plan"),
    ob.person("bill", "Bill Osei", "plan", "tripod"),
    ob.person("noor", "Noor Haddad", "plan", "level"),
    ob.person("callum", "Callum Price", "plan", "tripod", "tape"),
    ob.person("otto", "Otto Lindgren", "plan", "level"),
)


def raw_surveyors() -> dict[str, Any]:
    return ob.office_file(
        "surveyors",
        _PEOPLE,
        everyone_owns=["drawing"],
        desks=ob.desk_row(len(_PEOPLE), x0=4.0),
        rooms=[
            ob.room("plan_room", "Plan room", 4.0, 18.0),
            ob.room("post_room", "Post room", 16.0, 18.0),
        ],
        item_types=[
            ob.item("tape", "measuring tape", synonyms=["tape measure"]),
            ob.item("level", "spirit level", synonyms=["level"]),
            ob.item("tripod", "tripod"),
            ob.item(
                "stamp",
                "chartered stamp",
                seals=True,
                synonyms=["stamp", "embosser", "practice seal"],
            ),
            ob.item(
                "plan",
                "plan",
                "personal",
                signable=True,
                synonyms=["survey plan", "contract", "certificate"],
            ),
            ob.item(
                "drawing", "drawing file", "electronic", synonyms=["drawing", "draft", "cad file"]
            ),
            ob.item("pdf", "PDF", "electronic", synonyms=["pdf file"]),
            ob.item("plot", "plot", "product", synonyms=["printout"]),
            ob.item("copy", "copy", "product", synonyms=["photocopy"]),
        ],
        operations=[
            ob.operation("plot", "print", "plot", name="print", input="drawing", product="plot"),
            ob.operation("copy", "copy", "photocopy", input="plan", product="copy"),
            ob.operation(
                "scan", "scan", "digitise", input="plan", product="pdf", done="scanned to PDF"
            ),
            ob.operation("bind", "bind", input="plan"),
            ob.operation("courier", "courier", input="plan", sends_out=True),
            ob.operation("fax", "fax", input="plan", sends_out=True),
        ],
        facilities=[
            ob.facility(
                "copier",
                "copier",
                at="plan_room",
                guards=["otto"],
                operations=["copy", "scan", "bind"],
                synonyms=["photocopier"],
            ),
            ob.facility("plotter", "plotter", at="plan_room", guards=["otto"], operations=["plot"]),
            ob.facility(
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


surveyors = ob.parsed(raw_surveyors)
