"""Two requests joined by "+" or "&" as by "and" (``joining_signs``). Before, "copy my
document & bring me a water" asked "what you want me to do with the water" and did neither
part; now both are read, as with "and". "print my file + a coffee pls" is read as "print my
file and a coffee pls" is: the coffee with no verb of its own and no "too" may be a second
request or not, so the whole is restated and asked first ("Shall I print your file for you
and get coffee for you?", ``frames._made_beside(unsaid=True)``); a yes does both, a no
nothing. Before, only "what you want me to do with the coffee" was asked, a question the
requester could not answer, and nothing was done. With "too" both parts are read at once."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.joining_signs import signs_as_and
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import answered_reader, frame_reader

_DEFAULT = frame_reader(default_office, "wang")
_HARBOUR = frame_reader(harbour_office, "may")
_DEFAULT_ANSWERED = answered_reader(default_office, "wang")
_HARBOUR_ANSWERED = answered_reader(harbour_office, "may")


def _parts(frame) -> list[tuple[str, str, str | None]]:  # type: ignore[no-untyped-def]
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "parts"),
    [
        ("print my file + a coffee too pls", [("print", "file"), ("produce", "coffee")]),
        ("copy my document & bring me a water", [("copy", "document"), ("produce", "water")]),
        ("print my file & get me a coffee", [("print", "file"), ("produce", "coffee")]),
        # fix129e: wang has no lunch in the fridge (asked where it is, test_own_item_unknown.py)
        ("copy my document + bring me a coffee pls", [("copy", "document"), ("produce", "coffee")]),
        ("bring me the stapler & a coffee", [("transfer", "stapler"), ("produce", "coffee")]),
    ],
)
def test_default_both_parts_are_read(text: str, parts: list[tuple[str, str]]) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None and frame.decline is None, frame
    assert _parts(frame) == [(k, i, "wang") for k, i in parts]


@pytest.mark.parametrize(
    ("text", "parts"),
    [
        ("print my file + a tea as well pls", [("print", "file"), ("produce", "tea")]),
        ("scan my contract & bring me a ruler", [("copy", "document"), ("transfer", "ruler")]),
    ],
)
def test_harbour_both_parts_are_read(text: str, parts: list[tuple[str, str]]) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None and frame.decline is None, frame
    assert _parts(frame) == [(k, i, "may") for k, i in parts]


@pytest.mark.parametrize("sign", ["+", "&", "and"])
def test_a_made_thing_with_no_verb_is_restated_with_both_parts(sign: str) -> None:
    """The same question whichever joins: nothing moves before both parts are confirmed."""
    text = f"print my file {sign} a coffee pls"
    frame = _DEFAULT(text)
    assert not frame.tasks and frame.question is not None, frame
    assert frame.question.startswith("Shall I print your file")
    assert "coffee" in frame.question
    yes = _DEFAULT_ANSWERED(text, ["yes"])
    assert _parts(yes) == [("print", "file", "wang"), ("produce", "coffee", "wang")]
    no = _DEFAULT_ANSWERED(text, ["no"])
    assert not no.tasks


def test_harbour_a_tea_after_a_print_is_restated_with_both_parts() -> None:
    frame = _HARBOUR("print my file + a tea pls")
    assert frame.question is not None and "print your file" in frame.question
    assert "tea" in frame.question
    yes = _HARBOUR_ANSWERED("print my file + a tea pls", ["yes"])
    assert _parts(yes) == [("print", "file", "may"), ("produce", "tea", "may")]


def test_the_other_part_keeps_its_own_recipient() -> None:
    frame = _DEFAULT("get Zhang a coffee + print my file")
    assert _parts(frame) == [("produce", "coffee", "zhang"), ("print", "file", "wang")]


@pytest.mark.parametrize("name", ["R&D", "Q&A", "C++", "M&S"])
def test_a_sign_inside_a_name_is_left_alone(name: str) -> None:
    """Neighbour: written with no space, the sign is part of a name, never "and"."""
    assert signs_as_and(f"take my document to {name} please") == (
        f"take my document to {name} please"
    )


def test_a_spaced_sign_is_and() -> None:
    assert signs_as_and("print my file + a coffee") == "print my file and a coffee"
    assert signs_as_and("copy it &bring me a water") == "copy it and bring me a water"


@pytest.mark.parametrize(
    "text",
    [
        "fax my document to Harlow & Sons Ltd, thanks!",
        "send my contract to Hartwell & Co by courier please",
        "could you fax my contract to +44 20 7946 0000 please",
    ],
)
def test_a_name_or_a_number_keeps_its_sign(text: str) -> None:
    """Neighbours: "&" between capitalised words is a firm's name; "+" before digits a phone
    number."""
    assert signs_as_and(text) == text


def test_chats_n_between_words_is_and() -> None:
    assert signs_as_and("print my report n bring me a coffee") == (
        "print my report and bring me a coffee"
    )
    assert signs_as_and("scan my form n send the pdf to Grace") == (
        "scan my form and send the pdf to Grace"
    )


@pytest.mark.parametrize(
    "text",
    ["take my document to room N please", "play some rock 'n' roll", "desk 4 n 5", "n"],
)
def test_an_n_that_is_no_chat_and_is_left_alone(text: str) -> None:
    """Neighbours: a capital N (an initial, a room), "'n'" in a set phrase, an "n" after a
    number, a lone "n"."""
    assert signs_as_and(text) == text


def test_chats_n_joins_two_requests() -> None:
    """ "print my file n get Zhang a coffee": both parts, as with "and" (main asked what to do
    with the coffee)."""
    frame = _DEFAULT("print my file n get Zhang a coffee")
    assert _parts(frame) == [("print", "file", "wang"), ("produce", "coffee", "zhang")]
