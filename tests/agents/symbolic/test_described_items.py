"""A colleague's thing described with words the office does not list ("Chase's setting-out
file", "Wang's budget plan? just send me the file") is that colleague's item: the description
is no owner and no part left unread, and a later "the file" names what the thing is, the same
owner's, for whom the later clause says (``reading.described_items``)."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.described_items import (
    named_later,
    without_hyphened_description,
)
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader, parser_for

_DEFAULT = frame_reader(default_office, "lee")
_HARBOUR = frame_reader(harbour_office, "will")


def _tasks(frame: object) -> list[tuple[str, str, str | None, str | None]]:
    tasks = getattr(frame, "tasks", [])
    return sorted((t.kind, t.item, t.owner, t.recipient) for t in tasks)


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("can you get me Wang's setting-out file?", "wang"),  # the class's analogue
        ("hey could I have Wang's budget plan? just send me the file", "wang"),  # the other
        ("could you send me Zhang's year-end report file", "zhang"),
        ("I need Mao's site visit slides, can you send them over", "mao"),
        ("can you get me Wang's fit-out file?", "wang"),
        ("can you get me Zhang's handing-over slides?", "zhang"),
        ("I need Hu's crane lift plan, just send me the file", "hu"),
    ],
)
def test_default_office_a_described_file_is_the_owners_file_for_me(text: str, owner: str) -> None:
    assert _tasks(_DEFAULT(text)) == [("send_file", "file", owner, "lee")], _DEFAULT(text)


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("can you get me Grace's setting-out file?", "grace"),
        ("could I have Mark's crane lift plan? just send me the file", "mark"),
        ("could you send me Ken's quarter-end slides", "ken"),
    ],
)
def test_harbour_a_described_file_is_the_owners_file_for_me(text: str, owner: str) -> None:
    assert _tasks(_HARBOUR(text)) == [("send_file", "file", owner, "will")], _HARBOUR(text)


def test_a_hyphened_description_of_a_paper_item_keeps_the_paper() -> None:
    # a description changes no kind: Wang's report is still the paper document, carried
    assert _tasks(_DEFAULT("bring me Wang's write-up report")) == [
        ("transfer", "document", "wang", "lee")
    ]
    assert _tasks(_DEFAULT("please send my quarter-end slides to Wang")) == [
        ("send_file", "file", "lee", "wang")
    ]


@pytest.mark.parametrize(
    ("reader", "text", "expected"),
    [
        (_DEFAULT, "send Wang's file to Zhang", [("send_file", "file", "wang", "zhang")]),
        (_DEFAULT, "send my file to Wang", [("send_file", "file", "lee", "wang")]),
        (
            _DEFAULT,
            "could I have Wang's file? just send me the file",
            [("send_file", "file", "wang", "lee")],
        ),
        (_HARBOUR, "send Mark's file to Rose", [("send_file", "file", "mark", "rose")]),
    ],
)
def test_must_not_change_neighbours(
    reader: ReadFrame, text: str, expected: list[tuple[str, str, str, str]]
) -> None:
    frame = reader(text)
    assert _tasks(frame) == expected, frame


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("get me Wang's setting-out file", "get me Wang's file"),
        ("send my quarter-end slides to Wang", "send my slides to Wang"),
        # no hyphen: the frames read plain nouns before the item themselves
        ("send me Zhang's budget report", "send me Zhang's budget report"),
        # a hyphened word that is no description before an item: unchanged
        ("send Wang's file to Zhang's e-mail", "send Wang's file to Zhang's e-mail"),
        ("bring me Wang's stapler, a follow-up", "bring me Wang's stapler, a follow-up"),
    ],
)
def test_hyphened_description_rewrite(text: str, expected: str) -> None:
    assert without_hyphened_description(parser_for(default_office).lex, text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "could I have Wang's budget plan? just send me the file",
            "could I have Wang's budget plan file? just send me the file",
        ),
        # the thing is an office's item already: nothing to name
        (
            "could I have Wang's stapler? just bring me the file",
            "could I have Wang's stapler? just bring me the file",
        ),
        # another party named first as whom it is for: still Wang's thing, said as the
        # file (for whom is then asked: reading.back_reference_recipient)
        (
            "could I have Wang's budget plan? Zhang needs the file",
            "could I have Wang's budget plan file? Zhang needs the file",
        ),
        # another party named as whom to ask: "the file" may be theirs, left to the frames
        (
            "could I have Wang's budget plan? ask Zhang for the file",
            "could I have Wang's budget plan? ask Zhang for the file",
        ),
        # no later "the <item>"
        ("could I have Wang's budget plan? thanks", "could I have Wang's budget plan? thanks"),
        # said as a statement, not a thing asked for by name alone
        (
            "Wang's budget plan is done, print the file",
            "Wang's budget plan is done, print the file",
        ),
    ],
)
def test_named_later_rewrite(text: str, expected: str) -> None:
    assert named_later(parser_for(default_office).lex, text) == expected


def test_a_thing_named_by_a_word_of_an_item_is_left_to_its_own_stages() -> None:
    lex = parser_for(default_office).lex
    # "report" is a word of the office's items (a document): nothing to name later
    said = "could I have Wang's report? just send me the file"
    assert named_later(lex, said) == said
    # "not the file": what is not meant names nothing
    said = "could I have Wang's budget plan? not the file"
    assert named_later(lex, said) == said
