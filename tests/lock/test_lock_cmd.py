"""The ``lock-keys`` and ``lock-sim`` commands' handling of keys and bad input."""

from __future__ import annotations

import stat
from pathlib import Path

import pytest

from assistantx.cli import main
from assistantx.lock import LockKeys


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
