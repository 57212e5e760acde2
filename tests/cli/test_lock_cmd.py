"""The ``lock-keys`` and ``lock-sim`` commands' handling of keys and bad input."""

from __future__ import annotations

import stat
from pathlib import Path

import pytest

from assistantx.adapters.lock.protocol import LockKeys
from assistantx.cli import main
from assistantx.cli.lock_cmd import _load_keys
from assistantx.core.settings import Settings
from assistantx.service.runtime import lock_keys_for


def test_lock_keys_new_then_rotate(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "keys.json"
    assert main(["lock-keys", "new", str(path)]) == 0
    assert stat.S_IMODE(path.stat().st_mode) == 0o600
    first = LockKeys.from_file(path)
    assert main(["lock-keys", "new", str(path)]) == 1  # never overwrites keys
    assert main(["lock-keys", "rotate", str(path)]) == 0
    assert main(["lock-keys", "rotate", str(path)]) == 0
    rotated = LockKeys.from_file(path)
    assert rotated.link_key == first.link_key
    assert rotated.codes.key_ids() == ["k2", "k3"]
    assert "current key k3" in capsys.readouterr().out


def test_lock_sim_refuses_to_start_with_bad_keys(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    # Without any key it shares the service's (tests/cli/test_names_cli.py); bad keys stop it.
    monkeypatch.delenv("ASSISTANTX_LOCK_KEY_FILE", raising=False)
    monkeypatch.setenv("ASSISTANTX_DATA_DIR", str(tmp_path / "data"))
    monkeypatch.setenv("ASSISTANTX_LOCK_SHARED_KEY", "short")
    assert main(["lock-sim", "--port", "0"]) == 2
    assert "at least 16 bytes" in capsys.readouterr().out
    bad = tmp_path / "bad.json"
    bad.write_text("{not json")
    assert main(["lock-sim", "--port", "0", "--key-file", str(bad)]) == 2
    assert "not a lock key file" in capsys.readouterr().out


def test_serve_and_lock_sim_pick_the_same_keys_by_one_rule(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Both a key file and a shared secret configured: the key file wins, for the service
    and for lock-sim alike (else they would not understand each other)."""
    key_file = tmp_path / "keys.json"
    assert main(["lock-keys", "new", str(key_file)]) == 0
    monkeypatch.setenv("ASSISTANTX_LOCK_KEY_FILE", str(key_file))
    monkeypatch.setenv("ASSISTANTX_LOCK_SHARED_KEY", "a long shared secret for the test")
    settings = Settings()
    service = lock_keys_for(settings, tmp_path / "data-unused")
    lock_sim = _load_keys(settings.lock_key_file, settings)
    from_file = LockKeys.from_file(key_file)
    assert service.link_key == lock_sim.link_key == from_file.link_key
    assert service.codes.current_id == lock_sim.codes.current_id == "k1"
    # Only the secret: both derive the same keys from it.
    monkeypatch.delenv("ASSISTANTX_LOCK_KEY_FILE")
    settings = Settings()
    service = lock_keys_for(settings, tmp_path / "data-unused")
    lock_sim = _load_keys(settings.lock_key_file, settings)
    assert service.link_key == lock_sim.link_key != from_file.link_key


def test_a_missing_key_file_is_a_clear_error_not_a_new_key(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    missing = tmp_path / "typo.json"
    monkeypatch.delenv("ASSISTANTX_LOCK_SHARED_KEY", raising=False)
    assert main(["lock-sim", "--port", "0", "--key-file", str(missing)]) == 2
    assert f"lock-keys new {missing}" in capsys.readouterr().out
    assert not missing.exists()
