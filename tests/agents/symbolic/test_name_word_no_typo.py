"""A word of a colleague's name is never a typo of a thing's name. An outside tester's office
had Marta Ferreira-Lopes beside Marta Nowicka and a loupe among its things: the tokenizer
splits the name at its hyphen, "Lopes" alone was no name key, and the typo corrector made it
"loupes", so "take the copy to Marta Ferreira-Lopes" asked which Marta, and asked again after
the answer "Marta Ferreira-Lopes". A word of any name of the office (a person's, a thing's, a
place's) is that name's word, never corrected into another. Analogue on harbour with a loupe
added and two Martas."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import HARBOUR_FILE
from helpers.reading import answered_reader, frame_reader
from helpers.yaml_files import raw_yaml


@functools.cache
def _two_martas() -> Office:
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    raw["item_types"].append({"id": "loupe", "name": "loupe", "kind": "personal"})
    for p in raw["people"]:
        if p["id"] == "ray":
            p["name"], p["aliases"] = "Marta Ferreira-Lopes", []
            p["owns"].append({"type": "loupe", "known": True})
        elif p["id"] == "faith":
            p["name"], p["aliases"] = "Marta Nowicka", []
    return parse_office(raw, "harbour with two Martas and a loupe")


_read = frame_reader(_two_martas, "may")


@pytest.mark.parametrize(
    "text",
    [
        "take my ruler to Marta Ferreira-Lopes",
        "give Marta Ferreira-Lopes my tape",
        "take my ruler to Marta Ferreira Lopes please",
    ],
)
def test_the_hyphenated_full_name_is_her(text: str) -> None:
    frame = _read(text)
    assert frame.question is None, frame.question
    assert [t.recipient for t in frame.tasks] == ["ray"]


def test_the_answer_with_her_full_name_settles_which_marta() -> None:
    asked = _read("take my ruler to Marta")
    assert asked.tasks == [] and "Marta Ferreira-Lopes" in (asked.question or "")
    read = answered_reader(_two_martas, "may")
    frame = read("take my ruler to Marta", ["Marta Ferreira-Lopes"])
    assert [t.recipient for t in frame.tasks] == ["ray"]


def test_a_real_typo_of_the_thing_is_still_corrected() -> None:
    # must not change: "loupee" is no word of any name, and is the loupe
    frame = _read("can I borrow Marta Ferreira-Lopes's loupee")
    assert [(t.item, t.owner) for t in frame.tasks] == [("loupe", "ray")]
