"""Blind rounds 20 to 22, class 1: an office item's name as the first noun of a compound
("my wine list file", "the new wine list") names the compound's head, never the item. On
sentences of our own against a kitchen no sentence was written for (the rounds' office and
sentences were never read). No bottle moves for a file or a list."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic.reading.compound_heads import compound_noun
from assistantx.agents.symbolic.reading.tokens import tokenize
from helpers.airside_kitchen import airside_kitchen
from helpers.reading import frame_reader

_frame = frame_reader(airside_kitchen, "odile")

Row = tuple[str, str | None, str | None, str]


def _tasks(text: str, who: str = "odile") -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in _frame(text, who).tasks]


_FILE_TO_TOBIN = ("send_file", "doc_file", "odile", "tobin")


@pytest.mark.parametrize(
    "text",
    [
        "Send my wine list file to Tobin please.",
        "send tobin my wine list file",
        "could you send my new wine list file over to Tobin",
        "Tobin wants the new wine list, can you send him my file?",
        "Tobin needs the wine list. send him my file please",
    ],
)
def test_a_compound_whose_head_is_the_file_sends_the_file(text: str) -> None:
    """ "wine list file" is a file: only the file goes, no wine."""
    assert _tasks(text) == [_FILE_TO_TOBIN]


@pytest.mark.parametrize(
    "text",
    [
        "bring me the wine list",
        "send my wine list to Tobin",
        "can you grab Tobin the wine menu",
    ],
)
def test_a_compound_whose_head_the_office_lacks_moves_no_wine(text: str) -> None:
    """ "the wine list" is a list the office does not have: asked or declined, no wine."""
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.question is not None or frame.decline is not None


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("bring me my wine", [("transfer", "wine", "odile", "odile")]),
        ("can you bring my wine today", [("transfer", "wine", "odile", "odile")]),
        ("bring Bastian's wine to Tobin please", [("transfer", "wine", "bastian", "tobin")]),
        ("bring Tobin a bottle of wine", [("transfer", "wine", None, "tobin")]),
        ("bring me my wine, list the rest later", [("transfer", "wine", "odile", "odile")]),
        ("send my file to Tobin", [_FILE_TO_TOBIN]),
    ],
)
def test_the_item_named_as_the_head_is_still_the_item(text: str, expected: list[Row]) -> None:
    """Near-miss: the item's name at the end of its phrase, before an adverb, a pause or a
    name, is still the item."""
    assert _tasks(text) == expected


@pytest.mark.parametrize(
    "text",
    ["thanks for the wine list", "is the wine list ready?", "don't send the wine list file"],
)
def test_thanks_a_question_or_a_negation_moves_nothing(text: str) -> None:
    assert _tasks(text) == []


@pytest.mark.parametrize(
    ("said", "noun"),
    [
        ("list", True),
        ("menu", True),
        ("today", False),  # an adverb too: when
        ("home", False),  # an adjective and adverb too: where
        ("real", False),  # "a pen real quick"
        ("works", False),  # a finite verb: "my stapler works"
        ("pair", False),  # a unit measures the item before it
        ("cause", False),  # opens a reason clause
        ("List", False),  # written as a name or a sentence's start
        ("won't", False),  # a contraction
    ],
)
def test_compound_noun_is_a_plain_noun_nothing_else_reads(said: str, noun: bool) -> None:
    [token] = tokenize(said)
    assert compound_noun(token, lambda word: word == "file") is noun


async def test_no_bottle_is_handed_over_for_the_wine_list_file() -> None:
    run = await run_instruction(
        airside_kitchen(), "odile", "Send my wine list file to Tobin please."
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert "forward_file" in run.actions, run.actions
    # nothing is carried: no code for a locker, no trip (main fetched a bottle of wine)
    assert not {"send_qr", "move"} & set(run.actions), run.actions
