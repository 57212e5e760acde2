"""A service's word said as the subject of a clause is told, not asked for
(``reading/service_noun_subject``): "courier leaves at 3" beside a request, in an office whose
courier desk is called "courier", says when the courier goes, never asks for a courier; "post
goes at 4", "print is too small on this form", "water runs out fast" likewise. The service's
verb with its object ("courier my contract to the lawyer", "courier it please") is still
asked for."""

from __future__ import annotations

import functools
from typing import Any

import pytest
from _offices import parser

from assistantx.agents.symbolic import InstructionParser
from assistantx.agents.symbolic.reading.service_noun_subject import service_noun_subject
from assistantx.core.office import parse_office
from helpers.dataset_offices import DEFAULT_FILE
from helpers.dispatch_room import dispatch_room
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml


@functools.cache
def _courier_office() -> InstructionParser:
    """The default office with a courier desk, called "courier" and "the van", that sends
    documents out."""
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE)
    raw["operations"].append(
        {
            "id": "courier",
            "name": "courier",
            "verbs": ["courier"],
            "input": "document",
            "sends_out": True,
        }
    )
    raw["facilities"].append(
        {
            "id": "courier_desk",
            "name": "courier desk",
            "synonyms": ["courier", "the van"],
            "location": "print_room",
            "operations": ["courier"],
            "guards": ["xu"],
        }
    )
    return InstructionParser(parse_office(raw, "default with a courier desk"))


_SIGNED = ("sign", "document", "lin", "lin")


@pytest.mark.parametrize(
    "told",
    [
        "courier leaves at 3",
        "the van leaves at 3",  # already read as told: the reference
        "courier comes around noon",
        "courier's gone already",
        "post goes at 4",
    ],
)
def test_a_service_word_as_subject_beside_a_request_is_context(told: str) -> None:
    frame = _courier_office().parse(f"can you get my form signed by Wang? {told}", "lin")
    assert frame.question is None and frame.decline is None
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [_SIGNED]


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("default", "lin", "post goes at 4"),
        ("default", "lin", "courier leaves at 3"),
        ("default", "lin", "print is too small on this form"),
        ("default", "lin", "water runs out fast"),
        ("default", "lin", "copier's jammed again"),
        ("harbour", "may", "print is too small on this chart"),
        ("harbour", "may", "courier comes around noon"),
        ("harbour", "may", "scan is on your desk"),
    ],
)
def test_a_service_word_as_subject_alone_moves_nothing_and_declines_nothing(
    office: str, who: str, text: str
) -> None:
    frame = parser(office).parse(text, who)
    assert not frame.tasks and frame.question is None
    # noted, or thanked for a report; never a service declined as asked for
    assert frame.decline is not None and "offers that" not in frame.decline


def test_beside_a_request_on_harbour_only_the_request_is_done() -> None:
    frame = parser("harbour").parse("could you bring me a tape? courier comes around noon", "may")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "tape", "may")]


def test_beside_a_request_on_the_default_office_no_water_is_made() -> None:
    frame = parser("default").parse("can you bring me a cup? water runs out fast", "lin")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "cup", "lin")]


def test_the_service_asked_with_its_object_is_still_a_request() -> None:
    frame = _courier_office().parse("courier my contract to the lawyer at 4 Quay Street", "lin")
    assert frame.decline is None and len(frame.tasks) == 1
    assert frame.tasks[0].item == "document"
    # "courier it": the object is asked about, never read as told
    asked = _courier_office().parse("courier it please", "lin")
    assert not asked.tasks and asked.question is not None


@pytest.mark.parametrize(
    ("text", "declined"),
    [
        ("courier my book to Westgate", "courier"),  # an unoffered service, its verb first
        ("post the signed contract to Westgate", "post"),
    ],
)
def test_the_unoffered_service_with_its_object_is_still_declined(text: str, declined: str) -> None:
    frame = parser("default").parse(text, "lin")
    assert frame.decline is not None and f"can't {declined}" in frame.decline


@pytest.mark.parametrize(
    ("words", "subject"),
    [
        (["courier", "leaves", "at", "3"], True),
        (["the", "post", "goes", "at", "4"], True),
        (["print", "is", "too", "small"], True),
        (["posts", "late", "today"], True),  # "post's late today", its "'s" folded
        (["print", "labels", "for", "me"], False),  # a plural object, no tail of time
        (["copy", "files", "at", "3"], False),  # the office's files: the object
        (["courier", "it", "please"], False),
        (["print", "leaves", "for", "the", "collage"], False),
    ],
)
def test_service_noun_subject_reads_the_verb_after_the_word(
    words: list[str], subject: bool
) -> None:
    assert service_noun_subject(words, items={"files"}) is subject


# blind round 62's class (the round's own offices and sentences were never read): news of the
# one who does a service, said with the service's word as its subject, asks nothing
_dispatch = frame_reader(dispatch_room, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "courier just rang, he's still miles away so the pickup will be late",
        "courier just called, he'll be here at 3",
        "the courier's late again",
        "post's been, nothing for you",
        "printer guy rang back",
        "post came early, nothing for you",
        "the courier already called back",
    ],
)
def test_news_of_the_services_doer_is_told(text: str) -> None:
    frame = _dispatch(text)
    assert not frame.tasks and frame.question is None, frame


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        ("courier my case to Leeds", "courier"),
        ("courier just rang, can you courier my case", "courier"),
        ("post my letter", "post"),
        ("could you courier my case", "courier"),
    ],
)
def test_the_service_asked_is_still_asked(text: str, operation: str) -> None:
    frame = _dispatch(text)
    assert [t.operation for t in frame.tasks] == [operation] or (
        frame.question is not None and "Where should I" in frame.question
    ), frame


@pytest.mark.parametrize(
    ("words", "subject"),
    [
        (["courier", "just", "rang"], True),
        (["printer", "guy", "rang", "back"], True),
        (["courier", "called"], True),
        (["courier", "signed", "cases"], False),  # a participle describing the object
        (["shred", "printed", "drafts"], False),
        (["courier", "the", "case"], False),
    ],
)
def test_a_past_form_after_the_word_is_its_verb(words: list[str], subject: bool) -> None:
    assert service_noun_subject(words, {"courier", "printer", "shred"}, {"case"}) is subject


def test_a_name_after_the_word_is_no_past_verb() -> None:
    # "print Rose my file": Rose is whom it is for, never "rose", the past of "rise"
    assert not service_noun_subject(
        ["print", "rose", "my", "file"], {"print"}, {"file"}, {"rose"}.__contains__
    )
    assert service_noun_subject(["print", "rose", "my", "file"], {"print"}, {"file"})
