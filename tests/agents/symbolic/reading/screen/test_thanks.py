"""Thanks: answered; thanks to pass on is the requester's to give."""

from __future__ import annotations

from collections.abc import Callable

from assistantx.agents.symbolic.reading.screen.pieces import Message
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.screen.thanks import thanks

Read = Callable[[str], Message]


def test_thanks_are_welcomed(terms: Terms, message: Read) -> None:
    msg = message("thanks for the pen!")
    found = thanks(terms, msg, msg.pieces[0], "lee")
    assert found is not None and found.message == "You're welcome!"


def test_thanks_to_pass_on_name_who_to_tell(terms: Terms, message: Read) -> None:
    msg = message("say thanks to Wang for the pen")
    found = thanks(terms, msg, msg.pieces[0], "lee")
    assert found is not None
    assert found.message.endswith("so please tell Wang Fang yourself.")


def test_a_request_is_no_thanks(terms: Terms, message: Read) -> None:
    msg = message("bring me a pen")
    assert thanks(terms, msg, msg.pieces[0], "lee") is None
