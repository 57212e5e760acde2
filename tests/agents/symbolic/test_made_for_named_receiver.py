"""Whom the reader makes a thing for may collect it (fix139c, class 1): "Robin needs a copy
of my delivery note. oh and grab me a latte" was read right (a copy for Robin, a coffee for
the requester) but the consent guard refused Robin at the hand-over, as someone not named to
receive it. The guard's receivers now follow the reader's frame for things made at the
requester's request (``recipients.made_for``): the recipient of a copy, a printout or a
coffee whom the requester's own words name. A belonging still goes only to one named in a
receiving place, and one said to hold the thing is never its receiver."""

from __future__ import annotations

import pytest

from assistantx.core.actions import SendQR
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime import consent
from assistantx.runtime.recipients import made_for, named_receivers
from helpers.consent_memory import answered, memory
from helpers.dataset_offices import default_office, harbour_office


def _collect(office_name: str, requester: str, text: str, who: str, item: str) -> bool:
    office = default_office() if office_name == "default" else harbour_office()
    stm: ShortTermMemory = memory(requester, text)
    answered(stm, who)
    action = SendQR(contact=who, item=item, purpose="collect")
    return consent.check(office, stm, action) is None


@pytest.mark.parametrize(
    ("office", "requester", "text", "who", "item"),
    [
        # the class's analogues and variants with other words
        ("default", "lee", "Zhang needs a copy of my document. oh and grab me a coffee", "zhang",
         "copy:lee"),
        ("default", "lee", "Lin wants a printout of my document, can you sort it", "lin",
         "printout:lee"),
        ("default", "wang", "Zhou wants a copy of my document, can you sort it", "zhou",
         "copy:wang"),
        ("default", "wang", "Zhou needs a printout of my file. also grab me a water", "zhou",
         "printout:wang"),
        ("harbour", "may", "Grace wants a printout of my rota, can you sort it", "grace",
         "printout:may"),
    ],
)  # fmt: skip
def test_whom_the_thing_is_made_for_may_collect_it(
    office: str, requester: str, text: str, who: str, item: str
) -> None:
    assert _collect(office, requester, text, who, item), text


@pytest.mark.parametrize(
    ("office", "requester", "text", "who", "item"),
    [
        # the holder of a copy is where it comes from, never whom it goes to
        ("default", "lee", "Zhang has a copy of my file, can you bring it to me", "zhang",
         "copy:lee"),
        # a wish about where the thing goes names no receiver of it
        ("default", "lee", "print my document, Zhang wants it up on the board", "zhang",
         "printout:lee"),
        # harbour makes no copies: the frame hands over the report itself, a belonging,
        # which only a receiving place ("to Hope") names a receiver of
        ("harbour", "may", "Hope needs a copy of my report", "hope", "document:may"),
    ],
)  # fmt: skip
def test_must_not_change_no_one_else_collects(
    office: str, requester: str, text: str, who: str, item: str
) -> None:
    assert not _collect(office, requester, text, who, item), text


def test_the_frames_receiver_must_be_named_by_the_requester() -> None:
    office = default_office()
    said = "Zhang needs a copy of my document. oh and grab me a coffee"
    assert made_for(office, memory("lee", said)) == {"zhang"}
    # a coffee for the requester themselves adds nobody
    assert made_for(office, memory("lee", "get me a coffee")) == set()
    assert named_receivers(office, memory("lee", "get me a coffee")) == set()
