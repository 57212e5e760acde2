"""A title and a name nobody of the office has name a person outside it (blind round 139's
class: three requests ended "I don't know anyone called 'X' in this office"): whom the work
is for ("one for Ms Hartmann", "book a slot for Mr Evans and bring me the card") is context,
not a colleague to ask about; an outside address of a send-out is the destination; a
stranger who would be handed a thing is asked about, as "the client" is (only colleagues are
handed anything). Checked on a test mailing room, the default office and harbour."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office, harbour_that_posts
from helpers.mailing_room import mailing_room
from helpers.reading import ReadFrame, frame_reader

_mailing = frame_reader(mailing_room, "tom")
_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "may")
_posting = frame_reader(harbour_that_posts, "may")

_READERS = {"mailing": _mailing, "default": _default, "harbour": _harbour}


def _for_the_requester(frame: TaskFrame, requester: str) -> None:
    assert frame.question is None and frame.decline is None, frame
    assert frame.tasks, frame
    assert {t.recipient for t in frame.tasks} == {requester}, frame


@pytest.mark.parametrize(
    ("office", "text"),
    [
        # the class's analogues
        ("mailing", "print two copies of my report, one for me and one for Ms Hartmann"),
        ("mailing", "photocopy my letter, one for the file and one for Mrs Jenkins"),
        ("mailing", "book a slot for Mr Evans and bring me the card"),
        ("mailing", "copy my letter for Mr Ibrahim and bring it to me"),
        # other words, other offices
        ("mailing", "scan my contract for Prof Lindgren"),
        ("mailing", "print my report for Miss Okafor please"),
        ("default", "copy my document for Mrs Jenkins and bring it to me"),
        ("default", "photocopy my document, one for me and one for Dr Alvarez"),
        ("default", "print my file for Prof Lindgren"),
        ("harbour", "scan my document for Mr Ibrahim and bring it to me"),
        ("harbour", "print my file for Dr Alvarez"),
    ],
)
def test_whom_the_work_is_for_is_not_asked_about(office: str, text: str) -> None:
    requester = {"mailing": "tom", "default": "lee", "harbour": "may"}[office]
    _for_the_requester(_READERS[office](text), requester)


@pytest.mark.parametrize(
    ("read", "text", "operation", "place"),
    [
        (
            _mailing,
            "Send my parcel out on the courier to Mr Okoro, Harbour Marina, berth C14",
            "post",
            "Mr Okoro, Harbour Marina, berth C14",
        ),
        (
            _mailing,
            "post my contract to Dr Alvarez at Northfield Clinic",
            "post",
            "Dr Alvarez at Northfield Clinic",
        ),
        (
            _posting,
            "post my document to Dr Alvarez at Northfield Clinic",
            "frank",
            "Dr Alvarez at Northfield Clinic",
        ),
        (
            _posting,
            "frank my document to Mrs Patel, Kingsway Surgery",
            "frank",
            "Mrs Patel, Kingsway Surgery",
        ),
    ],
)
def test_a_stranger_in_a_send_out_is_the_address(
    read: ReadFrame, text: str, operation: str, place: str
) -> None:
    frame = read(text)
    assert frame.question is None, frame
    assert [(t.operation, t.destination) for t in frame.tasks] == [(operation, place)], frame


@pytest.mark.parametrize(
    ("office", "text", "who"),
    [
        # must not change: a stranger handed a thing is nobody to hand it to
        ("mailing", "give Mr Evans my stapler", "Mr Evans"),
        ("mailing", "bring my stapler to Mrs Jenkins", "Mrs Jenkins"),
        ("mailing", "get a stapler for Dr Ruiz", "Dr Ruiz"),
        ("default", "bring my pen to Mrs Jenkins", "Mrs Jenkins"),
        ("harbour", "give Ms Hartmann my tape dispenser", "Ms Hartmann"),
    ],
)
def test_a_stranger_who_would_be_handed_a_thing_is_asked_about(
    office: str, text: str, who: str
) -> None:
    frame = _READERS[office](text)
    assert not frame.tasks, frame
    assert frame.question is not None and f"I don't know who {who} is" in frame.question


@pytest.mark.parametrize(
    ("office", "text", "recipient"),
    [
        # must not change: a title before a colleague's name is the colleague
        ("default", "give Mr Zhang my pen", "zhang"),
        ("default", "give Dr Zhang my pen", "zhang"),
        ("mailing", "give Mr Blake my stapler", "owen"),
    ],
)
def test_a_title_before_a_colleagues_name_is_the_colleague(
    office: str, text: str, recipient: str
) -> None:
    frame = _READERS[office](text)
    assert [t.recipient for t in frame.tasks] == [recipient], frame


@pytest.mark.parametrize(
    ("office", "text"),
    [
        # must not change: a bare name nobody has may be a colleague misnamed: still asked
        ("default", "photocopy my document, one for me and one for Jenkins"),
        ("mailing", "book a slot for Evans and bring me the card"),
    ],
)
def test_an_untitled_unknown_name_is_still_asked_about(office: str, text: str) -> None:
    frame = _READERS[office](text)
    assert frame.question is not None and "I don't know anyone called" in frame.question, frame
