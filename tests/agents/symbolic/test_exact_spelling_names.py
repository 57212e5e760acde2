"""Two colleagues whose names differ only by diacritics ("Tomás Herrera", "Tomáš Novák"): the
name typed with its marks means the one who spells it so (``reading.exact_spelling``); typed
without any ("Tomas") it is asked, and the answer that names one of the two replaces the name
in the request (``reading.name_chosen``), wherever the name stands."""

from __future__ import annotations

import copy
import functools
from typing import Any

import pytest
import yaml

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import HARBOUR_FILE

# harbour's max and jack renamed, each called by the given name; bill and hope a pair
# declared with no aliases, where only one name carries a mark
_NAMES = {
    "max": ("Tomás Herrera", ["Tomás"]),
    "jack": ("Tomáš Novák", ["Tomáš"]),
    "bill": ("Renée Dubois", []),
    "hope": ("Renee Park", []),
}


@functools.cache
def _parser() -> InstructionParser:
    raw: dict[str, Any] = copy.deepcopy(yaml.safe_load(HARBOUR_FILE.read_text(encoding="utf-8")))
    for p in raw["people"]:
        if p["id"] in _NAMES:
            p["name"], p["aliases"] = _NAMES[p["id"]][0], list(_NAMES[p["id"]][1])
    raw["locations"].append(
        {"id": "studio_a", "kind": "room", "name": "Studio A", "x": 29.0, "y": 16.0}
    )
    office: Office = parse_office(raw, "harbour with namesakes by diacritics")
    return InstructionParser(office)


def _read(
    text: str, answers: tuple[str, ...] = ()
) -> tuple[list[tuple[str, str | None]], str | None]:
    frame = _parser().parse_with_answers(text, "mark", list(answers))
    return [
        (t.kind, t.recipient if t.kind == "transfer" else t.actor) for t in frame.tasks
    ], frame.question


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("bring my ruler to Tomás", "max"),  # spelled as Tomás Herrera spells it
        ("bring my ruler to Tomáš", "jack"),
        ("could Tomáš sign my form?", "jack"),
        ("give Renée my ruler", "bill"),  # the one whose name has the mark
    ],
)
def test_the_exact_spelling_picks_the_one_who_spells_it_so(text: str, who: str) -> None:
    tasks, question = _read(text)
    assert question is None
    assert [w for _, w in tasks] == [who]


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("bring my ruler to Tomas", "Tomas"),  # no marks typed: either of them
        ("give Renee my ruler", "Renee"),  # the unmarked spelling may be either's, typed plain
    ],
)
def test_a_name_typed_without_marks_is_still_asked(text: str, said: str) -> None:
    tasks, question = _read(text)
    assert not tasks
    assert question is not None and question.startswith(f"Who do you mean by '{said}'")


@pytest.mark.parametrize(
    ("text", "answer", "who"),
    [
        ("bring my ruler to Tomas", "Tomás Herrera", "max"),
        ("bring my ruler to Tomas", "Tomáš Novák", "jack"),
        ("bring my ruler to Tomas in Studio A", "Tomás Herrera", "max"),
        ("bring my ruler to Tomas in Studio A", "Herrera", "max"),
        ("could Tomas sign my form?", "Tomáš Novák.", "jack"),
        ("give Renee my ruler", "Renee Park", "hope"),
    ],
)
def test_an_answer_naming_one_of_the_offered_people_settles_it(
    text: str, answer: str, who: str
) -> None:
    tasks, question = _read(text, (answer,))
    assert question is None
    assert [w for _, w in tasks] == [who]


def test_an_answer_naming_neither_is_asked_again() -> None:
    _, question = _read("bring my ruler to Tomas", ("Rose Adeyemi",))
    assert question is not None and question.startswith("Who do you mean by 'Tomas'")
