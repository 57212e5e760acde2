"""A small office whose two send-out services are named by their facilities: a courier desk
that couriers parcels (a charger going back to its supplier is one) and a post bag that posts
letters, for the reader's tests of a facility said as the means ("send my form via the
courier desk to ...", "could my letter go in the post bag to ...", "can it go out with the
courier today?"); no sentence or name of a measured office is in it."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("lena", "Lena Voss"),
    ob.person("omar", "Omar Haddad"),
    ob.person("rui", "Rui Costa"),
    ob.person("tess", "Tess Ogden"),
)


def raw_dispatch_office() -> dict[str, Any]:
    return ob.office_file(
        "dispatch office",
        _PEOPLE,
        rooms=[
            ob.room("goods_in", "Goods in", 4.0, 20.0),
            ob.room("front_office", "Front office", 12.0, 20.0),
        ],
        item_types=[
            ob.item(
                "letter",
                "letter",
                "personal",
                synonyms=["declaration", "form", "cheque", "postcard"],
            ),
            ob.item("parcel", "parcel", "personal", synonyms=["charger", "sample", "box"]),
        ],
        operations=[
            ob.operation(
                "courier", "courier", name="send by courier", input="parcel", sends_out=True
            ),
            ob.operation("post", "post", "mail", name="post", input="letter", sends_out=True),
        ],
        facilities=[
            ob.facility(
                "courier_desk",
                "courier desk",
                at="goods_in",
                guards=["omar"],
                operations=["courier"],
            ),
            ob.facility(
                "post_bag",
                "post bag",
                at="front_office",
                guards=["rui"],
                operations=["post"],
                synonyms=["mail bag"],
            ),
        ],
        everyone_owns=["letter", "parcel"],
        home="front_office",
    )


dispatch_office = ob.parsed(raw_dispatch_office)
