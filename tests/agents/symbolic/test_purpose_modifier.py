"""A service's word said as a modifier of a purpose's noun after "for (the)" ("for the
signature comparisons", "for the print trimming") is what the thing is for, never the service
asked (fix60f class 2): "Which item do you mean to be signed?" or "not sure what you want me
to do with the loupe" was the answer. A signing asked ("get my contract signed", "for his
signature") is read as before."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.agents.symbolic.reading.purpose_modifier import without_purpose_modifier
from assistantx.core.office import load_office
from helpers import office_builder as ob
from helpers.reading import frame_reader

_LAB = ob.parsed(
    lambda: ob.office_file(
        "Lab",
        [
            ob.person("ann", "Ann Lee", "loupe", aliases=["Ann"]),
            ob.person("zoe", "Zoe Park", aliases=["Zoe"]),
            ob.person("bob", "Bob Ray", aliases=["Bob"]),
        ],
        rooms=[ob.room("lab", "Lab", 30.0, 6.0)],
        item_types=[ob.item("loupe", "loupe"), ob.item("document", "document", signable=True)],
        operations=[ob.operation("scan", "scan", input="document")],
        facilities=[
            ob.facility("scanner", "scanner", at="lab", guards=["bob"], operations=["scan"])
        ],
        home="lab",
        everyone_owns=["document"],
    )
)
_ann = frame_reader(_LAB, "ann")
_lee = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("read", "text", "item", "to"),
    [
        (
            _ann,
            "Zoe needs my loupe for the signature comparisons, could you take it to her",
            "loupe",
            "zoe",
        ),
        (
            _lee,
            "Wang needs my stapler for the signature pages, can you take it to him",
            "stapler",
            "wang",
        ),
        (_lee, "take my stapler to Wang for the signature check", "stapler", "wang"),
        (_lee, "bring me scissors for the print trimming", "scissors", "lee"),
        (_lee, "Zhang needs my book for the coffee chat, take it over", "book", "zhang"),
    ],
)
def test_a_purpose_is_no_service(read: Any, text: str, item: str, to: str) -> None:
    frame = read(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, to)], frame


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        # must not change: a signing asked, a printout brought
        ("I need Zhang's signature on my form", "sign"),
        ("take my contract to Wang for signature", "sign"),
        ("take my contract to Wang for his signature", "sign"),
        ("bring me the printout for the meeting", "print"),
    ],
)
def test_a_service_asked_stays(text: str, kind: str) -> None:
    frame = _lee(text)
    assert frame.question is None and frame.decline is None, frame
    assert [t.kind for t in frame.tasks] == [kind], frame


def test_a_signing_without_a_signer_is_still_asked() -> None:
    assert _lee("get my contract signed").question == (
        "Who should sign your document? Please tell me their name."
    )


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("for the signature pages", "for the pages"),
        ("for signature", "for signature"),  # the service named
        ("for signature today", "for signature today"),  # no noun after it
        ("for signing forms", "for signing forms"),  # the work itself
        ("to the print room for the print room", "to the print room for the print room"),
    ],
)
def test_the_rewrite(text: str, read: str) -> None:
    words = {"signature", "sign", "print"}
    assert without_purpose_modifier(text, words, {"print room"}) == read
