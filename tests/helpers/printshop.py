"""A small letterpress and signage studio for the reader's tests of blind round 10's classes
(the round's own office and sentences were never read). Two operations of one shape work on
a file: the printer prints it, the engraver engraves it (an "etched plate", also called "a
brass print"); a paper store keeps card stock for anyone (three sheets left) and cotton
string; a post desk where Ravi works sends papers out; ordinary belongings (a bone folder, also
called a creaser), and proofs that a colleague signs."""

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
    person("edda", "Edda Lund", "bone_folder", "proof"),
    person("kofi", "Kofi Mensah", "bone_folder", "proof"),
    person("lena", "Lena Ortiz", "loupe", "proof"),
    person("ravi", "Ravi Batra", "proof", at="front_desk"),
    person("noor", "Noor Haddad", "loupe", "proof"),
    person("ugo", "Ugo Ferri", "proof"),
)


def raw_printshop() -> dict[str, Any]:
    return office_file(
        "printshop",
        _PEOPLE,
        everyone_owns=["artwork"],
        rooms=[
            room("press_room", "Press room", 4.0, 20.5),
            room("front_desk", "Front desk", 11.0, 20.5),
        ],
        item_types=[
            item("bone_folder", "bone folder", synonyms=["creaser"]),
            item("loupe", "loupe", synonyms=["magnifier"]),
            item("proof", "proof", "personal", signable=True, synonyms=["proof sheet", "layout"]),
            item("artwork", "artwork file", "electronic", synonyms=["svg"]),
            item("printout", "printout", "product", synonyms=["print"]),
            item("plate", "etched plate", "product", synonyms=["brass print", "engraving"]),
            item("card_stock", "card stock", consumable=True, synonyms=["card"]),
            item("string", "cotton string", consumable=True),
        ],
        operations=[
            operation("print", "print", input="artwork", product="printout"),
            operation("engrave", "engrave", "etch", input="artwork", product="plate"),
            operation("post", "post", "mail", input="proof", sends_out=True),
        ],
        facilities=[
            facility(
                "printer",
                "printer",
                at="press_room",
                guards=["ugo"],
                operations=["print"],
                products=["printout"],
            ),
            facility(
                "engraver",
                "engraver",
                at="press_room",
                guards=["ugo"],
                operations=["engrave"],
                products=["plate"],
                synonyms=["etching machine"],
            ),
            facility(
                "paper_store",
                "paper store",
                at="press_room",
                guards=["ugo"],
                supplies=[{"type": "card_stock", "count": 3}, "string"],
            ),
            facility(
                "post_desk",
                "post desk",
                at="front_desk",
                guards=["ravi"],
                operations=["post"],
                synonyms=["mailroom"],
            ),
        ],
        home="press_room",
    )


printshop = parsed(raw_printshop)
