"""The symbolic ppdr on offices whose electronic file type is not called ``file`` (issue 23):
the requester's ``script`` or ``drawing`` is worked on at the machine, handed over, sent to a
colleague, and asked for from one; and the two-part errand whose file goes to a keeper of the
machine that works on it reaches both people, the file forwarded once."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.actions import ForwardFile
from assistantx.core.events import TraceEvent
from assistantx.core.goals import Milestone
from assistantx.core.office import Office, load_office
from assistantx.core.ports.messenger import ChatRef, persons_file
from assistantx.core.wording import file_noun
from assistantx.sim.office import SimOffice
from helpers.rehearsal_rooms import drafting_studio, rehearsal_rooms

OFFICES = {"script": rehearsal_rooms, "drawing": drafting_studio}

CASES = [
    (
        "script",
        "priya",
        "Could you make up a rehearsal script pack from my script?",
        [{"printed": "script:priya"}, {"holds": ["priya", "script_pack:priya"]}],
    ),
    (
        "script",
        "priya",
        "Please make up a script pack from my script and take it to Bruno.",
        [{"holds": ["bruno", "script_pack:priya"]}],
    ),
    (
        "script",
        "priya",
        "Send my script to Kwesi, please.",
        [{"received": ["kwesi", "script:priya"]}],
    ),
    ("script", "kwesi", "can you get me Bruno's script", [{"received": ["kwesi", "script:bruno"]}]),
    (
        "drawing",
        "femi",
        "Could you plot my drawing?",
        [{"printed": "drawing:femi"}, {"holds": ["femi", "plot:femi"]}],
    ),
    (
        "drawing",
        "femi",
        "Please plot my drawing and take it to Greta.",
        [{"holds": ["greta", "plot:femi"]}],
    ),
    ("drawing", "greta", "pass my drawing on to Yusuf", [{"received": ["yusuf", "drawing:greta"]}]),
    (
        "drawing",
        "yusuf",
        "Could you get me Femi's drawing?",
        [{"received": ["yusuf", "drawing:femi"]}],
    ),
]


def _office(name: str) -> Office:
    return OFFICES[name]()


@pytest.mark.parametrize(
    ("office", "who", "text", "goal"), CASES, ids=[f"{c[0]}-{n}" for n, c in enumerate(CASES)]
)
async def test_the_file_errand_is_done(
    office: str, who: str, text: str, goal: list[Milestone]
) -> None:
    run = await run_instruction(_office(office), who, text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert all(run.sim.world.check(m) for m in goal), goal
    assert not [r for r in run.stm.trace.actions() if r.refused]


@pytest.mark.parametrize(
    ("to", "forwards"),
    [("Tomas", [("ines", "tomas")]), ("Kwesi", [("ines", "tomas"), ("ines", "kwesi")])],
    ids=["to-the-keeper", "to-a-colleague"],
)
async def test_the_pack_goes_to_one_and_the_script_to_the_other(
    to: str, forwards: list[tuple[str, str]]
) -> None:
    """Ines keeps the photocopier with Tomas: Tomas makes the pack, Bruno gets it, and the
    script reaches ``to``; when that is Tomas, the one forward for the pack is it."""
    text = f"Please make up a script pack from my script for Bruno and send my script to {to}."
    run = await run_instruction(rehearsal_rooms(), "ines", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"holds": ["bruno", "script_pack:ines"]})
    assert run.sim.world.check({"received": [to.lower(), "script:ines"]})
    done = [r.action for r in run.stm.trace.actions() if not r.refused]
    assert [(a.source, a.target) for a in done if isinstance(a, ForwardFile)] == forwards
    assert not [r for r in run.stm.trace.actions() if r.refused]


async def test_a_file_labelled_by_a_messenger_that_knows_no_office_is_the_senders() -> None:
    """Matrix labels a file Bruno sends ``file:bruno`` (it cannot know the office calls its
    files scripts): the runtime reads it as Bruno's script, so the one Kwesi asked for is
    seen to have come and is passed on."""
    asked: list[str] = []

    async def hook(event: TraceEvent, sim: SimOffice) -> None:
        # Bruno's own simulated self is away: he answers the first question with his file
        result = event.data.get("result")
        if event.kind != "action_result" or not isinstance(result, dict) or asked:
            return
        action = result["action"]
        if action["type"] == "inquire" and action["contact"] == "bruno":
            asked.append(action["question"])
            sim.messenger.post(
                "bruno",
                ChatRef(kind="dm", id="bruno"),
                "here it is",
                files=[persons_file("bruno")],
                in_reply_to=result["data"]["question_id"],
            )

    run = await run_instruction(
        rehearsal_rooms(),
        "kwesi",
        "can you get me Bruno's script",
        unavailable=("bruno",),
        on_event=hook,
    )
    assert asked, "Bruno was never asked"
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"received": ["kwesi", "script:bruno"]})
    assert run.stm.files_received.get("bruno") == ["script:bruno"]


# -- the words: the office's name for its files, "file" where the office calls them so -------


@pytest.mark.parametrize(
    ("office", "who", "text", "said", "not_said"),
    [
        (
            "script",
            "priya",
            "Could you make up a rehearsal script pack from my script?",
            "the rehearsal script pack of your script was handed to you",
            "your file",
        ),
        ("script", "priya", "Send my script to Kwesi, please.", "your script was passed", "file"),
        ("drawing", "yusuf", "Could you get me Femi's drawing?", "Femi Adeyemi's drawing", "file"),
    ],
    ids=["made-from-it", "passed-on", "asked-for"],
)
async def test_the_outcome_names_the_file_as_the_office_does(
    office: str, who: str, text: str, said: str, not_said: str
) -> None:
    run = await run_instruction(_office(office), who, text)
    summary = run.stm.trace.summary or ""
    assert said in summary and not_said not in summary, summary


async def test_the_default_office_still_says_file() -> None:
    """Its type is an "electronic file", also called a "file": said the short way."""
    run = await run_instruction(load_office(), "zhou", "Print my file and bring it to me.")
    assert "the printout of your file was handed to you" in (run.stm.trace.summary or "")


@pytest.mark.parametrize(
    ("office", "who", "text", "question"),
    [
        ("script", "priya", "forward my script", "Who should I pass your script on to?"),
        ("drawing", "greta", "send my drawing on", "Who should I pass your drawing on to?"),
    ],
)
def test_whom_to_pass_it_on_to_is_asked_in_the_offices_words(
    office: str, who: str, text: str, question: str
) -> None:
    frame = InstructionParser(_office(office)).parse(text, who)
    assert (frame.tasks, frame.question) == ([], question)


@pytest.mark.parametrize(
    ("office", "noun"),
    [(rehearsal_rooms(), "script"), (drafting_studio(), "drawing"), (load_office(), "file")],
    ids=["script", "drawing", "default"],
)
def test_the_file_noun(office: Office, noun: str) -> None:
    assert file_noun(office) == noun
