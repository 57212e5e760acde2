"""A paper the office does not list, said as the object of a person's work on a paper done
with the office's seal ("seal the thingy for me", "stamp the cert for me"): the requester's
paper of the office, guessed from the work and restated before anything moves
(``reading.own_papers``: the verbs of the task kinds that work on a signable paper with a
tool join the operations' verbs). Read as the noun, the office's seal itself was carried to
the speaker. A seal asked for by its owner's name, and a paper the office lists, read as
before; signing keeps its own reading (no tool's name to mistake)."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    "text",
    ["seal the thingy for me", "can you stamp the thingy for me", "stamp the cert for me"],
)
def test_the_paper_is_guessed_and_the_stamping_asked(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and frame.decline is None
    assert frame.question == "Shall I get your document stamped with the seal?"


def test_on_a_yes_the_document_is_stamped_never_the_seal_moved() -> None:
    frame = parser("default").parse("seal the thingy for me", "lee", confirmed=True)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("seal", "document", "lee", "lee")
    ]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("bring me Wang's seal", [("transfer", "seal", "wang", "lee")]),
        ("seal my contract", [("seal", "document", "lee", "lee")]),
        # "my" and a noun nobody lists: the seal's own paper, as before
        ("can you stamp my thingy", [("seal", "document", "lee", "lee")]),
        # a word after the noun goes on naming the paper: read by the paper's own names
        (
            "Wang has to sign off my merch order form. could you take it to her and bring it back?",
            [("sign", "document", "lee", "lee")],
        ),
    ],
)
def test_neighbours_read_as_before(text: str, expected: list[tuple[str, str, str, str]]) -> None:
    assert tasks_of("default", text, "lee") == expected
