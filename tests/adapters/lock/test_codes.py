"""Sealing, unsealing, key rotation and drawing of one-time QR codes."""

from __future__ import annotations

import io
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from assistantx.adapters.lock.protocol import (
    CodeIssuer,
    Keyring,
    KeyringError,
    LockKeys,
    render_png,
    unseal,
)
from assistantx.adapters.lock.protocol.keys import b64decode, b64encode, new_key
from assistantx.core.clock import SimClock
from assistantx.core.errors import InvalidCodeError

from .conftest import LOCK_ID


def test_a_sealed_code_unseals_to_the_same_claims(issuer: CodeIssuer, keys: LockKeys) -> None:
    claims, payload = issuer.issue(
        instruction_id="ins-7", person="lee", purpose="sign", item="document:lee"
    )
    assert unseal(payload, keys.codes) == claims
    assert claims.lock_id == LOCK_ID
    assert claims.expires_at - claims.issued_at == 600
    # Compact and QR-friendly: base64url only, a few hundred characters.
    assert len(payload) < 300
    assert set(payload) <= set("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_")


def test_payloads_reveal_nothing_and_never_repeat(issuer: CodeIssuer) -> None:
    _, first = issuer.issue(instruction_id="i", person="lee", purpose="collect", item="key:lee")
    _, second = issuer.issue(instruction_id="i", person="lee", purpose="collect", item="key:lee")
    assert first != second
    for payload in (first, second):
        assert b"lee" not in b64decode(payload)


def test_a_code_under_another_key_is_forged(issuer: CodeIssuer) -> None:
    _, payload = issuer.issue(instruction_id="i", person="lee", purpose="deposit", item="x")
    stranger = Keyring.single(issuer.keyring.current_id, new_key())
    with pytest.raises(InvalidCodeError) as caught:
        unseal(payload, stranger)
    assert caught.value.reason == "forged"


def test_a_flipped_bit_is_forged(issuer: CodeIssuer, keys: LockKeys) -> None:
    _, payload = issuer.issue(instruction_id="i", person="lee", purpose="deposit", item="x")
    raw = bytearray(b64decode(payload))
    raw[-1] ^= 0x01
    with pytest.raises(InvalidCodeError) as caught:
        unseal(b64encode(bytes(raw)), keys.codes)
    assert caught.value.reason == "forged"


@pytest.mark.parametrize(
    "payload", ["", "!!!", "not base64 at all", "AQ", "A" * 5000, "AQJrMA", "\u00e9t\u00e9"]
)
def test_garbage_is_malformed(payload: str, keys: LockKeys) -> None:
    with pytest.raises(InvalidCodeError) as caught:
        unseal(payload, keys.codes)
    assert caught.value.reason == "malformed"


def test_a_truncated_code_is_malformed_or_forged(issuer: CodeIssuer, keys: LockKeys) -> None:
    _, payload = issuer.issue(instruction_id="i", person="lee", purpose="deposit", item="x")
    for cut in (4, 20, len(payload) // 2, len(payload) - 3):
        with pytest.raises(InvalidCodeError) as caught:
            unseal(payload[:cut], keys.codes)
        assert caught.value.reason in ("malformed", "forged")


def test_rotation_keeps_codes_of_the_previous_key_valid(clock: SimClock) -> None:
    keyring = Keyring.single("k1", new_key())
    issuer = CodeIssuer(LOCK_ID, keyring, clock, render=False)
    old_claims, old_payload = issuer.issue(
        instruction_id="i", person="lee", purpose="collect", item="x"
    )
    keyring.rotate("k2", new_key())
    new_claims, new_payload = issuer.issue(
        instruction_id="i", person="lee", purpose="collect", item="x"
    )
    assert keyring.current_id == "k2"
    assert unseal(old_payload, keyring) == old_claims
    assert unseal(new_payload, keyring) == new_claims
    keyring.rotate("k3", new_key())  # k1 falls off: keep_previous=1
    assert keyring.key_ids() == ["k2", "k3"]
    with pytest.raises(InvalidCodeError) as caught:
        unseal(old_payload, keyring)
    assert caught.value.reason == "unknown_key"
    assert unseal(new_payload, keyring) == new_claims


def test_an_added_key_decrypts_before_it_encrypts() -> None:
    keyring = Keyring.single("k1", new_key())
    keyring.add("k2", new_key())
    assert keyring.current_id == "k1"
    assert keyring.key_ids() == ["k1", "k2"]
    with pytest.raises(KeyringError):
        keyring.add("k2", new_key())  # an id never names two keys
    with pytest.raises(KeyringError):
        keyring.promote("k9")


def test_keyring_refuses_bad_keys() -> None:
    with pytest.raises(KeyringError):
        Keyring.single("k1", b"short")
    with pytest.raises(KeyringError):
        Keyring.single("", new_key())
    with pytest.raises(KeyringError):
        Keyring({"k1": new_key()}, "k2")
    assert "k1" in repr(Keyring.single("k1", b"\x01" * 32))
    assert "\\x01" not in repr(
        LockKeys(link_key=b"\x01" * 32, codes=Keyring.single("k1", new_key()))
    )


def test_key_file_round_trip(tmp_path: Path) -> None:
    keys = LockKeys.generate()
    keys.codes.rotate("k2", new_key())
    path = tmp_path / "lock-keys.json"
    path.write_text(keys.to_json())
    loaded = LockKeys.from_file(path)
    assert loaded.link_key == keys.link_key
    assert loaded.codes.current_id == "k2"
    assert loaded.codes.key_ids() == ["k1", "k2"]
    path.write_text('{"link_key": "AAAA"}')
    with pytest.raises(KeyringError, match=r"lock-keys\.json"):
        LockKeys.from_file(path)


def test_a_secret_derives_distinct_link_and_code_keys() -> None:
    keys = LockKeys.from_secret("sixteen bytes at least")
    assert keys.link_key != keys.codes.current_key
    assert LockKeys.from_secret("sixteen bytes at least").link_key == keys.link_key
    with pytest.raises(KeyringError):
        LockKeys.from_secret("short")


def test_png_is_a_scannable_size(issuer: CodeIssuer) -> None:
    _, payload = issuer.issue(instruction_id="ins-1", person="lee", purpose="sign", item="doc")
    png = render_png(payload)
    assert png.startswith(b"\x89PNG\r\n\x1a\n")
    assert 200 < len(png) < 20_000
    issuer.render = True
    claims, payload = issuer.issue(instruction_id="i", person="lee", purpose="sign", item="doc")
    qr = issuer.to_qrcode(claims, payload)
    assert qr.png is not None
    assert qr.payload == payload
    assert io.BytesIO(qr.png).read(4) == b"\x89PNG"


@settings(max_examples=300, deadline=None, derandomize=True)
@given(st.one_of(st.text(max_size=400), st.binary(max_size=300).map(b64encode)))
def test_fuzz_unseal_only_raises_invalid_code(payload: str) -> None:
    keyring = Keyring.single("k0", b"\x07" * 32)
    with pytest.raises(InvalidCodeError):
        unseal(payload, keyring)
