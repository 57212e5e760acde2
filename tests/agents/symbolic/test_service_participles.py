"""An operation named by its verb's participle, irregular ("rewound") or of a prefixed verb the
dictionary lacks ("restrung" of "restring"), or by the office's own ``done:`` word
("overhauled"): "get/have X <participle>" asks for that operation on X, brought back to the
speaker (blind round 59's class: the participle was not read, and the item was to be brought
to its own owner). A need said before it ("needs new strings", "needs rewinding") is context,
one errand; the participle in a statement of what happened asks nothing."""

from __future__ import annotations

import pytest

from assistantx.core import language, wording
from helpers.edit_suite import edit_suite
from helpers.reading import frame_reader

_frame = frame_reader(edit_suite, "nadia")


@pytest.mark.parametrize(
    ("text", "item", "operation"),
    [
        ("My tape's stretched, could you get it rewound at the deck?", "tape", "rewind"),
        ("get my spool rewound", "tape", "rewind"),
        ("have the tape rewound pls", "tape", "rewind"),
        ("my tape needs rewinding, get it rewound pls", "tape", "rewind"),
        ("my tape needs rewinding, could you rewind it", "tape", "rewind"),
        ("my guitar needs new strings, could you get it restrung", "guitar", "restring"),
        ("have my guitar restrung at the deck pls", "guitar", "restring"),
        ("get my guitar restrung would you", "guitar", "restring"),
        ("get my mic overhauled", "microphone", "service"),
        ("my mic's crackling, have it overhauled would you", "microphone", "service"),
    ],
)
def test_the_participle_asks_for_the_operation(text: str, item: str, operation: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        (item, "nadia", "nadia", operation)
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "the tape was rewound yesterday",
        "my guitar was restrung last week",
        "the mic got overhauled yesterday",
    ],
)
def test_the_participle_in_a_statement_asks_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame


@pytest.mark.parametrize(
    ("verb", "form"),
    [
        ("restring", "restrung"),
        ("regrind", "reground"),
        ("re-wind", "re-wound"),
        ("resew", "resewn"),
    ],
)
def test_a_prefixed_verb_is_inflected_as_its_stem(verb: str, form: str) -> None:
    assert form in language.verb_forms(verb)
    assert language.is_past_participle(form)


@pytest.mark.parametrize("name", ["unwin", "mistry", "outram"])
def test_a_name_that_starts_like_a_prefix_is_no_verb(name: str) -> None:
    assert not language.verb_lemmas(name)


def test_the_outcome_says_the_stems_participle() -> None:
    assert wording.done_words(edit_suite().operation("restring")) == "restrung"
