"""Round 186's needs said by their cause (the round's own offices and sentences were never
read; ``helpers.safety_bench`` is the tests' own office):

- the speaker's own thing broken or dirty, then one borrowed: someone else's, never the
  speaker's own (class 1: on the tests' office the reader already read these; where the
  speaker owns one, the state said with "'s" and where it came from ("my cup's dirty from
  lunch", english ``state_tails``, ``cause_prepositions``) or a part of the thing told of ("my
  cup handle snapped", ``screen.statement``) failed);
- a need said by the work the speaker will do to a material the office lacks: the thing
  for that work (class 2, ``reading.material_work``);
- "a fresh pair" after the speaker's own gloves were named: another pair of those (class 3,
  ``screen.described_one``);
- a trailing clause of the speaker about to do a thing: the reason, no service run on the
  things asked; "a pair of gloves" is gloves (class 4, ``screen.own_doing``, english
  ``unit_nouns``);
- a need said by a body part or a complaint: the thing whose purpose fits, which where
  several do, what the office has where none does (class 5, ``reading.problem_remedy``)."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of, understood_tasks

from helpers.reading import frame_reader
from helpers.safety_bench import safety_bench

_bench = frame_reader(safety_bench, "lee")


def _tasks(text: str) -> list[tuple[str, str | None, str | None, str]]:
    frame = _bench(text)
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


# -- class 1: one borrowed for the speaker's own that is broken ------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "my stapler just jammed for good, can someone lend me theirs this afternoon",
        "my stapler is broken, can someone lend me one",
        "lost my stapler, can anyone lend me theirs",
    ],
)
def test_a_borrowed_one_for_a_broken_own_is_someone_elses(text: str) -> None:
    assert _tasks(text) == [("transfer", "stapler", None, "lee")]


@pytest.mark.parametrize(
    "text",
    [
        # what it broke during is no thing stated (round 207's default set: Liu Yang's
        # document was brought to Chen for "my stapler broke halfway thru the report, can i
        # borrow one")
        "my stapler broke halfway thru the report, can i borrow one",
        "my stapler broke during the report, can someone lend me one",
        "my stapler jammed halfway through the contract, can i borrow one",
    ],
)
def test_what_it_broke_during_is_no_thing_borrowed(text: str) -> None:
    assert understood_tasks("default", "chen", text) == [("transfer", "stapler", None, "chen")]


def test_a_dirty_own_mug_then_one_borrowed() -> None:
    text = "my cup is still dirty from lunch, could you borrow a mug for me"
    assert _tasks(text) == [("transfer", "mug", None, "lee")]


# Dang owns a cup in the default office: the borrowed one is still someone else's when the
# state is said with "'s" and where it came from, or of a part of the speaker's thing.
@pytest.mark.parametrize(
    "text",
    [
        "my cup's still filthy from the meeting, can you borrow a mug for me",
        "my cup's dirty from lunch, could someone lend me one",
        "my cup is dirty from the coffee, can someone lend me theirs",
        "my cup handle just snapped, can someone lend me theirs",
    ],
)
def test_one_borrowed_for_an_own_cup_out_of_use_is_anyones(text: str) -> None:
    assert understood_tasks("default", "dang", text) == [("transfer", "cup", None, "dang")]


def test_a_part_of_an_own_thing_told_then_one_borrowed() -> None:
    text = "my stapler spring just broke, can someone lend me theirs"
    assert understood_tasks("default", "dang", text) == [("transfer", "stapler", None, "dang")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # a colleague's thing described, not told of: still theirs
        ("bring me Zhang's dirty cup from the kitchenette", [("transfer", "cup", "zhang", "dang")]),
        # a part told of with nothing asked: noted
        ("my cup handle just snapped", []),
        # the request names its own thing: the told one is context
        ("my coffee break is at 3, bring me a pen", [("transfer", "pen", None, "dang")]),
    ],
)
def test_own_thing_told_neighbours(
    text: str, expected: list[tuple[str, str, str | None, str]]
) -> None:
    assert tasks_of("default", text, "dang") == expected


# -- class 2: the work on a material the office lacks ------------------------------------------
@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("need to cut some string for the parcel, got anything?", "scissors"),
        ("I need to cut some string for the parcel, can you help", "scissors"),
        ("need to staple some pages, got anything?", "stapler"),
        ("have to cut the ribbon, got anything?", "scissors"),
    ],
)
def test_work_on_a_material_asks_for_the_thing_for_the_work(text: str, item: str) -> None:
    assert understood_tasks("default", "lee", text) == [("transfer", item, None, "lee")]


def test_the_same_on_the_tests_office() -> None:
    text = "need to trim some twine before the next job, anything around?"
    assert _tasks(text) == [("transfer", "scissors", None, "lee")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # the material is the office's own paper: it may be what is asked
        (
            "need to cut some paper for the parcel, got anything?",
            [("transfer", "paper", None, "lee")],
        ),
        # the thing said beside the need is what is asked
        (
            "need to cut some string, can you bring me a stapler",
            [("transfer", "stapler", None, "lee")],
        ),
        # a service of the office is a service asked
        ("need to print the report, got anything?", [("print", "file", "lee", "lee")]),
    ],
)
def test_work_that_names_the_office_s_thing_or_service_is_as_said(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of("default", text, "lee") == expected


# -- class 3: a fresh pair of the thing just named ---------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "tore my gloves on the bench, need a fresh pair before the next job",
        "tore my gloves on the bench, need a new pair",
        "my gloves are torn, need a clean pair",
        # must not change: "another", "a new one", a pair named outright
        "my gloves are torn, can I have another",
        "tore my gloves on the bench, need a new one",
    ],
)
def test_a_fresh_pair_is_another_of_the_thing_named(text: str) -> None:
    assert _tasks(text) == [("transfer", "gloves", None, "lee")]


def test_a_new_pair_of_another_thing_is_that_thing() -> None:
    assert _tasks("my goggles cracked, need a new pair of gloves") == [
        ("transfer", "gloves", None, "lee")
    ]


# -- class 4: the speaker about to do a thing is the reason ----------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "can you bring me safety goggles and a pair of gloves, heading in to weigh",
        "can you bring me safety goggles and gloves, about to print",
        "bring me goggles and gloves, I'm heading in to weigh",
        "heading in to weigh, can you bring me goggles and gloves",
    ],
)
def test_the_speaker_about_to_do_a_thing_runs_no_service(text: str) -> None:
    assert _tasks(text) == [
        ("transfer", "goggles", None, "lee"),
        ("transfer", "gloves", None, "lee"),
    ]


@pytest.mark.parametrize("text", ["bring me a pair of gloves", "bring me two pairs of gloves"])
def test_a_pair_of_a_thing_is_the_thing(text: str) -> None:
    assert _tasks(text) == [("transfer", "gloves", None, "lee")]


def test_a_service_asked_on_a_thing_is_still_asked() -> None:
    # must not change: the sample's weighing is asked, not the speaker's own doing
    frame = _bench("can you weigh my sample, heading in to print")
    assert [(t.kind, t.item) for t in frame.tasks] == [("heat", "sample")], frame  # its shape


# -- class 5: a complaint's remedy --------------------------------------------------------------
def test_a_complaint_one_thing_fits_offers_that_thing() -> None:
    # a question: the one thing that fits is offered, never fetched unasked (fix189c)
    for text in ("got anything for my sore hands?", "got anything for my hands? they're raw"):
        frame = _bench(text)
        assert frame.tasks == [] and frame.question is not None, frame
        assert "hand cream" in frame.question and "Shall I bring you" in frame.question


def test_a_complaint_several_things_fit_asks_which() -> None:
    frame = _bench("got anything for my cut finger?")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "plasters" in frame.question and "grip tape" in frame.question
    assert "scissors" not in frame.question  # cutting is their work, no cut's remedy


@pytest.mark.parametrize(
    "text", ["anything for a headache?", "do you have anything for a blister?"]
)
def test_a_complaint_nothing_fits_says_what_the_office_has(text: str) -> None:
    frame = _bench(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "What I can do here" in frame.decline


def test_a_complaint_on_the_default_office_fits_nothing() -> None:
    # the default office's scissors cut: no remedy for a cut finger, never offered
    got = parser("default").parse("got anything for my cut finger?", "lee")
    assert got.tasks == [] and got.question is None and got.decline is not None, got


@pytest.mark.parametrize(
    "text",
    [
        "bring me something for the meeting",  # no complaint asked alone
        "have you got anything for cutting?",  # a purpose: the scissors
    ],
)
def test_no_complaint_is_read_on_as_before(text: str) -> None:
    frame = _bench(text)
    assert frame.decline is None, frame


def test_a_need_said_as_going_to_is_no_doing_of_the_speakers() -> None:
    # must not change: "going to need" is a need, never the speaker's doing
    frame = _bench("bring me the stapler, I'm going to need a pen too")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "stapler")], frame
