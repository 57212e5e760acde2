"""A word that is part of two item types' names ("master" of the "master file" and of the
"master tape"), said as the thing an operation works on ("burn a ref CD of my master"): the
operation's input type settles it, the file burning takes, with no question (blind round 60's
class: "I'm not sure what you mean by 'my master'"). Without an operation the word is still
not guessed, and a phrase with a word the office does not know is still asked about."""

from __future__ import annotations

import pytest

from helpers.edit_suite import edit_suite
from helpers.reading import frame_reader

_frame = frame_reader(edit_suite, "nadia")


@pytest.mark.parametrize(
    "text",
    [
        "burn a ref cd of my master for me would ya",
        "burn a reference cd of my master",
        "could you burn me a ref CD of my master pls",
        "burn my master",
        "burn my master file",
    ],
)
def test_the_operations_input_settles_the_word(text: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        ("file", "nadia", "nadia", "burn")
    ], frame


@pytest.mark.parametrize("text", ["bring me my master", "burn my old session master"])
def test_without_the_operation_or_with_unknown_words_nothing_is_guessed(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None, frame
