"""A field studies centre staff base for the tests of blind round 17's classes (the round's own
office and sentences were never read). Two people share the first name Robin and are told apart
by an alias with an initial ("Robin B", "Robin O"); the deputy head has role aliases ("the
Deputy Head", "the deputy"); a reprographics room goes by "repro", and a colleague sits there;
a kit store keeps hi-vis vests for anyone (a supply); papers to sign (consent forms), a personal
banner, an electronic file that the print room renders as a printout, and ordinary belongings
(board markers, scissors, hole punches, a torch)."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("bea", "Bea Lindgren", "hole_punch", "consent_form", "file"),
    ob.person("robin_b", "Robin Baptiste", "scissors", "file", aliases=["Robin B"]),
    ob.person("robin_o", "Robin Okonkwo", "board_marker", "scissors", "file", aliases=["Robin O"]),
    ob.person("tomas", "Tomás Ibarra", "board_marker", "hole_punch", "file", "torch"),
    ob.person("nkechi", "Nkechi Adeyemi", "consent_form", "file"),
    ob.person("linh", "Linh Vo", "file"),
    ob.person(
        "marguerite",
        "Marguerite Sallow",
        "consent_form",
        "file",
        aliases=["the Deputy Head", "the deputy"],
    ),
    ob.person("hattie", "Hattie Quill", "hole_punch", at="repro_room"),
    ob.person("fenella", "Fenella Hart", "scissors", "board_marker"),
    ob.person("otto", "Otto Brisk", "banner"),
)


def raw_field_centre() -> dict[str, Any]:
    return ob.office_file(
        "field_centre",
        _PEOPLE,
        desk_for_everyone=False,
        rooms=[
            ob.room("repro_room", "Repro room", 4.0, 20.5),
            ob.room("kit_room", "Kit room", 20.0, 20.5),
        ],
        item_types=[
            ob.item("board_marker", "board marker", synonyms=["board pen"]),
            ob.item("scissors", "scissors", synonyms=["pair of scissors"]),
            ob.item("hole_punch", "hole punch"),
            ob.item("torch", "torch", synonyms=["flashlight"]),
            ob.item("hi_vis", "hi-vis vest", synonyms=["hi-vis", "high-vis vest"]),
            ob.item(
                "consent_form",
                "consent form",
                "personal",
                signable=True,
                synonyms=["permission slip"],
            ),
            ob.item("banner", "banner", "personal"),
            ob.item(
                "file",
                "electronic file",
                "electronic",
                synonyms=["file", "pdf", "lesson plan", "worksheet"],
            ),
            ob.item("printout", "printout", "product", synonyms=["hard copy"]),
        ],
        operations=[ob.operation("print", "print", input="file", product="printout")],
        facilities=[
            ob.facility(
                "reprographics",
                "reprographics room",
                synonyms=["repro"],
                at="repro_room",
                guards=["hattie"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "kit_store", "kit store", at="kit_room", guards=["linh"], supplies=["hi_vis"]
            ),
        ],
        home="kit_room",
    )


field_centre = ob.parsed(raw_field_centre)
