"""Every metric on hand-made episodes: perfect, redundant, wrong hand-over, false done, etc."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.actions import (
    Action,
    ForwardFile,
    Inform,
    Inquire,
    Move,
    SendQR,
    Stop,
    Wait,
    WaitInPlace,
)
from assistantx.core.trace import ActionResult, Trace, TraceStep
from assistantx.evaluation.episode import Episode, Handover, SentOut
from assistantx.evaluation.metrics import (
    judge_actions,
    score,
    success,
    wrong_handovers,
    wrong_sends,
)

STAPLER_GOAL = [{"holds": ["lee", "stapler:*"]}, {"informed": "lee"}]
PEOPLE = ["lee", "wang", "zhang", "hu", "gao", "office_work", "study_group"]
PLACES = ["desk_03", "desk_04", "desk_06", "desk_10", "desk_12"]

Step = list[tuple[Action, bool, dict[str, Any]]]


def _episode(
    steps: list[Step],
    *,
    outcome: str,
    milestones: list[bool],
    handovers: list[Handover] | None = None,
    achievable: bool = True,
    goal: list[dict[str, Any]] | None = None,
    optimal: int = 9,
    refused: set[int] | None = None,
) -> Episode:
    trace = Trace(
        instruction_id="ins-1", requester="lee", text="stapler", reasoner="t", started_at=0
    )
    t = 0.0
    n = 0
    for index, step in enumerate(steps):
        results = []
        for action, ok, data in step:
            is_refused = n in (refused or set())
            results.append(
                ActionResult(
                    action=action,
                    ok=ok and not is_refused,
                    observation="x",
                    refused=is_refused,
                    started_at=t,
                    ended_at=t + 1,
                    data=data,
                )
            )
            t += 1
            n += 1
        trace.steps.append(TraceStep(index=index, started_at=t, results=results))
    trace.outcome = outcome  # type: ignore[assignment]
    return Episode(
        task_id="t",
        run=0,
        method="hand",
        level="L1",
        achievable=achievable,
        requester="lee",
        goal=goal or STAPLER_GOAL,
        optimal_actions=optimal,
        relevant_people=PEOPLE,
        relevant_places=PLACES,
        milestones=milestones,
        handovers=handovers or [],
        trace=trace,
    )


def _perfect() -> list[Step]:
    return [
        [
            (Inquire(contact="wang", question="Could you lend Lee your stapler?"), True, {}),
            (Wait(reason="wang", timeout_s=60), True, {"replies": ["wang"]}),
        ],
        [(Move(place="desk_06"), True, {})],
        [
            (SendQR(contact="wang", item="stapler:wang"), True, {}),
            (WaitInPlace(person="wang"), True, {}),
        ],
        [(Move(place="desk_03"), True, {})],
        [
            (SendQR(contact="lee", item="stapler:wang", purpose="collect"), True, {}),
            (WaitInPlace(person="lee"), True, {}),
        ],
        [(Stop(outcome="done", summary="here it is"), True, {})],
    ]


HANDED = [Handover(item="stapler:wang", to="lee")]


def test_perfect_run_scores_full_marks() -> None:
    s = score(_episode(_perfect(), outcome="done", milestones=[True, True], handovers=HANDED))
    assert (s.sr, s.cr, s.rr, s.cta, s.rta) == (1.0, 1.0, 0.0, 1.0, 1.0)
    assert s.actions == 9 and s.redundant == 0 and not s.wrong_handover


def test_redundant_actions_are_counted_and_lower_cta_rta() -> None:
    steps = _perfect()
    ask_again = Inquire(contact="wang", question="Could you lend Lee your stapler?")
    # a repeat with nothing new in between, a message to nobody relevant, a needless drive
    steps.insert(1, [(ask_again, True, {})])
    steps.insert(0, [(ask_again, True, {})])
    steps.insert(2, [(Inform(contact="chen", content="hello"), True, {})])
    steps.insert(3, [(Move(place="desk_16"), True, {})])
    s = score(_episode(steps, outcome="done", milestones=[True, True], handovers=HANDED))
    assert s.sr == 1.0
    assert s.redundant == 3  # first ask is fine, the next ask repeats it; chen; desk_16
    assert s.rr == 3 / 9
    assert s.cta is not None and s.rta is not None
    assert s.cta == 5 / 7  # 7 cyber actions (wait included), two of them redundant
    assert s.rta == 4 / 5
    verdicts = judge_actions(
        _episode(steps, outcome="done", milestones=[True, True], handovers=HANDED)
    )
    whys = [w for v in verdicts for w in v.why]
    assert any("no new information" in w for w in whys)
    assert any("nobody relevant" in w for w in whys)
    assert any("irrelevant" in w for w in whys)


def test_action_aimed_at_known_unavailable_person_is_redundant() -> None:
    steps: list[Step] = [
        [
            (Inquire(contact="wang", question="stapler?"), True, {}),
            (Wait(reason="w", timeout_s=60), False, {"timed_out": True}),
        ],
        [(Move(place="desk_06"), True, {})],
        [(SendQR(contact="wang", item="stapler:wang"), True, {})],
        [(Stop(outcome="failed", summary="no"), True, {})],
    ]
    verdicts = judge_actions(_episode(steps, outcome="failed", milestones=[False, True]))
    qr = verdicts[3]
    assert qr.redundant and "known to be unavailable" in qr.why[0]
    assert not verdicts[1].redundant  # a timed-out wait is news, not a mistake
    assert verdicts[1].valid


def test_refused_and_failed_actions_are_not_correct() -> None:
    steps: list[Step] = [
        [(ForwardFile(source="wang", target="lee"), False, {})],  # no such file received
        [(Inform(contact="wang", content="hi"), True, {})],
        [(Stop(outcome="failed", summary="no"), True, {})],
    ]
    s = score(_episode(steps, outcome="failed", milestones=[False, True], refused={1}))
    assert s.cta == 0.0


def test_wrong_handover_fails_sr_even_when_the_goal_holds() -> None:
    wrong = [*HANDED, Handover(item="stapler:zhang", to="chen")]
    episode = _episode(_perfect(), outcome="done", milestones=[True, True], handovers=wrong)
    assert wrong_handovers(episode) == ["stapler:zhang → chen"]
    s = score(episode)
    assert s.sr == 0.0 and s.wrong_handover and s.cr == 1.0


def test_owner_taking_their_item_back_is_not_wrong() -> None:
    back = [Handover(item="stapler:wang", to="wang")]
    episode = _episode(_perfect(), outcome="done", milestones=[True, True], handovers=back)
    assert wrong_handovers(episode) == []


FAX_WORDS = "scan it at the robot to take Lee Ming's form out and fax it to {where}."


@pytest.mark.parametrize(
    ("told", "right"),
    [
        ("the County  Tax Office", True),  # the requester's words, in any case and spacing
        ("the tax office", False),  # not what the requester named
        ("", False),  # faxed with no word of where to
    ],
)
def test_an_item_sent_out_counts_only_where_its_sender_was_told_the_destination(
    told: str, right: bool
) -> None:
    episode = _episode(
        _perfect(), outcome="done", milestones=[True, True], handovers=HANDED
    ).model_copy(
        update={
            "sent_out": [SentOut(item="form:lee", told=FAX_WORDS.format(where=told))],
            "destinations": ["the county tax office"],
        }
    )
    assert wrong_sends(episode) == ([] if right else ["form:lee"])
    s = score(episode)
    assert (s.sr, s.wrong_handover) == ((1.0, False) if right else (0.0, True))


@pytest.mark.parametrize(
    ("told", "destination", "right"),
    [
        # every word of the destination told, in another order and punctuation (round 21)
        ("Dublin, attention Customer Relations", "Dublin customer relations", True),
        ("Broadcast Centre, White City", "Broadcast Centre, White City", True),
        ("Broadcast Centre", "Broadcast Centre, White City", False),  # half an address
        ("Relations", "Dublin customer relations", False),
        # an address word in its short form tells the word written out, either way round
        ("Powys County Council housing dept", "Powys County Council housing department", True),
        ("Acme Limited, 4 Mill Road", "Acme Ltd, 4 Mill Rd", True),
        ("Powys County Council", "Powys County Council housing dept", False),
    ],
)
def test_a_destination_is_told_when_all_its_words_are(
    told: str, destination: str, right: bool
) -> None:
    episode = _episode(
        _perfect(), outcome="done", milestones=[True, True], handovers=HANDED
    ).model_copy(
        update={
            "sent_out": [SentOut(item="form:lee", told=FAX_WORDS.format(where=told))],
            "destinations": [destination],
        }
    )
    assert wrong_sends(episode) == ([] if right else ["form:lee"])


def test_goal_unmet_or_not_done_fails() -> None:
    unmet = _episode(_perfect(), outcome="done", milestones=[False, True])
    assert not success(unmet) and score(unmet).cr == 0.5
    said_failed = _episode(_perfect(), outcome="failed", milestones=[True, True])
    assert not success(said_failed)


UNACHIEVABLE_GOAL = [{"informed": "lee"}]


def _asked_everyone(stop: Stop) -> list[Step]:
    return [
        [
            (Inquire(contact="wang", question="stapler?"), True, {}),
            (Wait(reason="w", timeout_s=60), False, {"timed_out": True}),
        ],
        [(stop, True, {})],
    ]


def test_false_done_on_unachievable_task_is_a_failure() -> None:
    episode = _episode(
        _asked_everyone(Stop(outcome="done", summary="Here is your stapler!")),
        outcome="done",
        milestones=[True],
        achievable=False,
        goal=UNACHIEVABLE_GOAL,
        optimal=3,
    )
    s = score(episode)
    assert s.sr == 0.0 and s.cr == 0.0


def test_correct_unachievable_succeeds() -> None:
    episode = _episode(
        _asked_everyone(Stop(outcome="unachievable", summary="Nobody could lend one.")),
        outcome="unachievable",
        milestones=[True],
        achievable=False,
        goal=UNACHIEVABLE_GOAL,
        optimal=3,
    )
    s = score(episode)
    assert (s.sr, s.cr, s.rr) == (1.0, 1.0, 0.0)


def test_being_told_of_a_failure_is_no_progress() -> None:
    # nothing was fetched; the requester heard "failed" (the informed milestone holds in the
    # world, but it is not progress toward the goal)
    told = [[(Stop(outcome="failed", summary="I could not do it."), True, {})]]
    s = score(_episode(told, outcome="failed", milestones=[False, True]))
    assert (s.sr, s.cr) == (0.0, 0.0)


def test_informing_someone_else_counts_whatever_the_outcome() -> None:
    goal = [{"informed": "wang"}, {"holds": ["lee", "stapler:*"]}]
    steps = [
        [(Inform(contact="wang", content="The meeting moved."), True, {})],
        [(Stop(outcome="failed", summary="No stapler."), True, {})],
    ]
    s = score(_episode(steps, outcome="failed", milestones=[True, False], goal=goal))
    assert s.cr == 0.5
