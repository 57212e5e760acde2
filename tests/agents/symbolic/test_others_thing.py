"""A colleague's thing the work cannot take is never swapped for the requester's own (fix103h,
class 3's analogue; ``reading.others_thing``): "Mark's laptop needs a scan, can you take it
over" said by Will scanned Will's own document. A colleague's possessive before a noun that
is no item of the office names the thing meant; with the work's item never said, the request
is declined in words and nothing moves."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    ("office", "text", "requester", "said"),
    [
        (
            "harbour",
            "Mark's laptop needs a scan, can you take it over",
            "will",
            "Mark Lindqvist's laptop",
        ),
        ("default", "Zhang's laptop needs printing", "lee", "Zhang Wei's laptop"),
        ("default", "Wang's tablet could do with a copy", "lee", "Wang Fang's tablet"),
        ("default", "can you print Zhang's monitor, thanks", "lee", "Zhang Wei's monitor"),
        # a word the dictionary lacks names a thing as well: printing the speaker's own
        # file for "Mao's rota" was a wrong physical action
        ("default", "print Mao's rota", "sun", "Mao Jun's rota"),
        ("default", "print Mao's powerpoint", "sun", "Mao Jun's powerpoint"),
    ],
)
def test_a_colleagues_other_thing_is_declined_not_swapped(
    office: str, text: str, requester: str, said: str
) -> None:
    frame = parser(office).parse(text, requester)
    assert frame.tasks == [], frame
    assert said in (frame.decline or ""), frame
    assert "won't use your own" in (frame.decline or ""), frame


# -- must not change: the work's item said, or the requester's own said ---------------------
@pytest.mark.parametrize(
    ("office", "text", "requester", "task"),
    [
        (
            "harbour",
            # the document itself named: worked on (the speaker asks for "it": theirs)
            "Mark's document needs a scan, can you take it over",
            "will",
            ("copy", "document", "mark", "will"),
        ),
        (
            "harbour",
            "scan my document, Mark's laptop is broken",
            "will",
            ("copy", "document", "will", "will"),
        ),
        (
            "harbour",
            "Mark's laptop is broken, can you scan my document",
            "will",
            ("copy", "document", "will", "will"),
        ),
        ("default", "copy Wang's contract", "lee", ("copy", "document", "wang", "lee")),
        (
            "default",
            "print my file, Zhang's laptop is broken",
            "lee",
            ("print", "file", "lee", "lee"),
        ),
    ],
)
def test_the_named_item_or_ones_own_is_worked_on(
    office: str, text: str, requester: str, task: tuple[str, str, str, str]
) -> None:
    assert tasks_of(office, text, requester) == [task]


def test_a_colleagues_thing_that_says_where_is_no_object() -> None:
    # "on Mark's desk": where the printout goes, the work's object is the requester's own
    tasks = tasks_of("harbour", "print the minutes and leave them on Mark's desk", "may")
    assert [(kind, recipient) for kind, _, _, recipient in tasks] == [("print", "mark")]
