"""A small photo studio for the reader's tests of blind round 14's speech-act classes (the
round's own office and sentences were never read): a proof printer that makes contact sheets
from a shoot file, an ordinary printer, a label printer and a film scanner other people keep,
shared tools (a magnifier, a tape measure, a ruler, a wide lens, a camera), a mug each, and
two folders told apart only by colour."""

from __future__ import annotations

from typing import Any

from helpers.office_builder import (
    facility,
    item,
    office_file,
    operation,
    parsed,
    person,
    room,
)

_PEOPLE = (
    person("lotte", "Lotte Brandt", "mug", "tape_measure"),
    person("kwame", "Kwame Osei", "mug", "magnifier", "wide_lens"),
    person("farida", "Farida Haddad", "mug", "camera", "wide_lens"),
    person("teodor", "Teodor Novak", "mug", "tape_measure", "ruler"),
    person("maren", "Maren Holt", "mug", "blue_folder", "red_folder"),
    person("yusuf", "Yusuf Demir", "mug", "camera", "negative"),
    person("frank", "Frank Ito", "mug"),
    person("june", "June Adler", "mug"),
    person("agnes", "Agnes Moreau", "mug", "camera", "wide_lens"),
)


def raw_studio() -> dict[str, Any]:
    return office_file(
        "studio",
        _PEOPLE,
        everyone_owns=["shoot_file"],
        desk_word="bench",
        rooms=[
            room("print_room", "Print room", 4.0, 20.5),
            room("darkroom", "Darkroom", 20.0, 20.5),
        ],
        item_types=[
            item("magnifier", "magnifier", synonyms=["loupe"]),
            item("tape_measure", "tape measure"),
            item("ruler", "ruler"),
            item("wide_lens", "wide lens", synonyms=["wide angle lens"]),
            item("camera", "camera"),
            item("mug", "mug", "personal"),
            item("blue_folder", "blue folder", "personal"),
            item("red_folder", "red folder", "personal"),
            item("negative", "negative strip", "personal"),
            item("shoot_file", "shoot file", "electronic", synonyms=["shoot", "photo file"]),
            item("printout", "printout", "product"),
            item("contact_sheet", "contact sheet", "product", synonyms=["proof sheet", "contacts"]),
            item("sticker", "sticker label", "product"),
        ],
        operations=[
            operation("print", "print", input="shoot_file", product="printout"),
            operation("proof", "proof", input="shoot_file", product="contact_sheet"),
            operation("label", "label", product="sticker"),
            operation("scan", "scan", input="negative"),
            operation("develop", "develop", "run", input="negative"),
        ],
        facilities=[
            facility(
                "printer",
                "printer",
                at="print_room",
                guards=["teodor"],
                operations=["print", "proof"],
                products=["printout", "contact_sheet"],
            ),
            facility(
                "label_printer",
                "label printer",
                at="print_room",
                guards=["teodor"],
                operations=["label"],
                products=["sticker"],
            ),
            facility(
                "scanner",
                "film scanner",
                at="darkroom",
                guards=["yusuf"],
                operations=["scan", "develop"],
                synonyms=["scanner"],
            ),
        ],
        home="print_room",
    )


studio = parsed(raw_studio)
