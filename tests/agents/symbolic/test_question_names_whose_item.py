"""A question that names whose an item is, then a request for "it"/"them": "does Wang still
have his stapler? could I borrow it", "Zhang has scissors right? can u bring them over". The
pronoun is the item the question named with its owner, so that colleague is asked and their
item comes, never anyone's. Three rules make it so: "his"/"her" before the item is the one
colleague named (said_owner.pronoun_owner), an adverb between the colleague and "have" is
passed over (said_owner.passed_over), a lower-case name word right after the "does"/"did"/
"has" opening a question is its subject (name_reading._question_subject), and a one-word
confirming tag ("right?", "yeah?") leaves a statement a statement (confirming_tag)."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "will")


def _read(office: str, text: str) -> TaskFrame:
    return (_harbour if office == "harbour" else _default)(text)


@pytest.mark.parametrize(
    ("office", "text", "item", "owner"),
    [
        # the class's analogues (default office, as Mao)
        (
            "default",
            "does wang still have his stapler? could i borrow it for the review",
            "stapler",
            "wang",
        ),
        (
            "default",
            "zhang has a stapler right? can u bring it over, meeting in 10",
            "stapler",
            "zhang",
        ),
        (
            "default",
            "lin has scissors right? can u bring them over, meeting in 10",
            "scissors",
            "lin",
        ),
        # variants: other owners, "her", an adverb, a tag word other than "right"
        (
            "default",
            "does hu still have her stapler? could i borrow it for the review",
            "stapler",
            "hu",
        ),
        ("default", "does gao still have a stapler? can you bring it over", "stapler", "gao"),
        ("default", "does lin still have his scissors? can you bring them", "scissors", "lin"),
        ("default", "gao has a stapler yeah? can you bring it to me", "stapler", "gao"),
        # harbour, lower-case name words that are also English words
        ("harbour", "does mark still have his ruler? could i borrow it", "ruler", "mark"),
        (
            "harbour",
            "does ken still have his charger? can u bring it over, standup in 5",
            "charger",
            "ken",
        ),
        (
            "harbour",
            "joy has a calculator right? can u bring it over, audit in 10",
            "calculator",
            "joy",
        ),
        ("harbour", "hope has an umbrella yeah? can you bring it to me", "umbrella", "hope"),
        ("harbour", "mark has a ruler right? can u bring it over", "ruler", "mark"),
        ("harbour", "has bill got a charger? can i borrow it", "charger", "bill"),
        (
            "harbour",
            "does Grace already have her highlighter? could i borrow it",
            "highlighter",
            "grace",
        ),
    ],
)
def test_the_pronoun_is_the_item_of_the_one_named(
    office: str, text: str, item: str, owner: str
) -> None:
    frame = _read(office, text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", item, owner)]


@pytest.mark.parametrize(
    ("office", "text", "item"),
    [
        ("default", "who has scissors? can u bring me some", "scissors"),
        ("harbour", "who has a ruler? can u bring me one", "ruler"),
    ],
)
def test_who_has_one_still_brings_anyones(office: str, text: str, item: str) -> None:
    frame = _read(office, text)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", item, None)]


@pytest.mark.parametrize(
    ("office", "text", "who"),
    [
        ("default", "does wang have a stapler?", "Wang Fang"),
        ("harbour", "does mark have a ruler?", "Mark Lindqvist has a ruler"),
    ],
)
def test_the_question_alone_is_answered_in_words(office: str, text: str, who: str) -> None:
    frame = _read(office, text)
    assert frame.tasks == []
    assert frame.question is not None and who in frame.question


@pytest.mark.parametrize(
    "text",
    [
        "is that right? bring me a ruler",  # a question opening with "is": no tag
        "the printer on the right? bring me a ruler",  # a direction, not a tag
    ],
)
def test_right_that_is_no_tag_names_nobody(text: str) -> None:
    frame = _harbour(text)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", "ruler", None)]


def test_a_negated_having_says_whose_it_is_not() -> None:
    # "never" is no adverb passed over: nothing says Hu's stapler is the one
    frame = _default("hu never has a stapler. can you bring me one")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "stapler")]
    assert frame.tasks[0].owner != "hu"
