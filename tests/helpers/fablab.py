"""Two small workshops for the reader's tests of an office's own operations named by
several words (no blind round's office or sentences were read).

``fablab``: a plotter plots a file (its verbs "plot" and "print"); a 3D printer runs "3D
print" (verbs "3d print", "3d-print"); a laser cutter runs "laser cut" (verbs "laser",
"lasercut", "laser-cut"); people own a laser measure, a tape measure and a first aid kit
(a "kit"); a stores cupboard kept by one person "makes up a kit bag" (operation id
``bundle``, an ordinary verb that does not describe it; a product from nothing). There is no
scanner.

``costume_works``: a theatre workshop whose declared phrases overlap the same way: a vinyl
cutter ("vinyl cut", verbs "vinyl cut", "vinyl-cut"), a laser engraver ("laser engrave",
verbs "engrave", "laser engrave"), a CNC router ("rout", verbs "rout", "mill", "cnc"), a
heat press ("heat press", verbs "heat press", "heat-press") beside a wardrobe that presses
costumes (verbs "press", "steam"), and a scanner (verbs "scan")."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_FAB_PEOPLE = (
    ob.person("ines", "Ines Varga", "laser_measure", "tape"),
    ob.person("tomas", "Tomas Reyes", "laser_measure", "drawing"),
    ob.person("hana", "Hana Ilves", "tape", "drawing"),
    ob.person("priit", "Priit Kask", "drawing"),
    ob.person("wanda", "Wanda Obi", "tape", "first_aid_kit"),
    ob.person("gus", "Gus Moreau", "drawing"),
)


def raw_fablab() -> dict[str, Any]:
    return ob.office_file(
        "fablab",
        _FAB_PEOPLE,
        everyone_owns=["design_file"],
        rooms=[
            ob.room("workshop", "Workshop", 4.0, 20.5),
            ob.room("store_room", "Store room", 14.0, 20.5),
        ],
        item_types=[
            ob.item("laser_measure", "laser measure", synonyms=["laser meter"]),
            ob.item("tape", "tape measure"),
            ob.item("drawing", "drawing", "personal", synonyms=["drawings"]),
            ob.item("design_file", "design file", "electronic", synonyms=["stl", "file"]),
            ob.item("plot", "plot", "product", synonyms=["plotted sheet"]),
            ob.item("model_part", "printed part", "product", synonyms=["3d print"]),
            ob.item("cut_parts", "cut parts", "product", synonyms=["bits"]),
            ob.item("kit_bag", "kit bag", "product"),
            ob.item("first_aid_kit", "first aid kit", synonyms=["kit"]),
        ],
        operations=[
            ob.operation("plot", "plot", "print", input="design_file", product="plot"),
            ob.operation(
                "print3d",
                "3d print",
                "3d-print",
                name="3D print",
                input="design_file",
                product="model_part",
            ),
            ob.operation(
                "cut",
                "laser",
                "lasercut",
                "laser-cut",
                name="laser cut",
                input="design_file",
                product="cut_parts",
            ),
            ob.operation("bundle", name="make up a kit bag", product="kit_bag"),
        ],
        facilities=[
            ob.facility(
                "plotter",
                "plotter",
                at="workshop",
                guards=["hana"],
                operations=["plot"],
                products=["plot"],
            ),
            ob.facility(
                "printer3d",
                "3D printer",
                at="workshop",
                guards=["priit"],
                operations=["print3d"],
                products=["model_part"],
            ),
            ob.facility(
                "laser_cutter",
                "laser cutter",
                at="workshop",
                guards=["priit"],
                operations=["cut"],
                products=["cut_parts"],
            ),
            ob.facility(
                "stores",
                "stores cupboard",
                at="store_room",
                guards=["wanda"],
                operations=["bundle"],
                products=["kit_bag"],
            ),
        ],
        home="workshop",
    )


fablab = ob.parsed(raw_fablab)


_COSTUME_PEOPLE = (
    ob.person("ada", "Ada Quist", "costume", "drawing"),
    ob.person("bram", "Bram Dekker", "costume", "drawing"),
    ob.person("cleo", "Cleo Marin", "costume"),
    ob.person("dov", "Dov Adler", "drawing"),
    ob.person("esme", "Esme Lind", "costume"),
    ob.person("fitz", "Fitz Amari", "drawing"),
)


def raw_costume_works() -> dict[str, Any]:
    return ob.office_file(
        "costume_works",
        _COSTUME_PEOPLE,
        everyone_owns=["artwork"],
        rooms=[
            ob.room("shop_floor", "Shop floor", 4.0, 20.5),
            ob.room("wardrobe_room", "Wardrobe room", 16.0, 20.5),
        ],
        item_types=[
            ob.item("costume", "costume", "personal"),
            ob.item("drawing", "drawing", "personal", synonyms=["drawings"]),
            ob.item("artwork", "artwork", "electronic", synonyms=["file"]),
            ob.item("decal", "vinyl decal", "product", synonyms=["decal"]),
            ob.item("plaque", "engraved plaque", "product", synonyms=["plaque"]),
            ob.item("routed_panel", "routed panel", "product", synonyms=["panel"]),
            ob.item("transfer", "pressed transfer", "product", synonyms=["transfer"]),
            ob.item("scan", "scan", "product", synonyms=["pdf"]),
        ],
        operations=[
            ob.operation(
                "vinyl",
                "vinyl cut",
                "vinyl-cut",
                name="vinyl cut",
                input="artwork",
                product="decal",
            ),
            ob.operation(
                "engrave",
                "engrave",
                "laser engrave",
                name="laser engrave",
                input="artwork",
                product="plaque",
            ),
            ob.operation("rout", "rout", "mill", "cnc", input="artwork", product="routed_panel"),
            ob.operation(
                "heatpress",
                "heat press",
                "heat-press",
                name="heat press",
                input="artwork",
                product="transfer",
            ),
            ob.operation("steam", "press", "steam", name="press", input="costume"),
            ob.operation("scan", "scan", input="drawing", product="scan"),
        ],
        facilities=[
            ob.facility(
                "vinyl_cutter",
                "vinyl cutter",
                at="shop_floor",
                guards=["dov"],
                operations=["vinyl"],
                products=["decal"],
            ),
            ob.facility(
                "laser_engraver",
                "laser engraver",
                at="shop_floor",
                guards=["dov"],
                operations=["engrave"],
                products=["plaque"],
            ),
            ob.facility(
                "cnc_router",
                "CNC router",
                at="shop_floor",
                guards=["fitz"],
                operations=["rout"],
                products=["routed_panel"],
            ),
            ob.facility(
                "heat_press",
                "heat press",
                at="shop_floor",
                guards=["fitz"],
                operations=["heatpress"],
                products=["transfer"],
            ),
            ob.facility(
                "wardrobe", "wardrobe", at="wardrobe_room", guards=["esme"], operations=["steam"]
            ),
            ob.facility(
                "scanner",
                "scanner",
                at="shop_floor",
                guards=["dov"],
                operations=["scan"],
                products=["scan"],
            ),
        ],
        home="shop_floor",
    )


costume_works = ob.parsed(raw_costume_works)
