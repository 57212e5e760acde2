"""Reading survey replies in the shapes people write them."""

from __future__ import annotations

import pytest

from assistantx.feedback.answers import (
    is_keyboard_mash,
    looks_like_request,
    parse_reply,
    says_something,
)


@pytest.mark.parametrize(
    ("text", "numbered", "ordered"),
    [
        ("1. yes 2. no 3 unsure 4 yes", {1: "yes", 2: "no", 3: "unsure", 4: "yes"}, ()),
        ("1) Yes, 2: NO; 3 - not sure, 4=yes", {1: "yes", 2: "no", 3: "unsure", 4: "yes"}, ()),
        ("q3 no", {3: "no"}, ()),
        ("4yes 1no", {4: "yes", 1: "no"}, ()),
        ("yes yes no yes", {}, ("yes", "yes", "no", "yes")),
        ("y/n/?/y", {}, ("yes", "no", "unsure", "yes")),
        ("yyn?", {}, ("yes", "yes", "no", "unsure")),
        ("👍 👎 🤷 👍", {}, ("yes", "no", "unsure", "yes")),
        ("I think yes, not really, don't know, yep", {}, ("yes", "no", "unsure", "yes")),
        ("n/a", {}, ("unsure",)),
        ("Nope", {}, ("no",)),
    ],
)
def test_answers_in_many_shapes(
    text: str, numbered: dict[int, str], ordered: tuple[str, ...]
) -> None:
    parsed = parse_reply(text)
    assert parsed.numbered == numbered
    assert parsed.ordered == ordered
    assert parsed.comment is None
    assert parsed.unclear == ()


@pytest.mark.parametrize("text", ["all yes", "yes to all", "All: YES", "everything yes"])
def test_one_answer_for_all(text: str) -> None:
    parsed = parse_reply(text)
    assert parsed.to_all == "yes"
    assert parsed.ordered == ()


def test_all_with_an_exception() -> None:
    parsed = parse_reply("all yes except 2 no")
    assert parsed.to_all == "yes"
    assert parsed.numbered == {2: "no"}


@pytest.mark.parametrize(
    ("text", "ordered", "comment"),
    [
        ("yes yes no yes - it was quick", ("yes", "yes", "no", "yes"), "it was quick"),
        ("Yes, all fine", ("yes",), "all fine"),
        ("yes yes no yes, took 2 minutes", ("yes", "yes", "no", "yes"), "took 2 minutes"),
        ("comment: The robot was Slow", (), "The robot was Slow"),
        ("yes no\n5. Great robot", ("yes", "no"), "Great robot"),
    ],
)
def test_comments_keep_their_words(text: str, ordered: tuple[str, ...], comment: str) -> None:
    parsed = parse_reply(text)
    assert parsed.ordered == ordered
    assert parsed.comment == comment
    assert parsed.to_all is None


def test_trailing_thanks_is_not_a_comment() -> None:
    parsed = parse_reply("yes yes no yes, thanks!")
    assert parsed.ordered == ("yes", "yes", "no", "yes")
    assert parsed.comment is None


def test_words_between_answers_are_kept_as_unclear() -> None:
    parsed = parse_reply("1 yes 2 banana 3 no")
    assert parsed.numbered == {1: "yes", 3: "no"}
    assert parsed.unclear == ("banana",)


@pytest.mark.parametrize("text", ["banana", "asdf qwer", "42", "", "   ", "!!!"])
def test_nonsense_is_empty(text: str) -> None:
    assert parse_reply(text).is_empty


@pytest.mark.parametrize(
    "text", ["stop surveys", "Stop", "no more surveys please", "unsubscribe", "opt out", "STOP."]
)
def test_opt_out(text: str) -> None:
    parsed = parse_reply(text)
    assert parsed.opt_out and not parsed.has_answers


def test_opt_in_and_skip() -> None:
    assert parse_reply("start surveys again").opt_in
    assert parse_reply("skip").skip
    assert parse_reply("No thanks").skip
    assert not parse_reply("no").skip


@pytest.mark.parametrize(
    ("text", "is_request"),
    [
        ("Could you bring me a stapler?", True),
        ("please print my file", True),
        ("hey, can you ask Zhang for the document", True),
        ("bring me coffee", True),
        ("The robot was late but it worked", False),
        ("yes yes no yes", False),
        ("not really", False),
    ],
)
def test_requests_are_told_apart(text: str, is_request: bool) -> None:
    assert looks_like_request(text) is is_request


def test_keyboard_mash_and_words() -> None:
    for mash in ("asdf", "qwerty", "lkj", "asdfasdf", "sdfsdf", "aaaa", "MNBV"):
        assert is_keyboard_mash(mash), mash
    for word in ("quite", "type", "ok", "slow", "flask", "robot", "were"):
        assert not is_keyboard_mash(word), word
    assert not says_something("asdf qwerty")
    assert not says_something("👍 !!")
    assert says_something("too slow") and says_something("asdf, too slow")
