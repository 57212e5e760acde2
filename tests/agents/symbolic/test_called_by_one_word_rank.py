""" "the Director": a colleague the office writes as one title before their surname
("Director Okafor") is called by that title alone, by the reader and the consent guard
alike (`core.ranks`), where one person holds it, the dictionary knows it as a noun and never
as an adjective ("Young Park" is a nickname), and nobody bears it as a name ("Marshal
Kowal"). Blind round 39's writer found the simulated office refused the hand-over of "get
the Director to sign my timesheet": the guard did not count "the Director" as naming her."""

from __future__ import annotations

import pytest

from assistantx.core.ranks import rank_titles
from assistantx.runtime.recipients import named_doers, named_recipients
from helpers.consent_memory import memory
from helpers.port_office import port_office
from helpers.reading import frame_reader

_frame = frame_reader(port_office, "tom")


def test_a_one_word_noun_title_one_person_holds_is_a_rank() -> None:
    assert rank_titles(port_office()) == {
        "director": frozenset({"ada"}),
        "captain": frozenset({"luis"}),
        "deputy": frozenset({"marshal"}),
    }


@pytest.mark.parametrize(
    "text",
    [
        "get the Director to sign my timesheet pls",
        "can the Director sign off my timesheet",
        "could you have the Director sign my timesheet",
    ],
)
def test_the_title_names_its_holder_as_the_signer(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [(t.kind, t.owner, t.actor) for t in frame.tasks] == [("sign", "tom", "ada")], frame


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("take my radio to the Captain", "luis"),
        ("send my spreadsheet to the Director", "ada"),
    ],
)
def test_the_title_names_its_holder_as_the_recipient(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [t.recipient for t in frame.tasks] == [recipient], frame


@pytest.mark.parametrize(
    "text",
    [
        "take my radio to the sister",  # two hold "Sister": nobody by it
        "take my radio to the young one",  # an adjective is no rank
    ],
)
def test_a_shared_title_or_an_adjective_names_nobody(text: str) -> None:
    frame = _frame(text)
    assert not any(t.recipient in {"mae", "ines", "jin"} for t in frame.tasks), frame


def test_the_guard_counts_the_title_as_naming_its_holder() -> None:
    office = port_office()
    signed = memory("tom", "get the Director to sign my timesheet pls")
    assert named_doers(office, signed) == {"ada"}
    sent = memory("tom", "send my spreadsheet to the Captain")
    assert named_recipients(office, sent) == {"luis"}
    shared = memory("tom", "send my spreadsheet to the Sister")
    assert named_recipients(office, shared) == set()


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("take my radio to the captain", "luis"),
        ("send my spreadsheet to the director pls", "ada"),
    ],
)
def test_the_rank_in_lower_case_names_its_holder(text: str, recipient: str) -> None:
    # round 234: "give the hard copy to the curator" (of "Curator Moreau") printed the
    # file for the speaker; people type ranks in lower case as "the manager" is
    frame = _frame(text)
    assert frame.question is None, frame
    assert [t.recipient for t in frame.tasks] == [recipient], frame
    assert named_recipients(port_office(), memory("tom", text)) == {recipient}


def test_the_lower_case_rank_as_signer_is_counted_by_the_guard() -> None:
    text = "get the director to sign my timesheet"
    frame = _frame(text)
    assert [(t.kind, t.actor) for t in frame.tasks] == [("sign", "ada")], frame
    assert named_doers(port_office(), memory("tom", text)) == {"ada"}


def test_a_lower_case_shared_rank_still_names_nobody() -> None:
    assert (
        named_recipients(port_office(), memory("tom", "send my spreadsheet to the sister")) == set()
    )
