"""The payloads of the QR codes the assistant sent, kept like the phones that received them.

A QR image's payload never reaches the journal (it opens the locker), so the service notes
each one as a messenger sends it, which is what a person's phone would hold. The book is
registered with every messenger at start-up (a code sent before anyone opened the dashboard
is as scannable as one sent after), and it is kept in an owner-only file beside the journal,
written before the message goes out, so after a restart the dashboard can still scan a code
of an instruction that resumes, and an in-process lock can be armed with it again.

Codes leave the file once expired. The lock, not the book, decides whether a code still
opens the door.
"""

from __future__ import annotations

import json
import logging
import os
from pathlib import Path

from assistantx.adapters.lock.protocol.codes import CodeClaims, unseal
from assistantx.adapters.lock.protocol.keys import Keyring
from assistantx.core.clock import Clock
from assistantx.core.errors import InvalidCodeError
from assistantx.core.ports.messenger import OutboundMessage

logger = logging.getLogger(__name__)


class CodeBook:
    """Payloads by code id; ``path``: the owner-only file that keeps them across restarts."""

    def __init__(self, keyring: Keyring, clock: Clock, path: Path | None = None) -> None:
        self._keyring = keyring
        self._clock = clock
        self._path = path
        self._codes: dict[str, tuple[CodeClaims, str]] = {}
        for payload in self._load():
            self._remember(payload)

    async def note(self, message: OutboundMessage) -> None:
        """A messenger relay: remember the codes ``message`` carries (before it is sent)."""
        added = [self._remember(a.qr_payload) for a in message.attachments if a.qr_payload]
        if any(added):
            self._save()

    def add(self, payload: str) -> None:
        if self._remember(payload):
            self._save()

    def payload(self, code_id: str) -> str | None:
        entry = self._codes.get(code_id)
        return entry[1] if entry is not None else None

    def payloads(self) -> list[str]:
        return [payload for _, payload in self._codes.values()]

    def _remember(self, payload: str) -> bool:
        try:
            claims = unseal(payload, self._keyring)
        except InvalidCodeError:
            logger.info("a QR payload under an unknown key was not noted")
            return False
        if claims.code_id in self._codes:
            return False
        self._codes[claims.code_id] = (claims, payload)
        return True

    def _save(self) -> None:
        now = self._clock.now()
        self._codes = {c: e for c, e in self._codes.items() if e[0].expires_at > now}
        if self._path is None:
            return
        temporary = self._path.with_name(f".{self._path.name}.tmp")
        fd = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            json.dump(self.payloads(), handle)
        temporary.replace(self._path)

    def _load(self) -> list[str]:
        if self._path is None:
            return []
        try:
            data = json.loads(self._path.read_text(encoding="utf-8"))
        except FileNotFoundError:
            return []
        except (OSError, ValueError) as exc:
            logger.warning("the dashboard's code book is unreadable (%s); it starts empty", exc)
            return []
        return [str(p) for p in data] if isinstance(data, list) else []
