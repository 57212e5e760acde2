"""Only a request moves the robot: every other speech act is answered in words or with one
"Shall I ...?" (issue 23). New sentences, on the default office and on harbour."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of

# (office, requester, text): nothing may be fetched, printed or handed over for these
WITHDRAWALS = [
    ("default", "lee", "forget about the stapler, Chen already lent me his"),
    ("default", "wang", "never mind the paper, I found a ream in my drawer"),
    ("default", "lee", "cancel my request for the scissors"),
    ("harbour", "may", "forget about the ruler, I've got one"),
    ("harbour", "ken", "Oh, never mind the calculator."),
]
WISHES = [
    ("default", "lee", "please keep everyone away from Zhang's seal this afternoon"),
    ("default", "wang", "nobody take my mug, it's the blue one"),
    ("default", "lee", "make sure no one borrows my stapler today"),
    ("harbour", "may", "nobody touch Joy's lunch in the fridge"),
    ("harbour", "ken", "keep people away from the label maker please"),
]
THANKS = [
    ("default", "lee", "thanks for the stapler earlier!"),
    ("default", "lee", "say thanks to Wang for the pen"),
    ("default", "wang", "Thank you so much for the coffee"),
    ("harbour", "may", "tell Ray thanks for the umbrella"),
    ("harbour", "ken", "cheers for the tape dispenser"),
]
QUESTIONS = [
    ("default", "lee", "is the printer working?"),
    ("default", "lee", "where is Zhou Yan?"),
    ("default", "wang", "who has a tape measure?"),
    ("harbour", "may", "is the laminator working today?"),
    ("harbour", "ken", "where's Faith?"),
]
STATEMENTS = [
    ("default", "lee", "my data cable is too short"),
    ("default", "wang", "I spilled coffee on my book"),
    ("harbour", "may", "Pat hurt her hand this morning"),
    ("harbour", "ken", "the ruler on my desk is broken"),
]


@pytest.mark.parametrize(("office", "who", "text"), WITHDRAWALS)
def test_a_withdrawal_fetches_nothing(office: str, who: str, text: str) -> None:
    frame = parser(office).parse(text, who)
    assert frame.tasks == [] and frame.decline_outcome == "done", frame
    assert frame.decline and "dropped" in frame.decline


@pytest.mark.parametrize(("office", "who", "text"), WISHES)
def test_a_wish_about_other_people_moves_nothing(office: str, who: str, text: str) -> None:
    frame = parser(office).parse(text, who)
    assert frame.tasks == [] and frame.decline_outcome == "done", frame
    assert frame.decline and "won't move" in frame.decline


@pytest.mark.parametrize(("office", "who", "text"), THANKS)
def test_a_thank_you_fetches_nothing(office: str, who: str, text: str) -> None:
    frame = parser(office).parse(text, who)
    assert frame.tasks == [] and frame.decline_outcome == "done", frame


@pytest.mark.parametrize(("office", "who", "text"), QUESTIONS)
def test_an_information_question_is_answered_in_words(office: str, who: str, text: str) -> None:
    frame = parser(office).parse(text, who)
    assert frame.tasks == [] and frame.decline_outcome == "done", frame
    assert frame.decline and "I did nothing" in frame.decline


@pytest.mark.parametrize(("office", "who", "text"), STATEMENTS)
def test_a_statement_alone_is_no_request(office: str, who: str, text: str) -> None:
    frame = parser(office).parse(text, who)
    assert frame.tasks == [], frame


def test_questions_answer_from_memory() -> None:
    where = parser("default").parse("where is Zhou Yan?", "lee").decline or ""
    assert "Zhou Yan" in where and "Desk" in where
    printer = parser("harbour").parse("is the laminator working today?", "may").decline or ""
    assert "laminator" in printer and "Badge office" in printer
    unknown = parser("default").parse("who has a tape measure?", "wang").decline or ""
    assert "tape measure" in unknown


@pytest.mark.parametrize(
    ("office", "who", "text", "item"),
    [
        ("default", "lee", "who has a stapler?", "stapler"),
        ("default", "wang", "does anybody have scissors?", "scissors"),
        ("harbour", "may", "has anyone got a calculator?", "calculator"),
        ("harbour", "ken", "who's got a highlighter?", "highlighter"),
    ],
)
def test_a_question_that_may_be_a_request_is_answered_then_offered(
    office: str, who: str, text: str, item: str
) -> None:
    p = parser(office)
    frame = p.parse(text, who)
    assert (
        frame.tasks == [] and frame.question and frame.question.endswith("Shall I bring you one?")
    )
    yes = p.parse_with_answers(text, who, ["yes please"])
    assert [(t.kind, t.item, t.recipient) for t in yes.tasks] == [("transfer", item, who)]
    no = p.parse_with_answers(text, who, ["no, just curious"])
    assert no.tasks == [] and no.decline_outcome == "done"


@pytest.mark.parametrize(
    ("office", "who", "text", "item"),
    [
        ("default", "lee", "can you get me a stapler?", "stapler"),
        ("default", "wang", "could someone lend me some scissors?", "scissors"),
        ("default", "lee", "does anyone have a pen I could borrow?", "pen"),
        ("harbour", "may", "May I borrow a ruler?", "ruler"),
        ("harbour", "ken", "would you mind bringing me a calculator?", "calculator"),
    ],
)
def test_a_polite_request_put_as_a_question_stays_a_request(
    office: str, who: str, text: str, item: str
) -> None:
    assert tasks_of(office, text, who) == [("transfer", item, None, who)]


@pytest.mark.parametrize(
    ("office", "who", "text", "item"),
    [
        (
            "default",
            "lee",
            "can you get me a data cable? my laptop cable is too short",
            "data_cable",
        ),
        ("default", "wang", "bring me some wipes please. I knocked my tea over", "wipes"),
        ("default", "lee", "I'm out of paper, can you find me some?", "paper"),
        ("harbour", "may", "could you grab me a ruler? the one on my desk snapped", "ruler"),
        ("harbour", "ken", "I don't have a calculator, could you bring me one?", "calculator"),
    ],
)
def test_an_explanation_does_not_take_over_the_request(
    office: str, who: str, text: str, item: str
) -> None:
    assert tasks_of(office, text, who) == [("transfer", item, None, who)]


@pytest.mark.parametrize(
    ("office", "who", "text", "item", "recipient"),
    [
        ("default", "lee", "Min needs scissors.", "scissors", "gao"),
        ("default", "wang", "Zhou Yan needs a data cable", "data_cable", "zhou"),
        ("harbour", "may", "Ray needs a ruler for the meeting.", "ruler", "ray"),
    ],
)
def test_a_third_persons_need_is_restated_and_asked(
    office: str, who: str, text: str, item: str, recipient: str
) -> None:
    p = parser(office)
    frame = p.parse(text, who)
    assert frame.tasks == [] and frame.question and frame.question.startswith("Shall I")
    yes = p.parse_with_answers(text, who, ["yes"])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in yes.tasks] == [
        ("transfer", item, None, recipient)
    ]


@pytest.mark.parametrize(
    ("office", "who", "text", "kind", "recipient"),
    [
        ("default", "lee", "I was wondering if you could print my report", "print", "lee"),
        (
            "default",
            "wang",
            "Chen is looking for a pen, could you help him out?",
            "transfer",
            "chen",
        ),
        (
            "harbour",
            "may",
            "Ray could do with a highlighter, can you take him one?",
            "transfer",
            "ray",
        ),
        ("harbour", "ken", "the ruler is for Hope, please bring it to her", "transfer", "hope"),
    ],
)
def test_requests_wrapped_in_statements(
    office: str, who: str, text: str, kind: str, recipient: str
) -> None:
    assert [(t[0], t[3]) for t in tasks_of(office, text, who)] == [(kind, recipient)]


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("default", "lee", "hold off on the coffee, I'll get it myself"),
        ("harbour", "may", "Yes, I have a ruler. Happy to lend it."),
        ("harbour", "ken", "I'll fetch the calculator myself"),
    ],
)
def test_the_speakers_own_plans_and_offers_move_nothing(office: str, who: str, text: str) -> None:
    frame = parser(office).parse(text, who)
    assert frame.tasks == [], frame


def test_a_question_about_one_person_is_answered_about_them() -> None:
    p = parser("harbour")
    has = p.parse("does Faith have a calculator?", "may")
    assert has.question and "Faith Oduya has a calculator" in has.question
    yes = p.parse_with_answers("does Faith have a calculator?", "may", ["yes"])
    assert [(t.item, t.owner, t.recipient) for t in yes.tasks] == [("calculator", "faith", "may")]
    has_not = p.parse("does Hope have a calculator?", "may").question or ""
    assert "Hope Mensah has no calculator" in has_not


def test_a_question_about_a_product_names_the_machine_that_makes_it() -> None:
    frame = parser("harbour").parse("where can I get a stamped envelope?", "may")
    assert frame.question and "franking machine" in frame.question


@pytest.mark.parametrize(
    ("office", "who", "text", "item"),
    [
        ("harbour", "may", "I'm hoping to borrow a ruler from someone", "ruler"),
        ("default", "lee", "we're trying to get hold of a stapler", "stapler"),
    ],
)
def test_the_speakers_own_want_is_a_request(office: str, who: str, text: str, item: str) -> None:
    assert tasks_of(office, text, who) == [("transfer", item, None, who)]


def test_a_name_that_is_also_a_verb_form_stays_a_name_as_a_subject() -> None:
    frame = parser("harbour").parse("rose needs a tape dispenser", "may")
    assert frame.question and "Rose Adeyemi" in frame.question


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("harbour", "may", "Did anyone find my umbrella?"),
        ("default", "lee", "has anybody seen my book?"),
    ],
)
def test_a_question_about_ones_own_item_fetches_nothing(office: str, who: str, text: str) -> None:
    frame = parser(office).parse(text, who)
    assert frame.tasks == [] and frame.decline_outcome == "done" and frame.decline
    assert "your" in frame.decline


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("default", "lee", "scrap the scissors request, Wu lent me a pair"),
        ("default", "wang", "You can forget the coffee, I'm leaving now"),
        ("default", "lee", "Please leave Mao's seal where it is"),
        ("default", "lee", "Hands off my stapler please"),
        ("default", "lee", "please pass my thanks to Hu for the scissors"),
        ("default", "wang", "big thanks to Zhang for lending me his stapler!"),
        ("harbour", "may", "leave Joy's lunch alone, she'll get it herself"),
    ],
)
def test_more_withdrawals_wishes_and_thanks_move_nothing(office: str, who: str, text: str) -> None:
    frame = parser(office).parse(text, who)
    assert frame.tasks == [] and frame.decline_outcome == "done", frame


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("default", "lee", "I wonder if anyone has a stapler"),
        ("harbour", "may", "do you happen to know who has a calculator?"),
    ],
)
def test_an_embedded_question_is_answered_then_offered(office: str, who: str, text: str) -> None:
    frame = parser(office).parse(text, who)
    assert frame.tasks == [] and frame.question and "Shall I" in frame.question


def test_a_possessive_pronoun_in_a_statement_keeps_the_owner() -> None:
    text = "Yang said I could borrow his book, can you fetch it?"
    assert tasks_of("default", text, "lee") == [("transfer", "book", "yang", "lee")]
