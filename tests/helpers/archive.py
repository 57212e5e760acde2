"""A small county records archive for the reader's tests of blind round 13's classes (the
round's own office and sentences were never read). An ordinary printer prints a document file;
a second operation on the same file has a display name that reads like a verb phrase ("print
box labels") though its only verb is "tag", at a tag printer other people guard; a badge
press makes visitor passes from nothing; a reel reader digitises a glass slide into an
electronic scan; a mounting press mounts a chart (the chart comes back changed); ordinary
belongings (a step ladder, a tape gun)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ines", "Ines Varga", "tape_gun", "chart", "slide"),
    ob.person("tobias", "Tobias Reed", "step_ladder", "chart"),
    ob.person("priya", "Priya Nair", "tape_gun", "slide"),
    ob.person("jonas", "Jonas Kell", "chart"),
    ob.person("mira", "Mira Sato", "slide"),
    ob.person("oskar", "Oskar Lind", "chart"),
)


def raw_archive() -> dict[str, Any]:
    return ob.office_file(
        "archive",
        _PEOPLE,
        everyone_owns=["doc_file"],
        rooms=[
            ob.room("copy_room", "Copy room", 4.0, 20.5),
            ob.room("stack_room", "Stack room", 20.0, 20.5),
        ],
        item_types=[
            ob.item("step_ladder", "step ladder", synonyms=["kick step"]),
            ob.item("tape_gun", "tape gun"),
            ob.item("chart", "chart", "personal", synonyms=["map sheet"]),
            ob.item("slide", "glass slide", "personal", synonyms=["slide"]),
            ob.item(
                "doc_file", "document file", "electronic", synonyms=["document", "box list", "pdf"]
            ),
            ob.item("printout", "printout", "product"),
            ob.item("box_label", "box labels", "product", synonyms=["box label"]),
            ob.item("pass_card", "visitor pass", "product", synonyms=["pass card"]),
            ob.item("slide_scan", "slide scan", "electronic", synonyms=["slide image"]),
        ],
        operations=[
            ob.operation("print", "print", input="doc_file", product="printout"),
            ob.operation(
                "tag", "tag", name="print box labels", input="doc_file", product="box_label"
            ),
            ob.operation("badge", "issue", name="issue passes", product="pass_card"),
            ob.operation("digitise", "scan", "digitise", input="slide", product="slide_scan"),
            ob.operation("mount", "mount", "backboard", input="chart"),
        ],
        facilities=[
            ob.facility(
                "printer",
                "printer",
                at="copy_room",
                guards=["jonas"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "tag_printer",
                "tag printer",
                at="stack_room",
                guards=["mira", "oskar"],
                operations=["tag"],
                products=["box_label"],
            ),
            ob.facility(
                "badge_press",
                "badge press",
                at="copy_room",
                guards=["jonas"],
                operations=["badge"],
                products=["pass_card"],
            ),
            ob.facility(
                "reel_reader",
                "reel reader",
                at="stack_room",
                guards=["mira"],
                operations=["digitise"],
            ),
            ob.facility(
                "mount_press",
                "mounting press",
                at="stack_room",
                guards=["oskar", "tobias"],
                operations=["mount"],
            ),
        ],
        home="copy_room",
    )


archive = ob.parsed(raw_archive)
