"""Bearer tokens: each bound to one person or to the operator role.

Tokens come from settings (``ASSISTANTX_TOKENS``: a JSON object ``{"token": "person"}`` or CSV
``token:person,...``; ``ASSISTANTX_OPERATOR_TOKEN``). Only their SHA-256 digests are kept in
memory, and a presented token is compared with every digest by ``hmac.compare_digest``, so
neither the stored tokens nor the timing of a check reveals them. With no token configured at
all, an operator token is generated at start-up and stored (0600) in the data directory, so a
local ``make run`` is usable; the CLI prints it, nothing logs it.
"""

from __future__ import annotations

import hashlib
import hmac
import json
import logging
import os
import secrets
from dataclasses import dataclass
from pathlib import Path

from assistantx.core.errors import GroundingError
from assistantx.memory.resolve import Resolver
from assistantx.service.errors import ForbiddenError, UnauthorizedError

logger = logging.getLogger(__name__)

OPERATOR = "operator"
TOKEN_FILE = "operator-token"


@dataclass(frozen=True)
class Principal:
    """Who is calling: a person (id) or the operator (person is None)."""

    person: str | None

    @property
    def is_operator(self) -> bool:
        return self.person is None

    def may_act_as(self, person: str) -> bool:
        return self.is_operator or self.person == person

    def require_operator(self) -> None:
        if not self.is_operator:
            raise ForbiddenError("this endpoint is for the operator only")

    def require_person(self, person: str) -> None:
        if not self.may_act_as(person):
            raise ForbiddenError(f"your token belongs to {self.person}, not to {person}")


def _digest(token: str) -> bytes:
    return hashlib.sha256(token.encode("utf-8")).digest()


def parse_person_tokens(raw: str) -> dict[str, str]:
    """``{"tok": "lee"}`` or ``tok:lee,tok2:zhang`` → token → person (ValueError if malformed)."""
    text = raw.strip()
    if not text:
        return {}
    if text.startswith("{"):
        try:
            data = json.loads(text)
        except json.JSONDecodeError as exc:
            raise ValueError(f"ASSISTANTX_TOKENS is not valid JSON: {exc.msg}") from exc
        if not all(isinstance(k, str) and isinstance(v, str) for k, v in data.items()):
            raise ValueError("ASSISTANTX_TOKENS must map token strings to person ids")
        return dict(data)
    pairs: dict[str, str] = {}
    for n, entry in enumerate(text.split(","), 1):
        token, sep, person = entry.strip().rpartition(":")
        if not sep or not token or not person:
            raise ValueError(f"ASSISTANTX_TOKENS entry {n} is not 'token:person'")
        pairs[token] = person.strip()
    return pairs


class TokenAuthority:
    def __init__(self) -> None:
        self._digests: list[tuple[bytes, Principal]] = []

    def add(self, token: str, principal: Principal) -> None:
        if len(token) < 16:
            raise ValueError("a token must be at least 16 characters long")
        self._digests.append((_digest(token), principal))

    def __len__(self) -> int:
        return len(self._digests)

    def authenticate(self, authorization: str | None) -> Principal:
        if not authorization:
            raise UnauthorizedError("missing bearer token (send 'Authorization: Bearer TOKEN')")
        scheme, _, token = authorization.partition(" ")
        if scheme.lower() != "bearer" or not token.strip():
            raise UnauthorizedError("the Authorization header must be 'Bearer TOKEN'")
        presented = _digest(token.strip())
        found: Principal | None = None
        for digest, principal in self._digests:  # no early exit: same work for every token
            if hmac.compare_digest(digest, presented):
                found = principal
        if found is None:
            raise UnauthorizedError("invalid bearer token")
        return found


@dataclass(frozen=True)
class AuthSetup:
    authority: TokenAuthority
    generated_token: str | None = None
    token_file: Path | None = None


def build_authority(
    operator_token: str | None, person_tokens: str | None, resolver: Resolver, data_dir: Path
) -> AuthSetup:
    """The token authority from settings; generates an operator token when none is set."""
    authority = TokenAuthority()
    for token, person in parse_person_tokens(person_tokens or "").items():
        try:
            person_id = resolver.person(person)
        except GroundingError as exc:
            raise ValueError(f"ASSISTANTX_TOKENS names an unknown person: {exc}") from exc
        authority.add(token, Principal(person=person_id))
    if operator_token:
        authority.add(operator_token, Principal(person=None))
    if len(authority):
        return AuthSetup(authority)
    path = data_dir / TOKEN_FILE
    token = _read_or_create_token(path)
    authority.add(token, Principal(person=None))
    logger.warning("no tokens configured; an operator token was generated into %s", path)
    return AuthSetup(authority, generated_token=token, token_file=path)


def generated_operator_token(data_dir: Path) -> str:
    """The operator token generated once into ``data_dir`` (the one ``build_authority`` makes
    when no token is configured)."""
    return _read_or_create_token(data_dir / TOKEN_FILE)


def _read_or_create_token(path: Path) -> str:
    path.parent.mkdir(parents=True, exist_ok=True)
    if path.exists():
        token = path.read_text(encoding="utf-8").strip()
        if len(token) >= 16:
            return token
    token = secrets.token_urlsafe(32)
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
    with os.fdopen(fd, "w", encoding="utf-8") as f:
        f.write(token + "\n")
    os.chmod(path, 0o600)
    return token
