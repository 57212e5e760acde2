"""A forward is grounded on the office's own file type, whatever its id (issue 23: an office
whose electronic type is ``script`` crashed with ``unknown item type 'file'``)."""

from __future__ import annotations

import pytest

from assistantx.core.actions import ForwardFile
from assistantx.core.errors import GroundingError
from assistantx.core.office import Office, parse_office
from assistantx.memory.resolve import Resolver
from helpers.rehearsal_rooms import (
    drafting_studio,
    raw_rehearsal_rooms,
    rehearsal_rooms,
    rehearsal_rooms_without_files,
)


@pytest.mark.parametrize(
    ("office", "source", "target", "expected"),
    [
        (rehearsal_rooms(), "priya", "company", "script:priya"),
        (rehearsal_rooms(), "Bruno Aalto", "kwesi", "script:bruno"),
        (drafting_studio(), "femi", "Greta", "drawing:femi"),
    ],
    ids=["script", "script-by-name", "drawing"],
)
def test_a_forward_with_no_file_named_is_the_sources_file(
    office: Office, source: str, target: str, expected: str
) -> None:
    grounded = Resolver(office).ground(ForwardFile(source=source, target=target))
    assert isinstance(grounded, ForwardFile)
    assert grounded.file == expected


def test_a_named_file_of_the_offices_type_is_kept() -> None:
    grounded = Resolver(rehearsal_rooms()).ground(
        ForwardFile(source="priya", target="bruno", file="Kwesi Boateng's script")
    )
    assert isinstance(grounded, ForwardFile)
    assert grounded.file == "script:kwesi"


def test_a_physical_item_is_no_file_and_the_hint_names_the_offices_type() -> None:
    with pytest.raises(GroundingError, match="script:<person>"):
        Resolver(rehearsal_rooms()).ground(
            ForwardFile(source="priya", target="bruno", file="contract:priya")
        )


def test_an_office_with_no_files_says_so_rather_than_crashing() -> None:
    office = rehearsal_rooms_without_files()
    with pytest.raises(GroundingError, match="no electronic files"):
        Resolver(office).ground(ForwardFile(source="priya", target="bruno"))


@pytest.mark.parametrize("name", ["file:priya", "Priya's file", "the file of Priya Raman"])
def test_the_word_file_is_the_offices_file_type(name: str) -> None:
    """The LLM agents' prompts and a messenger that knows no office say ``file:priya``."""
    grounded = Resolver(rehearsal_rooms()).ground(
        ForwardFile(source="priya", target="bruno", file=name)
    )
    assert isinstance(grounded, ForwardFile)
    assert grounded.file == "script:priya"


def test_a_type_the_office_calls_file_is_that_type() -> None:
    """A paper ``file`` (a folder) of the office's own is no electronic file to forward."""
    raw = raw_rehearsal_rooms()
    raw["item_types"].append({"id": "folder", "name": "file"})
    resolver = Resolver(parse_office(raw, "with_folders"))
    assert resolver.item("file:priya") == "folder:priya"
    with pytest.raises(GroundingError, match="not an electronic file"):
        resolver.ground(ForwardFile(source="priya", target="bruno", file="file:priya"))
