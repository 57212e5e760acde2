"""A remark that a colleague could use a thing, put with a hedge ("Wang would probably like a
coffee", "Zhang could really use some water I think") or tentatively ("Wang might want a
coffee"), is that colleague's want (``reading.named_want``, ``want_hedges``,
``tentative_wants``): restated and asked before anything moves, never the speaker's want (a
coffee made for the speaker, as "would probably like" was read) nor "Noted". With request
wording, or said by the speaker of themselves, it is read as before."""

from __future__ import annotations

import pytest
from _offices import parser


@pytest.mark.parametrize(
    ("name", "who", "text", "whom"),
    [
        # the class's analogues
        ("default", "wu", "Jun could do with a coffee I reckon", "Mao Jun"),
        ("default", "wu", "Zhang could use some water I think", "Zhang Wei"),
        ("default", "wu", "Wang would probably like a coffee", "Wang Fang"),
        # other hedges, other verbs, other offices
        ("default", "wu", "Wang might want a coffee", "Wang Fang"),
        ("default", "wu", "Zhang could probably use some water", "Zhang Wei"),
        ("default", "lin", "Zhang could really use some water I think", "Zhang Wei"),
        ("harbour", "will", "Rose would probably like a tea", "Rose Adeyemi"),
        ("harbour", "will", "Mark may want a tea", "Mark Lindqvist"),
    ],
)
def test_a_hedged_remark_about_a_colleague_is_asked(
    name: str, who: str, text: str, whom: str
) -> None:
    frame = parser(name).parse(text, who)
    assert not frame.tasks and frame.question is not None, frame
    assert frame.question.startswith("Shall I") and whom in frame.question, frame


@pytest.mark.parametrize(
    ("name", "who", "text", "recipient"),
    [
        # must not change: with request wording the colleague receives at once
        ("default", "wu", "Wang could do with a coffee, can you bring him one?", "wang"),
        ("default", "wu", "get Jun a coffee, he could do with one", "mao"),
        # must not change: the speaker's own want, hedged or not, is fetched for the speaker
        ("default", "wu", "I could do with a coffee", "wu"),
        ("default", "wu", "I would probably like a coffee", "wu"),
    ],
)
def test_a_request_or_the_speakers_want_acts(
    name: str, who: str, text: str, recipient: str
) -> None:
    frame = parser(name).parse(text, who)
    assert frame.tasks and frame.question is None, frame
    assert all(t.recipient in (recipient, None) for t in frame.tasks), frame
    assert any(t.recipient == recipient for t in frame.tasks) or recipient == who, frame


def test_a_tentative_want_of_work_is_read_as_before() -> None:
    # "Wang might want to know": nothing wanted after the verb, no coffee nor question of one
    frame = parser("default").parse("Wang might want to know", "wu")
    assert not frame.tasks, frame
