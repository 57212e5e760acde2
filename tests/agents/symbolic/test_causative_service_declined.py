"""A service asked for in the causative that the office does not offer is declined plainly
(fix139c, class 2): "can you get the survey report bound for the customer", with no binding
anywhere in the office, asked "Who should get your document?" and ended "OK, I won't do
anything, then." A thing named after "get"/"have"/"need"/"want" and followed by the past
participle of one of English's services ("laminated", "shredded", irregular "bound") asks
for that work (``screen.causative_service``): where no operation of the office runs it, the
reader declines it in one answer that says what the office can do. An offered one ("get my
file printed") stays a request; "bound" describing a thing to fetch binds nothing."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("text", "verb"),
    [
        ("can you get my report laminated for the client", "laminate"),
        ("get my file bound for the meeting pls", "bind"),
        ("can you get the survey report bound for the customer", "bind"),
        ("I need my document shredded", "shred"),
        ("could you have my report faxed to Zhang", "fax"),
    ],
)
def test_an_unoffered_service_in_the_causative_is_declined(text: str, verb: str) -> None:
    frame = _default(text)
    assert not frame.tasks and frame.question is None, text
    assert frame.decline is not None and frame.decline.startswith(f"Sorry, I can't {verb}:"), text
    assert "What I can do here" in frame.decline


def test_the_same_in_another_office() -> None:
    frame = _harbour("get my report bound for the meeting pls")
    assert not frame.tasks and frame.decline is not None
    assert frame.decline.startswith("Sorry, I can't bind:")


@pytest.mark.parametrize(
    ("read", "text", "task"),
    [
        (_default, "get my file printed", ("print", "lee")),
        (_default, "i need my file printed", ("print", "lee")),
        (_harbour, "get my report printed", ("print", "may")),
    ],
)
def test_must_not_change_an_offered_service_is_a_request(
    read: ReadFrame, text: str, task: tuple[str, str]
) -> None:
    frame = read(text)
    assert [(t.kind, t.recipient) for t in frame.tasks] == [task], text
    assert frame.decline is None


@pytest.mark.parametrize("text", ["find me a book bound in red", "get me a book bound in red"])
def test_must_not_change_bound_describing_a_thing_to_fetch(text: str) -> None:
    frame = _default(text)
    assert frame.decline is None or "bind" not in frame.decline, text
    assert all(t.kind == "transfer" and t.item == "book" for t in frame.tasks), text


@pytest.mark.parametrize(
    ("text", "verb"),
    [
        ("get my form stamped and then scanned", "scan"),
        ("can you get my contract stamped and faxed to the council", "fax"),
        ("I need my report printed and laminated", "laminate"),
    ],
)
def test_unoffered_work_joined_to_offered_work_is_declined(text: str, verb: str) -> None:
    """ "stamped and then scanned" where nothing scans: the stamp alone was done, the scan
    dropped unsaid; the joined participle asks the same thing's work, said as not offered."""
    frame = _default(text)
    assert not frame.tasks and frame.question is None, text
    assert frame.decline is not None and frame.decline.startswith(f"Sorry, I can't {verb}:"), text


def test_the_joined_work_in_another_office() -> None:
    frame = _harbour("get my report printed and then bound")
    assert frame.decline is not None and frame.decline.startswith("Sorry, I can't bind:")


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("get my form stamped and then bring it to Chen", ["seal"]),
        ("I printed my report and scanned it, can you bring me a stapler", ["transfer"]),
        ("get my report printed and then bring me the stapler", ["print", "transfer"]),
    ],
)
def test_must_not_change_joined_requests_and_statements(text: str, kinds: list[str]) -> None:
    frame = _default(text)
    assert frame.decline is None, text
    assert sorted(t.kind for t in frame.tasks) == kinds, text
