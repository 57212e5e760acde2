"""Place names are words of the lexicon; an office's own services are verbs even when their
names are nouns or destructive words; irregular participles; unknown items end in words;
Unicode names (issue 23, items 3 and 4)."""

from __future__ import annotations

import pytest
from _offices import office, parser, tasks_of


@pytest.mark.parametrize(
    ("name", "who", "text", "item"),
    [
        ("mail", "may", "get me a notepad from the mail room", "notepad"),
        ("harbour", "ken", "bring me a ruler from the post desk", "ruler"),
        ("harbour", "may", "can you fetch me a calculator from the copy room?", "calculator"),
        ("default", "lee", "bring me some paper from the print room", "paper"),
    ],
)
def test_a_place_name_is_a_place_not_a_verb(name: str, who: str, text: str, item: str) -> None:
    tasks = tasks_of(name, text, who)
    assert [(t[1], t[3]) for t in tasks] == [(item, who)]
    assert all(t[0] in ("transfer", "produce") for t in tasks)


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        ("shred my old drafts", "shred"),
        ("could you get my thesis bound by tomorrow?", "bind"),
        ("please have my draft bound", "bind"),
        ("fax my letter to the bank", "fax"),
        ("can you fax this contract for me", "fax"),
    ],
)
def test_an_offered_service_is_the_verb(text: str, operation: str) -> None:
    frame = parser("mail").parse(text, "may")
    assert frame.understood, frame.question or frame.decline
    assert [(t.item, t.operation, t.recipient) for t in frame.tasks] == [
        ("document", operation, "may")
    ]


@pytest.mark.parametrize(
    ("name", "text"),
    [("default", "shred my old drafts"), ("harbour", "shred my timesheet")],
)
def test_shredding_where_no_shredder_is_offered_is_declined(name: str, text: str) -> None:
    frame = parser(name).parse(text, "lee" if name == "default" else "may")
    assert frame.tasks == [] and frame.decline_outcome == "unachievable"


@pytest.mark.parametrize(
    ("name", "who", "text", "thing"),
    [
        ("default", "lee", "bring me a tape measure", "tape measure"),
        ("default", "wang", "could you get me a hammer?", "hammer"),
        ("harbour", "may", "fetch me a screwdriver please", "screwdriver"),
        ("harbour", "ken", "I need a projector", "projector"),
    ],
)
def test_an_unknown_item_ends_unachievable_in_words(
    name: str, who: str, text: str, thing: str
) -> None:
    frame = parser(name).parse(text, who)
    assert frame.tasks == [] and frame.decline_outcome == "unachievable"
    assert frame.decline and thing in frame.decline


@pytest.mark.parametrize(
    ("text", "owner", "recipient"),
    [
        ("bring me José Müller's calculator", "max", "may"),
        ("bring me Jose Muller's calculator", "max", "may"),
        ("please take a ruler to JOSÉ", None, "max"),
    ],
)
def test_names_with_diacritics(text: str, owner: str | None, recipient: str) -> None:
    item = "calculator" if "calculator" in text else "ruler"
    assert tasks_of("mail", text, "may") == [("transfer", item, owner, recipient)]


@pytest.mark.parametrize(
    ("name", "who", "text", "item"),
    [
        ("default", "lee", "brign me a stapler", "stapler"),
        ("default", "lee", "could you bring me some pnes", "pen"),
        ("harbour", "may", "fetch me a calcualtor", "calculator"),
        ("harbour", "ken", "bring me a highlgihter", "highlighter"),
    ],
)
def test_typos(name: str, who: str, text: str, item: str) -> None:
    assert tasks_of(name, text, who) == [("transfer", item, None, who)]


def test_no_office_names_in_the_english_data() -> None:
    from assistantx.core.english import entries_of

    lists = entries_of()
    months = set(lists["month_names"])
    listed = {w for key, words in lists.items() for e in words for w in e.split()}
    modal = {"will", "may"}  # function words of English, listed as such
    for name in ("default", "harbour"):
        for p in office(name).people:
            for word in p.name.lower().split():
                assert word not in listed or word in months | modal, word


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("grab Art's lunch from the fridge and bring it to him", "lunch", "art"),
        (
            "please take May's label maker out of the cupboard and bring it to her",
            "label_maker",
            "may",
        ),
    ],
)
def test_an_item_kept_at_a_facility_may_go_to_its_owner(text: str, item: str, owner: str) -> None:
    assert tasks_of("harbour", text, "ken") == [("transfer", item, owner, owner)]


def test_an_item_at_its_owners_desk_is_not_brought_to_them() -> None:
    frame = parser("harbour").parse("take Hope's lunch and bring it to her", "ken")
    assert frame.tasks == [] and frame.question
