"""A barristers' chambers for the reader's tests of blind rounds 59-64's class on sending a
thing out by a means said in any word order ("have my brief couriered to Leeds", "send my
signed deed to the Crown Court by courier"; the rounds' own offices and sentences were never
read): a clerks' room whose courier service is asked for by "dispatch" (its name says the
means, "send by courier"), a post desk that posts letters ("post", "mail"), and a fax machine
that faxes a form; papers everyone owns, and a laptop no service sends."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("nadia", "Nadia Hussain", "laptop"),
    ob.person("owen", "Owen Pryce"),
    ob.person("greta", "Greta Lund", "laptop"),
    ob.person("tomas", "Tomas Berg"),
)


def raw_chambers_post() -> dict[str, Any]:
    return ob.office_file(
        "chambers post",
        _PEOPLE,
        rooms=[
            ob.room("clerks_room", "Clerks' room", 4.0, 20.0),
            ob.room("post_room", "Post room", 12.0, 20.0),
            ob.room("library", "Library", 20.0, 20.0, kind="room"),
        ],
        item_types=[
            ob.item(
                "brief",
                "brief",
                "personal",
                signable=True,
                synonyms=["deed", "statement", "bundle", "affidavit"],
            ),
            ob.item("letter", "letter", "personal", synonyms=["envelope"]),
            ob.item("form", "form", "personal"),
            ob.item("laptop", "laptop"),
        ],
        operations=[
            ob.operation(
                "courier",
                "dispatch",
                name="send by courier",
                input="brief",
                sends_out=True,
            ),
            ob.operation("post", "post", "mail", name="post", input="letter", sends_out=True),
            ob.operation("fax", "fax", name="fax", input="form", sends_out=True),
        ],
        facilities=[
            ob.facility(
                "courier_desk",
                "courier desk",
                at="clerks_room",
                guards=["owen"],
                operations=["courier"],
            ),
            ob.facility(
                "post_desk", "post desk", at="post_room", guards=["tomas"], operations=["post"]
            ),
            ob.facility(
                "fax_machine", "fax machine", at="post_room", guards=["tomas"], operations=["fax"]
            ),
        ],
        everyone_owns=["brief", "letter", "form"],
        home="clerks_room",
    )


chambers_post = ob.parsed(raw_chambers_post)
