"""A sound-editing suite for the reader's tests of blind round 59-60's service classes (the
round's own offices and sentences were never read): a tape deck whose operations are named by
their participles, irregular ("rewound") or of a prefixed verb ("restrung"), or by the
office's own ``done:`` word ("overhauled"); a charging rack named by its agent noun ("the
charger"); a disc burner whose product has a clipped name ("ref CD") and whose input shares
a word of its synonym ("master") with another item type; a printer that prints files ("my rota"), a
kettle, and a store of hard hats."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("nadia", "Nadia Holm", "tape", "radio", "reel", "guitar", "microphone"),
    ob.person("oskar", "Oskar Bell", "tape", "radio", "reel"),
    ob.person("pim", "Pim Sauer", "tape", "guitar", "microphone", aliases=["Pim"]),
    ob.person("sam", "Sam Oduya", "radio"),
    ob.person("rhea", "Rhea Quist", "clipboard"),
)


def raw_edit_suite() -> dict[str, Any]:
    return ob.office_file(
        "edit suite",
        _PEOPLE,
        rooms=[
            ob.room("machine_room", "Machine room", 4.0, 20.0),
            ob.room("kitchen", "Kitchen", 20.0, 20.0),
            ob.room("stores", "Stores", 12.0, 20.0),
        ],
        item_types=[
            ob.item("tape", "tape", synonyms=["spool", "cassette"]),
            ob.item("radio", "radio", synonyms=["handset"]),
            ob.item("reel", "open reel", synonyms=["master tape", "tape reel"]),
            ob.item("file", "file", "electronic", synonyms=["master file", "mix", "rota"]),
            ob.item("clipboard", "clipboard"),
            ob.item("guitar", "guitar"),
            ob.item("microphone", "microphone", synonyms=["mic"]),
            ob.item("reference_cd", "reference CD", "product"),
            ob.item("printout", "printout", "product"),
            ob.item("tea", "tea", "product"),
            ob.item("hard_hat", "hard hat", consumable=True),
        ],
        operations=[
            ob.operation("rewind", "rewind", "re-wind", input="tape", done="rewound"),
            ob.operation("restring", "restring", input="guitar"),
            ob.operation("service", "service", input="microphone", done="overhauled"),
            ob.operation("charge", "charge", "recharge", input="radio"),
            ob.operation("burn", "burn", input="file", product="reference_cd"),
            ob.operation("print", "print", input="file", product="printout"),
            ob.operation("boil", "boil", "brew", name="make tea", product="tea"),
        ],
        facilities=[
            ob.facility(
                "tape_deck",
                "tape deck",
                at="machine_room",
                guards=["rhea"],
                operations=["rewind", "restring", "service"],
                synonyms=["deck"],
            ),
            ob.facility(
                "charging_rack",
                "charging rack",
                at="machine_room",
                guards=["rhea"],
                operations=["charge"],
                synonyms=["radio charger", "charger rack"],
            ),
            ob.facility(
                "disc_burner",
                "disc burner",
                at="machine_room",
                guards=["rhea"],
                operations=["burn"],
                products=["reference_cd"],
            ),
            ob.facility(
                "printer",
                "printer",
                at="machine_room",
                guards=["rhea"],
                operations=["print"],
                products=["printout"],
            ),
            ob.facility(
                "kettle",
                "kettle",
                at="kitchen",
                guards=["sam"],
                operations=["boil"],
                products=["tea"],
            ),
            ob.facility("stores", "stores", at="stores", guards=["rhea"], supplies=["hard_hat"]),
        ],
        everyone_owns=["file"],
        home="stores",
    )


edit_suite = ob.parsed(raw_edit_suite)
