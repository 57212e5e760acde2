"""The reader on an office nobody wrote it for (``_survey_office``), with new sentences, by
the failure classes of blind round 5 (never its sentences): only a request moves the robot;
the rest is answered in words, and a need for later is answered and offered, not fetched."""

from __future__ import annotations

import pytest
from _survey_office import REQUESTER, office, parser
from _survey_office import read as _read
from symbolic_run import run_instruction

from assistantx.agents.symbolic import build_factory
from assistantx.core.settings import Settings
from assistantx.sim.office import SimOffice
from helpers.office import run_one, sim_assistant


@pytest.mark.parametrize(
    "text",
    [
        # a condition with information beside it
        "if Wren ever needs a ruler, Ciaran has one",
        "in case anyone asks, the spare umbrella is Wren's",
        # a note to keep, also when its verb is someone's name
        "note this down: the tape ran out; no need to do anything",
        "mark this down: Hedda is away next week",
        "jot this down: Priya is off on Friday",
        "Mark this down please: Wren's umbrella is in the kitchen",
        "note to self: Bill has the spare calculator",
        "just for your records, Bill has the spare calculator",
        "Note this down. Ciaran needs his laser measure on Friday.",
        # a hedged wish about a facility
        "it'd be nice if the supply cupboard had more tape",
        "it'd be lovely if the kettle were quicker",
        # a past report that closes a matter
        "Hedda returned my umbrella this morning, all sorted",
        "Bill gave back my calculator yesterday, all good now",
    ],
)
def test_a_message_that_asks_for_nothing_is_answered_in_words(text: str) -> None:
    tasks, question, decline = _read(text)
    assert tasks == [] and question is None, (tasks, question)
    assert decline and decline.startswith("Noted"), decline


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        ("please note I need a ruler", [("transfer", "ruler", None, REQUESTER)]),
        (
            "if you could bring me a ruler that would be great",
            [("transfer", "ruler", None, REQUESTER)],
        ),
        ("when Ciaran is back, bring me his ruler", [("transfer", "ruler", "ciaran", REQUESTER)]),
        ("if possible bring me a calculator", [("transfer", "calculator", None, REQUESTER)]),
    ],
)
def test_a_request_beside_a_note_or_condition_is_still_read(
    text: str, wanted: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _read(text)[0] == wanted


@pytest.mark.parametrize(
    ("text", "owners"),
    [
        ("does anyone own a laser measure I could use later?", ("Ciaran O'Keeffe", "Hedda Moss")),
        ("does anyone have a ruler I could borrow tomorrow?", ("Ciaran O'Keeffe", "Wren Halloway")),
        ("does anybody have a calculator I could borrow on Thursday?", ("Bill Okafor",)),
    ],
)
def test_a_need_for_later_is_answered_and_offered_never_fetched_now(
    text: str, owners: tuple[str, ...]
) -> None:
    """Answered (who has one, and the offer for then in words), never left as a question
    open on it, nothing fetched now."""
    tasks, question, decline = _read(text)
    assert tasks == [] and question is None, question
    assert decline is not None and "when" in decline, decline
    assert all(name in decline for name in owners), decline


def test_a_need_for_now_is_still_fetched() -> None:
    assert _read("does anyone have a ruler I could borrow?")[0] == [
        ("transfer", "ruler", None, REQUESTER)
    ]


@pytest.mark.parametrize(
    "text",
    [
        "bring me Ciaran O'Keeffe's ruler",
        "bring me O'Keeffe's ruler",
        "could you fetch Ciaran O’Keeffe’s ruler for me",
    ],
)
def test_a_surname_with_an_apostrophe_names_its_owner(text: str) -> None:
    assert _read(text)[0] == [("transfer", "ruler", "ciaran", REQUESTER)]


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        (
            "can you bring me Wren's umbrella, sorry, her ruler, not the umbrella",
            [("transfer", "ruler", "wren", REQUESTER)],
        ),
        (
            "bring me Ciaran's ruler, oops, the laser measure not the ruler",
            [("transfer", "laser", "ciaran", REQUESTER)],
        ),
        (
            "get me some tape from the supply cupboard and Ciaran's ruler, sorry, the laser "
            "measure not the ruler",
            [("transfer", "tape", None, REQUESTER), ("transfer", "laser", "ciaran", REQUESTER)],
        ),
    ],
)
def test_a_corrected_item_replaces_the_withdrawn_one(
    text: str, wanted: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _read(text)[0] == wanted


async def test_the_withdrawn_item_is_never_fetched_from_anyone() -> None:
    """The supply comes from the cupboard with nobody's yes, the colleague's item with its
    owner's; the ruler the requester took back moves from no one's desk."""
    run = await run_instruction(
        office(),
        REQUESTER,
        "could you get me some tape from the supply cupboard and Ciaran's ruler, sorry, "
        "his laser measure, not the ruler",
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    world = run.sim.world
    assert world.check({"holds": [REQUESTER, "tape:cupboard"]})
    assert world.check({"holds": [REQUESTER, "laser:ciaran"]})
    assert world.holder["ruler:ciaran"] != REQUESTER and world.holder["ruler:wren"] != REQUESTER
    asked = " ".join(m.text for m in run.sim.messenger.sent).lower()
    assert "ruler" not in asked, asked


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("Wren lent me her umbrella, please return it to her; it's on my desk", "umbrella", "wren"),
        ("I borrowed Ciaran's ruler, can you take it back to him", "ruler", "ciaran"),
        (
            "Hedda lent me her laser measure, could you give it back to her? it's on my desk",
            "laser",
            "hedda",
        ),
    ],
)
def test_an_item_given_back_is_taken_from_whoever_has_it_now(
    text: str, item: str, owner: str
) -> None:
    frame = parser().parse(text, REQUESTER)
    assert [(t.kind, t.item, t.owner, t.recipient, t.source) for t in frame.tasks] == [
        ("transfer", item, owner, owner, REQUESTER)
    ], frame.question


def test_a_return_with_no_holder_named_is_taken_from_the_speaker() -> None:
    """Giving back says the speaker has it (``reading/given_back``): the office file's record
    that its owner does is out of date, so it is collected from the speaker."""
    frame = parser().parse("please return Wren's umbrella to her", REQUESTER)
    assert [(t.item, t.owner, t.recipient, t.source) for t in frame.tasks] == [
        ("umbrella", "wren", "wren", REQUESTER)
    ]


def test_a_return_of_an_item_the_office_does_not_know_as_theirs_is_taken_from_the_speaker() -> None:
    """The speaker says whose it is and that they were lent it: no "already has" question."""
    frame = parser().parse("Hedda lent me her umbrella, please bring it back to her", REQUESTER)
    assert frame.question is None
    assert [(t.item, t.owner, t.recipient, t.source) for t in frame.tasks] == [
        ("umbrella", "hedda", "hedda", REQUESTER)
    ]


async def test_the_lent_item_goes_from_the_borrower_back_to_its_lender() -> None:
    sim = SimOffice(office())
    sim.world.holder["umbrella:wren"] = REQUESTER  # the truth: Wren lent it to Tomasz
    assistant = sim_assistant(sim, build_factory(office(), Settings()))
    stm = await run_one(
        sim,
        assistant,
        REQUESTER,
        "Wren lent me her umbrella last week, please return it to her. It's on my desk.",
    )
    assert stm.trace.outcome == "done", stm.trace.summary
    assert sim.world.check({"holds": ["wren", "umbrella:wren"]})


@pytest.mark.parametrize(
    ("text", "where"),
    [
        ("can you send out my report to Harlow & Finch", "Harlow & Finch"),
        # a role or firm alone ("the client", "our lawyers") asks where since fix129e
        ("send out my drawing to the client's office today", "the client's office"),
        (
            "please courier my contract to our lawyers at 4 Quay Street",
            "our lawyers at 4 Quay Street",
        ),
        # a task word as the item's adjective says what was done, not what to do
        ("please send out the signed drawing to our surveyors in Leeds", "our surveyors in Leeds"),
    ],
)
def test_a_send_out_service_sends_to_the_place_outside(text: str, where: str) -> None:
    frame = parser().parse(text, REQUESTER)
    assert [(t.operation, t.destination, t.recipient) for t in frame.tasks] == [
        ("courier", where, REQUESTER)
    ], frame.question


def test_a_send_out_to_a_colleagues_name_is_asked_then_sent_as_answered() -> None:
    """ "courier my drawing to Bill" where Bill works here: sending it outside and handing it
    to Bill are different physical actions (blind round 7), so the reader asks; "send it
    out" sends it to the place as written."""
    text = "courier my drawing to Bill"
    first = parser().parse(text, REQUESTER)
    assert first.tasks == [] and first.question and "bring it to Bill" in first.question
    frame = parser().parse_with_answers(text, REQUESTER, ["send it out please"])
    assert [(t.operation, t.destination, t.recipient) for t in frame.tasks] == [
        ("courier", "Bill", REQUESTER)
    ]


@pytest.mark.parametrize("answer", ["the client", "to our lawyers", "Harlow & Finch."])
def test_the_answer_to_where_is_the_place_outside_asked_once(answer: str) -> None:
    first = parser().parse("send out my drawing.", REQUESTER)
    assert first.question and first.question.startswith("Where should I courier")
    frame = parser().parse_with_answers("send out my drawing.", REQUESTER, [answer])
    assert [(t.operation, t.recipient) for t in frame.tasks] == [("courier", REQUESTER)]
    assert frame.tasks[0].destination == answer.removeprefix("to ").rstrip(".")


@pytest.mark.parametrize(
    ("text", "signer"),
    [
        ("can you get Wren to sign off the bill? it's the invoice on my desk", "wren"),
        ("please have Hedda sign off the bill. It's the invoice on my desk.", "hedda"),
        ("get Wren to sign the bill, it's the invoice on my desk", "wren"),
    ],
)
def test_an_item_named_in_a_later_sentence_is_the_one_meant(text: str, signer: str) -> None:
    """ "the bill" is no item word here (and Bill is a colleague's name); the sentence after
    it names the office's signable paper, so that is the one to sign."""
    frame = parser().parse(text, REQUESTER)
    assert [(t.kind, t.item, t.owner, t.actor) for t in frame.tasks] == [
        ("sign", "document", REQUESTER, signer)
    ], frame.question


@pytest.mark.parametrize(
    "text", ["get Wren to sign off the bill", "get Wren to sign off the bill, it's by my ruler"]
)
def test_with_no_such_item_named_elsewhere_the_item_is_asked(text: str) -> None:
    frame = parser().parse(text, REQUESTER)
    assert frame.tasks == [] and frame.question and "item" in frame.question
