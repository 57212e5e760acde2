"""The dataset's own office files, for the tests that run on them, and the ``harbour``
fixture (tests/conftest.py offers it everywhere): the harbour office parsed once, since an
office is immutable."""

from __future__ import annotations

import functools
from pathlib import Path
from typing import TYPE_CHECKING, Any

import pytest

if TYPE_CHECKING:
    from assistantx.core.office import Office
from helpers.yaml_files import raw_yaml

ROOT = Path(__file__).resolve().parents[2]
DEFAULT_FILE = ROOT / "dataset" / "office.yaml"
HARBOUR_FILE = ROOT / "dataset" / "offices" / "harbour" / "office.yaml"


@functools.cache
def default_office() -> Office:
    from assistantx.core.office import load_office  # not at import: tests/conftest.py's

    return load_office(DEFAULT_FILE)


@functools.cache
def harbour_office() -> Office:
    from assistantx.core.office import load_office

    return load_office(HARBOUR_FILE)


@pytest.fixture(scope="session")
def harbour() -> Office:
    """The dataset's harbour office (dataset/offices/harbour)."""
    return harbour_office()


def default_office_that_scans(
    op_id: str, product: str | dict[str, Any], *, pdf_names_files: bool = True
) -> Office:
    """The default office with a scan to PDF at its printer (beside print and copy):
    ``product`` is an item type id already there ("file") or a new electronic type's entry;
    without ``pdf_names_files`` "pdf" is no name of the office's files (only part of the
    scan's product's name, as in blind round 77's ferry office)."""
    raw = raw_yaml(DEFAULT_FILE)
    if not pdf_names_files:
        files = next(t for t in raw["item_types"] if t["id"] == "file")
        files["synonyms"] = [w for w in files["synonyms"] if w != "pdf"]
    if isinstance(product, dict):
        raw["item_types"].append({"kind": "electronic", **product})
        product = str(product["id"])
    raw["operations"].append(
        {
            "id": op_id,
            "name": "scan to PDF",
            "verbs": ["scan"],
            "input": "document",
            "product": product,
        }
    )
    printer = next(f for f in raw["facilities"] if f["id"] == "printer")
    printer["operations"].append(op_id)
    printer["products"].append(product)
    from assistantx.core.office import parse_office

    return parse_office(raw)


@functools.cache
def default_office_that_sends_out(op_id: str, name: str, verb: str, asked: str) -> Office:
    """The default office whose printer room also sends a document out of the office (a
    fax, a courier, a dispatch): ``name`` and ``verb`` are the operation's words, ``asked``
    what its operator needs to know ("the fax number")."""
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE)
    raw["operations"].append(
        {
            "id": op_id,
            "name": name,
            "verbs": [verb],
            "input": "document",
            "sends_out": True,
            "destination_asked": asked,
        }
    )
    printer = next(f for f in raw["facilities"] if f["id"] == "printer")
    printer["operations"].append(op_id)
    from assistantx.core.office import parse_office

    return parse_office(raw)


@functools.cache
def harbour_that_posts() -> Office:
    """Harbour whose franking machine takes a document and posts it out."""
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    frank = next(o for o in raw["operations"] if o["id"] == "frank")
    del frank["product"]
    frank.update(
        {"input": "document", "sends_out": True, "destination_asked": "the postal address"}
    )
    machine = next(f for f in raw["facilities"] if f["id"] == "franking_machine")
    machine["products"] = []
    from assistantx.core.office import parse_office

    return parse_office(raw)
