"""Where someone has been, told beside a request to deliver to them, is no absence
(``screen.been_through``): "Zhang's been out in the rain all morning, bring him a coffee" was
read as "a fact: Zhang Wei is away" and the coffee ended unachievable, "known to be away". A
state in the perfect or the past of the one delivered to drops the absence (whether they can
receive is asked, as for anyone). An absence in the present stays one ("Zhang is out today,
so take it to Wang instead", "Dara is away, take her some batteries"), and so does a past one
of someone the message does not deliver to."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import SendQR
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "wang")
_harbour = frame_reader(harbour_office, "may")


def _read(office: str, text: str) -> TaskFrame:
    frame = (_default if office == "default" else _harbour)(text)
    assert frame.question is None and frame.decline is None, frame
    return frame


@pytest.mark.parametrize(
    ("office", "text", "task"),
    [
        # the class's analogues
        (
            "default",
            "Zhang's been out in the rain all morning, bring him a coffee",
            ("produce", "coffee", "zhang"),
        ),
        (
            "harbour",
            "Grace has been out on site all day, take her a ruler when she's back",
            ("transfer", "ruler", "grace"),
        ),
        # variants with other words, tenses and offices
        (
            "harbour",
            "Rose's been out in the cold all afternoon, could you bring her a tea",
            ("produce", "tea", "rose"),
        ),
        (
            "default",
            "Lin was out at the dentist this morning, take her my stapler",
            ("transfer", "stapler", "lin"),
        ),
        (
            "default",
            "Chen has been away at a client's all week. Please get him a coffee",
            ("produce", "coffee", "chen"),
        ),
    ],
)
def test_where_the_recipient_has_been_is_no_absence(
    office: str, text: str, task: tuple[str, str, str]
) -> None:
    frame = _read(office, text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [task], frame
    assert task[2] not in frame.away(), frame
    # the reading a user sees says so too
    assert not any(e.meaning.endswith("is away") for e in frame.evidence), frame.evidence


@pytest.mark.parametrize(
    ("office", "text", "away", "recipient"),
    [
        # the class's neighbours: an absence said to send the thing elsewhere
        ("default", "Zhang is out today, so take my stapler to Lin instead", "zhang", "lin"),
        ("harbour", "Mark's off sick, give the ruler to Grace", "mark", "grace"),
        # a past state of someone the message does not deliver to is still their absence
        ("default", "Zhang has been off sick all week, give the stapler to Lin", "zhang", "lin"),
        ("harbour", "Will has been away all week, take my tape to Rose", "will", "rose"),
    ],
)
def test_an_absence_of_someone_else_still_holds(
    office: str, text: str, away: str, recipient: str
) -> None:
    frame = _read(office, text)
    assert [t.recipient for t in frame.tasks] == [recipient], frame
    assert frame.away() == {away}, frame


@pytest.mark.parametrize(
    ("office", "text", "away"),
    [
        # said in the present, of the one delivered to: still away (the speaker says so now)
        ("default", "Zhang is away, bring him a coffee", "zhang"),
        ("harbour", "Grace is off today, can you take her a ruler", "grace"),
    ],
)
def test_a_present_absence_of_the_recipient_still_holds(office: str, text: str, away: str) -> None:
    frame = _read(office, text)
    assert frame.away() == {away}, frame


@pytest.mark.parametrize(
    ("office", "requester", "text", "recipient"),
    [
        (
            "default",
            "wang",
            "Zhang's been out in the rain all morning, bring him a coffee",
            "zhang",
        ),
        (
            "harbour",
            "may",
            "Grace has been out on site all day, take her a ruler when she's back",
            "grace",
        ),
    ],
)
async def test_end_to_end_the_thing_reaches_them(
    office: str, requester: str, text: str, recipient: str
) -> None:
    # the reader drops the absence and the consent guard lets "her" receive ("has been" is
    # no having): the thing is handed over, not ended "known to be away"
    of = default_office() if office == "default" else harbour_office()
    run = await run_instruction(of, requester, text)
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    collected = [
        r.action
        for r in trace.actions()
        if isinstance(r.action, SendQR) and r.action.purpose == "collect" and not r.refused
    ]
    assert [a.contact for a in collected] == [recipient], trace.summary
