"""A service's word inside a thing's noun phrase asks for no service (blind round 57's classes;
their offices and sentences were never read): right after an article, going on with plain nouns
to the thing's name ("the *print* queue file", "the *copy* log file"), or inside the phrase that
says what the thing is about ("Gwen's file on the *shred* bins", "my doc about the *laminate*
orders"). The service said as a verb, or asked for by its noun, is read as before."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, load_office
from helpers.bursary import bursary
from helpers.dataset_offices import DEFAULT_FILE
from helpers.reading import frame_reader, parser_for

_frame = frame_reader(bursary, "ana")


@pytest.mark.parametrize(
    ("text", "owner", "recipient"),
    [
        ("send the print queue file to Bronwen", "ana", "bronwen"),
        ("forward the copy log file to Miles", "ana", "miles"),
        ("could you send the print rota doc to Bronwen", "ana", "bronwen"),
        ("send Miles the copy request form file", "ana", "miles"),
        ("please forward the scan settings file to Gwen", "ana", "gwen"),
    ],
)
def test_a_service_word_after_the_article_names_the_thing(
    text: str, owner: str, recipient: str
) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        ("send_file", "file", owner, recipient, None)
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "get me Gwen's file on the shred bins",
        "could you send me Gwen's file on the scan backlog",
        "send me Gwen's doc about the laminate orders",
        "forward me Gwen's file about the print costs",
        "get me Gwen's file about copies",
        "send me Gwen's file about laminating",
        "email me Gwen's doc regarding the print queue",
    ],
)
def test_a_service_word_in_the_things_topic_asks_no_service(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        ("send_file", "file", "gwen", "ana", None)
    ], frame


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        ("print the file", "print"),
        ("print my file", "print"),
        ("I need a print of my file", "print"),
        ("my file needs a print", "print"),
        ("laminate my file", "laminate"),
        ("send me a copy of my file", "copy"),
        ("get the print done on my file", "print"),
    ],
)
def test_the_service_asked_for_is_read_as_before(text: str, operation: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.operation) for t in frame.tasks] == [("file", operation)], frame


def test_an_operation_asked_as_a_noun_alone_is_still_asked_about() -> None:
    frame = _frame("my file needs a shred")
    assert frame.question is not None and "a shred" in frame.question, frame


@functools.cache
def _default() -> Office:
    return load_office(DEFAULT_FILE)


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("forward the scan settings file to Wang", "lee"),
        ("forward Zhang's scan settings file to Wang", "zhang"),
        ("please send the scan log file to Wang", "lee"),
    ],
)
def test_a_service_nobody_offers_inside_a_things_name_is_no_service(text: str, owner: str) -> None:
    frame = parser_for(_default).parse(text, "lee")
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [
        ("send_file", owner, "wang")
    ], frame


@pytest.mark.parametrize("text", ["bring me a scan", "get me a scan of my file", "scan my file"])
def test_a_service_nobody_offers_asked_for_is_still_declined(text: str) -> None:
    frame = parser_for(_default).parse(text, "lee")
    assert frame.tasks == [] and frame.decline is not None and "scan" in frame.decline, frame
