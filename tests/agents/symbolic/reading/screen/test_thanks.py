"""Thanks: answered; thanks to pass on is the requester's to give."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.thanks import thanks
from reading.screen._judge import Judge


def test_thanks_are_welcomed(judged: Judge) -> None:
    found = judged(thanks, "thanks for the pen!", "lee")
    assert found is not None and found.message == "You're welcome!"


def test_thanks_to_pass_on_name_who_to_tell(judged: Judge) -> None:
    found = judged(thanks, "say thanks to Wang for the pen", "lee")
    assert found is not None
    assert found.message.endswith("so please tell Wang Fang yourself.")


def test_a_request_is_no_thanks(judged: Judge) -> None:
    assert judged(thanks, "bring me a pen", "lee") is None
