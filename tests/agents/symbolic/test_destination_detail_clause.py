"""How to reach a send-out's place, said in a clause after it, goes out with the place (fixer
80c, class 1: "Fax my incident report to the county hospital, their number is 01632 960 123."
faxed to "the county hospital" with no number: the screen set the second clause aside as a
statement). A clause that names a way of reaching a place (a number, a postcode, an address,
or the words of the service's ``destination_asked``) owned by the place or by nobody, with a
value that can be dialled or addressed, joins the destination
(``reading/destination_detail.py``). The requester's own number, a clause about something
else, or a number before the place change nothing.

On the default office with a fax that sends out (the standard services' fax shape with
``sends_out`` and "the fax number" asked), and on Harbour whose franking machine posts a
document out (its "frank"/"post" verbs, "the postal address" asked)."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office_that_sends_out, harbour_that_posts
from helpers.reading import frame_reader


def _default_with_a_fax() -> Office:
    return default_office_that_sends_out("fax", "fax", "fax", "the fax number")


_fax = frame_reader(_default_with_a_fax, "mao")
_post = frame_reader(harbour_that_posts, "may")


def _sent(frame: TaskFrame) -> list[tuple[str | None, str | None]]:
    return [(t.operation, t.destination) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "where"),
    [
        # the class's analogue
        (
            "Fax my incident report to the county hospital, their number is 01632 960 123.",
            "the county hospital, number 01632 960 123",
        ),
        (
            "fax my report to the county hospital, the fax is 01632 960 123",
            "the county hospital, fax 01632 960 123",
        ),
        (
            "fax my report to the county hospital. Number: 01632 960 123",
            "the county hospital, number 01632 960 123",
        ),
        # variants: other places, other words for the number, other joins
        (
            "could you fax my form to the tax office please, the number's 0161 496 0000",
            "the tax office, number 0161 496 0000",
        ),
        (
            "fax my contract to Acme Ltd - fax number 0113 496 0000, thanks",
            "Acme Ltd, fax number 0113 496 0000",
        ),
        (
            "fax my contract to Acme Ltd. Their fax no. is 0113 496 0000",
            "Acme Ltd, fax no 0113 496 0000",
        ),
        (
            "please fax my invoice to the insurers, their fax number is 020 7946 0018",
            "the insurers, fax number 020 7946 0018",
        ),
        # said inside the place's own words already (unchanged)
        (
            "fax my report to the county hospital on 01632 960 123",
            "the county hospital on 01632 960 123",
        ),
    ],
)
def test_the_number_said_after_the_place_is_sent_with_it(text: str, where: str) -> None:
    assert _sent(_fax(text)) == [("fax", where)]


@pytest.mark.parametrize(
    ("text", "where"),
    [
        # the class's Harbour analogue
        (
            "frank my letter and post it to the Leeds office, the postcode is LS1 4AP",
            "the Leeds office, postcode LS1 4AP",
        ),
        (
            "post my contract to Harlow Associates, their address is 12 Kiln Street, Bristol "
            "BS1 5TT",
            "Harlow Associates, address 12 Kiln Street, Bristol BS1 5TT",
        ),
        (
            "post my form to the tax office. Postcode LS1 4AP please",
            "the tax office, postcode LS1 4AP",
        ),
    ],
)
def test_the_postcode_said_after_the_place_is_posted_with_it(text: str, where: str) -> None:
    assert _sent(_post(text)) == [("frank", where)]


@pytest.mark.parametrize(
    ("text", "where"),
    [
        # a number that is no destination: a count before the place
        ("fax my 2 reports to the county hospital", "the county hospital"),
        # the requester's own number is no place's
        (
            "fax my report to the county hospital, my number is 07700 900 123 if they call",
            "the county hospital",
        ),
        # a clause about something else, or a number nobody can dial
        ("fax my report to the county hospital, the meeting is at 3", "the county hospital"),
        (
            "fax my report to the county hospital, the number is on the letterhead",
            "the county hospital",
        ),
        ("fax my report to the county hospital, thanks", "the county hospital"),
    ],
)
def test_other_clauses_and_numbers_leave_the_place_alone(text: str, where: str) -> None:
    assert _sent(_fax(text)) == [("fax", where)]


def test_a_clause_of_thanks_after_a_pronoun_send_changes_nothing() -> None:
    """ "fax it to the hospital, thanks": nothing said that "it" is; still asked which item."""
    frame = _fax("fax it to the hospital, thanks")
    assert frame.tasks == [] and frame.question is not None


def test_a_second_request_after_the_place_stays_a_request() -> None:
    frame = _post("post my form to the Leeds tax office, and then bring me a tape")
    assert [(t.kind, t.item, t.destination) for t in frame.tasks] == [
        ("heat", "document", "the Leeds tax office"),
        ("transfer", "tape", None),
    ]
