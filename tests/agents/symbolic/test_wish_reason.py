"""A wish with its reason (class 79a-4): "don't let anyone borrow my stapler today, I need it"
asked "Who should get your stapler?" (the need read as a new one, of the speaker's own
stapler). After a wish that keeps the speaker's own thing from others, "I need it/them" is
why: answered in words with the wish, and nothing moves, as after a negated errand ("please
don't lend my scissors to anyone, I need them"). A need of another thing is a new need."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import OfficeOf, frame_reader

_READERS = {
    default_office: frame_reader(default_office, "mao"),
    harbour_office: frame_reader(harbour_office, "will"),
}


@pytest.mark.parametrize(
    ("office", "text", "thing"),
    [
        (default_office, "don't let anyone borrow my stapler today, I need it", "stapler"),
        # variants: other wishes, other things, a reason with "still ... for"
        (default_office, "nobody take my stapler, I need it", "stapler"),
        (default_office, "keep my scissors away from everyone, I need them", "scissors"),
        (
            default_office,
            "don't let anyone use my book this week, I still need it for the report",
            "book",
        ),
        (harbour_office, "don't let anyone borrow my calculator, I need it", "calculator"),
        (harbour_office, "nobody touch my ruler please, I need it", "ruler"),
    ],
)
def test_the_need_after_a_wish_about_ones_own_thing_is_its_reason(
    office: OfficeOf, text: str, thing: str
) -> None:
    frame = _READERS[office](text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and f"the {thing}" in frame.decline


def test_a_negated_errand_with_its_reason_is_unchanged() -> None:
    frame = _READERS[default_office]("please don't lend my scissors to anyone, I need them")
    assert frame.tasks == [] and frame.question is None
    assert frame.decline is not None and frame.decline.startswith("OK, I won't do that")


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("forget the scissors, I need a stapler", ("transfer", "stapler", "mao")),
        ("nobody take my stapler, I need a pen", ("transfer", "pen", "mao")),
    ],
)
def test_a_need_of_another_thing_is_a_new_need(text: str, task: tuple[str, str, str]) -> None:
    frame = _READERS[default_office](text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [task]


def test_a_need_after_a_wish_about_someone_elses_thing_is_not_a_reason() -> None:
    """ "nobody take Wang's stapler, I need it": not the speaker's own thing kept, so the need
    is read as before (never answered as the wish's reason)."""
    frame = _READERS[default_office]("nobody take Wang's stapler, I need it")
    assert frame.decline is None
