"""A theatre sound desk for the reader's tests of the requester's own file said in an
unlisted everyday noun ("print my cue sheets", "send Cliff my profiler capture"): the office
lists its electronic file only as "file" and its personal paper only as "permit", and prints
files on a printer. Two colleagues whose first names are also English nouns (Hunter, Robin)
own a pad each ("can i borrow hunters pad")."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ingrid", "Ingrid Sole", "headset"),
    ob.person("cliff", "Cliff Warden", "headset", aliases=["Cliff"]),
    ob.person("pia", "Pia Moss", "headset"),
    ob.person("hunter", "Hunter Gray", "pad", aliases=["Hunter"]),
    ob.person("robin", "Robin Carr", "pad", aliases=["Robin"]),
)


def raw_sound_desk() -> dict[str, Any]:
    return ob.office_file(
        "sound desk",
        _PEOPLE,
        rooms=[ob.room("booth", "Print booth", 4.0, 20.0)],
        item_types=[
            ob.item("file", "file", "electronic"),
            ob.item("permit", "permit", "personal", signable=True),
            ob.item("headset", "headset"),
            ob.item("pad", "pad"),
            ob.item("printout", "printout", "product"),
        ],
        operations=[ob.operation("print", "print", "reprint", input="file", product="printout")],
        facilities=[
            ob.facility("printer", "printer", at="booth", guards=["pia"], operations=["print"])
        ],
        everyone_owns=["file", "permit"],
        home="booth",
    )


sound_desk = ob.parsed(raw_sound_desk)
