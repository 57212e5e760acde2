"""Blind round 18's reader classes (second half), by mechanism, on sentences of our own
against a vet practice no sentence was written for (the round's office and sentences were
never read). Only what is asked for moves, and only whose it was said to be."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.clipped_names import clipped_item
from helpers.reading import answered_reader, frame_reader
from helpers.vet_practice import vet_practice

_frame = frame_reader(vet_practice, "frank")


def _tasks(text: str, who: str = "frank") -> list[tuple[str, str | None, str | None, str]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in _frame(text, who).tasks]


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("Could you bring me an ice bucket? Running minipreps in 10", "ice_bucket"),
        ("Could you bring me an ice bucket? Printing the rota later", "ice_bucket"),
        ("could you bring me some gloves, stamping forms all afternoon", "gloves"),
        ("bring me some gloves please. Running gels after lunch", "gloves"),
        # a participle of no service here names the speaker's own samples, none to fetch
        ("Could you bring me an ice bucket? Spinning down minipreps in 10", "ice_bucket"),
        ("bring me some gloves please. Loading gels after lunch", "gloves"),
    ],
)
def test_a_service_participle_after_a_request_is_the_speakers_doing(text: str, item: str) -> None:
    """1: "Running minipreps in 10" after a request is why it is asked, not a service."""
    assert _tasks(text) == [("transfer", item, None, "frank")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Printing my file please", [("print", "case_file", "frank", "frank")]),
        (
            "bring me some gloves. printing my file too please",
            [("transfer", "gloves", None, "frank"), ("print", "case_file", "frank", "frank")],
        ),
    ],
)
def test_a_service_participle_that_asks_is_still_a_request(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    """1, near-miss: alone, or with "too please", the participle asks for the service."""
    assert _tasks(text) == expected


_PRINT = ("print", "case_file", "frank", "frank")


@pytest.mark.parametrize(
    ("text", "second"),
    [
        (
            "print off my file, and while you're at it grab me some gloves from stores",
            ("transfer", "gloves", None, "frank"),
        ),
        (
            "print off my file and while you are at it grab me some gloves",
            ("transfer", "gloves", None, "frank"),
        ),
        (
            "print my file, and if you can bring me an ice bucket",
            ("transfer", "ice_bucket", None, "frank"),
        ),
        (
            "print my file, and if you get a chance bring me an ice bucket",
            ("transfer", "ice_bucket", None, "frank"),
        ),
        (
            "print my file and while you're at it bring Hazel's stethoscope to me",
            ("transfer", "stethoscope", "hazel", "frank"),
        ),
    ],
)
def test_an_aside_joins_a_second_request(
    text: str, second: tuple[str, str | None, str | None, str]
) -> None:
    """2: "while you're at it", "if you can" join a second request; both are done in order."""
    assert _tasks(text) == [_PRINT, second]


@pytest.mark.parametrize(
    "text",
    [
        "print my file, and while you're at it don't bring me any gloves",
        "print my file and while you're at it thanks for the gloves",
    ],
)
def test_an_aside_before_a_negation_or_thanks_moves_no_gloves(text: str) -> None:
    """2, near-miss: what follows the aside is no request: no gloves move."""
    assert all(t[1] != "gloves" for t in _tasks(text))


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("can you bring me a steth", [("transfer", "stethoscope", None, "hazel")]),
        ("could I borrow Frank's stetho please", [("transfer", "stethoscope", "frank", "hazel")]),
        ("bring me a thermom", [("transfer", "thermometer", None, "hazel")]),
    ],
)
def test_a_clipped_item_name_is_the_item(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    """3: "steth" clips only "stethoscope": read as it."""
    assert _tasks(text, "hazel") == expected


def test_a_clipped_name_with_a_reason_is_fetched_for_the_asker() -> None:
    """3: "anyone got a spare steth? mine's in the wash" reads as the whole name would: the
    speaker's own one amiss beside the ask makes it a request (blind round 59-60 class 3),
    so one is fetched for the asker, its owner asked."""
    read = answered_reader(vet_practice, "hazel")
    text = "anyone got a spare steth? mine's in the wash, puppy wee all over it lol"
    assert [(t.kind, t.item, t.owner, t.recipient) for t in read(text).tasks] == [
        ("transfer", "stethoscope", None, "hazel")
    ]


@pytest.mark.parametrize(
    "text", ["thanks for the steth", "does anyone have a steth?", "don't bring me a steth"]
)
def test_a_clipped_name_in_thanks_a_question_or_a_negation_moves_nothing(text: str) -> None:
    """3, near-miss: the clipped name changes what is named, never what is asked."""
    assert _tasks(text, "hazel") == []


@pytest.mark.parametrize(
    ("word", "names", "expected"),
    [
        ("steth", {"stethoscope": "steth_id", "stapler": "s"}, "stethoscope"),
        ("therm", {"thermometer": "t", "thermos": "f"}, None),  # two clipped: asked
        ("ther", {"thermometer": "t"}, None),  # an English word form, left alone
        ("stet", {"stethoscope": "steth_id"}, "stethoscope"),
        ("ste", {"stethoscope": "steth_id"}, None),  # too short to say which
        ("glov", {"glove": "g"}, None),  # only one letter short: a typo's business
    ],
)
def test_clipped_item_needs_one_item_and_an_unknown_word(
    word: str, names: dict[str, str], expected: str | None
) -> None:
    assert clipped_item(word, names) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "Frank's stethoscope for me please, he said he's not using it till after lunch",
            [("transfer", "stethoscope", "frank", "hazel")],
        ),
        ("Frank's stethoscope for me please.", [("transfer", "stethoscope", "frank", "hazel")]),
        (
            "Frank's thermometer for Jonno please, he's not using it",
            [("transfer", "thermometer", "frank", "jonno")],
        ),
    ],
)
def test_a_verbless_request_opening_with_an_owners_name_is_asked(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    """4: "Frank's" is Frank's, not the verb "franks": the owner is asked for his item."""
    assert _tasks(text, "hazel") == expected


@pytest.mark.parametrize(
    "text",
    [
        "Frank's stethoscope is broken",
        "Frank's stethoscope snapped yesterday",
        "Frank's stethoscope works fine",
        "Frank's stethoscope for me please. actually never mind",
        "thanks for Frank's stethoscope",
    ],
)
def test_a_statement_about_an_owners_item_moves_nothing(text: str) -> None:
    """4, near-miss: told, withdrawn or thanked for, Frank's stethoscope stays."""
    assert _tasks(text, "hazel") == []


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        (
            "make up 14 days of meloxicam for the cat in kennel 6 and bring it to me when "
            "it's done",
            "hazel",
        ),
        ("dispense 5 days of meloxicam for me please", "hazel"),
        ("can you make up a course of amoxicillin for Jonno", "jonno"),
    ],
)
def test_a_course_of_an_unknown_drug_is_the_dispensarys_product(text: str, recipient: str) -> None:
    """5: "14 days of meloxicam" beside the dispensary's verb names what it makes; "for the
    cat in kennel 6" is a purpose, the asker still the recipient."""
    assert _tasks(text, "hazel") == [("produce", "meds", None, recipient)]


@pytest.mark.parametrize(
    "text",
    [
        "bring me 14 days of meloxicam",  # no making service said: nothing guessed
        "don't make up 14 days of meloxicam",
        "thanks for making up 14 days of meloxicam",
    ],
)
def test_a_course_without_the_service_asked_makes_nothing(text: str) -> None:
    """5, near-miss: no service asked, or its making negated or thanked for."""
    assert _tasks(text, "hazel") == []


@pytest.mark.parametrize(
    "text",
    [
        "jonno's asked for a thermometer down in kennels, can you get one to him?",
        "Jonno's asked for a thermometer down in kennels, can you get one to him?",
        "jonno's asked for a thermometer up in the lab, can you take one to him",
    ],
)
def test_him_after_a_name_that_has_asked_is_that_person(text: str) -> None:
    """6: "jonno's asked" is "Jonno has asked"; "him" is Jonno, the one person named, and
    "down in kennels" says where, it names no kind of thermometer."""
    assert _tasks(text, "hazel") == [("transfer", "thermometer", None, "jonno")]


@pytest.mark.parametrize(
    "text",
    [
        "jonno's asked for a thermometer",
        "Jonno has asked for a thermometer",
        "jonno's asked for a thermometer down in kennels",
    ],
)
def test_a_name_that_has_asked_alone_is_offered_to_that_person(text: str) -> None:
    """6, near-miss: said alone, a colleague's need is restated and asked first, offered to
    the colleague (never the speaker), and nothing moves."""
    frame = _frame(text, "hazel")
    assert not frame.tasks
    assert frame.question is not None and "Jonno" in frame.question


@pytest.mark.parametrize(
    "text",
    [
        "the insurance form for Biscuit needs stamping please",
        "can you get the insurance form for Biscuit stamped",
        "stamp my insurance form for Biscuit please",
    ],
)
def test_a_name_after_a_personal_paper_and_for_is_what_it_is_about(text: str) -> None:
    """7: "for Biscuit" after the form names the patient it is about, nobody in the office:
    the requester's form is stamped and comes back to her."""
    assert _tasks(text, "hazel") == [("seal", "form", "hazel", "hazel")]


@pytest.mark.parametrize(
    ("text", "unknown"),
    [
        ("bring a thermometer for Biscuit", "Biscuit"),  # an ordinary thing: for someone
        ("stamp my form for Biscuit and give it to Bob", "Bob"),  # a recipient named
    ],
)
def test_an_unknown_recipient_is_still_asked_about(text: str, unknown: str) -> None:
    """7, near-miss: a thing for an unknown name, or handed to one, is asked about first."""
    frame = _frame(text, "hazel")
    assert not frame.tasks
    assert frame.question is not None and repr(unknown) in frame.question


def test_a_name_of_the_office_after_a_paper_is_still_its_recipient() -> None:
    """7, near-miss: "the insurance form for Frank" gives the stamped form to Frank."""
    assert _tasks("the insurance form for Frank needs stamping please", "hazel") == [
        ("seal", "form", "hazel", "frank")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "the holly wreath on the reception desk is shedding everywhere lol",
        "the wreath on the reception desk by the window is shedding everywhere",
        "fyi the gel doc is down, UV bulb's gone. told Hazel already",
    ],
)
def test_a_statement_with_a_long_subject_moves_nothing(text: str) -> None:
    """8: a statement whose subject carries where its thing is ("on the reception desk") is
    words, answered and noted, not an unclear request; "holly" names a plant, not Holly."""
    frame = _frame(text, "hazel")
    assert not frame.tasks and frame.question is None and frame.decline is not None


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "the gloves in the stores room by the door please bring me some",
            [("transfer", "gloves", None, "hazel")],
        ),
        (
            "Holly's thermometer on the desk by the window, bring it to me please",
            [("transfer", "thermometer", "holly", "hazel")],
        ),
    ],
)
def test_a_request_with_a_long_subject_is_still_done(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    """8, near-miss: an errand's verb or "please" after the long subject still asks."""
    assert _tasks(text, "hazel") == expected
