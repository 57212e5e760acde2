"""bench/phrasings.py: its judge on real runs of the assistant in the default office, case by
case, the phrasings file's checks, and (slow) the whole tool in its own processes."""

from __future__ import annotations

import asyncio
import copy
import json
import os
import subprocess
import sys
from functools import cache
from pathlib import Path
from typing import Any

import pytest

from assistantx.agents.registry import reasoner_factory
from assistantx.core.office import Office, load_office
from assistantx.core.settings import Settings
from assistantx.sim.requester import Wish
from assistantx.sim.run import run_in_sim
from helpers.dataset_offices import default_office_that_scans

BENCH = Path(__file__).resolve().parents[2] / "bench"
sys.path.insert(0, str(BENCH))

from _phrasing_judge import (  # noqa: E402  (bench/ is no package: on the path above)
    Case,
    PhrasingsError,
    judge,
    load_phrasings,
    truth_goal,
)

OFFICE = load_office()


@cache
def _run(requester: str, text: str) -> str:
    """The trace JSON of one real symbolic run, as ``assistantx run --trace-out`` writes it
    (a string, so no test can change another's copy)."""
    factory = reasoner_factory("symbolic", OFFICE, Settings())
    run = asyncio.run(run_in_sim(OFFICE, requester, text, factory, reasoner_name="symbolic"))
    return run.trace.model_dump_json()


def trace(requester: str, text: str) -> dict[str, Any]:
    loaded: dict[str, Any] = json.loads(_run(requester, text))
    return loaded


@cache
def _run_as_the_case_says(
    text: str, expect: str, recipient: str | None, item: str = "printout"
) -> str:
    """The trace JSON of a real run whose requester answers as the bench's does: from the
    case's truth for a deliver case (``truth_goal``, what ``--goal`` carries), else from the
    words they wrote."""
    fields = {} if recipient is None else {"recipient": recipient, "item": item}
    goal = truth_goal(case(text, expect, **fields))
    wish = None if goal is None else Wish.from_goal(OFFICE, "lee", goal)
    factory = reasoner_factory("symbolic", OFFICE, Settings())
    run = asyncio.run(run_in_sim(OFFICE, "lee", text, factory, reasoner_name="symbolic", wish=wish))
    return run.trace.model_dump_json()


def case(text: str, expect: str, **fields: Any) -> Case:
    return Case.model_validate({"id": "c", "as": "lee", "text": text, "expect": expect, **fields})


BORROW = "bring me Zhang's stapler"
QUESTION = "bring me the thing"
THANKS = "thanks for the stapler earlier"
UNKNOWN = "bring me a unicorn"


@pytest.mark.parametrize("item", ["stapler:zhang", "stapler"])
def test_the_borrowed_stapler_handed_to_the_requester_is_a_right_delivery(item: str) -> None:
    borrowed = case(BORROW, "deliver", recipient="lee", item=item, owner_asked="zhang")
    verdict = judge(borrowed, trace("lee", BORROW), OFFICE)
    assert (verdict.got, verdict.right, verdict.wrong_physical) == ("deliver", True, None)


@pytest.mark.parametrize(
    ("fields", "why"),
    [
        ({"item": "stapler:wang"}, "stapler:wang never handed to lee"),
        ({"item": "scissors"}, "scissors never handed to lee"),
        ({"item": "stapler", "owner_asked": "wang"}, "wang not asked before stapler:zhang moved"),
    ],
)
def test_another_item_or_an_owner_never_asked_is_wrong_but_not_physical(
    fields: dict[str, str], why: str
) -> None:
    verdict = judge(
        case(BORROW, "deliver", recipient="lee", **fields), trace("lee", BORROW), OFFICE
    )
    assert (verdict.right, verdict.wrong_physical, verdict.why) == (False, None, why)


def test_the_item_handed_to_someone_else_than_the_recipient_is_a_wrong_physical_action() -> None:
    verdict = judge(
        case(BORROW, "deliver", recipient="wang", item="stapler"), trace("lee", BORROW), OFFICE
    )
    assert not verdict.right
    assert verdict.wrong_physical == "handed stapler:zhang to lee"


def test_an_owned_item_moved_before_its_owner_was_asked_is_a_wrong_physical_action() -> None:
    # the real run with its question to Zhang taken out: as if the assistant had not asked
    unasked = copy.deepcopy(trace("lee", BORROW))
    for step in unasked["steps"]:
        step["results"] = [r for r in step["results"] if r["action"]["type"] != "inquire"]
    verdict = judge(case(BORROW, "deliver", recipient="lee", item="stapler"), unasked, OFFICE)
    assert verdict.wrong_physical == "moved stapler:zhang without asking zhang"
    # the requester's own item needs nobody's yes
    own = "take my book to Wang"
    assert judge(
        case(own, "deliver", recipient="wang", item="book"), trace("lee", own), OFFICE
    ).right


@pytest.mark.parametrize("expect", ["words", "decline"])
def test_a_real_request_judged_as_words_or_a_refusal_is_a_wrong_physical_action(
    expect: str,
) -> None:
    verdict = judge(case(BORROW, expect), trace("lee", BORROW), OFFICE)
    assert (verdict.got, verdict.right) == ("deliver", False)
    assert verdict.wrong_physical == f"move on a {expect} case"


def test_a_question_before_any_step_is_ask_and_nothing_else() -> None:
    asked = trace("lee", QUESTION)
    assert judge(case(QUESTION, "ask"), asked, OFFICE).right
    delivered = judge(case(QUESTION, "deliver", recipient="lee", item="stapler"), asked, OFFICE)
    assert (delivered.got, delivered.right, delivered.wrong_physical) == ("ask", False, None)
    # the run ends saying it did not understand: no decline, and no answer in words either
    assert not judge(case(QUESTION, "words"), asked, OFFICE).right
    assert judge(
        case(QUESTION, "deliver", recipient="lee", item="pen", accept=["ask"]), asked, OFFICE
    ).right


def test_asking_after_no_question_or_after_acting_is_no_ask() -> None:
    verdict = judge(case(BORROW, "ask"), trace("lee", BORROW), OFFICE)
    assert (verdict.right, verdict.why) == (False, "never asked the requester")
    # the stapler went to the person the text names: no wrong physical action on an ask case
    third = "take Zhang's stapler to Wang"
    verdict = judge(case(third, "ask"), trace("lee", third), OFFICE)
    assert (verdict.got, verdict.right, verdict.wrong_physical) == ("deliver", False, None)


def test_a_thank_you_is_words_and_a_known_nothing_is_a_decline() -> None:
    thanked = trace("lee", THANKS)
    assert judge(case(THANKS, "words"), thanked, OFFICE).right
    for other in ("decline", "ask"):
        assert judge(case(THANKS, other), thanked, OFFICE).got == "words"
        assert not judge(case(THANKS, other), thanked, OFFICE).right
    refused = trace("lee", UNKNOWN)
    assert judge(case(UNKNOWN, "decline"), refused, OFFICE).right
    verdict = judge(case(UNKNOWN, "words"), refused, OFFICE)
    assert (verdict.got, verdict.right, verdict.wrong_physical) == ("decline", False, None)


COMBINED = "take my book to Wang, and get me a coffee"


def test_a_combinations_other_hand_over_named_under_also_is_required_and_allowed() -> None:
    run = trace("lee", COMBINED)
    book = {"recipient": "wang", "item": "book"}
    # the coffee to the requester is not the case's recipient: wrong unless the case names it
    unnamed = judge(case(COMBINED, "deliver", **book), run, OFFICE)
    assert (unnamed.right, unnamed.wrong_physical) == (False, "handed coffee:lee to lee")
    named = judge(
        case(COMBINED, "deliver", **book, also=[{"recipient": "lee", "item": "coffee"}]),
        run,
        OFFICE,
    )
    assert (named.right, named.wrong_physical) == (True, None)
    # a second hand-over the run never made is unmet, and naming it allows nothing else
    missing = judge(
        case(COMBINED, "deliver", **book, also=[{"recipient": "lee", "item": "stapler"}]),
        run,
        OFFICE,
    )
    assert (missing.right, missing.wrong_physical) == (False, "handed coffee:lee to lee")
    unmet = judge(
        case(
            COMBINED,
            "deliver",
            **book,
            also=[{"recipient": "lee", "item": "coffee"}, {"recipient": "lee", "item": "stapler"}],
        ),
        run,
        OFFICE,
    )
    assert (unmet.right, unmet.wrong_physical, unmet.why) == (
        False,
        None,
        "stapler never handed to lee",
    )
    elsewhere = judge(
        case(COMBINED, "deliver", **book, also=[{"recipient": "zhang", "item": "coffee"}]),
        run,
        OFFICE,
    )
    assert (elsewhere.right, elsewhere.wrong_physical) == (False, "handed coffee:lee to lee")


def test_also_belongs_to_a_deliver_case() -> None:
    with pytest.raises(ValueError, match="only a deliver case"):
        case(THANKS, "words", also=[{"recipient": "lee", "item": "coffee"}])


def test_a_product_and_a_printed_file_are_delivered_with_no_one_elses_hand_over() -> None:
    coffee = "get me a coffee"
    verdict = judge(
        case(coffee, "deliver", recipient="lee", item="coffee"), trace("lee", coffee), OFFICE
    )
    assert (verdict.right, verdict.wrong_physical) == (True, None)
    # the file forwarded to the printer's keeper is what printing takes, not a delivery to him
    printed = "print my report and bring it to me"
    verdict = judge(
        case(printed, "deliver", recipient="lee", item="printout"), trace("lee", printed), OFFICE
    )
    assert (verdict.right, verdict.wrong_physical) == (True, None)


def test_a_file_sent_to_a_colleague_who_then_makes_a_drink_is_delivered_to_them() -> None:
    # Lin Tao is the water's first maker: the file forwarded to him is a delivery, not the
    # input of a service (only a service that works on a file, a print, takes one)
    text = "send my slides to Lin Tao and get me a glass of water"
    run = trace("lee", text)
    makers = [
        a["contact"]
        for step in run["steps"]
        for a in step["decision"]["actions"]
        if a["type"] == "send_qr" and a["purpose"] == "produce"
    ]
    assert makers == ["lin"]
    verdict = judge(
        case(
            text,
            "deliver",
            recipient="lin",
            item="file:lee",
            also=[{"recipient": "lee", "item": "water"}],
        ),
        run,
        OFFICE,
    )
    assert (verdict.right, verdict.wrong_physical) == (True, None)


# "questionnaire" is no word of the office: the reader restates before it acts
PRINT_MINE = "pls print my questionnaire for me, thx"
PRINT_FIXED = "print my questionnaire and take it to Wang. Sorry, I meant Chen"


@pytest.mark.parametrize(("text", "recipient"), [(PRINT_MINE, "lee"), (PRINT_FIXED, "chen")])
def test_a_right_restatement_of_a_deliver_case_is_answered_yes_and_delivered(
    text: str, recipient: str
) -> None:
    run = json.loads(_run_as_the_case_says(text, "deliver", recipient))
    assert "Shall I print your file for" in json.dumps(run)  # it was restated and asked
    verdict = judge(case(text, "deliver", recipient=recipient, item="printout"), run, OFFICE)
    assert (verdict.got, verdict.right, verdict.wrong_physical) == ("deliver", True, None)


@pytest.mark.parametrize(
    ("text", "recipient", "item"),
    [
        (PRINT_MINE, "wang", "printout"),  # the wrong person: "for you"
        (PRINT_FIXED, "wang", "printout"),  # the wrong person: "for Chen Jie"
        (PRINT_FIXED, "lee", "printout"),
        (PRINT_MINE, "lee", "book"),  # the wrong item
    ],
)
def test_a_wrong_restatement_of_the_cases_truth_is_answered_no(
    text: str, recipient: str, item: str
) -> None:
    run = json.loads(_run_as_the_case_says(text, "deliver", recipient, item))
    verdict = judge(case(text, "deliver", recipient=recipient, item=item), run, OFFICE)
    assert (verdict.got, verdict.right, verdict.wrong_physical) == ("ask", False, None)
    assert "won't do anything" in run["summary"]


@pytest.mark.parametrize("text", [PRINT_MINE, PRINT_FIXED])
def test_an_ask_case_keeps_the_requester_of_the_words_only(text: str) -> None:
    assert truth_goal(case(text, "ask")) is None
    assert truth_goal(case(text, "words")) is None
    run = json.loads(_run_as_the_case_says(text, "ask", None))
    assert judge(case(text, "ask"), run, OFFICE).right
    assert "won't do anything" in run["summary"]  # a yes would be a guess: "No, thanks."


def test_the_truth_of_a_deliver_case_is_its_hand_overs_with_the_owner_asked() -> None:
    borrowed = case(BORROW, "deliver", recipient="lee", item="stapler", owner_asked="zhang")
    assert truth_goal(borrowed) == [{"holds": ["lee", "stapler:zhang"]}]
    combined = case(
        COMBINED,
        "deliver",
        recipient="wang",
        item="book",
        also=[{"recipient": "lee", "item": "coffee"}],
    )
    assert truth_goal(combined) == [{"holds": ["wang", "book"]}, {"holds": ["lee", "coffee"]}]
    wish = Wish.from_goal(OFFICE, "lee", truth_goal(borrowed) or [])
    assert (wish.owners, wish.recipients) == (("zhang",), ("lee",))


def _write(tmp_path: Path, cases: str) -> Path:
    office = Path(__file__).resolve().parents[2] / "dataset" / "office.yaml"
    path = tmp_path / "phrasings.yaml"
    path.write_text(f"office: {office}\ncases:\n{cases}\n")
    return path


@pytest.mark.parametrize(
    ("cases", "error"),
    [
        ("  - {id: a, as: nobody, text: hi, expect: words}", "case a: as: 'nobody' is no person"),
        ("  - {id: a, as: lee, expect: words}", "case a.text: Field required"),
        ("  - {id: a, as: lee, text: hi, expect: maybe}", "case a.expect: 'maybe' is not one of"),
        ("  - {id: a, as: lee, text: hi, expect: deliver, item: pen}", "needs both recipient"),
        (
            "  - {id: a, as: lee, text: hi, expect: deliver, item: pen, recipient: bob}",
            "case a: recipient: 'bob' is no person id",
        ),
        (
            "  - {id: a, as: lee, text: hi, expect: deliver, item: unicorn, recipient: lee}",
            "case a: item: 'unicorn' is no item id",
        ),
        (
            "  - {id: a, as: lee, text: hi, expect: deliver, item: pen, recipient: lee,"
            " also: [{recipient: bob, item: pen}]}",
            "case a: also: 'bob' is no person id",
        ),
        (
            "  - {id: a, as: lee, text: hi, expect: deliver, item: pen, recipient: lee,"
            " also: [{recipient: lee, item: unicorn}]}",
            "case a: also: 'unicorn' is no item id",
        ),
    ],
)
def test_a_bad_phrasings_file_is_one_clear_line(tmp_path: Path, cases: str, error: str) -> None:
    with pytest.raises(PhrasingsError) as raised:
        load_phrasings(_write(tmp_path, cases))
    assert error in str(raised.value)
    assert "\n" not in str(raised.value)


@pytest.mark.slow
def test_the_tool_runs_each_case_in_its_own_process_and_ends_with_one_json_line(
    tmp_path: Path,
) -> None:
    path = _write(
        tmp_path,
        f'  - {{id: thanks, as: lee, text: "{THANKS}", expect: words}}\n'
        f'  - {{id: taken, as: lee, text: "{BORROW}", expect: words}}\n'
        # restated before it acts: the requester answers the offer from the case's truth
        f'  - {{id: printed, as: lee, text: "{PRINT_MINE}", expect: deliver, recipient: lee,'
        " item: printout}",
    )
    env = {**os.environ, "PYTHONPATH": str(BENCH.parent / "src")}
    done = subprocess.run(
        [
            *(sys.executable, str(BENCH / "phrasings.py"), "--phrasings", str(path)),
            *("--label", "t", "--out", str(tmp_path / "out")),
        ],
        env=env,
        capture_output=True,
        text=True,
        check=True,
        timeout=120,
    )
    lines = done.stdout.splitlines()
    assert lines[:3] == [
        "thanks: expected words, got words, right",
        "taken: expected words, got deliver, WRONG (wrong physical action: move on a words case)",
        "printed: expected deliver, got deliver, right",
    ]
    report = json.loads(lines[-1])
    assert report == {
        "label": "t",
        "cases": 3,
        "right": 2,
        "wrong_physical": 1,
        "by_expect": {
            "words": {"cases": 2, "right": 1, "wrong_physical": 1},
            "deliver": {"cases": 1, "right": 1, "wrong_physical": 0},
        },
        "wrong": ["taken"],
    }
    kept = json.loads((tmp_path / "out" / "results.json").read_text())
    assert [c["id"] for c in kept["per_case"]] == ["thanks", "taken", "printed"]
    assert json.loads((tmp_path / "out" / "traces" / "taken.json").read_text())["text"] == BORROW


@pytest.mark.slow
@pytest.mark.parametrize(
    ("goal", "error"),
    [
        ("not json", "--goal is no JSON"),
        ("{}", "--goal is a JSON list of milestones"),
        ('[{"wants": ["lee"]}]', "unknown predicate 'wants'"),
    ],
)
def test_a_bad_goal_on_the_command_line_is_one_line(goal: str, error: str) -> None:
    done = subprocess.run(
        [sys.executable, "-m", "assistantx", "run", "--as", "lee", "--goal", goal, BORROW],
        env={**os.environ, "PYTHONPATH": str(BENCH.parent / "src")},
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert done.returncode == 2
    assert done.stderr.strip().startswith("error: ")
    assert error in done.stderr and len(done.stderr.strip().splitlines()) == 1


def _office_that_scans_to_pdf() -> Office:
    """The default office with a scan to PDF at its printer: the PDF is an electronic type
    of its own, sent to the paper's owner by message when the keeper scans it."""
    product = {"id": "scan_pdf", "name": "scanned PDF", "synonyms": ["pdf"]}
    return default_office_that_scans("scan", product)


def test_a_pdf_sent_by_message_by_the_scanner_is_delivered_to_the_papers_owner() -> None:
    """A scan to PDF hands the PDF over by message, not at the locker: the judge counts it
    as delivered to the paper's owner once the keeper took the paper to scan it (blind round
    77 counted 'scan my waybill to pdf' wrong although the PDF reached its owner)."""
    office = _office_that_scans_to_pdf()
    text = "scan my document to pdf please"
    factory = reasoner_factory("symbolic", office, Settings())
    run = asyncio.run(run_in_sim(office, "lee", text, factory, reasoner_name="symbolic"))
    scanned = json.loads(run.trace.model_dump_json())
    assert scanned["outcome"] == "done", scanned["summary"]
    mine = judge(case(text, "deliver", recipient="lee", item="scan_pdf"), scanned, office)
    assert (mine.right, mine.wrong_physical) == (True, None), mine.why
    theirs = judge(case(text, "deliver", recipient="chen", item="scan_pdf"), scanned, office)
    assert not theirs.right
