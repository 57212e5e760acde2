"""Blind round 14's speech-act classes, by mechanism, on sentences of our own against a small
photo studio no sentence was written for (``helpers.photo_studio``): what kind of act a message or
a piece of it is (a statement, a question, an aside, a correction, a reason, a withdrawal),
never moving anything on a piece that asks for nothing (the round's own office and sentences
were never read)."""

from __future__ import annotations

import functools

import pytest
from symbolic_run import run_instruction

from assistantx.core.task_schema import TaskFrame
from helpers.photo_studio import studio
from helpers.reading import frame_reader, parser_for

_parser = functools.partial(parser_for, studio)
_frame = frame_reader(studio, "lotte")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


# -- 5. a reason clause is no withdrawal ----------------------------------------------------


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("take my mug to Kwame, he lent me his last week and his went missing", "kwame"),
        ("take my mug over to Farida - she lent me hers yesterday and hers is lost now", "farida"),
        ("bring my mug to Kwame, Farida lent me hers the other day and it's gone", "kwame"),
        ("take my mug to Kwame, his went missing", "kwame"),
    ],
)
def test_a_reason_told_with_the_request_does_not_withdraw_it(text: str, recipient: str) -> None:
    """What someone did before the asking ("lent me his last week") and what happened to
    their own thing ("his went missing") is why the request is made, not news that it is
    had already: the request is done."""
    frame = _frame(text)
    assert frame.decline is None, frame.decline
    assert frame.question is None, frame.question
    assert _tasks(frame) == [("transfer", "mug", "lotte", recipient)]


@pytest.mark.parametrize(
    "text",
    [
        "take my mug to Kwame, forget it",
        "take my mug to Kwame. actually never mind, Farida already lent me hers",
        "bring me a tape measure - oh wait, Teodor lent me his",
        "bring me a tape measure, cancel that",
    ],
)
def test_a_withdrawal_of_the_request_itself_still_drops_it(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.decline is not None and "dropped" in frame.decline


# -- 2. "who has an X I could use (tomorrow)?" is answered ----------------------------------


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("who has a magnifier I could use tomorrow?", "Kwame Osei"),
        ("who's got a tape measure I could borrow on Friday?", "Teodor Novak"),
        ("does anyone have a ruler I could borrow this afternoon?", "Teodor Novak"),
    ],
)
def test_a_question_about_a_later_need_is_answered_and_nothing_asked(text: str, owner: str) -> None:
    """A time after now: who has one, and the offer for then in words; no question is left
    open and nothing is fetched now."""
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None
    assert frame.decline is not None and frame.decline_outcome == "done"
    assert owner in frame.decline and "tell me when" in frame.decline.lower()


def test_a_question_for_now_is_still_answered_and_offered() -> None:
    frame = _frame("who's got a tape measure I could borrow?")
    assert frame.tasks == []
    assert frame.question is not None
    assert "Teodor Novak" in frame.question and frame.question.endswith("Shall I bring you one?")


@pytest.mark.parametrize(
    "reply", ["hmm, not sure", "I'll ask him myself", "maybe later", "tomorrow is fine"]
)
def test_a_reply_that_is_no_yes_for_now_ends_the_answer(reply: str) -> None:
    """The question was answered already: a reply that does not accept the offer for now
    (unsure, the requester's own plan, a later time) ends as the answer, nothing fetched."""
    frame = _parser().parse_with_answers(
        "who's got a tape measure I could borrow?", "lotte", [reply]
    )
    assert frame.tasks == [] and frame.question is None
    assert frame.decline is not None and frame.decline_outcome == "done"


def test_a_plain_yes_still_fetches_and_a_no_still_declines() -> None:
    asked = "who's got a tape measure I could borrow?"
    yes = _parser().parse_with_answers(asked, "lotte", ["yes please"])
    assert _tasks(yes) == [("transfer", "tape_measure", None, "lotte")]
    no = _parser().parse_with_answers(asked, "lotte", ["no thanks"])
    assert no.tasks == [] and no.decline_outcome == "done"


def test_not_sure_is_no_yes_to_a_third_persons_need() -> None:
    """ "Kwame needs a magnifier" is restated and asked; "hmm, not sure" is no yes: asked
    again, nothing fetched."""
    frame = _parser().parse_with_answers("Kwame needs a magnifier", "lotte", ["hmm, not sure"])
    assert frame.tasks == []
    yes = _parser().parse_with_answers("Kwame needs a magnifier", "lotte", ["yes please"])
    assert _tasks(yes) == [("transfer", "magnifier", None, "kwame")]


# -- 1. statements about a person or a facility are answered in words -----------------------


@pytest.mark.parametrize(
    ("text", "person"),
    [
        ("Kwame's at the dentist till 3 fyi", "kwame"),
        ("Farida's off sick till Thursday fyi", "farida"),
        ("Yusuf is on a course this week, btw", "yusuf"),
        ("btw Teodor's at the vet this morning", "teodor"),
    ],
)
def test_a_person_said_to_be_elsewhere_is_noted_away(text: str, person: str) -> None:
    """ "<Name>'s at the dentist": the 's is "is"; a place that is none of the office's
    puts them away, and what follows (a time, "fyi") says no more. Noted, nothing moves."""
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None
    assert frame.decline is not None and frame.decline_outcome == "done"
    assert frame.away() == {person}


@pytest.mark.parametrize(
    ("text", "value"),
    [("Kwame's in the darkroom", "darkroom"), ("Kwame's at his desk", "here")],
)
def test_a_person_at_a_place_of_the_office_is_not_away(text: str, value: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.away() == set()
    assert [h.value for h in frame.hints] == [value]


def test_a_request_beside_someone_elsewhere_is_still_read() -> None:
    frame = _frame("Kwame's at the dentist, can you bring me his magnifier?")
    assert frame.away() == {"kwame"}
    assert _tasks(frame) == [("transfer", "magnifier", "kwame", "lotte")]


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("the label printer's out of black ribbon again, ugh", "label printer is out of black"),
        ("scanner's jammed btw", "film scanner is jammed"),
        ("fyi the film scanner is down today", "film scanner is down"),
        ("the printer is playing up again", "printer is playing up"),
    ],
)
def test_a_facility_said_to_be_in_some_state_is_answered_in_words(text: str, said: str) -> None:
    """A report on a facility: answered in words, never its operation's verb ("scanner" is
    no "scan"), never "what do you need?", nothing moves."""
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None
    assert frame.decline is not None and frame.decline_outcome == "done"
    assert said in frame.decline


def test_a_request_beside_a_facility_report_is_still_read() -> None:
    frame = _frame("the label printer's jammed, can you print my shoot?")
    assert _tasks(frame) == [("print", "shoot_file", "lotte", "lotte")]


def test_a_question_about_a_facility_is_still_a_question() -> None:
    frame = _frame("is the scanner jammed?")
    assert frame.tasks == [] and frame.decline is not None
    assert "in service" in frame.decline


# -- 3. idioms and nouns that look like verbs or names -------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "mine ran out in June, could you bring me a magnifier?",
        "could you bring me a magnifier? mine ran out in june",
        "to be fair, mine ran out. can you bring me a magnifier?",
        "to be frank, could you bring me a magnifier?",
        "can you bring me a magnifier before the run?",
        "could you bring me a magnifier after the print run?",
        "could you bring me a magnifier? need to check the contacts",
        "bring me a magnifier, i need to look at the contacts",
        "could you bring me a magnifier? I have to go over the contacts before the run",
    ],
)
def test_an_aside_that_looks_like_a_request_leaves_the_request_alone(text: str) -> None:
    """ "ran" only tells (the office's "run" is asked by its other forms), "the run" after
    a preposition is an event, "June" after "in" is the month, "to be frank" is no
    colleague Frank, and what the speaker will look at themselves is no thing to fetch:
    only the magnifier is asked for."""
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == [("transfer", "magnifier", None, "lotte")]


@pytest.mark.parametrize(
    "text", ["run my negative strip", "can you run my negative strip before lunch?"]
)
def test_the_operations_verb_still_asks_for_it(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.operation) for t in frame.tasks] == [("heat", "negative", "develop")]


@pytest.mark.parametrize(
    ("text", "recipient"),
    [("take my mug to June", "june"), ("could you bring June a magnifier?", "june")],
)
def test_a_colleague_named_like_a_month_is_still_the_colleague(text: str, recipient: str) -> None:
    assert [t.recipient for t in _frame(text).tasks] == [recipient]


def test_the_product_asked_for_by_its_name_is_still_made() -> None:
    frame = _frame("proof my shoot and bring me the contacts")
    assert [(t.kind, t.operation) for t in frame.tasks] == [("print", "proof")]


# -- 4. corrections: "not X, (I meant) Y" --------------------------------------------------


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        (
            "sorry not a ruler, i meant a tape measure - can i borrow Teodor's?",
            [("transfer", "tape_measure", "teodor", "lotte")],
        ),
        (
            "not a ruler, a tape measure. can i borrow Teodor's?",
            [("transfer", "tape_measure", "teodor", "lotte")],
        ),
        (
            "bring me Maren's folder - not the blue folder, the red one",
            [("transfer", "red_folder", "maren", "lotte")],
        ),
        (
            "can you bring me Maren's blue folder? not the blue folder, the red one",
            [("transfer", "red_folder", "maren", "lotte")],
        ),
        (
            "bring me Maren's blue folder, no wait, not the blue folder, the red one",
            [("transfer", "red_folder", "maren", "lotte")],
        ),
    ],
)
def test_the_thing_said_after_not_x_is_the_one_meant(
    text: str, wanted: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    """The rejected thing is never acted on; the replacement takes its place (or the place
    of the thing a bare possessive left unsaid), whose owner is the one named."""
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == wanted


def test_the_replacement_answers_a_question_about_which() -> None:
    frame = _parser().parse_with_answers(
        "can you bring me Maren's folder?", "lotte", ["not the blue folder, the red one"]
    )
    assert _tasks(frame) == [("transfer", "red_folder", "maren", "lotte")]


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        ("bring me a ruler, not a pen, thanks", [("transfer", "ruler", None, "kwame")]),
        ("bring me a ruler, not Lotte's, thanks", [("transfer", "ruler", None, "kwame")]),
        (
            "bring me Lotte's tape measure - sorry, I meant Teodor's",
            [("transfer", "tape_measure", "teodor", "kwame")],
        ),
    ],
)
def test_a_plain_exclusion_or_correction_reads_as_before(
    text: str, wanted: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    assert _tasks(_frame(text, "kwame")) == wanted


# -- 7. "it" with nothing to refer to -------------------------------------------------------


@pytest.mark.parametrize(
    "text",
    ["can you print it and bring it over", "print it please", "proof it", "print it for Kwame"],
)
def test_it_with_nothing_said_before_is_asked_about(text: str) -> None:
    """Nothing in the message is what "it" could be: which file is asked, never guessed as
    the requester's own."""
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.question is not None and "'it'" in frame.question


@pytest.mark.parametrize(
    "text",
    [
        "print my shoot and bring it over",
        "my shoot's ready, print it",
        "can you print this for me",
    ],
)
def test_it_after_a_named_file_or_this_at_hand_reads_as_before(text: str) -> None:
    assert _tasks(_frame(text)) == [("print", "shoot_file", "lotte", "lotte")]


@pytest.mark.parametrize(
    ("answer", "owner"),
    [("my shoot", "lotte"), ("Kwame's shoot file", "kwame"), ("Kwame Osei's.", "kwame")],
)
def test_the_answer_is_what_it_means(answer: str, owner: str) -> None:
    frame = _parser().parse_with_answers("can you print it and bring it over", "lotte", [answer])
    assert _tasks(frame) == [("print", "shoot_file", owner, "lotte")]


# -- 6. "not his/her X" after one colleague named --------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "I might need Farida's wide lens tonight, not her camera",
        "could I borrow Farida's wide lens tonight? I'll let you know. not her camera",
    ],
)
def test_not_her_x_after_one_colleague_changes_nothing(text: str) -> None:
    """The request is set aside for later; "not her camera" is Farida's camera, not wanted:
    no question of whom "her" means, nothing moves."""
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame.question
    assert frame.decline is not None and frame.decline_outcome == "done"
    assert frame.unusable("camera") == {"farida"}


@pytest.mark.parametrize(
    "text",
    [
        "could I borrow Farida's wide lens tonight? the 24mm one, not her camera",
        "bring me Farida's wide lens, not his camera",
    ],
)
def test_the_request_beside_not_her_x_is_done(text: str) -> None:
    frame = _frame(text)
    assert _tasks(frame) == [("transfer", "wide_lens", "farida", "lotte")]


@pytest.mark.parametrize(
    "text",
    [
        "Kwame said Farida has one. not her camera",
        "Kwame said Farida has one. I might need a wide lens tonight, not her camera",
        "not her camera",
    ],
)
def test_not_her_x_after_two_colleagues_or_none_is_asked(text: str) -> None:
    """Whom "her" means is asked; the aside is never read as a request for someone's
    camera (main took Kwame's camera for the first two)."""
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.question is not None and "'her'" in frame.question


# -- in the simulated office: answered messages end done, nothing moved ---------------------


@pytest.mark.parametrize(
    "text",
    [
        "who has a magnifier I could use tomorrow?",
        "Kwame's at the dentist till 3 fyi",
        "scanner's jammed btw",
    ],
)
async def test_an_answered_message_ends_done_and_moves_nothing(text: str) -> None:
    run = await run_instruction(studio(), "lotte", text)
    assert run.actions == ["stop"], run.actions
    assert run.stm.trace.outcome == "done"


async def test_a_reason_clause_still_hands_the_mug_over() -> None:
    run = await run_instruction(
        studio(), "lotte", "take my mug to Kwame, he lent me his last week and his went missing"
    )
    assert "move" in run.actions
    assert run.stm.trace.outcome == "done"
