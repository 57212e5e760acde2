"""A verb of making that is only the office's services' that take nothing in ("pour" of the
water, "brew" of the tea) said on a thing of the speaker's that none of them makes: work
nothing here does, declined; never a transfer of the speaker's thing nor the service's
product made instead (``reading.screen.unknown_work``)."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "zhang")
_HARBOUR = frame_reader(harbour_office, "rose")


@pytest.mark.parametrize(
    "text",
    [
        "can you pour up my impressions in stone?",  # the class's analogue
        "can you pour my stapler?",
        "please pour up my data cable",
        "could you brew up my report?",
    ],
)
def test_default_the_speakers_thing_under_a_making_verb_is_declined(text: str) -> None:
    frame = _DEFAULT(text)
    assert frame.tasks == [], frame
    assert frame.decline is not None and "nothing in this office does that" in frame.decline


@pytest.mark.parametrize(
    "text",
    ["can you brew up my badge?", "could you brew my calculator in resin?"],
)
def test_harbour_the_speakers_thing_under_a_making_verb_is_declined(text: str) -> None:
    frame = _HARBOUR(text)
    assert frame.tasks == [], frame
    assert frame.decline is not None and "nothing in this office does that" in frame.decline


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("can you pour me a water?", "water"),  # must not change: the service's product
        ("pour my coffee please", "coffee"),  # a made thing, "pour" of making
    ],
)
def test_the_product_is_still_made(text: str, item: str) -> None:
    frame = _DEFAULT(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", item, "zhang")]


def test_harbour_the_product_is_still_made() -> None:
    frame = _HARBOUR("boil my tea please")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "tea", "rose")]


def test_a_services_own_verb_that_makes_nothing_is_left_alone() -> None:
    frame = _HARBOUR("frank my letter please")  # must not change: "frank" is no making verb
    assert frame.question is not None, frame


def test_a_service_with_an_input_declines_in_its_own_words() -> None:
    frame = _DEFAULT("can you heat up my stapler?")  # must not change
    assert frame.decline is not None and "only heat" in frame.decline, frame


def test_no_thing_of_the_office_after_my_is_the_drink_asked_as_before() -> None:
    """ "pour my usual please": no thing of the office follows "my", so nothing of the
    speaker's is worked on; declined as work nobody does, it told an office with a water
    dispenser that nothing here pours."""
    frame = _DEFAULT("pour my usual please")
    assert frame.decline is None or "nothing in this office does that" not in frame.decline


@pytest.mark.parametrize("text", ["can you pour up my ruler in resin?", "could you pour my ruler"])
def test_a_making_verb_no_service_of_the_office_has_is_declined_on_the_speakers_thing(
    text: str,
) -> None:
    """Harbour has no service that pours: "pour up my impressions in stone" in a blind round's
    dental lab (nothing pours there either) handed the speaker their own impressions."""
    frame = frame_reader(harbour_office, "mark")(text)
    assert frame.tasks == [], frame
    assert frame.decline is not None and "nothing in this office does that" in frame.decline


def test_must_not_change_a_general_making_verb_where_no_service_has_it() -> None:
    frame = frame_reader(harbour_office, "may")("make my file into a printout")
    assert [t.kind for t in frame.tasks] == ["print"], frame
