"""``assistantx matrix registration`` writes the file a homeserver loads."""

from __future__ import annotations

import stat
from pathlib import Path

import pytest
import yaml

from assistantx.cli import main

MATRIX_YAML = """
homeserver_url: http://127.0.0.1:8008
server_name: office.example
as_token: as-secret-token
hs_token: hs-secret-token
appservice_url: http://127.0.0.1:8009
people: {lee: "@lee:office.example"}
"""


def test_registration_is_written_private_and_complete(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    config = tmp_path / "matrix.yaml"
    config.write_text(MATRIX_YAML, encoding="utf-8")
    out = tmp_path / "registration.yaml"
    assert main(["matrix", "registration", "--config", str(config), "-o", str(out)]) == 0
    assert stat.S_IMODE(out.stat().st_mode) == 0o600  # it holds both tokens
    written = yaml.safe_load(out.read_text(encoding="utf-8"))
    assert written["url"] == "http://127.0.0.1:8009"
    assert (written["as_token"], written["hs_token"]) == ("as-secret-token", "hs-secret-token")
    assert written["sender_localpart"] == "assistant"
    assert written["namespaces"]["users"] == [
        {"exclusive": True, "regex": r"^@assistant:office\.example$"}
    ]
    assert "app_service_config_files" in capsys.readouterr().out


def test_registration_without_a_push_url_is_a_clear_error(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    config = tmp_path / "matrix.yaml"
    config.write_text(MATRIX_YAML.replace("appservice_url: http://127.0.0.1:8009\n", ""))
    assert main(["matrix", "registration", "--config", str(config), "-o", "-"]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "appservice_url" in err
    assert "secret" not in err
