"""A small photo studio for the reader's tests of blind round 14's speech-act classes (the
round's own office and sentences were never read): a proof printer that makes contact sheets
from a shoot file, an ordinary printer, a label printer and a film scanner other people keep,
shared tools (a magnifier, a tape measure, a ruler, a wide lens, a camera), a mug each, and
two folders told apart only by colour."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("lotte", "Lotte Brandt", "mug", "tape_measure"),
    ob.person("kwame", "Kwame Osei", "mug", "magnifier", "wide_lens"),
    ob.person("farida", "Farida Haddad", "mug", "camera", "wide_lens"),
    ob.person("teodor", "Teodor Novak", "mug", "tape_measure", "ruler"),
    ob.person("maren", "Maren Holt", "mug", "blue_folder", "red_folder"),
    ob.person("yusuf", "Yusuf Demir", "mug", "camera", "negative"),
    ob.person("frank", "Frank Ito", "mug"),
    ob.person("june", "June Adler", "mug"),
    ob.person("agnes", "Agnes Moreau", "mug", "camera", "wide_lens"),
)


def raw_studio() -> dict[str, Any]:
    return ob.office_file(
        "studio",
        _PEOPLE,
        everyone_owns=["shoot_file"],
        desk_word="bench",
        rooms=[
            ob.room("print_room", "Print room", 4.0, 20.5),
            ob.room("darkroom", "Darkroom", 20.0, 20.5),
        ],
        item_types=[
            ob.item("magnifier", "magnifier", synonyms=["loupe"]),
            ob.item("tape_measure", "tape measure"),
            ob.item("ruler", "ruler"),
            ob.item("wide_lens", "wide lens", synonyms=["wide angle lens"]),
            ob.item("camera", "camera"),
            ob.item("mug", "mug", "personal"),
            ob.item("blue_folder", "blue folder", "personal"),
            ob.item("red_folder", "red folder", "personal"),
            ob.item("negative", "negative strip", "personal"),
            ob.item("shoot_file", "shoot file", "electronic", synonyms=["shoot", "photo file"]),
            ob.item("printout", "printout", "product"),
            ob.item(
                "contact_sheet", "contact sheet", "product", synonyms=["proof sheet", "contacts"]
            ),
            ob.item("sticker", "sticker label", "product"),
        ],
        operations=[
            ob.operation("print", "print", input="shoot_file", product="printout"),
            ob.operation("proof", "proof", input="shoot_file", product="contact_sheet"),
            ob.operation("label", "label", product="sticker"),
            ob.operation("scan", "scan", input="negative"),
            ob.operation("develop", "develop", "run", input="negative"),
        ],
        facilities=[
            ob.facility(
                "printer",
                "printer",
                at="print_room",
                guards=["teodor"],
                operations=["print", "proof"],
                products=["printout", "contact_sheet"],
            ),
            ob.facility(
                "label_printer",
                "label printer",
                at="print_room",
                guards=["teodor"],
                operations=["label"],
                products=["sticker"],
            ),
            ob.facility(
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


studio = ob.parsed(raw_studio)
