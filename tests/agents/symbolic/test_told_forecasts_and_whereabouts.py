"""A message that asks nothing is answered in words, never met with a service's question.

"gale warning's up for tomorrow, van run might be off" (an office whose courier service is
the "van run") and "where's Dewi? need to ask him about the van run" both ended "Which item do
you mean for me to ... van run?". A subject then "might"/"could" and a verb is a forecast
about the thing (``reading.modal_told``; no imperative has a modal after its verb), "X's up"
is "X is up" (``screen.contracted_is``), and after "where is <colleague>?" the speaker's need
to speak with them is why they ask (``screen.whereabouts_reason``): the question is answered
(where they sit) and the service named as the talk's topic is never asked for."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.request_screen import RequestScreen
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader, parser_for
from helpers.rigging_loft import rigging_loft

_loft = frame_reader(rigging_loft, "nia")
_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "jack")


def _asks_nothing(text: str, read: ReadFrame) -> None:
    frame = read(text)
    assert frame.question is None, frame.question
    assert frame.tasks == []


@pytest.mark.parametrize(
    "text",
    [
        "gale warning's up for tomorrow, van run might be off",
        "storm warning's up, van run could be cancelled",
        "van run might not go today",
        "splicing could take a while this week",
    ],
)
def test_a_forecast_asks_nothing_in_a_small_office(text: str) -> None:
    _asks_nothing(text, _loft)


@pytest.mark.parametrize(
    "text",
    [
        "rose prices are up again, franking might be pricey this month",
        "frank might be pricey this month",
        "storm warning's up, post might be late",
        "laminating could take a while today",
    ],
)
def test_a_forecast_asks_nothing_on_harbour(text: str) -> None:
    _asks_nothing(text, _harbour)


@pytest.mark.parametrize(
    "text",
    ["print might be slow today, the coffee could run out too", "the copier might be off later"],
)
def test_a_forecast_asks_nothing_on_the_default_office(text: str) -> None:
    _asks_nothing(text, _default)


@pytest.mark.parametrize(
    ("read", "text"),
    [
        (_loft, "where's Dewi? need to ask him about the van run"),
        (_loft, "where is Gale? need a quick word about the splicing"),
        (_harbour, "where's Mark? need a word about the franking"),
        (_harbour, "where's May? gotta talk to her about the laminator"),
        (_default, "where is Lee? I need to ask him about the printer"),
        (_default, "where's Zhang? want a chat with him about the coffee"),
    ],
)
def test_why_a_colleagues_whereabouts_are_asked_asks_nothing(read: ReadFrame, text: str) -> None:
    _asks_nothing(text, read)


def _verdicts(text: str, requester: str) -> list[str]:
    """What the harbour screen makes of each piece of ``text``."""
    screen = next(
        v for v in vars(parser_for(harbour_office)).values() if isinstance(v, RequestScreen)
    )
    return [f.verdict for f in screen.verdicts(text, requester).findings]


def test_the_whereabouts_question_is_answered_and_its_reason_is_context() -> None:
    assert _verdicts("where's Mark? need a word about the franking", "jack") == [
        "question",
        "statement",
    ]


def test_a_request_with_a_modal_after_you_still_asks() -> None:
    """Neighbour: "you could bring me a stapler" asks; "you" is no thing told of."""
    frame = _default("you could bring me a stapler")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "stapler")]


def test_a_request_beside_a_forecast_is_still_read() -> None:
    """Neighbour: the forecast is context, the request after it is asked."""
    frame = _default("the printer might be slow, print my file please")
    assert [(t.kind, t.item) for t in frame.tasks] == [("print", "file")]


def test_a_service_asked_for_is_still_a_request() -> None:
    """Neighbour: "frank my letter please" asks for the franking (whom it goes to is asked)."""
    frame = _harbour("frank my letter please")
    assert frame.question is not None


def test_finding_a_colleague_to_hand_over_is_a_request() -> None:
    """Neighbour: "can you find May and give her my ruler" moves the ruler."""
    frame = frame_reader(harbour_office, "mark")("can you find May and give her my ruler")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "ruler", "may")]


def test_a_need_that_is_no_talk_is_read_as_before() -> None:
    """Neighbour: "where's Mark? need my stapler back" is a need of a thing, no reason told:
    only the question is read as one, the need is left to the request's stages."""
    assert _verdicts("where's Mark? need my ruler back", "jack") == ["question"]
