"""Fixer fix59c classes 2 and 3, on a small lab built here where "check" and "compare" are a
service of the office and "my results" is read as a guessed form.

Class 3: after a complete request that names one colleague to give to, what that colleague
will do ("She needs to check my results before the write-up", "he wants to compare my
readings") is why, never work asked of me nor a thing to ask about
(``screen.recipients_doing``). A second need ("He also needs my stapler") is a second request;
a request whose thing is only "it" is read as before.

Class 2: "their" said of the outsider who opens the sentence as the subject of a need ("a
visitor needs their pass signed off", "my patient needs their document copied") is the
outsider's thing in the speaker's hands: nobody is asked about by "their"
(``_parties._outsiders_in_hand``). "their" with nobody before it, a thing wanted back ("the
client wants their stapler back") and two colleagues' things are read as before."""

from __future__ import annotations

import pytest
from _offices import parser

from helpers import office_builder as ob
from helpers.reading import frame_reader

_PEOPLE = (
    ob.person("ines", "Ines Moreau", "lab_book", "binder", "draft"),
    ob.person("renee", "Renée Dubois", "lab_book", aliases=["Renée", "Renee"]),
    ob.person("omar", "Omar Said", "ruler", "stapler", aliases=["Omar"]),
    ob.person("kai", "Kai Lund", "ruler", aliases=["Kai"]),
)


def _raw() -> ob.Row:
    return ob.office_file(
        "reason lab",
        _PEOPLE,
        rooms=[ob.room("store", "Store room", 12.0, 20.0)],
        item_types=[
            ob.item("lab_book", "lab book", "personal"),
            ob.item("binder", "binder", "personal"),
            ob.item("draft", "draft", "personal"),
            ob.item("ruler", "ruler"),
            ob.item("stapler", "stapler"),
            ob.item("form", "form", "personal", signable=True),
            ob.item("copy", "copy", "product"),
        ],
        operations=[
            ob.operation("check", "check", "compare", input="form"),
            ob.operation("copy", "copy", input="form", product="copy"),
        ],
        facilities=[
            ob.facility(
                "copier", "copier", at="store", guards=["omar"], operations=["copy", "check"]
            )
        ],
        home="store",
    )


_lab = frame_reader(ob.parsed(_raw), "ines")


@pytest.mark.parametrize(
    ("text", "item", "to"),
    [
        (
            "Please take my lab book over to Renée. She needs to check my results before "
            "the write-up",
            "lab_book",
            "renee",
        ),
        ("Take my binder to Kai, he wants to compare my readings", "binder", "kai"),
        ("Take my binder to Kai. Kai wants to compare my readings", "binder", "kai"),
        ("Bring my draft to Omar. He has to look over my figures first", "draft", "omar"),
    ],
)
def test_what_the_colleague_will_do_is_why(text: str, item: str, to: str) -> None:
    frame = _lab(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, "ines", to)
    ]


def test_a_second_need_is_a_second_request() -> None:
    frame = _lab("Bring my draft to Omar. He also needs my stapler")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("draft", "omar"), ("stapler", "omar")]


def test_a_request_of_it_alone_is_read_as_before() -> None:
    frame = _lab("Take it to Kai. He wants to compare my readings")
    assert frame.tasks == [] and frame.question is not None, frame


@pytest.mark.parametrize(
    "text",
    [
        "a visitor needs their document copied, it's on my desk",
        "my patient needs their document copied",
        "the client needs their document copied, it's the one in my tray",
    ],
)
def test_an_outsiders_their_is_in_the_speakers_hands(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.question is not None and "their" not in frame.question, frame
    confirmed = parser("default").parse(text, "lee", confirmed=True)
    tasks = [(t.kind, t.item, t.owner, t.recipient) for t in confirmed.tasks]
    assert tasks == [("copy", "document", "lee", "lee")], confirmed


def test_an_outsiders_their_to_sign_asks_only_who_signs() -> None:
    frame = parser("default").parse("a visitor needs their document signed, it's on my desk", "lee")
    assert frame.question is not None and frame.question.startswith("Who should sign your"), frame


@pytest.mark.parametrize(
    "text",
    [
        "their document needs copying",
        "the client wants their stapler back",
        "the client wants his stapler back",
    ],
)
def test_their_with_no_outsiders_work_still_asks(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.question is not None and "mean by" in frame.question, frame


def test_two_colleagues_their_is_read_as_before() -> None:
    frame = _lab("Kai and Omar need their forms copied")
    assert frame.tasks == [] and frame.question is not None, frame
    assert frame.question.startswith("Should the form go to"), frame


def test_a_persons_work_on_the_thing_handed_is_read_as_before() -> None:
    frame = parser("default").parse("take my contract to Sun Li, she needs to stamp it", "mao")
    assert [t.kind for t in frame.tasks] == ["seal"], frame


def test_a_plan_on_a_thing_of_the_office_is_read_as_before() -> None:
    frame = _lab("Take my binder to Kai, he needs to sign my form")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "binder")], frame


@pytest.mark.parametrize(
    ("text", "task"),
    [
        # round 234: the fish's treatment sheet is the speaker's, not someone to ask about
        (
            "the new seedlings in the lab need their document copied, can you sort that",
            ("copy", "document", "lee", "lee"),
        ),
        (
            "the new tadpoles in the quarantine tank need their document copied pls",
            ("copy", "document", "lee", "lee"),
        ),
    ],
)
def test_things_or_creatures_their_is_in_the_speakers_hands(
    text: str, task: tuple[str, str, str, str]
) -> None:
    frame = parser("default").parse(text, "lee", confirmed=True)
    assert frame.question is None or "their" not in frame.question, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [task], frame


@pytest.mark.parametrize(
    "text",
    [
        "Mark and Grace need their document copied",  # colleagues: whose is asked
        "they need their document copied",  # a pronoun: nobody to take it from
    ],
)
def test_colleagues_or_pronouns_before_their_are_no_things(text: str) -> None:
    frame = parser("default").parse(text, "lee", confirmed=True)
    assert frame.tasks == [], frame
