"""A restaurant kitchen with an airside pass office, for the reader's tests of blind rounds
20 to 22's classes: people with names nobody else uses, bottles of wine the owners keep in a
wine fridge, an electronic file type, a label printer whose product is labels, two operations
that both take the cooks' prep (vacuum sealing and blast chilling), a digester that consumes
trimmings, a disc burner that makes a disc from a file, a pass office whose supply is a
temporary pass, and a photocopier that copies a paper document."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_CELLAR = {"at": "cellar", "facility": "wine_fridge"}

_PEOPLE = (
    ob.person("odile", "Odile Ferrand", {"type": "wine", **_CELLAR}, "prep", "trimmings"),
    ob.person("bastian", "Bastian Krol", {"type": "wine", **_CELLAR}, "prep"),
    ob.person("maren", "Maren Ilves", "prep", "trimmings"),
    ob.person("tobin", "Tobin Achebe", aliases=["Tobes"]),
    ob.person("ines", "Ines Vaclav"),
)


def raw_airside_kitchen() -> dict[str, Any]:
    return ob.office_file(
        "airside kitchen",
        _PEOPLE,
        everyone_owns=["doc_file", "contract"],
        rooms=[
            ob.room("cellar", "Cellar", 4.0, 18.0),
            ob.room("office", "Back office", 12.0, 18.0),
            ob.room("cold_room", "Cold room", 20.0, 18.0),
            ob.room("yard", "Yard", 28.0, 18.0),
            ob.room("security", "Security", 36.0, 18.0),
        ],
        item_types=[
            ob.item("wine", "wine", synonyms=["bottle of wine"]),
            ob.item("doc_file", "file", "electronic", synonyms=["e-file", "recipe file", "recipe"]),
            ob.item("contract", "contract", "personal", signable=True, synonyms=["paperwork"]),
            ob.item("prep", "prep", "personal", synonyms=["mise en place"]),
            ob.item("trimmings", "trimmings", "personal", synonyms=["offcuts"]),
            ob.item("printout", "printout", "product"),
            ob.item("labels", "labels", "product", synonyms=["date labels", "stickers"]),
            ob.item("disc", "disc", "product", synonyms=["cd"]),
            ob.item("photocopy", "photocopy", "product", synonyms=["copy", "copies"]),
            ob.item("airside_pass", "temporary pass", consumable=True, synonyms=["visitor pass"]),
        ],
        operations=[
            ob.operation("print", "print", input="doc_file", product="printout"),
            ob.operation("label", "label", name="print labels", input="doc_file", product="labels"),
            ob.operation("burn", "burn", name="burn a disc", input="doc_file", product="disc"),
            ob.operation("photocopy", "photocopy", "copy", input="contract", product="photocopy"),
            ob.operation(
                "vac_seal",
                "vacuum seal",
                "vac pack",
                name="vacuum seal",
                input="prep",
                done="sealed",
            ),
            ob.operation("chill", "blast chill", name="blast chill", input="prep", done="chilled"),
            ob.operation("digest", "digest", name="digest", input="trimmings", consumes=True),
        ],
        facilities=[
            ob.facility("wine_fridge", "wine fridge", at="cellar", guards=["bastian"]),
            ob.facility(
                "office_printer",
                "printer",
                at="office",
                guards=["ines"],
                operations=["print", "photocopy"],
                products=["printout", "photocopy"],
            ),
            ob.facility(
                "label_printer",
                "label printer",
                at="office",
                guards=["ines"],
                operations=["label"],
                products=["labels"],
            ),
            ob.facility(
                "burner",
                "disc burner",
                at="office",
                guards=["tobin"],
                operations=["burn"],
                products=["disc"],
            ),
            ob.facility(
                "vac_packer",
                "vacuum packer",
                at="cold_room",
                guards=["maren"],
                operations=["vac_seal"],
            ),
            ob.facility(
                "blast_chiller",
                "blast chiller",
                at="cold_room",
                guards=["maren"],
                operations=["chill"],
            ),
            ob.facility("digester", "digester", at="yard", guards=["tobin"], operations=["digest"]),
            ob.facility(
                "pass_office",
                "pass office",
                at="security",
                guards=["tobin"],
                supplies=[{"type": "airside_pass", "count": 5}],
            ),
        ],
        home="office",
        group=("brigade", "Brigade"),
    )


airside_kitchen = ob.parsed(raw_airside_kitchen)
