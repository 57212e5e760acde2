"""A product named with what it is made of ("a printout of my rota", "a ref CD of my master")
beside another thing in one request ("bring me a tea and a printout of my rota"): the
operation that makes that product from that input, for the speaker, and the other thing too
(blind round 60's class: "I'm not sure what you want me to do with the printout"). One
paper's two products for two people stay one paper's ("a copy ... and a PDF ...")."""

from __future__ import annotations

import pytest

from helpers.edit_suite import edit_suite
from helpers.reading import frame_reader

_frame = frame_reader(edit_suite, "nadia")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "Could you bring me a tea and a printout of my rota?",
            [("produce", "tea", None), ("print", "file", "print")],
        ),
        (
            "could you bring me a printout of my rota and a tea",
            [("print", "file", "print"), ("produce", "tea", None)],
        ),
        (
            "bring me a hard hat and a printout of my rota pls",
            [("transfer", "hard_hat", None), ("print", "file", "print")],
        ),
        (
            "bring me a tea and a ref cd of my master",
            [("produce", "tea", None), ("print", "file", "burn")],
        ),
        ("bring me a printout of my rota", [("print", "file", "print")]),
    ],
)
def test_the_product_of_its_input_and_the_other_thing(
    text: str, expected: list[tuple[str, str, str | None]]
) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.operation) for t in frame.tasks] == expected, frame
    assert all(t.recipient == "nadia" for t in frame.tasks), frame


def test_for_someone_else_both_go_to_them() -> None:
    frame = _frame("bring Oskar a tea and a printout of my rota")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("tea", "oskar"), ("file", "oskar")]
