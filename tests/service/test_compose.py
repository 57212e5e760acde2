"""compose.yaml, read statically (no Docker on the test machines): two replicas of the image
on one PostgreSQL, each with its own name and data folder, the same database and secrets."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml

ROOT = Path(__file__).resolve().parents[2]


def test_two_replicas_share_one_database_each_with_its_own_name_and_data() -> None:
    compose: dict[str, Any] = yaml.safe_load((ROOT / "compose.yaml").read_text())
    services = compose["services"]
    replicas = [s for name, s in services.items() if name.startswith("replica-")]
    assert len(replicas) == 2
    envs = [r["environment"] for r in replicas]
    assert {e["ASSISTANTX_REPLICA_ID"] for e in envs} == {"replica-1", "replica-2"}
    for key in (
        "ASSISTANTX_DATABASE_URL",
        "ASSISTANTX_LOCK_SHARED_KEY",
        "ASSISTANTX_OPERATOR_TOKEN",
    ):
        assert envs[0][key] == envs[1][key], key
    assert envs[0]["ASSISTANTX_DATABASE_URL"].startswith("postgresql://")
    assert "@postgres:5432/" in envs[0]["ASSISTANTX_DATABASE_URL"]
    data = [next(v for v in r["volumes"] if v.endswith(":/data")) for r in replicas]
    assert data[0] != data[1]
    assert all(r["build"] == "." and r["restart"] == "unless-stopped" for r in replicas)
    assert all(r["depends_on"]["postgres"]["condition"] == "service_healthy" for r in replicas)
    assert services["postgres"]["image"].startswith("postgres:")


def test_every_command_in_compose_is_one_the_cli_accepts() -> None:
    """No Docker here: the commands the services run are parsed by the CLI's own parser (a
    misspelt sub-command or option fails), and every ASSISTANTX_ variable names a setting."""
    from assistantx.cli import build_parser
    from assistantx.core.settings import Settings

    compose: dict[str, Any] = yaml.safe_load((ROOT / "compose.yaml").read_text())
    ours = {n: s for n, s in compose["services"].items() if s.get("build") == "."}
    assert set(ours) == {"replica-1", "replica-2", "matrix-registration"}
    fields = {f"ASSISTANTX_{name.upper()}" for name in Settings.model_fields}
    for name, service in ours.items():
        program, *argv = service["command"]
        assert program == "assistantx", name
        args = build_parser(argv).parse_args(argv)  # SystemExit on anything it does not know
        assert callable(args.func), name
        unknown = {k for k in service.get("environment", {}) if k not in fields}
        assert not unknown, (name, unknown)


def test_synapse_is_optional_and_loads_the_registration_the_cli_writes() -> None:
    compose: dict[str, Any] = yaml.safe_load((ROOT / "compose.yaml").read_text())
    services = compose["services"]
    assert services["synapse"]["profiles"] == services["matrix-registration"]["profiles"]
    assert services["synapse"]["profiles"] == ["matrix"]  # `up` alone starts no homeserver
    written = services["matrix-registration"]["command"][-1]
    config_dir = services["synapse"]["environment"]["SYNAPSE_CONFIG_DIR"]
    assert written.startswith(config_dir + "/")
    needs = services["synapse"]["depends_on"]["matrix-registration"]["condition"]
    assert needs == "service_completed_successfully"
