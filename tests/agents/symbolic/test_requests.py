"""Which direct messages are requests: explicit wording always; what the parser understands
unless the sender writes back about an instruction that has ended."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.requests import RequestRecognizer
from assistantx.core.office import Office

CASES = [
    # text, a request from anyone, a request from a colleague just contacted
    ("please bring me a stapler", True, True),
    ("Bring me a stapler", True, True),
    ("Hi, heat my lunch", True, True),
    ("Can you print my file?", True, True),
    ("I need a coffee", True, True),
    ("bring me his stapler", True, True),  # unclear, but a request: it asks who
    ("a stapler", True, False),
    # statements, not requests (issue 23: only a request moves the robot)
    ("Yes, I have a stapler. Happy to lend it.", False, False),
    ("I came to the robot, but: I don't have a stapler", False, False),
    ("I came to the robot, but: the locker is empty", False, False),
    ("ok thanks", False, False),
    ("Sure, I'll bring it", False, False),
    ("What's the weather?", False, False),
]


@pytest.mark.parametrize(("text", "anyone", "contacted"), CASES)
def test_requests_are_recognised(office: Office, text: str, anyone: bool, contacted: bool) -> None:
    recognise = RequestRecognizer(office)
    assert recognise(text, "lee", strict=False) is anyone
    assert recognise(text, "wang", strict=True) is contacted
