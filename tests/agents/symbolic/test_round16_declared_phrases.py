"""An office's own operations asked for by a phrase of several words it declares ("3D print",
"laser cut", "vinyl cut", "heat press"), on two workshops no sentence was written for
(``helpers.fablab``; the blind round's office and sentences were never read): the longest
declared phrase says the operation, never the shorter verb inside it ("print" is the
plotter's), in its case, hyphen and spacing variants; a thing whose name holds a phrase's
word ("laser measure") or is the phrase itself after a determiner ("the heat press") stays a
thing; a question, thanks or a negation with the phrase moves nothing."""

from __future__ import annotations

import functools

import pytest
from symbolic_run import answer_first_question, run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.verb_phrases import VerbPhrases
from assistantx.core.office import Office
from assistantx.core.ports.messenger import ChatRef
from assistantx.core.task_schema import TaskFrame
from helpers.fablab import costume_works, fablab

_OFFICES = {"fablab": fablab, "costume_works": costume_works}


@functools.cache
def _parser(office: str) -> InstructionParser:
    return InstructionParser(_OFFICES[office]())


def _frame(office: str, text: str, who: str) -> TaskFrame:
    return _parser(office).parse(text, who)


def _tasks(frame: TaskFrame) -> list[tuple[str | None, str | None, str]]:
    return [(t.item, t.operation, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("office", "who", "text", "tasks"),
    [
        # the fablab: "3d print" holds the plotter's "print"
        (
            "fablab",
            "ines",
            "3d print the stl I attached and drop it at my desk",
            [("design_file", "print3d", "ines")],
        ),
        (
            "fablab",
            "ines",
            "could you 3d print my file? bring it here when done",
            [("design_file", "print3d", "ines")],
        ),
        ("fablab", "ines", "can you 3D-print my file", [("design_file", "print3d", "ines")]),
        ("fablab", "ines", "3-D print my file", [("design_file", "print3d", "ines")]),
        ("fablab", "tomas", "could you 3 D print my file", [("design_file", "print3d", "tomas")]),
        ("fablab", "hana", "Could you 3D print my stl?", [("design_file", "print3d", "hana")]),
        ("fablab", "ines", "can I get my file 3D printed", [("design_file", "print3d", "ines")]),
        ("fablab", "gus", "I need my file 3d printed", [("design_file", "print3d", "gus")]),
        (
            "fablab",
            "ines",
            "3d print my file on the 3D printer",
            [("design_file", "print3d", "ines")],
        ),
        # "laser cut" is the laser cutter's name of its work (its verbs: laser, lasercut)
        (
            "fablab",
            "ines",
            "can you laser cut my file for the model",
            [("design_file", "cut", "ines")],
        ),
        (
            "fablab",
            "ines",
            "laser cut my file and bring the bits to Tomas",
            [("design_file", "cut", "tomas")],
        ),
        ("fablab", "hana", "could you laser-cut my design file", [("design_file", "cut", "hana")]),
        (
            "fablab",
            "ines",
            "could you get my file laser cut and bring the bits to Tomas",
            [("design_file", "cut", "tomas")],
        ),
        ("fablab", "gus", "lasercut my file please", [("design_file", "cut", "gus")]),
        # the costume works: phrases whose first word is no verb, or another service's
        ("costume_works", "ada", "vinyl cut my artwork", [("artwork", "vinyl", "ada")]),
        (
            "costume_works",
            "ada",
            "could you get my file vinyl cut",
            [("artwork", "vinyl", "ada")],
        ),
        ("costume_works", "bram", "laser engrave my artwork", [("artwork", "engrave", "bram")]),
        ("costume_works", "ada", "heat press my artwork", [("artwork", "heatpress", "ada")]),
        (
            "costume_works",
            "ada",
            "could you heat-press my file and bring it to Bram",
            [("artwork", "heatpress", "bram")],
        ),
        (
            "costume_works",
            "cleo",
            "can you heat press my artwork",
            [("artwork", "heatpress", "cleo")],
        ),
        ("costume_works", "ada", "can you mill my file", [("artwork", "rout", "ada")]),
        ("costume_works", "ada", "can you CNC my artwork", [("artwork", "rout", "ada")]),
    ],
)
def test_the_longest_declared_phrase_names_the_operation(
    office: str, who: str, text: str, tasks: list[tuple[str, str, str]]
) -> None:
    frame = _frame(office, text, who)
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == tasks


@pytest.mark.parametrize(
    ("office", "who", "text", "tasks"),
    [
        ("fablab", "ines", "print my file", [("design_file", "plot", "ines")]),
        (
            "fablab",
            "ines",
            "plot my file and bring it to Tomas",
            [("design_file", "plot", "tomas")],
        ),
        ("fablab", "ines", "print my file on the plotter", [("design_file", "plot", "ines")]),
        ("fablab", "ines", "bring me the laser measure", [("laser_measure", None, "ines")]),
        ("fablab", "hana", "can I borrow Tomas's laser measure", [("laser_measure", None, "hana")]),
        ("costume_works", "ada", "press my costume", [("costume", None, "ada")]),
        ("costume_works", "ada", "engrave my file", [("artwork", "engrave", "ada")]),
    ],
)
def test_the_shorter_verb_and_the_things_keep_their_reading(
    office: str, who: str, text: str, tasks: list[tuple[str, str | None, str]]
) -> None:
    frame = _frame(office, text, who)
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == tasks


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("fablab", "ines", "did you 3d print my file?"),
        ("fablab", "ines", "thanks for 3d printing my file"),
        ("fablab", "ines", "don't 3d print my file"),
        ("fablab", "ines", "who runs the 3D printer?"),
        ("fablab", "ines", "never mind the laser cut, I did it myself"),
        ("costume_works", "ada", "is the heat press free?"),
    ],
)
def test_the_phrase_outside_a_request_moves_nothing(office: str, who: str, text: str) -> None:
    assert not _frame(office, text, who).tasks


def test_the_verb_of_one_machine_at_another_named_is_asked_about() -> None:
    """ "print" is the plotter's verb; said at the 3D printer, which is meant is the
    requester's to say: never both, never a guess."""
    frame = _frame("fablab", "print my file on the 3D printer", "ines")
    assert not frame.tasks
    assert frame.question == "Which do you mean: plot or 3D print?"


def test_the_machine_named_after_a_determiner_is_a_thing() -> None:
    lex = Lexicon.from_office(costume_works())
    joined = lex.read("could you heat press my file")
    assert [t.word for t in joined.tokens] == ["could", "you", "heat press", "my", "file"]
    thing = lex.read("take my costume to the heat press")
    assert [t.word for t in thing.tokens][-2:] == ["heat", "press"]
    assert [m.kind for m in thing.mentions if m.text == "heat press"] == ["facility"]


def test_a_joined_phrase_keeps_its_typed_text() -> None:
    lex = Lexicon.from_office(fablab())
    tokens = lex.read("Could you 3D-print it").tokens
    assert [(t.text, t.word) for t in tokens][2] == ("3D-print", "3d print")


def _phrases(office: Office) -> dict[str, str]:
    return VerbPhrases.from_office(office).forms


def test_the_phrases_come_from_the_office_file() -> None:
    """Verbs of several words, every form; a name that opens with one of its own verbs
    ("laser cut" of the operation asked for by "laser"); never a name that names a thing
    ("make up a kit bag"): the product is named, and read, on its own."""
    forms = _phrases(fablab())
    assert forms["3d print"] == forms["3d printed"] == forms["3d printing"] == "print3d"
    assert forms["laser cut"] == forms["laser cutting"] == "cut"
    assert not [f for f in forms if "kit bag" in f]
    costume = _phrases(costume_works())
    assert costume["heat press"] == "heatpress"
    assert costume["vinyl cut"] == "vinyl"
    assert "press" not in costume  # one word: the lexicon's, as before


async def test_the_3d_print_goes_to_the_3d_printer_and_comes_back() -> None:
    run = await run_instruction(
        fablab(), "ines", "3d print the stl I attached and drop it at my desk"
    )
    assert run.stm.trace.outcome == "done"
    moved = [r.action for r in run.stm.trace.actions() if r.action.type == "forward_file"]
    assert [(a.source, a.target) for a in moved] == [("ines", "priit")]  # type: ignore[union-attr]
    assert not [r for r in run.stm.trace.actions() if r.refused]
    assert run.sim.world.holder["model_part:ines"] == "ines"


async def test_the_laser_cut_parts_go_to_the_colleague_named() -> None:
    run = await run_instruction(fablab(), "ines", "laser cut my file and bring the bits to Tomas")
    assert run.stm.trace.outcome == "done"
    assert not [r for r in run.stm.trace.actions() if r.refused]
    assert run.sim.world.holder["cut_parts:ines"] == "tomas"


async def test_the_heat_press_runs_beside_the_wardrobe_that_presses() -> None:
    run = await run_instruction(
        costume_works(), "ada", "could you heat-press my file and bring it to Bram"
    )
    assert run.stm.trace.outcome == "done"
    assert run.sim.world.holder["transfer:ada"] == "bram"


async def test_a_yes_in_the_group_from_another_machines_keeper_binds_nobody() -> None:
    """The 3D printer's keeper is away; the plotter's keeper says yes in the group to "could
    anyone 3D print ... at the 3D printer?": no file goes to her, no code, nothing refused."""
    asked: list[str] = []
    hook = answer_first_question(
        "all", "hana", ChatRef(kind="group", id="all"), "Yes, sure!", asked
    )
    run = await run_instruction(
        fablab(), "ines", "3d print my file please", unavailable=("priit",), on_event=hook
    )
    assert asked and "3D print" in asked[0]
    assert "forward_file" not in run.actions and "send_qr" not in run.actions
    assert not [r for r in run.stm.trace.actions() if r.refused]
    assert run.stm.trace.outcome != "done"


def test_two_services_verbs_glued_together_are_asked_about() -> None:
    """ "laser print" is no phrase the office declares: the laser cutter's "laser" and the
    plotter's "print" side by side are one compound, not two requests; "laser and plot" is
    two."""
    frame = _frame("fablab", "laser print my file", "ines")
    assert not frame.tasks and frame.question == "Which do you mean: laser cut or plot?"
    both = _frame("fablab", "laser and plot my file", "ines")
    assert [t.operation for t in both.tasks] == ["cut", "plot"]


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("could someone print my file?", [("design_file", "plot", "ines")]),
        ("can anybody 3d print my file", [("design_file", "print3d", "ines")]),
        ("could someone make up a kit bag for Tomas?", [("kit_bag", None, "tomas")]),
    ],
)
def test_who_is_asked_is_no_modifier_of_the_verb(
    text: str, tasks: list[tuple[str, str | None, str]]
) -> None:
    """ "could someone print it" was declined as "I can't someone print"."""
    frame = _frame("fablab", text, "ines")
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == tasks


def test_a_missing_service_asked_of_someone_is_declined_by_its_verb() -> None:
    frame = _frame("fablab", "could someone scan my drawings", "ines")
    assert not frame.tasks and frame.decline is not None
    assert frame.decline.startswith("Sorry, I can't scan:")
