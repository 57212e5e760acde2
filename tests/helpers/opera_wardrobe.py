"""An opera house's wardrobe office for the reader's tests of blind round 16's classes (written
without the round's names): spirit levels and seam rippers owned by people, a scene dock whose
only service (rigging) the assistant cannot run, PP3 batteries counted at a goods door whose
keepers also send gowns out to be dry cleaned (asking the cleaner's name), and a shake bar
whose service is asked for with the verb "shake" and whose product is also called "a shake"."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("kasia", "Kasia Nowak", "spirit_level", "gown"),
    ob.person("bram", "Bram Oosterhuis", "seam_ripper", "gown"),
    ob.person("ilse", "Ilse Brandt", "spirit_level", "seam_ripper", "gown"),
    ob.person("tomas", "Tomás Reyes", "gown"),
    ob.person("gwen", "Gwen Price", "seam_ripper", "gown"),
)


def raw_opera_wardrobe() -> dict[str, Any]:
    return ob.office_file(
        "opera_wardrobe",
        _PEOPLE,
        desks=ob.desk_row(len(_PEOPLE), x0=4.0, y=5.0),
        rooms=[
            ob.room("scene_dock", "Scene dock", 30.0, 6.0, kind="room"),
            ob.room("goods_door", "Goods door", 20.0, 18.0),
            ob.room("canteen", "Canteen", 8.0, 18.0),
        ],
        item_types=[
            ob.item("spirit_level", "spirit level", synonyms=["level"]),
            ob.item("seam_ripper", "seam ripper", synonyms=["unpicker"]),
            ob.item("gown", "gown", "personal", synonyms=["frock"]),
            ob.item(
                "pp3_batteries", "PP3 batteries", consumable=True, synonyms=["PP3s", "batteries"]
            ),
            ob.item("milkshake", "milkshake", "product", synonyms=["shake"]),
        ],
        operations=[
            ob.operation(
                "dryclean",
                "dry clean",
                "send to the cleaners",
                name="send to the dry cleaner",
                input="gown",
                sends_out=True,
                destination_asked="the name of the cleaner",
            ),
            ob.operation("shake", "shake", "whip up", name="make a milkshake", product="milkshake"),
            ob.operation("rig", name="rig"),
        ],
        facilities=[
            ob.facility(
                "scene_dock", "scene dock", at="scene_dock", guards=["tomas"], operations=["rig"]
            ),
            ob.facility(
                "goods_door",
                "goods door",
                at="goods_door",
                guards=["gwen", "bram"],
                operations=["dryclean"],
                supplies=[{"type": "pp3_batteries", "count": 6}],
            ),
            ob.facility(
                "shake_bar",
                "shake bar",
                at="canteen",
                guards=["kasia"],
                operations=["shake"],
                products=["milkshake"],
            ),
        ],
        home="canteen",
        group=("wardrobe", "Wardrobe"),
    )


opera_wardrobe = ob.parsed(raw_opera_wardrobe)
