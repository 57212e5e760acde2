"""A need said, then a product made from the needed thing for the one who needs it: one
errand, the product ("Zhang needs my document, make him a copy of it" is one copy to Zhang,
never the document handed over as well; ``needs_met._makes_from``). Handing the thing over
after the need is still the hand-over."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    ("text", "to"),
    [
        ("Zhang needs my document, make him a copy of it", "zhang"),
        ("Zhang needs my report, make him a copy of it", "zhang"),
        ("Zhang needs my document, could you make him a copy", "zhang"),
        ("Chen needs my contract, make him a copy", "chen"),
        ("Chen needs my report, photocopy it for him", "chen"),
    ],
)
def test_one_copy_for_the_one_who_needs_it(text: str, to: str) -> None:
    assert tasks_of("default", text, "wang") == [("copy", "document", "wang", to)]


@pytest.mark.parametrize(
    "text",
    [
        "Mark needs my document, scan it for him",
        "Mark needs my report, make him a scan of it",
    ],
)
def test_one_scan_for_the_one_who_needs_it_harbour(text: str) -> None:
    assert tasks_of("harbour", text, "may") == [("copy", "document", "may", "mark")]


@pytest.mark.parametrize(
    ("office", "text", "who", "tasks"),
    [
        (
            "default",
            "Zhang needs my document, take it to him",
            "wang",
            [("transfer", "document", "wang", "zhang")],
        ),
        (
            "harbour",
            "Will needs my file, print it for him",
            "may",
            [("print", "file", "may", "will")],
        ),
        # another thing for the one who needs it: both are done
        (
            "default",
            "Zhang needs my document, bring me a pen",
            "wang",
            [("transfer", "document", "wang", "zhang"), ("transfer", "pen", None, "wang")],
        ),
    ],
)
def test_must_not_change(
    office: str, text: str, who: str, tasks: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert tasks_of(office, text, who) == tasks


@pytest.mark.parametrize(
    ("text", "to"),
    [
        ("Chen needs my contract, make her a copy", "chen"),
        ("Chen needs my document, could you make her a copy of it", "chen"),
        ("Gao needs my report, could you make her two copies", "gao"),
    ],
)
def test_her_copy_is_the_product_made_for_her(text: str, to: str) -> None:
    # "her" before "a copy" is whom it is for; the copy is what is made, no item worked on
    assert tasks_of("default", text, "wang") == [("copy", "document", "wang", to)]


@pytest.mark.parametrize(
    "text",
    [
        "Zhang needs my document, make him a copy of it and bring me the original back",
        "make Zhang a copy of my document and bring me the original back",
        "make Zhang a copy of my document and bring the original back to me",
    ],
)
def test_the_original_back_to_me_is_part_of_the_copy(text: str) -> None:
    # the original comes back to whoever put it in: the copy still goes to Zhang
    assert tasks_of("default", text, "wang") == [("copy", "document", "wang", "zhang")]


@pytest.mark.parametrize(
    "text",
    [
        "make Zhang a copy of my document and give the original to Chen",
        "copy my document for Zhang and give him the original",
    ],
)
def test_the_original_to_anyone_else_is_asked(text: str) -> None:
    frame = parser("default").parse(text, "wang")
    assert frame.tasks == [] and frame.question is not None and "original" in frame.question


def test_another_thing_after_a_copy_is_its_own_errand() -> None:
    assert tasks_of("default", "make Zhang a copy of my document and bring me a pen", "wang") == [
        ("copy", "document", "wang", "zhang"),
        ("transfer", "pen", None, "wang"),
    ]
