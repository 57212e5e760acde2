"""The generator and its optimal policy on compositions real offices need (issue 23, fix14c),
on the studio office: a roll of film kept at a facility (the picture archive, the fridge)
developed in the darkroom, and a signature followed by a courier outside or by a stamp. Each
base instruction's every availability variant is verified in the simulator, and the plan
says who is asked, what each hand-over is and where the item ends."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import yaml

import assistantx.evaluation.report as eval_report
from assistantx.agents.oracle.plan import REQUESTER, build_plan
from assistantx.agents.oracle.policy import dry_run
from assistantx.cli import main
from assistantx.core.actions import Inquire, SendQR
from assistantx.core.office import Office
from assistantx.core.task_spec import BaseInstruction, Part, check_base
from assistantx.evaluation.dataset.generate import _task, classify, run_optimal
from helpers.dataset_tasks import verify_every_variant
from helpers.studio import studio, write_studio

FILM_IN_ARCHIVE = BaseInstruction(
    id="s1", requester="ada", text="Please develop my film.", parts=(Part(kind="copy"),)
)
FILM_IN_FRIDGE_TO_CYRUS = BaseInstruction(
    id="s2",
    requester="bo",
    text="Could you develop my film and take the prints to Cyrus?",
    parts=(Part(kind="copy", to="cyrus"),),
)
SIGN_THEN_COURIER = BaseInstruction(
    id="s4",
    requester="ada",
    text="Get my drawings signed by Dr. Osei, then courier them to Harlow & Sons.",
    parts=(
        Part(kind="sign", signer="amara"),
        Part(kind="heat", operation="courier", destination="Harlow & Sons"),
    ),
)
SIGN_THEN_STAMP = BaseInstruction(
    id="s5",
    requester="ada",
    text="Get my drawings signed by Amara Osei and then stamped.",
    parts=(Part(kind="sign", signer="amara"), Part(kind="seal")),
)
# Blind rounds 28 and 30's refused bases: one's own thing kept at a facility handed to a
# colleague, and a signature followed by a hand-over to a third person (the optimal policy
# took the thing from the requester's desk, where it never was, and ended "failed").
KEPT_FILM_TO_CYRUS = BaseInstruction(
    id="s6",
    requester="ada",
    text="Could you take my film over to Cyrus?",
    parts=(Part(kind="deliver", item="film", to="cyrus"),),
)
SIGN_THEN_TO_LUC = BaseInstruction(
    id="s7",
    requester="ada",
    text="Get Amara to sign my drawings and then take them to Luc.",
    parts=(Part(kind="sign", signer="amara"), Part(kind="deliver", item="drawings", to="luc")),
)
BASES = (
    FILM_IN_ARCHIVE,
    FILM_IN_FRIDGE_TO_CYRUS,
    SIGN_THEN_COURIER,
    SIGN_THEN_STAMP,
    KEPT_FILM_TO_CYRUS,
    SIGN_THEN_TO_LUC,
)


def _codes(base: BaseInstruction, office: Office) -> list[tuple[str, ...]]:
    """The dry run's locker codes: (to whom, item, purpose[, where it is sent])."""
    run = dry_run(base, build_plan(base, office), office, set())
    return [
        (a.contact, a.item, a.purpose, *([a.destination] if a.destination else []))
        for a in run.actions
        if isinstance(a, SendQR)
    ]


def _asked(base: BaseInstruction, office: Office) -> list[str]:
    run = dry_run(base, build_plan(base, office), office, set())
    return [a.contact for a in run.actions if isinstance(a, Inquire)]


@pytest.mark.parametrize("base", BASES, ids=lambda b: b.id)
async def test_every_variant_is_solved_by_the_optimal_policy_in_the_simulator(
    base: BaseInstruction,
) -> None:
    office = studio()
    check_base(base, office)
    await verify_every_variant(office, base)


def test_a_kept_film_is_taken_out_by_its_keeper_and_both_come_back_to_the_owner() -> None:
    office = studio()
    developer, *keeper = _asked(FILM_IN_ARCHIVE, office)
    assert developer in ("pia", "sven") and keeper == ["otto"]  # a darkroom guard, the keeper
    assert _codes(FILM_IN_ARCHIVE, office) == [
        ("otto", "film:ada", "deposit"),
        (developer, "film:ada", "copy"),
        ("ada", "film:ada", "collect"),
        ("ada", "photo_prints:ada", "collect"),
    ]
    assert build_plan(FILM_IN_ARCHIVE, office).goal == [
        {"copied": "film:ada"},
        {"holds": ["ada", "photo_prints:ada"]},
        {"holds": ["ada", "film:ada"]},
        {"informed": "ada"},
    ]
    # the fridge's keeper for Bo's film; the prints go to Cyrus, the film back to Bo
    assert _asked(FILM_IN_FRIDGE_TO_CYRUS, office) == [developer, "kai", "cyrus"]
    assert _codes(FILM_IN_FRIDGE_TO_CYRUS, office) == [
        ("kai", "film:bo", "deposit"),
        (developer, "film:bo", "copy"),
        ("bo", "film:bo", "collect"),
        ("cyrus", "photo_prints:bo", "collect"),
    ]


def test_with_the_keeper_away_nothing_moves() -> None:
    run = dry_run(FILM_IN_ARCHIVE, build_plan(FILM_IN_ARCHIVE, studio()), studio(), {"otto"})
    assert run.outcome == "unachievable"
    assert not [a for a in run.actions if isinstance(a, SendQR)]


def test_signed_drawings_come_back_first_then_go_out_with_where_to() -> None:
    office = studio()
    assert _asked(SIGN_THEN_COURIER, office) == ["amara", "luc"]
    assert _codes(SIGN_THEN_COURIER, office) == [
        ("ada", "drawings:ada", "deposit"),
        ("amara", "drawings:ada", "sign"),
        ("ada", "drawings:ada", "collect"),
        ("ada", "drawings:ada", "deposit"),
        ("luc", "drawings:ada", "heat", "Harlow & Sons"),
    ]
    # couriered out: nobody in the office holds it at the end
    assert build_plan(SIGN_THEN_COURIER, office).goal == [
        {"signed": ["drawings:ada", "amara"]},
        {"heated": "drawings:ada"},
        {"informed": "ada"},
    ]
    plan = build_plan(SIGN_THEN_COURIER, office)
    assert plan.deliveries == []  # the hand-back moved before the courier's visit
    assert [v.person for v in plan.visits] == [
        REQUESTER,
        "person:amara",
        REQUESTER,  # the hand-back of the signed drawings ...
        REQUESTER,  # ... and their deposit again, one stop when the policy merges them
        "guard:post_desk",
    ]


async def test_the_courier_is_told_where_and_the_drawings_leave_signed() -> None:
    office = studio()
    [variant] = [v for v in classify(SIGN_THEN_COURIER, office)["L1"] if not v.unavailable]
    task = _task(variant, office, 1)
    count, reached, outcome = await run_optimal(office, task)
    assert (count, outcome, all(reached)) == (18, "done", True)


def test_signed_then_stamped_drawings_end_with_the_requester() -> None:
    office = studio()
    codes = _codes(SIGN_THEN_STAMP, office)
    assert [c[2] for c in codes] == ["deposit", "sign", "collect", "deposit", "seal", "collect"]
    assert {c[0] for c in codes if c[2] == "seal"} <= {"amara", "pia"}  # a stamp's owner
    goal = build_plan(SIGN_THEN_STAMP, office).goal
    assert goal.count({"holds": ["ada", "drawings:ada"]}) == 1
    assert goal[-2:] == [{"holds": ["ada", "drawings:ada"]}, {"informed": "ada"}]


def test_the_commands_generate_and_both_methods_complete_the_tasks(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """``dataset generate`` on the office file (verified in the simulator), then ``eval`` by
    the optimal policy and by the embedded reasoner: every task succeeds."""
    monkeypatch.setattr(eval_report, "charts", lambda _summary, _out: [])  # drawn elsewhere
    office = write_studio(tmp_path / "office.yaml")
    base = tmp_path / "base.yaml"
    entries = [b.model_dump(exclude_none=True) for b in (FILM_IN_ARCHIVE, SIGN_THEN_COURIER)]
    base.write_text(yaml.safe_dump({"instructions": entries}, sort_keys=False), encoding="utf-8")
    tasks = tmp_path / "tasks.jsonl"
    generate = ["dataset", "generate", "--office", str(office), "--base", str(base)]
    assert main([*generate, "--out", str(tasks)]) == 0
    for method in (["--method", "optimal"], ["--method", "ppdr", "--reasoner", "symbolic"]):
        out = tmp_path / method[1]
        args = ["eval", "--tasks", str(tasks), "--office", str(office), *method]
        assert main([*args, "--runs", "1", "--out", str(out), "--quiet"]) == 0
        summary = json.loads((out / "summary.json").read_text())
        assert summary["levels"]["all"]["sr"]["mean"] == 1.0, method


def test_ones_own_kept_film_is_taken_out_by_its_keeper_and_handed_to_the_colleague() -> None:
    office = studio()
    assert _asked(KEPT_FILM_TO_CYRUS, office) == ["cyrus", "otto"]
    assert _codes(KEPT_FILM_TO_CYRUS, office) == [
        ("otto", "film:ada", "deposit"),
        ("cyrus", "film:ada", "collect"),
    ]


def test_signed_drawings_go_on_to_the_colleague_from_the_locker() -> None:
    """As the embedded planner does it: signed, they stay in the locker and Luc takes them
    out; nothing comes back to Ada first."""
    office = studio()
    assert _codes(SIGN_THEN_TO_LUC, office) == [
        ("ada", "drawings:ada", "deposit"),
        ("amara", "drawings:ada", "sign"),
        ("luc", "drawings:ada", "collect"),
    ]
    assert build_plan(SIGN_THEN_TO_LUC, office).goal == [
        {"signed": ["drawings:ada", "amara"]},
        {"holds": ["luc", "drawings:ada"]},
        {"informed": "ada"},
    ]
