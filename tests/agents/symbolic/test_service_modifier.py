"""A service asked by its noun with a thing of the office before it ("my glove needs a virkon
dip", where the wash station keeps virkon): the thing says how the work is done, the service is
asked on the speaker's thing and it comes back to them; never "what should I do with the
disinfectant?" (reading/service_modifier.py). The bare service noun, an unknown word before it,
the thing asked for alone and the owner's thing fetched are read as before."""

from __future__ import annotations

import pytest
from _mews_office import mews_office

from helpers.reading import frame_reader

_ava = frame_reader(mews_office, "ava")


@pytest.mark.parametrize(
    "text",
    [
        "my glove needs a virkon dip, it's been on the owl. bring it back after pls",
        "my glove needs a virkon dip",
        "my fist needs a virkon dip please",
        # neighbours: the bare service noun, and a describing word nothing of the office
        "my glove needs a dip",
        "my glove needs a quick dip, bring it back after",
        "my glove needs a brolex dip. bring it back after pls",
    ],
)
def test_service_noun_with_a_word_before_it_is_the_service(text: str) -> None:
    frame = _ava(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.operation or "disinfect", t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("disinfect", "glove", "ava", "ava")
    ], frame
    assert frame.tasks[0].kind != "transfer", frame


@pytest.mark.parametrize(
    ("text", "item"),
    [("bring me the virkon", "disinfectant"), ("can I have some virkon please", "disinfectant")],
)
def test_the_thing_asked_alone_is_still_fetched(text: str, item: str) -> None:
    frame = _ava(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "ava")]


def test_two_things_joined_are_not_one_service() -> None:
    frame = _ava("my glove needs a virkon and a dip")
    assert not any(t.item == "glove" and t.kind == "transfer" for t in frame.tasks), frame
