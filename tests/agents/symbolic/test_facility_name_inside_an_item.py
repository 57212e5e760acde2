"""A facility's name inside an item's noun phrase says which one is meant, no service: "send
my shredder log spreadsheet to Hana" forwards the file (blind rounds 34-36's class: it was
declined as a service the facility cannot do on a file). Where the facility works on or makes
that item, and where its verb is asked for, the reading is as before."""

from __future__ import annotations

import pytest

from helpers.notary_office import notary_office
from helpers.reading import frame_reader

_frame = frame_reader(notary_office, "ruth")


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("Send my shredder log spreadsheet to Hana", "hana"),
        ("send the shredder rota spreadsheet over to Kwesi", "kwesi"),
        ("email Tomasz my shredder spreadsheet", "tomasz"),
        ("forward my photocopier usage log pdf to Felix", "felix"),
    ],
)
def test_the_file_is_sent(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("send_file", "file", "ruth", recipient)
    ], frame


@pytest.mark.parametrize(
    ("text", "kind", "operation"),
    [
        ("shred my letter", "heat", "shred"),
        ("put my old policy through the shredder", "heat", "shred"),
        ("make me a copy of my letter at the photocopier", "copy", None),
    ],
)
def test_the_facilitys_own_work_is_read_as_before(
    text: str, kind: str, operation: str | None
) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.operation) for t in frame.tasks] == [(kind, operation)], frame


def test_a_product_named_with_its_maker_is_read_as_before() -> None:
    frame = _frame("bring me a coffee machine latte")
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", "coffee")], frame
