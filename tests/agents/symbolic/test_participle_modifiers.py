"""A person-service's participle describing the item ("courier the signed publishing
contract to ...", "photocopy my signed legal contract") is no request for that service, also
where plain words that describe the item stand between it and the item; the sentence's own
verb is the request. "get my contract signed by Hana" is still a signing."""

from __future__ import annotations

import pytest

from helpers.notary_office import notary_office
from helpers.reading import frame_reader

_frame = frame_reader(notary_office, "ruth")


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("Please courier the signed publishing contract to Acme Ltd, 3 High Street, Leeds", "heat"),
        ("courier my signed rental contract to Acme Ltd, 3 High Street, Leeds", "heat"),
        ("photocopy the signed publishing contract", "copy"),
        ("could you photocopy my signed legal contract", "copy"),
        ("photocopy the signed contract", "copy"),
    ],
)
def test_a_participle_before_the_item_describes_it(text: str, kind: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.owner, t.item) for t in frame.tasks] == [(kind, "ruth", "document")], frame


@pytest.mark.parametrize(
    "text",
    [
        "get my contract signed by Hana",
        "get my legal contract signed by Hana",
        "could you have my rental contract signed by Hana",
    ],
)
def test_a_signing_asked_is_still_a_signing(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.actor) for t in frame.tasks] == [("sign", "hana")], frame
