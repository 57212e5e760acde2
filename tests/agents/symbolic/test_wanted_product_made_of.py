"""A copy wanted for a colleague, where nothing copies, is declined, never the original handed
over (fix139c, class 1): in harbour (no copier) "Hope needs a copy of my report" was read as
taking the report itself to Hope, and only the consent guard stopped that hand-over after a
wasted trip. A product made *of* a thing ("a copy of", "a printout of") after a verb of
wanting or getting asks for it to be made, as "make Hope a copy of my report" does
(``screen.made_product``): where the office makes no such thing it is declined, saying what
the office can do. Where the office makes it (the default office copies) it is read as
before; a thing wanted with no "of" ("Hope needs my report") is not a product."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "grace")


@pytest.mark.parametrize(
    "text",
    [
        "Hope needs a copy of my report",
        "Hope should get a copy of my report",
        "Ray wants a copy of my notes, can you sort it",
        "I need a copy of my report",
    ],
)
def test_a_copy_wanted_where_nothing_copies_is_declined(text: str) -> None:
    frame = _harbour(text)
    assert not frame.tasks and frame.question is None, text
    assert frame.decline is not None and frame.decline.startswith("Sorry, I can't copy"), text


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "Zhang needs a copy of my document. oh and grab me a coffee",
            [("copy", "zhang"), ("produce", "lee")],
        ),
        ("I need a copy of my document", [("copy", "lee")]),
    ],
)
def test_must_not_change_where_the_office_copies(text: str, tasks: list[tuple[str, str]]) -> None:
    assert [(t.kind, t.recipient) for t in _default(text).tasks] == tasks, text


@pytest.mark.parametrize("text", ["Hope needs my report", "Hope needs a printout of my rota"])
def test_must_not_change_no_unmade_product(text: str) -> None:
    assert _harbour(text).decline is None, text
