"""An airline catering unit for the reader's tests of blind rounds 20-22's name classes (the
rounds' own offices and sentences were never read): a bag desk prints rush tags, a galley
kitchen plates tasting menus, a print room prints anyone's file. Two colleagues share a first
name (Luca Ferrand, Luca Bianchi); one's first name is another's surname (Cliff Adebayo,
Marcus Cliff); one is called by a title ("Chef Ramón"), one by her initials ("DK"), one has a
name that is an ordinary word (Holly). Everyone keeps a costings spreadsheet and a running
order; the release form is signable."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("nia", "Nia Osei", "stapler", "release_form"),
    ob.person("holly", "Holly Grant", "stapler"),
    ob.person("ramon", "Ramón Ortiz", "knife_roll", aliases=["Chef Ramón"]),
    ob.person("luca_f", "Luca Ferrand", "stapler"),
    ob.person("luca_b", "Luca Bianchi", "knife_roll"),
    ob.person("cliff", "Cliff Adebayo", "stapler"),
    ob.person("marcus", "Marcus Cliff", "stapler"),
    ob.person("deepa", "Deepa Kaur", "stapler", aliases=["DK"]),
)


def raw_galley() -> dict[str, Any]:
    return ob.office_file(
        "galley",
        _PEOPLE,
        everyone_owns=["costings", "running_order"],
        rooms=[
            ob.room("bag_room", "Bag room", 4.0, 20.5),
            ob.room("kitchen", "Galley kitchen", 14.0, 20.5),
            ob.room("print_room", "Print room", 24.0, 20.5),
        ],
        item_types=[
            ob.item("stapler", "stapler"),
            ob.item("knife_roll", "knife roll"),
            ob.item(
                "release_form", "release form", "personal", signable=True, synonyms=["release"]
            ),
            ob.item("costings", "costings", "electronic", synonyms=["spreadsheet"]),
            ob.item("running_order", "running order", "personal"),
            ob.item("rush_tag", "rush tag", "product", synonyms=["rush label"]),
            ob.item("printout", "printout", "product"),
        ],
        operations=[
            ob.operation("tag", name="make a rush tag", product="rush_tag"),
            ob.operation("print", "print", input="costings", product="printout"),
        ],
        facilities=[
            ob.facility(
                "bag_desk",
                "bag desk",
                at="bag_room",
                guards=["holly"],
                operations=["tag"],
                products=["rush_tag"],
            ),
            ob.facility(
                "printer",
                "printer",
                at="print_room",
                guards=["deepa"],
                operations=["print"],
                products=["printout"],
            ),
        ],
        home="bag_room",
    )


galley = ob.parsed(raw_galley)
