"""A colleague who wants the requester's own thing, then "it" handed on, names that colleague
as its recipient (fix135c, class 3): "wang wants my report, can u send it over" was read as
forwarding the requester's file to Wang, and the consent guard then refused Wang as someone
not named to receive it. The guard reads the wish for the requester's own thing, followed by
"it"/"them" handed on with no receiver of its own, as naming the one who wished
(runtime/wanted_own.py). A wish about another's thing, or "it" wanted somewhere, names no one."""

from __future__ import annotations

import pytest

from assistantx.runtime.recipients import named_recipients
from assistantx.runtime.wanted_own import handed_on, wants_own_thing
from helpers.consent_memory import memory
from helpers.dataset_offices import default_office, harbour_office


@pytest.mark.parametrize(
    ("text", "named"),
    [
        ("wang wants my report, can u send it over", {"wang"}),
        ("Zhang needs my file, can you forward it", {"zhang"}),
        ("zhang wants my document, can you take it over", {"zhang"}),
        ("Wang needs my stapler. could you bring it", {"wang"}),
    ],
)
def test_the_one_who_wants_my_thing_receives_it(text: str, named: set[str]) -> None:
    assert named_recipients(default_office(), memory("lin", text)) == named


@pytest.mark.parametrize(
    ("text", "named"),
    [
        ("grace wants my ruler, can you take it over", {"grace"}),
        ("Hope needs my calculator, bring it", {"hope"}),
    ],
)
def test_the_same_in_another_office(text: str, named: set[str]) -> None:
    assert named_recipients(harbour_office(), memory("may", text)) == named


@pytest.mark.parametrize(
    "text",
    [
        "Wang wants Zhang's file, can you send it over",  # another's thing: its owner decides
        "Wang wants it on the board, can you send it over",  # no thing of mine wanted
        "Wang wants my file",  # nothing handed on
        "Wang wants my file and Zhang wants it too, forward it",  # two: nobody picked
    ],
)
def test_nobody_else_is_named(text: str) -> None:
    assert named_recipients(default_office(), memory("lin", text)) == set()


def test_a_receiver_said_after_it_is_the_one_named() -> None:
    assert named_recipients(
        default_office(), memory("lin", "Wang wants my file, send it to Zhang")
    ) == {"zhang"}


def test_the_words_of_the_rule() -> None:
    assert wants_own_thing(["wang", "wants", "my", "report"], 1)
    assert not wants_own_thing(["wang", "wants", "zhang", "file"], 1)
    assert handed_on(["forward", "it"], lambda w: w == "forward")
    assert not handed_on(["forward", "it", "to", "zhang"], lambda w: w == "forward")
