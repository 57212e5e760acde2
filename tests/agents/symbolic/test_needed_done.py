"""A paper the office has no word for, said needed with its work done ("need my certificate
photocopied, the auditors want one") is the request to have that work done, as "get my
certificate photocopied" is: restated about the requester's own paper before anything moves
(``reading.needed_done``); it had been "What should I do?". A thing the office knows, and a
colleague's need, read as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_lee = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "question"),
    [
        ("need my certificate photocopied", "Shall I copy your document for you?"),
        (
            "need my certificate copied, the auditors want one",
            "Shall I copy your document for you?",
        ),
        ("i really need my certificate photocopied pls", "Shall I copy your document for you?"),
    ],
)
def test_an_unknown_paper_needed_with_work_done_is_that_work_restated(
    text: str, question: str
) -> None:
    frame = _lee(text)
    assert frame.tasks == [] and frame.question == question, frame


@pytest.mark.parametrize(
    ("text", "kind", "actor"),
    [
        ("I need this certificate signed by Wang", "sign", "wang"),
        ("need my contract photocopied", "copy", None),  # must not change: a known thing
    ],
)
def test_the_work_is_read(text: str, kind: str, actor: str | None) -> None:
    frame = _lee(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.actor) for t in frame.tasks] == [
        (kind, "document", "lee", actor)
    ]


def test_a_colleagues_need_is_not_the_speakers_request() -> None:
    # must not change: "Wang needs ..." is Wang's need, never said again as "get"
    frame = _lee("Wang needs the certificate signed")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "get" not in " ".join(e.words for e in frame.evidence).split()[:1], frame
