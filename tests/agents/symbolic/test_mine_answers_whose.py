""" "Mine." answering "Whose X do you mean?" names the requester's own X, however the request
said the thing: "take lunch to Chen" (a bare noun) asks "Whose lunch do you mean?", and
"Mine.", "mine!", "it's mine", "my one", "me" take the requester's lunch; before, only "the
lunch" was filled and the answer "did not tell me". A colleague's name ("Lee's") fills the
bare noun too. From someone who has none, "Mine." is said back with the question ("As far as
I know, you have no lunch of your own"), never their own thing looked for where there is
none (several_owners.with_owner, unowned_mine)."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadAnswered, answered_reader

_lee = answered_reader(default_office, "lee")  # Lee owns a lunch
_mao = answered_reader(default_office, "mao")  # Mao owns none
_will = answered_reader(harbour_office, "will")  # Will owns a lunch, no badge
_dawn = answered_reader(harbour_office, "dawn")  # Dawn owns a badge


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize("answer", ["Mine.", "mine!", "it's mine", "my one", "me"])
def test_mine_is_the_requesters_own(answer: str) -> None:
    assert _lee("take lunch to chen").question == "Whose lunch do you mean?"
    frame = _lee("take lunch to chen", [answer])
    assert _tasks(frame) == [("transfer", "lunch", "lee", "chen")]


@pytest.mark.parametrize(
    ("read", "text", "answer", "want"),
    [
        (_will, "take lunch to june", "Mine.", [("transfer", "lunch", "will", "june")]),
        (_dawn, "take badge to june", "mine", [("transfer", "badge", "dawn", "june")]),
        (_dawn, "take badge to june", "Jack's", [("transfer", "badge", "jack", "june")]),
        (_mao, "lunch needs heating, sort it pls", "Lee's", [("heat", "lunch", "lee", "mao")]),
    ],
)
def test_the_answer_fills_a_bare_noun(
    read: ReadAnswered, text: str, answer: str, want: list[tuple[str, str, str, str]]
) -> None:
    frame = read(text, [answer])
    assert frame.question is None, frame.question
    assert _tasks(frame) == want


@pytest.mark.parametrize(
    ("read", "text", "name"),
    [
        (_mao, "lunch needs heating, sort it pls", "lunch"),
        (_will, "take badge to june", "badge"),
    ],
)
def test_mine_from_one_with_none_is_said_so(read: ReadAnswered, text: str, name: str) -> None:
    frame = read(text, ["Mine."])
    assert frame.tasks == []
    assert frame.question == (
        f"Whose {name} do you mean? As far as I know, you have no {name} of your own."
    )


def test_a_name_after_mine_from_one_with_none_still_decides() -> None:
    frame = _mao("lunch needs heating, sort it pls", ["Mine.", "Lee's"])
    assert _tasks(frame) == [("heat", "lunch", "lee", "mao")]


def test_several_have_one_still_asks_after_mine_from_one_with_none() -> None:
    # the neighbour: "the lunch" where several colleagues have one, Mao none: asked again
    frame = _mao("take the lunch to chen", ["Mine."])
    assert frame.tasks == [] and frame.question is not None
