"""Instructions end, simulated requesters answer the survey in assorted ways, and the usage
report counts exactly what they said (through the real Assistant, messenger and store)."""

from __future__ import annotations

import math
import threading
from pathlib import Path
from typing import Any

import pytest

import assistantx.feedback.surveyor as surveyor_module
from assistantx.core.actions import Inform, Inquire, Move, Stop, Wait
from assistantx.core.office import Office
from assistantx.feedback.impact import InstructionRecord, summarise
from assistantx.feedback.report import load_report, render_markdown
from assistantx.feedback.survey import SurveyState

from .scripted import Harness, harness

HOUR = 3600.0


def _desk_distance(office: Office, a: str, b: str) -> float:
    la, lb = office.location(office.person(a).location), office.location(office.person(b).location)
    return math.hypot(la.x - lb.x, la.y - lb.y)


async def _run_office_day(h: Harness) -> dict[str, str]:
    ids: dict[str, str] = {}
    lee = await h.run(
        "lee",
        "bring me Zhang's stapler",
        [[Move(place="zhang")], [Move(place="lee")], [Stop(outcome="done", summary="here")]],
    )
    ids["lee"] = lee.instruction_id
    await h.say("lee", "1. yes 2. no 3 unsure 4 yes")
    await h.say("lee", "The robot took the long way round")

    wang = await h.run(
        "wang",
        "tell Zhang the meeting moved",
        [
            [Inform(contact="zhang", content="The meeting moved.")],
            [Stop(outcome="done", summary="told")],
        ],
    )
    ids["wang"] = wang.instruction_id
    await h.say("wang", "banana")
    await h.say("wang", "banana")
    await h.say("wang", "yes yes no yes")

    chen = await h.run(
        "chen",
        "find me some scissors",
        [
            [Inquire(contact="office_work", question="Who has scissors?"), Wait(timeout_s=30)],
            [Stop(outcome="unachievable", summary="nobody can lend scissors now")],
        ],
    )
    ids["chen"] = chen.instruction_id  # chen never answers

    dang = await h.run(
        "dang",
        "bring me Wang's seal",
        [[Move(place="wang")], [Stop(outcome="failed", summary="Wang was away")]],
    )
    ids["dang"] = dang.instruction_id
    await h.say("dang", "stop surveys")
    dang2 = await h.run(
        "dang",
        "tell Lee hello",
        [[Inform(contact="lee", content="Hello from Dang.")], [Stop(outcome="done", summary="ok")]],
    )
    ids["dang2"] = dang2.instruction_id

    zhou = await h.run(
        "zhou",
        "tell Hu hi",
        [[Inform(contact="hu", content="Hi from Zhou.")], [Stop(outcome="done", summary="ok")]],
    )
    ids["zhou"] = zhou.instruction_id
    for answer in ("yes", "no", "unsure"):  # one message per question, the fourth never comes
        await h.say("zhou", answer)

    yang = await h.run(
        "yang",
        "tell Lin thanks",
        [
            [Inform(contact="lin", content="Thanks from Yang.")],
            [Stop(outcome="done", summary="ok")],
        ],
    )
    ids["yang"] = yang.instruction_id
    await h.say("yang", "all yes")

    hu = await h.run(
        "hu",
        "tell Xu hi",
        [[Inform(contact="xu", content="Hi from Hu.")], [Stop(outcome="done", summary="ok")]],
    )
    ids["hu"] = hu.instruction_id
    # A new request while the survey is open is a new instruction, not a survey comment.
    h.scripts.append(
        [[Move(place="gao")], [Move(place="hu")], [Stop(outcome="done", summary="stapler")]]
    )
    await h.say("hu", "Could you bring me Gao's stapler?")
    hu2_id = next(
        i for i in h.assistant.running.keys() | h.assistant.finished.keys() if i not in ids.values()
    )
    await h.assistant.wait(hu2_id)
    ids["hu2"] = hu2_id
    await h.say("hu", "skip")  # declines the latest survey
    return ids


async def test_survey_answers_reach_the_report_with_exact_counts(
    office: Office, tmp_path: Path
) -> None:
    async with harness(office, tmp_path / "journal.sqlite3") as h:
        ids = await _run_office_day(h)
        store, surveyor = h.store, h.surveyor

        # Every requester but the opted-out one got exactly one invitation per instruction.
        assert store.survey(ids["dang2"]) is None
        assert sum("A short survey" in t for t in h.texts_to("dang")) == 1
        assert sum("A short survey" in t for t in h.texts_to("hu")) == 2
        # Two unreadable replies, one re-ask.
        assert sum(t.startswith("Sorry, I could not read") for t in h.texts_to("wang")) == 1
        assert [e for _, _, e in store.replies(ids["wang"])][:2] == ["invalid", "invalid"]

        # Reminders: once, after four hours, to the surveys still open.
        h.sim.clock.advance(5 * HOUR)
        assert await surveyor.tick() == 3
        h.sim.clock.advance(HOUR)
        assert await surveyor.tick() == 0
        reminded = {
            p for p in ("chen", "zhou", "hu") if any("reminder" in t for t in h.texts_to(p))
        }
        assert reminded == {"chen", "zhou", "hu"}
        assert not any("reminder" in t for t in h.texts_to("lee") + h.texts_to("dang"))
        h.sim.clock.advance(48 * HOUR)
        await surveyor.tick()
        assert store.survey(ids["chen"]).state is SurveyState.EXPIRED  # type: ignore[union-attr]

        report = load_report(store)

    ins = report.instructions
    assert ins.total == 9
    assert ins.by_outcome == {"done": 7, "failed": 1, "unachievable": 1, "cancelled": 0}
    assert ins.by_kind == {
        "delivery": {"done": 2, "failed": 1},
        "message": {"done": 5, "unachievable": 1},
    }
    assert ins.time_to_completion.count == 7
    assert report.group_requests.total == 1 and report.group_requests.instructions == 1

    s = report.surveys
    assert (s.sent, s.answered, s.complete, s.partial, s.no_answer) == (8, 4, 3, 1, 4)
    assert (s.declined, s.opted_out, s.invalid, s.reminded) == (1, 1, 1, 3)
    assert s.response_rate == 0.5
    by_id = {q.id: q for q in s.questions}
    counts = {
        qid: ({c: a.count for c, a in q.answers.items()}, q.answered, q.no_answer)
        for qid, q in by_id.items()
    }
    assert counts == {
        "success": ({"yes": 4, "no": 0, "unsure": 0}, 4, 4),
        "walking": ({"yes": 2, "no": 2, "unsure": 0}, 4, 4),
        "satisfied": ({"yes": 1, "no": 1, "unsure": 2}, 4, 4),
        "productivity": ({"yes": 3, "no": 0, "unsure": 0}, 3, 5),
    }
    shares = {qid: {c: a.share for c, a in q.answers.items()} for qid, q in by_id.items()}
    assert shares["satisfied"] == {"yes": 0.25, "no": 0.25, "unsure": 0.5}
    assert shares["walking"] == {"yes": 0.5, "no": 0.5, "unsure": 0.0}
    assert shares["productivity"] == {"yes": 1.0, "no": 0.0, "unsure": 0.0}
    assert [(c.person, c.text) for c in s.comments] == [
        ("lee", "The robot took the long way round")
    ]

    walking = report.walking
    lee_saved = 2 * _desk_distance(office, "lee", "zhang")
    hu_saved = 2 * _desk_distance(office, "hu", "gao")
    assert walking.by_person["lee"].saved_m == round(lee_saved, 3)
    assert walking.by_person["hu"].saved_m == round(hu_saved, 3)
    assert walking.by_person["dang"].saved_m == 0.0  # failed, and a message
    assert walking.saved_m == round(round(lee_saved, 3) + round(hu_saved, 3), 3)

    markdown = render_markdown(report)
    assert "| Are you satisfied? | 1 (25%) | 1 (25%) | 2 (50%) | 4 |" in markdown
    assert "8 sent, 4 answered (50%)" in markdown


async def test_opted_out_person_is_never_surveyed_again(office: Office, tmp_path: Path) -> None:
    async with harness(office, tmp_path / "journal.sqlite3") as h:
        await h.say("lin", "please stop surveys")  # no survey running: honoured all the same
        stm = await h.run(
            "lin",
            "tell Xu hi",
            [[Inform(contact="xu", content="hi")], [Stop(outcome="done", summary="ok")]],
        )
        assert h.store.opted_out("lin")
        assert h.store.survey(stm.instruction_id) is None
        assert not any("survey" in t and "A short" in t for t in h.texts_to("lin"))
        await h.say("lin", "start surveys")
        stm = await h.run(
            "lin",
            "tell Xu bye",
            [[Inform(contact="xu", content="bye")], [Stop(outcome="done", summary="ok")]],
        )
        assert h.store.survey(stm.instruction_id) is not None
        # The instructions were real instructions, not swallowed as survey replies.
        assert len(h.assistant.finished) == 2


async def test_the_walking_estimate_runs_off_the_event_loop(
    office: Office, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Planning the walk a person was spared takes seconds on a big floor: the end hook runs it
    in a worker thread, never on the loop that serves everyone else."""
    threads: list[int] = []

    def recorded(*args: Any, **kwargs: Any) -> InstructionRecord:
        threads.append(threading.get_ident())
        return summarise(*args, **kwargs)

    monkeypatch.setattr(surveyor_module, "summarise", recorded)
    async with harness(office, tmp_path / "journal.sqlite3") as h:
        loop_thread = threading.get_ident()
        stm = await h.run(
            "lee",
            "bring me Zhang's stapler",
            [[Move(place="zhang")], [Move(place="lee")], [Stop(outcome="done", summary="here")]],
        )
        record = h.store.instruction(stm.instruction_id)
    assert len(threads) == 1 and threads[0] != loop_thread
    assert record is not None and record.walking.saved_m > 0
