"""A small office with a post desk and a coffee machine, for the reader's tests of a send-out
whose destination is a proper name holding one of the office's product words ("post my
parcel to Blue Kettle Coffee on Mill Street"): the post desk posts a parcel or a letter out
("post", "ship", "courier", "mail", "dispatch"), the coffee machine makes coffee."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("lee", "Lee Hart", "parcel", "stapler"),
    ob.person("rosa", "Rosa Quint", "parcel"),
    ob.person("tom", "Tom Brady"),
)


def raw_post_and_coffee() -> dict[str, Any]:
    return ob.office_file(
        "post and coffee",
        _PEOPLE,
        rooms=[
            ob.room("post_room", "Post room", 4.0, 20.0),
            ob.room("kitchen", "Kitchen", 12.0, 20.0),
        ],
        item_types=[
            ob.item("parcel", "parcel", "personal", synonyms=["package", "letter"]),
            ob.item("stapler", "stapler"),
            ob.item("coffee", "coffee", "product", synonyms=["latte", "espresso"]),
        ],
        operations=[
            ob.operation(
                "post",
                "post",
                "ship",
                "courier",
                "mail",
                "dispatch",
                "send out",
                name="post",
                input="parcel",
                sends_out=True,
            ),
            ob.operation("brew", "make", "brew", name="make coffee", product="coffee"),
        ],
        facilities=[
            ob.facility(
                "post_desk", "post desk", at="post_room", guards=["tom"], operations=["post"]
            ),
            ob.facility(
                "coffee_machine",
                "coffee machine",
                at="kitchen",
                guards=[],
                operations=["brew"],
                products=["coffee"],
            ),
        ],
        home="post_room",
    )


post_and_coffee = ob.parsed(raw_post_and_coffee)
