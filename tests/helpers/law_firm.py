"""Offices whose seal has a name English derives a verb from, for the reader's tests of tools
that lend their work a verb (fix115d): the default office as a law firm whose seal is a
"notary stamp" (also "notarial seal", "stamp", "seal") and whose papers include an
affidavit; and harbour with a "certification stamp" two colleagues own."""

from __future__ import annotations

import functools
from typing import TYPE_CHECKING, Any

from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.yaml_files import raw_yaml

if TYPE_CHECKING:
    from assistantx.core.office import Office


@functools.cache
def law_firm() -> Office:
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE)
    seal = next(t for t in raw["item_types"] if t["id"] == "seal")
    seal.update({"name": "notary stamp", "synonyms": ["notarial seal", "stamp", "seal"]})
    papers = next(t for t in raw["item_types"] if t["id"] == "document")
    papers["synonyms"].append("affidavit")
    from assistantx.core.office import parse_office

    return parse_office(raw)


@functools.cache
def certifying_harbour() -> Office:
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    raw["item_types"].append(
        {"id": "seal", "name": "certification stamp", "seals": True, "synonyms": ["stamp"]}
    )
    for person in raw["people"]:
        if person["id"] in ("mark", "will"):
            person.setdefault("owns", []).append({"type": "seal", "known": True})
    from assistantx.core.office import parse_office

    return parse_office(raw)
