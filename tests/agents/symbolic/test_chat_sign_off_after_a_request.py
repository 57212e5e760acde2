"""A chat sign-off after a request only closes it (round 61's class): "..., bring it back when
it's done ta" answered "You're welcome! I did nothing." (the "ta" within a short piece's first
words made it a thanks), and a word run into the request's last noun ("heat my lunch cheers")
was read as part of it and asked which item. The sign-offs (``chat_sign_offs``: ta, cheers,
thx, x, xx, lol, :) ...) at the very end of a request are taken off (reading/signed_off.py);
thanks alone, thanks before a request, a sign-off after a comma, and a colleague whose name is
one of those words read as before."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, default_office
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml

_DEFAULT = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "done"),
    [
        ("my lunch is cold, heat it ta", ("heat", "lunch", "lee")),
        ("my lunch is cold, heat it cheers", ("heat", "lunch", "lee")),
        ("my lunch is cold, heat it thx", ("heat", "lunch", "lee")),
        (
            "my lunch is cold, take it to the kitchenette and bring it back when it's done ta",
            ("heat", "lunch", "lee"),
        ),
        ("heat my lunch cheers", ("heat", "lunch", "lee")),
        ("heat my lunch ta v much", ("heat", "lunch", "lee")),
        ("my file is ready, print it ta", ("print", "file", "lee")),
        ("send my file to Wang x", ("send_file", "file", "wang")),
        ("send my file to wang xoxo", ("send_file", "file", "wang")),
        ("can you bring me a stapler xx", ("transfer", "stapler", "lee")),
        ("bring me a pen lol", ("transfer", "pen", "lee")),
        ("copy my contract ta v much", ("copy", "document", "lee")),
    ],
)
def test_the_sign_off_only_closes_the_request(text: str, done: tuple[str, str, str]) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [done], frame


@pytest.mark.parametrize("text", ["ta", "thanks", "ta x", "thank you x", "thanks, that's all"])
def test_thanks_alone_is_still_thanks(text: str) -> None:
    frame = _DEFAULT(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "welcome" in frame.decline, frame


@pytest.mark.parametrize(
    "text",
    [
        "thanks for the stapler, can you bring me a pen",
        "thanks for the stapler, can you bring me a pen x",
        "bring me a pen, ta",
    ],
)
def test_thanks_beside_a_request_leaves_the_request(text: str) -> None:
    frame = _DEFAULT(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "pen")], frame


@functools.cache
def _ta_office() -> Office:
    """The default office with Wang Fang also called "Ta"."""
    raw = raw_yaml(DEFAULT_FILE)
    wang = next(p for p in raw["people"] if p["id"] == "wang")
    wang["aliases"] = [*wang.get("aliases", []), "Ta"]
    return parse_office(raw)


def test_a_colleague_called_by_the_word_is_the_recipient() -> None:
    frame = frame_reader(_ta_office, "lee")("send my file to Ta")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("send_file", "wang")], frame
