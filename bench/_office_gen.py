"""Generated offices of any size for the scale benchmarks: the default office, replicated.

Copy ``k`` of a person is ``<id>_k`` (``zhang_2``, named "Zhang Wei 2"), at a new
workstation ``<desk>_k`` placed where the original desk is (the kinematic simulated robot
needs no map anchor), owning the same item types, member of the same groups, with one more
group per copy (``team_k``) holding that copy's people. Facilities and their guards stay as
they are, so a 1,024-person office has the same 7 public places and 64 teams.
"""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

import yaml

from assistantx.core.office import DEFAULT_OFFICE


def office_dict(people: int, source: Path = DEFAULT_OFFICE) -> dict[str, Any]:
    base = yaml.safe_load(source.read_text(encoding="utf-8"))
    originals = base["people"]
    copies = -(-people // len(originals))  # ceiling
    out = copy.deepcopy(base)
    out["name"] = f"Generated office, {people} people"
    desks = {loc["id"]: loc for loc in base["locations"]}
    new_people: list[dict[str, Any]] = []
    for k in range(1, copies + 1):
        team: list[str] = []
        for person in originals:
            if len(new_people) >= people:
                break
            if k == 1:
                new_people.append(person)
                team.append(person["id"])
                continue
            clone = copy.deepcopy(person)
            clone["id"] = f"{person['id']}_{k}"
            clone["name"] = f"{person['name']} {k}"
            clone["aliases"] = []
            clone["handle"] = f"@{clone['id']}"
            desk = dict(desks[person["location"]])
            desk["id"] = f"{person['location']}_{k}"
            desk["name"] = f"{desk['name']} ({k})"
            out["locations"].append(desk)
            clone["location"] = desk["id"]
            new_people.append(clone)
            team.append(clone["id"])
            for group in out["groups"]:
                if person["id"] in group["members"]:
                    group["members"].append(clone["id"])
        if k > 1 and team:
            out["groups"].append({"id": f"team_{k}", "name": f"Team {k}", "members": team})
    out["people"] = new_people
    return out


def write_office(people: int, path: Path) -> Path:
    path.write_text(yaml.safe_dump(office_dict(people), sort_keys=False), encoding="utf-8")
    return path
