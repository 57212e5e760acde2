"""One-time QR codes: what a code says, how it is sealed, and how it is drawn.

A payload is base64url (no padding) of::

    version (1 byte) | key id length (1) | key id (ASCII) | GCM nonce (12) | AES-GCM ciphertext

The header (version and key id) is the associated data, so it cannot be swapped; the
plaintext is a compact JSON array of the claims. A typical payload is about 200 characters,
well inside a version-10 QR code at error-correction level M.

Decoding proves only that the payload was sealed by a holder of the key; whether the code is
for this lock, unexpired, unused and provisioned is the controller's business.
"""

from __future__ import annotations

import asyncio
import binascii
import io
import json
import math
import os
import secrets
from dataclasses import dataclass

from cryptography.exceptions import InvalidTag
from cryptography.hazmat.primitives.ciphers.aead import AESGCM

from assistantx.adapters.lock.protocol.keys import Keyring, b64decode, b64encode
from assistantx.core import task_kinds
from assistantx.core.clock import Clock
from assistantx.core.errors import InvalidCodeError
from assistantx.core.ports.lock import Purpose, QRCode

CODE_FORMAT_VERSION = 1
GCM_NONCE_BYTES = 12
CODE_ID_BYTES = 12
# A payload longer than this is not ours; refuse it before any base64 or crypto work.
MAX_PAYLOAD_CHARS = 2048


@dataclass(frozen=True)
class CodeClaims:
    """What a one-time code grants: one opening of one lock, for one person and purpose."""

    code_id: str
    lock_id: str
    instruction_id: str
    person: str
    purpose: Purpose
    item: str
    issued_at: float
    expires_at: float

    def to_qrcode(self, payload: str, png: bytes | None = None) -> QRCode:
        return QRCode(
            code_id=self.code_id,
            payload=payload,
            lock_id=self.lock_id,
            instruction_id=self.instruction_id,
            person=self.person,
            purpose=self.purpose,
            item=self.item,
            issued_at=self.issued_at,
            expires_at=self.expires_at,
            png=png,
        )


def new_code_id() -> str:
    return b64encode(secrets.token_bytes(CODE_ID_BYTES))


def seal(claims: CodeClaims, keyring: Keyring) -> str:
    """Encrypt ``claims`` under the keyring's current key into a QR text payload."""
    key_id = keyring.current_id.encode("ascii")
    header = bytes([CODE_FORMAT_VERSION, len(key_id)]) + key_id
    body = [
        claims.code_id,
        claims.lock_id,
        claims.instruction_id,
        claims.person,
        claims.purpose,
        claims.item,
        claims.issued_at,
        claims.expires_at,
    ]
    plaintext = json.dumps(body, separators=(",", ":"), ensure_ascii=False).encode("utf-8")
    nonce = os.urandom(GCM_NONCE_BYTES)
    ciphertext = AESGCM(keyring.current_key).encrypt(nonce, plaintext, header)
    return b64encode(header + nonce + ciphertext)


def unseal(payload: str, keyring: Keyring) -> CodeClaims:
    """Decrypt and check a payload; raises ``InvalidCodeError`` with reason ``malformed``,
    ``unknown_key`` or ``forged``. Never raises anything else, whatever the input."""
    if not isinstance(payload, str) or len(payload) > MAX_PAYLOAD_CHARS:
        raise InvalidCodeError("malformed", "not a lock code: too long or not text")
    try:
        raw = b64decode(payload.strip())
    except (binascii.Error, ValueError) as exc:
        raise InvalidCodeError("malformed", "not a lock code: bad base64url") from exc
    if len(raw) < 2 or raw[0] != CODE_FORMAT_VERSION:
        raise InvalidCodeError("malformed", "not a lock code: unknown format version")
    header_end = 2 + raw[1]
    # 16 = the GCM tag; anything shorter is a truncated payload.
    if len(raw) < header_end + GCM_NONCE_BYTES + 16:
        raise InvalidCodeError("malformed", "lock code is truncated")
    header = raw[:header_end]
    try:
        key_id = header[2:].decode("ascii")
    except UnicodeDecodeError as exc:
        raise InvalidCodeError("malformed", "lock code has a bad key id") from exc
    key = keyring.get(key_id)
    if key is None:
        raise InvalidCodeError("unknown_key", f"lock code sealed under unknown key {key_id!r}")
    nonce = raw[header_end : header_end + GCM_NONCE_BYTES]
    try:
        plaintext = AESGCM(key).decrypt(nonce, raw[header_end + GCM_NONCE_BYTES :], header)
    except InvalidTag as exc:
        raise InvalidCodeError("forged", "lock code failed authentication") from exc
    return _claims_from_plaintext(plaintext)


def _claims_from_plaintext(plaintext: bytes) -> CodeClaims:
    # Authenticated, so written by a key holder; still checked, a key holder can have bugs.
    try:
        body = json.loads(plaintext)
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise InvalidCodeError("malformed", "lock code body is not JSON") from exc
    if not isinstance(body, list) or len(body) != 8:
        raise InvalidCodeError("malformed", "lock code body has the wrong shape")
    code_id, lock_id, instruction_id, person, purpose, item, issued_at, expires_at = body
    texts = (code_id, lock_id, instruction_id, person, purpose, item)
    times = (issued_at, expires_at)
    if not all(isinstance(t, str) for t in texts) or not all(
        isinstance(t, (int, float)) and not isinstance(t, bool) and math.isfinite(t) for t in times
    ):
        raise InvalidCodeError("malformed", "lock code body has wrong field types")
    if purpose not in task_kinds.purposes():
        raise InvalidCodeError("malformed", f"lock code has unknown purpose {purpose!r}")
    return CodeClaims(
        code_id=code_id,
        lock_id=lock_id,
        instruction_id=instruction_id,
        person=person,
        purpose=purpose,
        item=item,
        issued_at=float(issued_at),
        expires_at=float(expires_at),
    )


def render_png(payload: str, *, scale: int = 4) -> bytes:
    """Draw the payload as a QR code (PNG bytes, error correction M, quiet zone 4)."""
    import segno  # on the first code drawn: ~20 ms of every service start otherwise

    buffer = io.BytesIO()
    segno.make_qr(payload, error="m", boost_error=False).save(buffer, kind="png", scale=scale)
    return buffer.getvalue()


class CodeIssuer:
    """The assistant's side: mints sealed one-time codes for one lock."""

    def __init__(
        self,
        lock_id: str,
        keyring: Keyring,
        clock: Clock,
        *,
        expiry_s: float = 15 * 60,
        render: bool = True,
    ) -> None:
        if expiry_s <= 0:
            raise ValueError("expiry_s must be positive")
        self.lock_id = lock_id
        self.keyring = keyring
        self.clock = clock
        self.expiry_s = expiry_s
        self.render = render

    def issue(
        self, *, instruction_id: str, person: str, purpose: Purpose, item: str
    ) -> tuple[CodeClaims, str]:
        if purpose not in task_kinds.purposes():
            raise ValueError(f"unknown purpose {purpose!r}")
        now = self.clock.now()
        claims = CodeClaims(
            code_id=new_code_id(),
            lock_id=self.lock_id,
            instruction_id=instruction_id,
            person=person,
            purpose=purpose,
            item=item,
            issued_at=now,
            expires_at=now + self.expiry_s,
        )
        return claims, seal(claims, self.keyring)

    def to_qrcode(self, claims: CodeClaims, payload: str) -> QRCode:
        return claims.to_qrcode(payload, render_png(payload) if self.render else None)

    async def ato_qrcode(self, claims: CodeClaims, payload: str) -> QRCode:
        """``to_qrcode`` with the PNG rendered in a worker thread (tens of ms of CPU that
        would otherwise hold the event loop)."""
        png = await asyncio.to_thread(render_png, payload) if self.render else None
        return claims.to_qrcode(payload, png)
