"""Which end of a name is the family name is each person's own where their alias says it.
Blind round 81's police station had one titled alias, "Ms Nguyễn" (family name first), so the
whole office was read family-first: Priya Morgan's family name became "Priya", and "take my
overtime form to Morgan" went to Morgan Tallis without asking, although at a station Priya
Morgan ("Inspector Morgan") is called Morgan too. A person's own alias of a title or a rank and
one word of their name ("Inspector Morgan", "Manager Mao") now says their own order; the
office's order stays for everyone else (the default office: family name first)."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office
from helpers.dataset_offices import HARBOUR_FILE, default_office
from helpers.reading import frame_reader
from helpers.renamed_offices import renamed

_MORGAN = "Who do you mean by 'Morgan': Morgan Tallis or Priya Morgan?"


@functools.cache
def _station() -> Office:
    """Harbour with its three English-order titled aliases gone and one family-first one
    ("Ms Nguyễn"), beside Morgan Tallis ("Morgan") and Priya Morgan ("Inspector Morgan")."""
    return renamed(
        HARBOUR_FILE,
        (
            ("grace", "Grace Huang", ("Grace",)),
            ("art", "Art Kowalski", ("Art",)),
            ("sue", "Sue Whitfield", ("Sue",)),
            ("pat", "Nguyễn Thị Lan", ("Lan", "Ms Nguyễn")),
            ("bill", "Morgan Tallis", ("Morgan",)),
            ("jack", "Priya Morgan", ("Priya", "Inspector Morgan")),
        ),
        "a station with one family-first name",
    )


_read = frame_reader(_station, "will")


@pytest.mark.parametrize(
    "text",
    [
        "can you take my overtime form to Morgan",
        "drop my document with Morgan please",
        # Morgan Tallis has no alias of his own that says his order, so the office's
        # (family first, from "Ms Nguyễn" alone) still makes "Morgan" his family name too:
        # asked, never settled the wrong way
        "give my document to Ms Morgan",
    ],
)
def test_a_bare_family_name_of_another_is_asked(text: str) -> None:
    assert _read(text).question == _MORGAN


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("give my document to Inspector Morgan", "jack"),
        ("give my document to Morgan Tallis", "bill"),
        ("give my document to Ms Nguyễn", "pat"),
        ("give my document to Lan", "pat"),
    ],
)
def test_what_decides_it_still_decides(text: str, who: str) -> None:
    frame = _read(text)
    assert [t.recipient for t in frame.tasks] == [who], frame.question


_default = frame_reader(default_office, "mao")


@pytest.mark.parametrize(
    ("text", "who", "question"),
    [
        # the default office writes every name family first: unchanged
        ("give Mr Yang my stapler", "yang", None),
        ("give Yang my stapler", None, "Who do you mean by 'Yang': Liu Yang or Yang Lei?"),
    ],
)
def test_the_office_order_stays_for_everyone_else(
    text: str, who: str | None, question: str | None
) -> None:
    frame = _default(text)
    assert frame.question == question
    assert [t.recipient for t in frame.tasks] == ([who] if who else [])
