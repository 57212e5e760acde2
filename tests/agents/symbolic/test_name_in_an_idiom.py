"""A colleague's name word inside a fixed English phrase is the ordinary word (blind round
62's class; the round's own offices and sentences were never read): in an office with Miles,
Hope and Frank, "the stores are miles away", "hope so, thanks", "to be frank the printer is
useless" name nobody (``english.yaml``: ``name_idioms``, read by ``core.name_reading``). A
word that makes a person before the phrase ("tell Hope you're well"), a question after
someone ("is Miles away today?") or the name set off at a clause's start ("Miles away
today") keeps the colleague; so does every plain mention of them."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.tokens import tokenize
from assistantx.core.name_reading import in_idiom
from helpers.dispatch_room import dispatch_room
from helpers.reading import frame_reader, parser_for

_frame = frame_reader(dispatch_room, "lee")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("kit room is Miles off and im stuck, can u grab me some AAs", "battery", None),
        ("Hope you're well, can I have some tape", "tape", None),
        ("Hope you're well, could I borrow a stapler", "stapler", None),
        ("Frank with you, I need the stapler", "stapler", None),
        ("To be Frank, can you print my file", "file", "lee"),
        # read so already: the neighbours the phrase table must keep
        ("the stores are miles away, can you bring me the tape", "tape", None),
        ("he's still Miles away, can you bring me the tape", "tape", None),
        ("To be Frank the printer is useless, can you print my file", "file", "lee"),
        ("hope ur well, stapler pls", "stapler", None),
    ],
)
def test_the_idiom_names_nobody(text: str, item: str, owner: str | None) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [(item, owner, "lee")], frame
    assert frame.question is None, frame


@pytest.mark.parametrize("text", ["hope so", "Hope so, thanks", "Hope so!", "and hope so x"])
def test_hope_so_asks_nothing(text: str) -> None:
    frame = _frame(text)
    assert not frame.tasks and frame.question is None, frame


@pytest.mark.parametrize(
    ("text", "person"),
    [
        ("Miles away today, can you bring me his stapler", "miles"),
        ("is Miles away today?", "miles"),
        ("tell Hope you're well", "hope"),
        ("take this to Miles", "miles"),
        ("Miles needs the stapler", "miles"),
        ("Frank's stapler pls", "frank"),
        ("ask Hope for the key", "hope"),
        ("bring Miles a coffee", "miles"),
        ("Frank and Miles away today", "miles"),
        ("Hope needs the key", "hope"),
    ],
)
def test_the_colleague_outside_an_idiom_is_still_read(text: str, person: str) -> None:
    lexed = parser_for(dispatch_room).lex.read(text)
    assert any(m.kind == "person" and person in m.ids for m in lexed.mentions), lexed.mentions


@pytest.mark.parametrize(
    ("text", "at", "idiom"),
    [
        ("hope so thanks", 0, True),
        ("i grant you it is late", 1, True),
        ("the stores are miles away", 3, True),
        ("miles away today", 0, False),  # the start: Miles may be away
        ("tell hope youre well", 1, False),
        ("when is miles off", 2, False),
        ("the stores are miles, away", 3, False),  # a pause inside: no phrase
        ("take it to miles", 3, False),
    ],
)
def test_in_idiom_reads_the_phrase_around_the_word(text: str, at: int, idiom: bool) -> None:
    assert in_idiom(tokenize(text), at) is idiom
