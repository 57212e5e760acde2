"""A reason clause that names other items or facilities, said without its "I" (blind round 17's
class, on a school office no sentence was written for, ``helpers.playschool``, here with coffee
from the urn and a dye vat): "bring me some wipes, just knocked coffee all over my keyboard",
"Bring me my lunch from the green room fridge please, can't leave the vat." ask for the wipes
and the lunch only; on main the first offered "an ordinary coffee instead" of "a knocked
coffee" and the second declined dyeing a lunch. An unhelpful answer to such an offer keeps it
open, never drops the request as a no. "can't you ...", "just bring ...", "just put ..." are
still requests."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.dropped_subject import subject_restored
from helpers.playschool import playschool_with_vat
from helpers.reading import answered_reader, frame_reader

_frame = frame_reader(playschool_with_vat, "ada")
_answered = answered_reader(playschool_with_vat, "ada")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("bring me some wipes, just knocked coffee all over my keyboard", "wipes", None),
        ("just spilt coffee everywhere, wipes please", "wipes", None),
        ("can someone bring me wipes? cant leave the vat", "wipes", None),
        (
            "Bring me my lunch from the green room fridge please, can't leave the vat.",
            "lunch",
            "ada",
        ),
        ("been at the vat since 8, could you bring me my lunch from the fridge", "lunch", "ada"),
        ("can't find my stapler, bring me Rory's", "stapler", "rory"),
    ],
)
def test_only_the_requests_item_is_fetched(text: str, item: str, owner: str | None) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, "ada")
    ]


@pytest.mark.parametrize(
    ("text", "kept"),
    [
        ("can't you bring me my lunch", True),
        ("bring me wipes, just put them on my desk", True),
        ("just bring me the wipes", True),
        ("can't leave the vat, bring me my lunch", False),
        ("bring me wipes. just knocked my coffee over", False),
    ],
)
def test_only_a_clause_without_its_i_gets_it_back(text: str, kept: bool) -> None:
    restored, evidence = subject_restored(text)
    assert (restored == text, evidence == []) == (kept, kept), restored


def test_a_request_to_dye_is_still_dyeing() -> None:
    frame = _frame("could you dye my costume at the vat")
    # the office's one operation on a thing brought to it is the "heat" kind's
    assert [(t.kind, t.item) for t in frame.tasks] == [("heat", "costume")], frame


def test_an_unhelpful_answer_to_an_instead_offer_keeps_it_open() -> None:
    text = "bring me a knocked coffee"
    first = _frame(text)
    assert first.question is not None and "instead" in first.question
    after = _answered(text, ["Sorry, I don't know more than I wrote."])
    assert after.decline is None and after.tasks == []
    assert after.question == first.question
    no = _answered(text, ["No, thanks."])
    assert no.tasks == [] and no.decline is not None
