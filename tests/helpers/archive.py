"""A small county records archive for the reader's tests of blind round 13's classes (the
round's own office and sentences were never read). An ordinary printer prints a document file;
a second operation on the same file has a display name that reads like a verb phrase ("print
box labels") though its only verb is "tag", at a tag printer other people guard; a badge
press makes visitor passes from nothing; a reel reader digitises a glass slide into an
electronic scan; a mounting press mounts a chart (the chart comes back changed); ordinary
belongings (a step ladder, a tape gun)."""

from __future__ import annotations

from typing import Any

from helpers.office_builder import facility, item, office_file, operation, parsed, person, room

_PEOPLE = (
    person("ines", "Ines Varga", "tape_gun", "chart", "slide"),
    person("tobias", "Tobias Reed", "step_ladder", "chart"),
    person("priya", "Priya Nair", "tape_gun", "slide"),
    person("jonas", "Jonas Kell", "chart"),
    person("mira", "Mira Sato", "slide"),
    person("oskar", "Oskar Lind", "chart"),
)


def raw_archive() -> dict[str, Any]:
    return office_file(
        "archive",
        _PEOPLE,
        everyone_owns=["doc_file"],
        rooms=[
            room("copy_room", "Copy room", 4.0, 20.5),
            room("stack_room", "Stack room", 20.0, 20.5),
        ],
        item_types=[
            item("step_ladder", "step ladder", synonyms=["kick step"]),
            item("tape_gun", "tape gun"),
            item("chart", "chart", "personal", synonyms=["map sheet"]),
            item("slide", "glass slide", "personal", synonyms=["slide"]),
            item(
                "doc_file", "document file", "electronic", synonyms=["document", "box list", "pdf"]
            ),
            item("printout", "printout", "product"),
            item("box_label", "box labels", "product", synonyms=["box label"]),
            item("pass_card", "visitor pass", "product", synonyms=["pass card"]),
            item("slide_scan", "slide scan", "electronic", synonyms=["slide image"]),
        ],
        operations=[
            operation("print", "print", input="doc_file", product="printout"),
            operation("tag", "tag", name="print box labels", input="doc_file", product="box_label"),
            operation("badge", "issue", name="issue passes", product="pass_card"),
            operation("digitise", "scan", "digitise", input="slide", product="slide_scan"),
            operation("mount", "mount", "backboard", input="chart"),
        ],
        facilities=[
            facility(
                "printer",
                "printer",
                at="copy_room",
                guards=["jonas"],
                operations=["print"],
                products=["printout"],
            ),
            facility(
                "tag_printer",
                "tag printer",
                at="stack_room",
                guards=["mira", "oskar"],
                operations=["tag"],
                products=["box_label"],
            ),
            facility(
                "badge_press",
                "badge press",
                at="copy_room",
                guards=["jonas"],
                operations=["badge"],
                products=["pass_card"],
            ),
            facility(
                "reel_reader",
                "reel reader",
                at="stack_room",
                guards=["mira"],
                operations=["digitise"],
            ),
            facility(
                "mount_press",
                "mounting press",
                at="stack_room",
                guards=["oskar", "tobias"],
                operations=["mount"],
            ),
        ],
        home="copy_room",
    )


archive = parsed(raw_archive)
