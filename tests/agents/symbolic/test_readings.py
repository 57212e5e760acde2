"""Competing readings are kept and, when they lead to different actions, asked about (issue 23):
a name that is also an ordinary word, a pronoun's referent, a third-party delivery."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("harbour", "may", "print the flyer for the grace period talk"),
        ("harbour", "ken", "to be frank I need a ruler"),  # frank: an operation's verb here
        ("harbour", "may", "print the poster about the rose garden"),
        ("harbour", "ken", "print my notes for the art workshop"),
        ("default", "lee", "print the flyer for the sun deck party"),
    ],
)
def test_a_lowercase_word_that_is_also_a_name_stays_a_word(
    office: str, who: str, text: str
) -> None:
    for kind, _item, _owner, recipient in tasks_of(office, text, who):
        assert recipient == who, (kind, recipient)


@pytest.mark.parametrize(
    ("office", "who", "text", "recipient"),
    [
        ("harbour", "may", "print my slides for Grace", "grace"),
        ("harbour", "ken", "take this ruler to mark", "mark"),  # after "to": a person
        ("harbour", "may", "give rose a calculator", "rose"),
        ("default", "lee", "bring Sun Li a stapler", "sun"),
    ],
)
def test_syntax_makes_a_word_name_a_person(
    office: str, who: str, text: str, recipient: str
) -> None:
    assert [t[3] for t in tasks_of(office, text, who)] == [recipient]


@pytest.mark.parametrize(
    ("office", "who", "text", "person", "word"),
    [
        ("harbour", "may", "print the flyer for the Grace period talk", "Grace Huang", "grace"),
        ("harbour", "ken", "print the invites for the Joy Division night", "Joy Achebe", "joy"),
    ],
)
def test_disagreeing_evidence_asks_one_question_naming_both(
    office: str, who: str, text: str, person: str, word: str
) -> None:
    p = parser(office)
    frame = p.parse(text, who)
    assert frame.tasks == [] and frame.question
    assert person in frame.question and f"the {word}" in frame.question.lower()
    as_word = p.parse_with_answers(text, who, [f"the {word} one, not a person"])
    assert [t.recipient for t in as_word.tasks] == [who]
    as_person = p.parse_with_answers(text, who, [person])
    assert [t.recipient for t in as_person.tasks] == [person.split()[0].lower()]


@pytest.mark.parametrize(
    ("office", "who", "text", "item", "owner", "recipient"),
    [
        ("default", "lee", "Gao hurt her wrist, please take her my cup", "cup", "lee", "gao"),
        ("default", "wang", "Min needs a pen, bring her one", "pen", None, "gao"),
        ("default", "lee", "Zhou Yan has a cold. Bring him some wipes", "wipes", None, "zhou"),
        (
            "harbour",
            "may",
            "Pat hurt her hand, please take her my umbrella",
            "umbrella",
            "may",
            "pat",
        ),
        (
            "harbour",
            "ken",
            "Rose needs a highlighter, can you bring her one?",
            "highlighter",
            None,
            "rose",
        ),
    ],
)
def test_a_pronoun_recipient_is_the_person_it_refers_to(
    office: str, who: str, text: str, item: str, owner: str | None, recipient: str
) -> None:
    assert tasks_of(office, text, who) == [("transfer", item, owner, recipient)]


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("default", "lee", "please take her my cup"),
        ("harbour", "may", "bring him a ruler"),
    ],
)
def test_a_pronoun_with_no_referent_is_asked_never_the_requester(
    office: str, who: str, text: str
) -> None:
    frame = parser(office).parse(text, who)
    assert frame.tasks == [] and frame.question


@pytest.mark.parametrize(
    ("office", "who", "text", "kind", "recipient"),
    [
        ("harbour", "may", "print the minutes and leave them on Mark's desk", "print", "mark"),
        ("harbour", "ken", "drop a calculator by Hope's desk", "transfer", "hope"),
        ("default", "lee", "print my report and put it on Zhang's desk", "print", "zhang"),
        ("default", "wang", "leave some paper at Chen's desk", "transfer", "chen"),
    ],
)
def test_a_third_party_delivery_goes_to_the_person_named(
    office: str, who: str, text: str, kind: str, recipient: str
) -> None:
    assert [(t[0], t[3]) for t in tasks_of(office, text, who)] == [(kind, recipient)]


@pytest.mark.parametrize(
    ("office", "who", "text", "item", "recipient"),
    [
        (
            "default",
            "lee",
            "Hu's scissors are broken. could you bring her another pair?",
            "scissors",
            "hu",
        ),
        (
            "harbour",
            "may",
            "Dawn's calculator is broken. could you bring her another one?",
            "calculator",
            "dawn",
        ),
    ],
)
def test_a_pronoun_after_a_stated_fact_is_the_person_it_named(
    office: str, who: str, text: str, item: str, recipient: str
) -> None:
    assert tasks_of(office, text, who) == [("transfer", item, None, recipient)]


@pytest.mark.parametrize(
    ("office", "who", "text", "excluded", "item"),
    [
        ("default", "lee", "bring me a stapler, not from Wang though", "wang", "stapler"),
        ("default", "wang", "Bring me scissors. Not Chen's, they're blunt", "chen", "scissors"),
        ("harbour", "may", "get me a calculator, but not Will's", "will", "calculator"),
    ],
)
def test_an_excluded_person_is_kept_out_never_made_the_owner(
    office: str, who: str, text: str, excluded: str, item: str
) -> None:
    frame = parser(office).parse(text, who)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", item, None)]
    assert excluded in frame.unusable(item)


@pytest.mark.parametrize(
    ("office", "who", "text", "owner", "recipient"),
    [
        ("default", "lee", "Gao asked for my scissors, please bring them to her", "lee", "gao"),
        (
            "harbour",
            "may",
            "Ken wants to borrow my umbrella, can you take it to him?",
            "may",
            "ken",
        ),
    ],
)
def test_a_stated_item_keeps_its_owner_when_referred_back_to(
    office: str, who: str, text: str, owner: str, recipient: str
) -> None:
    assert [(t[2], t[3]) for t in tasks_of(office, text, who)] == [(owner, recipient)]


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("default", "lee", "Chen borrowed my stapler. Can you get it back for me?"),
        ("default", "wang", "get me a pen. no wait, a pencil"),
    ],
)
def test_an_unclear_owner_or_correction_is_asked_not_guessed(
    office: str, who: str, text: str
) -> None:
    frame = parser(office).parse(text, who)
    assert frame.tasks == [] and frame.question, frame


@pytest.mark.parametrize(
    ("office", "who", "text"),
    [
        ("default", "lee", "I need a pen for the sun li meeting"),
        ("default", "wang", "print my notes for the Zhang Wei review"),
        ("harbour", "may", "print the agenda for the Okafor project"),
    ],
)
def test_a_name_that_modifies_a_noun_is_no_party(office: str, who: str, text: str) -> None:
    tasks = tasks_of(office, text, who)
    assert tasks and all(t[3] == who and t[2] in (None, who) for t in tasks), tasks
