"""Only a request moves the robot: thanks, praise for an errand done, a wish that an item
stays where it is, and a withdrawal are answered in words, on a clinic office none of whose
sentences the reader was built on; a request beside them still moves."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import InstructionParser


@pytest.mark.parametrize(
    ("text", "reply"),
    [
        ("thanks so much for the thermometer earlier, lifesaver", "welcome"),
        ("big thank you for the printout this morning", "welcome"),
        ("appreciate you bringing the thermometer", "welcome"),
        ("much appreciated, the form arrived", "welcome"),
        ("you're a star for fetching the clipboard", "welcome"),
        ("could you thank Rich for the clipboard", "tell Rich Adeyemi yourself"),
        ("leave May's ice pack in the fridge", "won't move"),
        ("disregard that, I've got one", "dropped"),
        ("disregard the clipboard, Hal lent me his", "dropped"),
    ],
)
def test_words_that_ask_for_nothing_move_nothing(
    clinic_parser: InstructionParser, text: str, reply: str
) -> None:
    frame = clinic_parser.parse(text, "ines")
    assert not frame.tasks and frame.question is None, (text, frame)
    assert reply in (frame.decline or ""), (text, frame.decline)


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I'd appreciate it if you could bring me a thermometer", "thermometer"),
        ("thank you for the clipboard, can you bring me a thermometer too?", "thermometer"),
        ("leave my form on Hal's desk", "document"),
        ("drop my clipboard off at Hal's desk", "clipboard"),
    ],
)
def test_a_request_beside_thanks_still_moves(
    clinic_parser: InstructionParser, text: str, item: str
) -> None:
    assert [t.item for t in clinic_parser.parse(text, "ines").tasks] == [item], text
