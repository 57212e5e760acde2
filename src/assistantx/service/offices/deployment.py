"""Which offices one deployment runs: ``ASSISTANTX_OFFICES`` names a YAML file, else one office.

A deployment file lists the offices, each with an id (lower-case letters, digits, ``-``), a
name people read, and any ``ASSISTANTX_*`` setting of its own (lower-case, without the
prefix: ``office``, ``map``, ``map_anchors``, ``lock_port``, ``matrix_config``,
``sim_unavailable`` ...); what an office does not set it takes from the environment. Relative
paths are read from the file's folder::

    offices:
      - id: hq
        name: Headquarters
      - id: harbour
        name: Harbour Street
        office: ../dataset/offices/harbour/office.yaml
        map_anchors: ../dataset/offices/harbour/office.anchors.yaml
        operator_token: harbour-operator-token-0001
        tokens: {harbour-will-token-00001: will}

Each office keeps its own people, map, robot, lock, Matrix rooms and memory, and its own
journal: the first office listed (the *home* office) keeps where a single-office deployment
keeps it (the data folder; PostgreSQL's ``public`` schema), so turning one office into
several keeps its history; every other office has the folder ``DATA_DIR/offices/ID`` and, on
PostgreSQL, the schema ``office_ID`` of the same database (every table of the journal, the
surveys and the Matrix state, migrated on its own). Nothing crosses from one office's rows to
another's, and no statement of the stores had to learn of offices.

Tokens: ``operator_token`` and ``tokens`` in an office's entry hold for that office only (a
token of one office is refused on another: 403); ``ASSISTANTX_OPERATOR_TOKEN`` is the
deployment operator's and holds for every office. ``ASSISTANTX_TOKENS`` names people, who
belong to one office, so with a deployment file it is refused: give each office its own.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any
from urllib.parse import parse_qsl, quote, urlencode, urlsplit, urlunsplit

from pydantic import SecretStr, ValidationError

from assistantx.core.errors import JournalError
from assistantx.core.settings import Settings
from assistantx.core.yaml_file import read_yaml
from assistantx.store.journal import Journal

OFFICE_ID = re.compile(r"^[a-z][a-z0-9-]{0,39}$")
OFFICES_DIR = "offices"  # DATA_DIR/offices/ID: each office but the home one
PATH_SETTINGS = ("office", "map", "map_anchors", "lock_key_file", "matrix_config", "matrix_store")
NOT_PER_OFFICE = ("data_dir", "database_url", "offices", "host", "port", "replica_id")


class DeploymentError(ValueError):
    """A deployment file that cannot be used; the message names the file and the entry."""


@dataclass(frozen=True)
class OfficeSpec:
    """One office of the deployment: ``settings`` are the ones its runtime starts with."""

    id: str
    name: str
    settings: Settings
    home: bool  # the first office: the data folder's and the database's own place
    operator_token: str | None = None  # this office's operator (not the deployment's)

    @property
    def schema(self) -> str | None:
        """Its PostgreSQL schema; None: ``public`` (the home office)."""
        return None if self.home else schema_name(self.id)


def schema_name(office_id: str) -> str:
    return "office_" + office_id.replace("-", "_")


def load_deployment(settings: Settings) -> list[OfficeSpec]:
    """The offices to run: the deployment file's, or the one office of ``settings``."""
    if settings.offices is None:
        return [OfficeSpec(id="default", name="", settings=settings, home=True)]
    return _read(settings.offices, settings)


def _read(path: Path, base: Settings) -> list[OfficeSpec]:
    where = str(path)
    raw = read_yaml(path, lambda why: DeploymentError(f"{where}: {why}"))
    entries = raw.get("offices") if isinstance(raw, dict) else None
    if not isinstance(entries, list) or not entries:
        raise DeploymentError(f"{where}: needs 'offices:', a list of offices")
    if base.tokens is not None and base.tokens.get_secret_value().strip():
        raise DeploymentError(
            f"{where}: ASSISTANTX_TOKENS names people of one office; with several offices give"
            " each office its own 'tokens:'"
        )
    specs: list[OfficeSpec] = []
    for n, entry in enumerate(entries, 1):
        spec = _office(entry, n, path.parent, base, home=not specs, where=where)
        if any(s.id == spec.id for s in specs):
            raise DeploymentError(f"{where}: office {n}: the id {spec.id!r} is listed twice")
        specs.append(spec)
    _one_registration_each(specs, where)
    return specs


def _one_registration_each(specs: list[OfficeSpec], where: str) -> None:
    """Refuse two offices on Matrix with one application-service token: the pushes of one
    homeserver token reach one office only, so the other office's people would be answered
    by nobody (or by the wrong office) with nothing in any log saying why."""
    from assistantx.adapters.messenger.matrix.config import load_matrix_config
    from assistantx.core.errors import MessengerError

    seen: dict[tuple[str, str], str] = {}
    for spec in specs:
        path = spec.settings.matrix_config
        if spec.settings.messenger != "matrix" or path is None:
            continue
        try:
            config = load_matrix_config(path)
        except MessengerError:
            continue  # the office's own start says what is wrong with its file
        tokens = (
            ("homeserver token (hs_token)", config.hs_token.get_secret_value()),
            ("application service token (as_token)", config.as_token.get_secret_value()),
        )
        for name, token in tokens:
            other = seen.setdefault((name, token), spec.id)
            if other != spec.id:
                raise DeploymentError(
                    f"{where}: offices {other!r} and {spec.id!r} have the same {name}: give"
                    " each office its own application-service registration"
                )


def _office(
    entry: Any, n: int, folder: Path, base: Settings, *, home: bool, where: str
) -> OfficeSpec:
    here = f"{where}: office {n}"
    if not isinstance(entry, dict):
        raise DeploymentError(f"{here}: must be a mapping with 'id' and 'name'")
    fields = dict(entry)
    office_id = str(fields.pop("id", ""))
    if not OFFICE_ID.match(office_id):
        raise DeploymentError(
            f"{here}: 'id' must be lower-case letters, digits and '-', starting with a letter"
        )
    name = str(fields.pop("name", "") or office_id)
    own_operator = fields.pop("operator_token", None)
    tokens = fields.pop("tokens", None)
    for key in fields:
        if key in NOT_PER_OFFICE:
            raise DeploymentError(f"{here}: {key!r} is the deployment's, not an office's")
        if key not in Settings.model_fields:
            raise DeploymentError(f"{here}: {key!r} is no setting")
    for key in PATH_SETTINGS:
        if fields.get(key) is not None:
            fields[key] = folder / str(fields[key])
    data_dir = base.data_dir if home else base.data_dir / OFFICES_DIR / office_id
    database = base.database
    if database is not None and not home:
        database = scoped_url(database, schema_name(office_id))
    fields.update(
        data_dir=data_dir,
        database_url=SecretStr(database) if database is not None else None,
        tokens=SecretStr(_token_text(tokens, here)) if tokens else None,
        offices=None,
    )
    try:
        settings = Settings(**{**base.model_dump(), **fields})
    except ValidationError as exc:
        first = exc.errors()[0]
        raise DeploymentError(
            f"{here}: {'.'.join(str(p) for p in first['loc'])}: {first['msg']}"
        ) from exc
    operator = str(own_operator) if own_operator is not None else None
    if operator is not None and len(operator) < 16:
        raise DeploymentError(f"{here}: 'operator_token' must be at least 16 characters long")
    return OfficeSpec(office_id, name, settings, home, operator)


def _token_text(tokens: Any, here: str) -> str:
    if not isinstance(tokens, dict) or not all(
        isinstance(k, str) and isinstance(v, str) for k, v in tokens.items()
    ):
        raise DeploymentError(f"{here}: 'tokens' must map token strings to person ids")
    return ",".join(f"{token}:{person}" for token, person in tokens.items())


def scoped_url(url: str, schema: str) -> str:
    """``url`` with its search path starting at ``schema`` (libpq reads ``options`` from the
    URL's query): every table an office's stores create is made there (PostgreSQL creates in
    the path's first schema, and ``IF NOT EXISTS`` looks only there) and read from there
    first; ``public`` after it holds what the deployment shares, the leases table, which the
    fencing check of every journal write reads."""
    parts = urlsplit(url)
    query = [(k, v) for k, v in parse_qsl(parts.query) if k != "options"]
    query.append(("options", f"-c search_path={schema},public"))
    return urlunsplit(parts._replace(query=urlencode(query, quote_via=quote)))


OFFICE_STATE = "deployment_office"  # the journal's state row naming the office it belongs to


def claim_journal(journal: Journal, office_id: str, where: str) -> None:
    """Mark ``journal`` as ``office_id``'s, or refuse it when it is another office's.

    The home office's journal is the data folder's (the database's ``public`` schema) by its
    place in the file, not by its id: listing another office first would hand it the home
    office's instructions, people's answers and memory. A journal of one office (no mark yet)
    becomes the home office's on the first start with a deployment file."""
    claim = journal.state(OFFICE_STATE)
    if claim is None:
        journal.put_state(OFFICE_STATE, {"id": office_id})
    elif claim.get("id") != office_id:
        raise JournalError(
            f"{where}: this journal belongs to office {claim.get('id')!r}, not {office_id!r}:"
            " keep the office that was listed first in the deployment file first"
        )
