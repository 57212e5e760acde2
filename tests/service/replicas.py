"""The offices file and the replica processes of the multi-office service tests: up to three
offices (the default one as Headquarters, the harbour dataset's as Harbour Street, an Annex)
over replica processes that share the tests' PostgreSQL."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml

from service.server import Server, free_port, serve

HARBOUR_OFFICE = Path(__file__).resolve().parents[2] / "dataset/offices/harbour/office.yaml"
_ENTRIES: dict[str, dict[str, Any]] = {
    "hq": {"id": "hq", "name": "Headquarters"},
    "harbour": {"id": "harbour", "name": "Harbour Street", "office": str(HARBOUR_OFFICE)},
    "annex": {"id": "annex", "name": "Annex"},
}


def deployment(folder: Path, *offices: str) -> Path:
    """``folder``/offices.yaml listing ``offices`` (of hq, harbour, annex) in that order."""
    path = folder / "offices.yaml"
    entries = [_ENTRIES[o] for o in offices]
    path.write_text(yaml.safe_dump({"offices": entries}), encoding="utf-8")
    return path


def replica(folder: Path, name: str, url: str, offices: Path, **env: str) -> Server:
    """A replica process ``name`` running the offices file ``offices`` on the database
    ``url`` with the simulated robot and no tokens; ``env``: more of its settings."""
    return serve(
        folder / name,
        free_port(),
        ASSISTANTX_OFFICES=str(offices),
        ASSISTANTX_DATABASE_URL=url,
        ASSISTANTX_REPLICA_ID=name,
        ASSISTANTX_ROBOT="sim",
        ASSISTANTX_TOKENS="",
        **env,
    )
