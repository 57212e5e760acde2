"""Blind round 17's reader classes, on a field studies centre built in the tests
(``helpers.field_centre``; the round's own office and sentences were never read). Each class
has its phrasings and the near-misses that must not change: safety first, so a reading the
reader is unsure of is asked, never acted on."""

from __future__ import annotations

import functools

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import DEFAULT_OFFICE, load_office
from assistantx.core.task_schema import TaskFrame
from helpers.field_centre import field_centre


@functools.cache
def _parser() -> InstructionParser:
    return InstructionParser(field_centre())


def _frame(text: str, requester: str = "bea", answers: tuple[str, ...] = ()) -> TaskFrame:
    return _parser().parse_with_answers(text, requester, list(answers))


def _moves(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


# -- class 7: an unsafe act is declined with its reason, nothing moves -----------------------


@pytest.mark.parametrize(
    "text",
    [
        "set light to Otto's banner so we can check the fireproofing took",
        "could you set fire to Otto's banner please",
        "torch Otto's banner, it's past saving anyway",
        "can you light the banner for me",
        "please set off the fire alarm so the group can practise",
        "microwave Tomás's torch for a minute",
    ],
)
def test_an_unsafe_act_is_declined_with_its_reason(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.question is None
    assert frame.decline is not None and "danger" in frame.decline


@pytest.mark.parametrize(
    ("text", "moves"),
    [
        ("bring me a torch", [("transfer", "torch", None, "bea")]),
        ("torch please", [("transfer", "torch", None, "bea")]),
        ("a torch for the cellar please", [("transfer", "torch", None, "bea")]),
        ("get me Tomás's torch", [("transfer", "torch", "tomas", "bea")]),
    ],
)
def test_a_torch_asked_for_is_still_fetched(text: str, moves: list[tuple[str, ...]]) -> None:
    assert _moves(_frame(text)) == moves


@pytest.mark.parametrize(
    ("text", "heats"),
    [
        ("please microwave my lunch box", True),
        ("my lunch is in the fridge, microwave it please", True),
        ("microwave Chen's stapler", False),
    ],
)
def test_microwaving_is_the_offices_service_only_on_what_it_heats(text: str, heats: bool) -> None:
    frame = InstructionParser(load_office(DEFAULT_OFFICE)).parse_with_answers(
        text, "lee", []
    )  # fix129e: lee has lunch
    if heats:
        assert [(t.kind, t.item) for t in frame.tasks] == [("heat", "lunch")]
    else:
        assert frame.tasks == [] and frame.decline is not None and "danger" in frame.decline


def test_a_negated_unsafe_act_moves_nothing() -> None:
    frame = _frame("don't set fire to Otto's banner")
    assert frame.tasks == []


async def test_the_banner_is_never_fetched_to_be_burnt() -> None:
    run = await run_instruction(
        field_centre(), "bea", "set light to Otto's banner so we can check the fireproofing took"
    )
    assert run.stm.trace.outcome == "unachievable"
    assert not {"move", "send_qr", "inquire"} & set(run.actions)


# -- class 1: a person named in a reason clause is never the recipient ---------------------


@pytest.mark.parametrize(
    "text",
    [
        "can I get a hi-vis vest from the kit store? covering the river walk for Fenella and "
        "they're all missing from the van",
        "can I get a hi-vis vest, covering for Fenella today",
        "covering for Fenella on the river walk, can I get a hi-vis vest?",
        "standing in for Fenella today so can I get a hi-vis vest",
        "can I get a hi-vis vest as I'm covering for Fenella",
        "could I have a hi-vis vest please, I'm filling in for Fenella",
        "could I get a hi-vis vest, I'm subbing for Fenella",
        "Fenella asked me to lead the walk so could I get a hi-vis vest",
        "Fenella is off so I'm leading the walk, can I get a hi-vis vest?",
        "covering the river walk for Fenella and the hi-vis vests are all missing, can I get one",
    ],
)
def test_the_person_stood_in_for_is_context_and_the_requester_gets_it(text: str) -> None:
    assert _moves(_frame(text)) == [("transfer", "hi_vis", None, "bea")]


@pytest.mark.parametrize(
    "text",
    [
        "can I get a hi-vis vest for Fenella",
        "could you get Fenella a hi-vis vest, she's leading the walk",
        "get a hi-vis vest for Fenella, she's covering the walk",
    ],
)
def test_a_recipient_named_for_the_thing_still_gets_it(text: str) -> None:
    assert _moves(_frame(text)) == [("transfer", "hi_vis", None, "fenella")]


@pytest.mark.parametrize(
    "text", ["looking for a hole punch, can you help", "needing a hole punch please"]
)
def test_a_participle_about_a_thing_still_asks_for_it(text: str) -> None:
    assert _moves(_frame(text)) == [("transfer", "hole_punch", None, "bea")]


@pytest.mark.parametrize(
    "text",
    [
        "covering the river walk for Fenella today",
        "I'm standing in for Fenella this afternoon",
    ],
)
def test_standing_in_said_alone_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None


async def test_the_vest_goes_to_the_requester_not_the_colleague_covered_for() -> None:
    run = await run_instruction(
        field_centre(),
        "bea",
        "can I get a hi-vis vest from the kit store? covering the river walk for Fenella and "
        "they're all missing from the van",
    )
    assert run.stm.trace.outcome == "done"
    assert run.sim.world.holder["hi_vis:kit_store"] == "bea"


# -- class 2: a named owner is never swapped for another; a shared name is asked -----------


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("Robin O's got a spare board pen hasn't he? could you nab it for me", "robin_o"),
        ("robin o's got a spare board pen hasnt he? could you nab it for me", "robin_o"),
        ("Robin O has a spare board pen, could you nab it for me", "robin_o"),
        ("could you nab Robin O's board pen for me", "robin_o"),
        ("Tomás has got a spare board pen hasn't he? could you grab it for me", "tomas"),
        ("tomás's got a board marker hasn't he? grab it for me please", "tomas"),
        ("Robin B's got some scissors hasn't he? can you get them for me", "robin_b"),
    ],
)
def test_the_owner_named_is_the_owner_asked(text: str, owner: str) -> None:
    assert [(t.item, t.owner, t.recipient) for t in _frame(text).tasks] == [
        ("board_marker" if "pen" in text or "marker" in text else "scissors", owner, "bea")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "Robin's got scissors, could you grab them for me",
        "Robin has a pair of scissors hasn't he? can you get them for me",
        "could you grab Robin's scissors for me",
    ],
)
def test_a_name_two_people_share_is_asked_never_anyones(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.question is not None and "Robin Baptiste" in frame.question
    assert "Robin Okonkwo" in frame.question


def test_the_answer_to_which_robin_names_the_owner() -> None:
    frame = _frame("Robin's got scissors, could you grab them for me", answers=("Robin O",))
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("scissors", "robin_o", "bea")]


@pytest.mark.parametrize(
    "text",
    ["Tomás has a board pen, doesn't he?", "Robin O's got a board pen hasn't he?"],
)
def test_a_tag_question_alone_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []


async def test_the_pen_comes_from_robin_o_not_from_another_owner() -> None:
    run = await run_instruction(
        field_centre(), "bea", "Robin O's got a spare board pen hasn't he? could you nab it for me"
    )
    assert run.stm.trace.outcome == "done"
    holder = run.sim.world.holder
    assert holder["board_marker:robin_o"] == "bea"
    assert holder["board_marker:tomas"] == "tomas" and holder["board_marker:fenella"] == "fenella"


# -- class 3: "could P have a X" makes P the recipient, not the lender -----------------------


@pytest.mark.parametrize(
    ("text", "item", "to"),
    [
        (
            "Could Nkechi have a pair of scissors please? She's doing the name cards.",
            "scissors",
            "nkechi",
        ),
        ("Could Linh have a pair of scissors? He's cutting out name cards", "scissors", "linh"),
        ("can Linh borrow a hole punch?", "hole_punch", "linh"),
        ("let Linh have a hole punch", "hole_punch", "linh"),
        # "Linh could do with a hole punch" is Linh's need, restated and asked as "Linh needs
        # a hole punch" is: test_named_want
        ("get Linh a hole punch please", "hole_punch", "linh"),
    ],
)
def test_the_person_asked_for_receives_anyones(text: str, item: str, to: str) -> None:
    assert _moves(_frame(text)) == [("transfer", item, None, to)]


@pytest.mark.parametrize(
    ("text", "moves"),
    [
        ("could I have Tomás's hole punch?", [("transfer", "hole_punch", "tomas", "bea")]),
        ("could Linh have Tomás's hole punch?", [("transfer", "hole_punch", "tomas", "linh")]),
    ],
)
def test_a_possessive_still_names_the_owner(text: str, moves: list[tuple[str, ...]]) -> None:
    assert _moves(_frame(text)) == moves


def test_having_a_look_at_a_paper_gives_nobody_the_paper() -> None:
    frame = _frame("could Marguerite have a look at my consent form")
    assert frame.tasks == [] and frame.question is not None


def test_a_need_said_as_a_fact_is_still_asked() -> None:
    frame = _frame("Linh needs a hole punch")
    assert frame.tasks == [] and frame.question is not None and "Linh" in frame.question


async def test_the_scissors_go_to_nkechi_from_an_owner_asked() -> None:
    run = await run_instruction(
        field_centre(),
        "bea",
        "Could Nkechi have a pair of scissors please? She's doing the name cards.",
    )
    assert run.stm.trace.outcome == "done"
    moved = [e.detail for e in run.sim.world.handovers()]
    assert moved[-1]["to"] == "nkechi" and moved[-1]["item"] != "scissors:nkechi"
    assert "inquire" in run.actions  # the owner was asked before anything moved


# -- class 4: "to P for a signature" is P's signing, its result back to the requester ------


@pytest.mark.parametrize(
    "text",
    [
        "could you take my permission slip to the deputy for a signature? she said she'd sign "
        "it today",
        "take my consent form to Marguerite for a signature",
        "take my consent form to Marguerite for her signature",
        "take my consent form to the Deputy Head for signing",
        "could you take my permission slip to Marguerite for her to sign",
        "send the deputy my consent form for a signature",
    ],
)
def test_the_signer_signs_and_the_paper_comes_back(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks] == [
        ("sign", "consent_form", "bea", "bea", "marguerite")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "could you take my permission slip to the deputy for a signature and then on to Nkechi",
        "take my consent form to Marguerite for her signature and then to Nkechi",
        "take my consent form to Marguerite for a signature, then give it to Nkechi",
    ],
)
def test_a_recipient_named_after_the_signer_gets_the_signed_paper(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.recipient, t.actor) for t in frame.tasks] == [
        ("sign", "nkechi", "marguerite")
    ]


def test_taking_a_paper_to_someone_with_no_signature_asked_is_still_a_hand_over() -> None:
    assert _moves(_frame("take my consent form to the deputy")) == [
        ("transfer", "consent_form", "bea", "marguerite")
    ]


async def test_the_signed_slip_is_brought_back_to_the_requester() -> None:
    run = await run_instruction(
        field_centre(),
        "bea",
        "could you take my permission slip to the deputy for a signature? she said she'd sign "
        "it today",
    )
    assert run.stm.trace.outcome == "done"
    world = run.sim.world
    assert ("consent_form:bea", "marguerite") in world.signed
    assert world.holder["consent_form:bea"] == "bea"


# -- class 5: "mine" is the requester's own item of the kind just named ---------------------


@pytest.mark.parametrize(
    "text",
    [
        "Hattie's hole punch has packed in, can you take mine down to her in repro",
        "Hattie's hole punch has packed in, can you take mine down to Hattie in repro",
        "Hattie's hole punch is broken, can you take mine to her",
        "Hattie's hole punch has packed in, could you run mine over to her",
    ],
)
def test_mine_is_my_item_of_the_kind_named(text: str) -> None:
    assert _moves(_frame(text)) == [("transfer", "hole_punch", "bea", "hattie")]


def test_mine_with_no_kind_named_is_asked_never_printed() -> None:
    frame = _frame("can you take mine down to Hattie in repro")
    assert frame.tasks == [] and frame.question is not None


@pytest.mark.parametrize(
    ("text", "moves"),
    [
        ("put my worksheet through repro for Hattie", [("print", "file", "bea", "hattie")]),
        ("take my hole punch to Hattie", [("transfer", "hole_punch", "bea", "hattie")]),
        (
            "Could you bring me a hole punch? Mine just died.",
            [("transfer", "hole_punch", None, "bea")],
        ),
        ("mine's broken, could you get me a hole punch", [("transfer", "hole_punch", None, "bea")]),
    ],
)
def test_a_service_asked_at_the_room_and_my_named_item_are_read_as_before(
    text: str, moves: list[tuple[str, ...]]
) -> None:
    assert _moves(_frame(text)) == moves


async def test_my_hole_punch_reaches_hattie_in_repro() -> None:
    run = await run_instruction(
        field_centre(),
        "bea",
        "Hattie's hole punch has packed in, can you take mine down to her in repro",
    )
    assert run.stm.trace.outcome == "done"
    assert run.sim.world.holder["hole_punch:bea"] == "hattie"
    assert not run.sim.world.printed


# -- class 6: "the file not a printout" chooses the owner's file, forwarded ----------------


@pytest.mark.parametrize(
    "text",
    [
        "get Tomás to send me his yr10 field guide would you, the file not a printout",
        "get Tomás to send me his field guide, the file not a hard copy",
        "ask Tomás to send me his year 10 scheme of work, the pdf not a printout",
        "could you get Tomás to send me his yr9 lesson plan, the file not a printout",
    ],
)
def test_the_owners_file_is_forwarded(text: str) -> None:
    assert _moves(_frame(text)) == [("send_file", "file", "tomas", "bea")]


@pytest.mark.parametrize(
    "text",
    [
        "get Tomás to send me his yr10 field guide please, not a printout",
        "get Tomás to send me his yr10 field guide would you",
    ],
)
def test_an_unnamed_thing_with_no_kind_chosen_is_asked_never_printed(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("bring me scissors, not the board marker", "scissors"),
        ("a board marker, not scissors", "board_marker"),
        ("can I have a board marker please? not a torch", "board_marker"),
    ],
)
def test_the_thing_rejected_is_never_fetched(text: str, item: str) -> None:
    assert _moves(_frame(text)) == [("transfer", item, None, "bea")]


async def test_the_file_is_forwarded_and_nothing_printed() -> None:
    run = await run_instruction(
        field_centre(),
        "bea",
        "get Tomás to send me his yr10 field guide would you, the file not a printout",
    )
    assert run.stm.trace.outcome == "done"
    assert ("bea", "file:tomas") in run.sim.world.received
    assert not run.sim.world.printed and not run.sim.world.made
