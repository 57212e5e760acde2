"""A field survey hut for the reader's tests of blind round 50's signer classes (the round's
own office and sentences were never read): colleagues usually called by title and surname
("Dr Halvorsen", "Ms Adeyemi") who sign the requester's paper, a signable paper type with
other names than the one a request may use, a stores room with a supply for anyone, and van
keys two colleagues keep in a key safe."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_KEYS = ob.kept("van_keys", at="yard", facility="key_safe")
_PEOPLE = (
    ob.person("okafor", "Ada Okafor", "gauge", _KEYS),
    ob.person("halvorsen", "Ingrid Halvorsen", aliases=["Dr Halvorsen", "Dr. Halvorsen"]),
    ob.person("adeyemi", "Ruth Adeyemi", "gauge", _KEYS, aliases=["Ms Adeyemi"]),
    ob.person("miles", "Miles Brook", "gauge", "clipboard"),
    ob.person("pim", "Pim Vos", "clipboard"),
)


def raw_survey_hut() -> dict[str, Any]:
    return ob.office_file(
        "survey hut",
        _PEOPLE,
        rooms=[
            ob.room("stores", "Stores", 4.0, 20.0),
            ob.room("yard", "Yard", 20.0, 20.0),
        ],
        item_types=[
            ob.item("gauge", "pressure gauge", synonyms=["gauge"]),
            ob.item("clipboard", "clipboard"),
            ob.item(
                "paper",
                "paperwork",
                "personal",
                signable=True,
                synonyms=["paper", "document", "report", "contract"],
            ),
            ob.item("vest", "hi-vis vest", consumable=True, synonyms=["vest"]),
            ob.item("van_keys", "van keys", "personal", synonyms=["keys"]),
        ],
        operations=[],
        facilities=[
            ob.facility("stores_shelf", "stores", at="stores", guards=["pim"], supplies=["vest"]),
            ob.facility("key_safe", "key safe", at="yard", guards=["pim"]),
        ],
        everyone_owns=["paper"],
        home="stores",
    )


survey_hut = ob.parsed(raw_survey_hut)
