"""A small letterpress and signage studio for the reader's tests of blind round 10's classes
(the round's own office and sentences were never read). Two operations of one shape work on
a file: the printer prints it, the engraver engraves it (an "etched plate", also called "a
brass print"); a paper store keeps card stock for anyone (three sheets left) and cotton
string; a post desk where Ravi works sends papers out; ordinary belongings (a bone folder, also
called a creaser), and proofs that a colleague signs."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("edda", "Edda Lund", "bone_folder", "proof"),
    ob.person("kofi", "Kofi Mensah", "bone_folder", "proof"),
    ob.person("lena", "Lena Ortiz", "loupe", "proof"),
    ob.person("ravi", "Ravi Batra", "proof", at="front_desk"),
    ob.person("noor", "Noor Haddad", "loupe", "proof"),
    ob.person("ugo", "Ugo Ferri", "proof"),
)


def raw_printshop() -> dict[str, Any]:
    return ob.office_file(
        "printshop",
        _PEOPLE,
        everyone_owns=["artwork"],
        rooms=[
            ob.room("press_room", "Press room", 4.0, 20.5),
            ob.room("front_desk", "Front desk", 11.0, 20.5),
        ],
        item_types=[
            ob.item("bone_folder", "bone folder", synonyms=["creaser"]),
            ob.item("loupe", "loupe", synonyms=["magnifier"]),
            ob.item(
                "proof", "proof", "personal", signable=True, synonyms=["proof sheet", "layout"]
            ),
            ob.item("artwork", "artwork file", "electronic", synonyms=["svg"]),
            ob.item("printout", "printout", "product", synonyms=["print"]),
            ob.item("plate", "etched plate", "product", synonyms=["brass print", "engraving"]),
            ob.item("card_stock", "card stock", consumable=True, synonyms=["card"]),
            ob.item("string", "cotton string", consumable=True),
        ],
        operations=[
            ob.operation("print", "print", input="artwork", product="printout"),
            ob.operation("engrave", "engrave", "etch", input="artwork", product="plate"),
            ob.operation("post", "post", "mail", input="proof", sends_out=True),
        ],
        facilities=[
            ob.facility(
                "printer",
                "printer",
                at="press_room",
                guards=["ugo"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "engraver",
                "engraver",
                at="press_room",
                guards=["ugo"],
                operations=["engrave"],
                products=["plate"],
                synonyms=["etching machine"],
            ),
            ob.facility(
                "paper_store",
                "paper store",
                at="press_room",
                guards=["ugo"],
                supplies=[{"type": "card_stock", "count": 3}, "string"],
            ),
            ob.facility(
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


printshop = ob.parsed(raw_printshop)
