"""The default office and the loader's errors on bad files."""

from __future__ import annotations

from collections import Counter
from pathlib import Path
from typing import Any

import pytest
import yaml

from assistantx.core.errors import OfficeError
from assistantx.core.office import DEFAULT_OFFICE, load_office
from helpers.yaml_files import raw_yaml

PAPER_PEOPLE = {
    "mao",
    "sun",
    "lee",
    "zhang",
    "dang",
    "wang",
    "zhou",
    "chen",
    "yang",
    "hu",
    "lin",
    "gao",
    "xu",
    "zheng",
    "wu",
    "liu",
}
PAPER_TYPES = {
    "stapler",
    "scissors",
    "book",
    "data_cable",
    "paper",
    "pen",
    "wipes",
    "seal",
    "cup",
    "document",
    "file",
}


def test_default_office_matches_the_paper() -> None:
    office = load_office()
    assert len(office.locations) == 23
    assert len(office.workstations()) == 16
    assert len(office.public_places()) == 7
    assert PAPER_PEOPLE <= {p.id for p in office.people}
    assert all(p.owns for p in office.people)
    assert PAPER_TYPES <= {t.id for t in office.item_types}
    owned = Counter(o.type for p in office.people for o in p.owns)
    for t in office.item_types:
        if t.kind != "product":
            assert owned[t.id] >= 3, t.id
    facilities = {f.id for f in office.facilities}
    assert {
        "printer",
        "coffee_machine",
        "water_dispenser",
        "fridge",
        "microwave",
        "vending_machine",
    } <= facilities
    assert all(f.guards for f in office.facilities)
    assert {"Office Work", "Study Group"} <= {g.name for g in office.groups}
    assert any(not o.known for p in office.people for o in p.owns)


def _write(tmp_path: Path, mutate: Any) -> Path:
    raw = raw_yaml(DEFAULT_OFFICE)
    mutate(raw)
    path = tmp_path / "office.yaml"
    path.write_text(yaml.safe_dump(raw))
    return path


@pytest.mark.parametrize(
    ("mutate", "entry", "problem"),
    [
        (
            lambda r: r["people"][3].update(location="desk_99"),
            "people (zhang).location",
            "unknown location 'desk_99'",
        ),
        (lambda r: r["people"].append(dict(r["people"][0])), "people (mao)", "duplicate id"),
        (lambda r: r["people"][2].pop("handle"), "people[2] (lee).handle", "Field required"),
        (
            lambda r: r["people"][1]["owns"].append({"type": "unicorn"}),
            "people (sun).owns",
            "unknown item type 'unicorn'",
        ),
        (
            lambda r: r["facilities"][0]["guards"].append("ghost"),
            "facilities (printer).guards",
            "unknown person 'ghost'",
        ),
        (
            lambda r: r["groups"][1]["members"].append("nobody"),
            "groups (study_group).members",
            "unknown person 'nobody'",
        ),
        (lambda r: r["locations"][0].update(x="far"), "locations[0] (desk_01).x", "valid number"),
    ],
)
def test_bad_office_files_name_file_entry_and_problem(
    tmp_path: Path, mutate: Any, entry: str, problem: str
) -> None:
    path = _write(tmp_path, mutate)
    with pytest.raises(OfficeError) as info:
        load_office(path)
    assert info.value.path == str(path)
    assert info.value.entry == entry
    assert problem in info.value.problem
    assert str(path) in str(info.value)


def test_missing_and_malformed_files(tmp_path: Path) -> None:
    with pytest.raises(OfficeError, match="cannot be read"):
        load_office(tmp_path / "nope.yaml")
    bad = tmp_path / "bad.yaml"
    bad.write_text("people: [unclosed")
    with pytest.raises(OfficeError, match="not valid YAML"):
        load_office(bad)
    bad.write_text("- just a list")
    with pytest.raises(OfficeError, match="must be a mapping"):
        load_office(bad)
