"""Secrets shared by the lock and the assistant: the link key and the QR code keyring.

Two secrets with two jobs:

- the **link key** authenticates the TCP link (challenge–response, then per-frame MACs);
- the **code keyring** encrypts QR payloads. Each key has a short id that travels in the
  payload, so keys rotate without downtime: the lock first learns the new key (``add``), then
  the assistant starts encrypting with it (``promote``); codes issued under the previous key
  still decrypt until they expire, and older keys are dropped.

Key file (JSON, base64url-encoded 32-byte keys)::

    {"link_key": "...", "code_keys": {"k1": "...", "k2": "..."}, "current": "k2"}

A single secret (e.g. from ``ASSISTANTX_LOCK_SHARED_KEY``) also works: both keys are derived
from it with HKDF-SHA256, the code key under id ``k0``.

Where the keys come from follows one rule everywhere (``assistantx serve``, ``assistantx
lock-sim``, the settings), in ``load_lock_keys``: a key file (``--key-file`` or
``ASSISTANTX_LOCK_KEY_FILE``) wins; else the shared secret; else a fallback file the caller
names (the service's ``DATA_DIR/lock-keys.json``, generated on first start).
"""

from __future__ import annotations

import base64
import binascii
import json
import os
import secrets
from dataclasses import dataclass
from pathlib import Path

from cryptography.hazmat.primitives import hashes
from cryptography.hazmat.primitives.kdf.hkdf import HKDF

KEY_BYTES = 32
MAX_KEY_ID_LENGTH = 16
DERIVED_CODE_KEY_ID = "k0"


class KeyringError(ValueError):
    """A key, key id or key file that cannot be used."""


def b64encode(data: bytes) -> str:
    return base64.urlsafe_b64encode(data).rstrip(b"=").decode("ascii")


def b64decode(text: str) -> bytes:
    """Decode unpadded base64url; raises ``binascii.Error`` on anything else."""
    if not isinstance(text, str) or not text.isascii():
        raise binascii.Error("not ASCII text")
    return base64.urlsafe_b64decode(text + "=" * (-len(text) % 4))


def new_key() -> bytes:
    return secrets.token_bytes(KEY_BYTES)


def _check_key(key_id: str, key: bytes) -> None:
    if not key_id or len(key_id) > MAX_KEY_ID_LENGTH or not key_id.isascii():
        raise KeyringError(f"key id {key_id!r} must be 1-{MAX_KEY_ID_LENGTH} ASCII characters")
    if len(key) != KEY_BYTES:
        raise KeyringError(f"key {key_id!r} must be {KEY_BYTES} bytes, got {len(key)}")


class Keyring:
    """AES-256 keys by id: the current one encrypts; current and previous ones decrypt.

    ``keep_previous`` bounds how many superseded keys stay valid for decryption; keep it at
    least 1 so codes issued just before a rotation still open the door.
    """

    def __init__(self, keys: dict[str, bytes], current: str, *, keep_previous: int = 1) -> None:
        if keep_previous < 0:
            raise KeyringError("keep_previous must be >= 0")
        if current not in keys:
            raise KeyringError(f"current key {current!r} is not in the keyring")
        for key_id, key in keys.items():
            _check_key(key_id, key)
        self.keep_previous = keep_previous
        # Insertion order is age order: the last entries are the newest.
        self._keys = {k: v for k, v in keys.items() if k != current}
        self._keys[current] = keys[current]
        self._current = current
        self._trim()

    @classmethod
    def single(cls, key_id: str, key: bytes) -> Keyring:
        return cls({key_id: key}, key_id)

    @property
    def current_id(self) -> str:
        return self._current

    @property
    def current_key(self) -> bytes:
        return self._keys[self._current]

    def key_ids(self) -> list[str]:
        """Key ids, oldest first."""
        return list(self._keys)

    def get(self, key_id: str) -> bytes | None:
        return self._keys.get(key_id)

    def add(self, key_id: str, key: bytes) -> None:
        """Accept ``key_id`` for decryption without encrypting with it yet."""
        _check_key(key_id, key)
        existing = self._keys.get(key_id)
        if existing is not None and existing != key:
            raise KeyringError(f"key id {key_id!r} already names another key")
        if existing is None:
            self._keys[key_id] = key

    def promote(self, key_id: str) -> None:
        """Make ``key_id`` the encrypting key; the old current key becomes a previous one."""
        if key_id not in self._keys:
            raise KeyringError(f"key {key_id!r} must be added before it is promoted")
        key = self._keys.pop(key_id)
        self._keys[key_id] = key
        self._current = key_id
        self._trim()

    def rotate(self, key_id: str, key: bytes) -> None:
        self.add(key_id, key)
        self.promote(key_id)

    def replace_with(self, other: Keyring) -> None:
        """Adopt another keyring's keys (a reloaded key file) in place."""
        self._keys = dict(other._keys)
        self._current = other._current
        self.keep_previous = other.keep_previous

    def _trim(self) -> None:
        # Keys older than the current one are "previous"; keys added but not yet promoted
        # sit after it and are always kept.
        ids = list(self._keys)
        previous = ids[: ids.index(self._current)]
        for key_id in previous[: max(0, len(previous) - self.keep_previous)]:
            del self._keys[key_id]

    def __repr__(self) -> str:  # never show key material
        return f"Keyring(current={self._current!r}, ids={self.key_ids()!r})"


@dataclass(frozen=True, repr=False)
class LockKeys:
    """Everything secret the lock and the assistant share."""

    link_key: bytes
    codes: Keyring

    def __repr__(self) -> str:
        return f"LockKeys(link_key=***, codes={self.codes!r})"

    @classmethod
    def generate(cls, code_key_id: str = "k1") -> LockKeys:
        return cls(link_key=new_key(), codes=Keyring.single(code_key_id, new_key()))

    @classmethod
    def from_secret(cls, secret: str | bytes) -> LockKeys:
        """Derive both keys from one shared secret (at least 16 bytes)."""
        raw = secret.encode() if isinstance(secret, str) else secret
        if len(raw) < 16:
            raise KeyringError("the shared lock secret must be at least 16 bytes")
        return cls(
            link_key=_derive(raw, b"assistantx-lock/link"),
            codes=Keyring.single(DERIVED_CODE_KEY_ID, _derive(raw, b"assistantx-lock/codes/k0")),
        )

    @classmethod
    def from_file(cls, path: Path) -> LockKeys:
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
            link_key = b64decode(data["link_key"])
            code_keys = {str(k): b64decode(v) for k, v in data["code_keys"].items()}
            current = str(data["current"])
        except (OSError, ValueError, KeyError, TypeError, AttributeError) as exc:
            raise KeyringError(f"{path}: not a lock key file ({exc})") from exc
        if len(link_key) != KEY_BYTES:
            raise KeyringError(f"{path}: link_key must be {KEY_BYTES} bytes")
        keep = max(1, len(code_keys) - 1)
        try:
            keyring = Keyring(code_keys, current, keep_previous=keep)
        except KeyringError as exc:
            raise KeyringError(f"{path}: {exc}") from exc
        return cls(link_key=link_key, codes=keyring)

    def to_json(self) -> str:
        keys = {k: b64encode(v) for k in self.codes.key_ids() if (v := self.codes.get(k))}
        return json.dumps(
            {
                "link_key": b64encode(self.link_key),
                "code_keys": keys,
                "current": self.codes.current_id,
            },
            indent=2,
        )


def load_lock_keys(
    *, key_file: Path | None, secret: str | None, fallback_file: Path | None = None
) -> LockKeys:
    """The lock's keys by the one precedence rule: ``key_file`` (must exist), else the shared
    ``secret``, else ``fallback_file`` (created, owner-only, when missing)."""
    if key_file is not None:
        if not key_file.exists():
            raise KeyringError(
                f"lock key file {key_file} does not exist "
                f"(create one with `assistantx lock-keys new {key_file}`)"
            )
        return LockKeys.from_file(key_file)
    if secret is not None:
        return LockKeys.from_secret(secret)
    if fallback_file is None:
        raise KeyringError("no lock keys: give a key file or a shared secret")
    if fallback_file.exists():
        return LockKeys.from_file(fallback_file)
    keys = LockKeys.generate()
    fd = os.open(fallback_file, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    with os.fdopen(fd, "w", encoding="utf-8") as handle:
        handle.write(keys.to_json())
    return keys


def _derive(secret: bytes, info: bytes) -> bytes:
    return HKDF(algorithm=hashes.SHA256(), length=KEY_BYTES, salt=None, info=info).derive(secret)
