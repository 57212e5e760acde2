"""A real Synapse homeserver for tests: installed into its own virtualenv by
``.ci/install-synapse`` (``$SYNAPSE_VENV``, default ``.cache/synapse-venv`` in the repository,
where ``make test`` puts it), configured in a temporary directory, started as a subprocess on a free
127.0.0.1 port, and stopped by its process id.

The configuration is made for tests: SQLite, no federation, no URL previews, no stats, no
open registration (users come from the shared-secret admin API), rate limits lifted, and one
application service registered (the assistant), whose URL the caller chooses.
"""

from __future__ import annotations

import hashlib
import hmac
import os
import secrets
import signal
import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import httpx
import yaml

from helpers.processes import wait_ready
from helpers.servers import free_port

REPO_ROOT = Path(__file__).resolve().parents[2]
INSTALL_SCRIPT = REPO_ROOT / ".ci" / "install-synapse"
SERVER_NAME = "office.test"
STARTUP_TIMEOUT_S = 90.0


class SynapseUnavailableError(RuntimeError):
    """Synapse could not be installed or started (tests must fail, never skip)."""


def install_synapse() -> Path:
    """Run the idempotent install script; returns the Synapse venv's python."""
    result = subprocess.run(
        ["bash", str(INSTALL_SCRIPT)], capture_output=True, text=True, check=False, timeout=900
    )
    if result.returncode != 0:
        raise SynapseUnavailableError(
            f"{INSTALL_SCRIPT} failed ({result.returncode}):\n{result.stderr[-4000:]}"
        )
    python = Path(result.stdout.strip().splitlines()[-1])
    if not python.exists():
        raise SynapseUnavailableError(f"{INSTALL_SCRIPT} printed {python}, which does not exist")
    return python


def _lifted(rate: float = 1000.0) -> dict[str, float]:
    return {"per_second": rate, "burst_count": rate}


def homeserver_config(workdir: Path, port: int, appservice_files: list[Path]) -> dict[str, Any]:
    return {
        "server_name": SERVER_NAME,
        "public_baseurl": f"http://127.0.0.1:{port}/",
        "pid_file": str(workdir / "homeserver.pid"),
        "listeners": [
            {
                "port": port,
                "bind_addresses": ["127.0.0.1"],
                "type": "http",
                "tls": False,
                "x_forwarded": False,
                "resources": [{"names": ["client"], "compress": False}],
            }
        ],
        "database": {"name": "sqlite3", "args": {"database": str(workdir / "homeserver.db")}},
        "log_config": str(workdir / "log.config"),
        "media_store_path": str(workdir / "media"),
        "signing_key_path": str(workdir / "signing.key"),
        "registration_shared_secret": secrets.token_hex(16),
        "macaroon_secret_key": secrets.token_hex(16),
        "form_secret": secrets.token_hex(16),
        "enable_registration": False,
        "report_stats": False,
        "enable_metrics": False,
        "url_preview_enabled": False,
        "trusted_key_servers": [],
        "suppress_key_server_warning": True,
        "federation_domain_whitelist": [],
        "presence": {"enabled": False},
        "app_service_config_files": [str(path) for path in appservice_files],
        # Every test account is registered with a password nobody types: bcrypt's default
        # cost (12) made each registration 0.66 s of wall time (0.34 CPU-s of Synapse's);
        # at 4 it is 0.18 s (0.03 CPU-s), and the suite registers hundreds.
        "bcrypt_rounds": 4,
        "rc_message": _lifted(),
        "rc_registration": _lifted(),
        "rc_login": {"address": _lifted(), "account": _lifted(), "failed_attempts": _lifted()},
        "rc_joins": {"local": _lifted(), "remote": _lifted()},
        "rc_joins_per_room": _lifted(),
        "rc_invites": {"per_room": _lifted(), "per_user": _lifted(), "per_issuer": _lifted()},
        "rc_media_create": _lifted(),
        "rc_admin_redaction": _lifted(),
    }


def _log_config(log_file: Path) -> dict[str, Any]:
    return {
        "version": 1,
        "formatters": {"plain": {"format": "%(asctime)s %(levelname)s %(name)s: %(message)s"}},
        "handlers": {
            "file": {
                "class": "logging.FileHandler",
                "filename": str(log_file),
                "formatter": "plain",
            }
        },
        "loggers": {"synapse.storage.SQL": {"level": "WARNING"}},
        "root": {"level": "INFO", "handlers": ["file"]},
        "disable_existing_loggers": False,
    }


@dataclass
class Account:
    user_id: str
    access_token: str


class SynapseHomeserver:
    """One running Synapse. ``start()`` blocks until /health answers."""

    def __init__(self, workdir: Path, appservice_files: list[Path]) -> None:
        self.workdir = workdir
        self.port = free_port()
        self.url = f"http://127.0.0.1:{self.port}"
        self.server_name = SERVER_NAME
        self.log_file = workdir / "homeserver.log"
        self._config = homeserver_config(workdir, self.port, appservice_files)
        self._config_path = workdir / "homeserver.yaml"
        self._process: subprocess.Popen[bytes] | None = None

    @property
    def shared_secret(self) -> str:
        return str(self._config["registration_shared_secret"])

    def log_tail(self, chars: int = 6000) -> str:
        try:
            return self.log_file.read_text(encoding="utf-8", errors="replace")[-chars:]
        except OSError:
            return "(no homeserver log)"

    def start(self, python: Path) -> None:
        (self.workdir / "media").mkdir(exist_ok=True)
        self._config_path.write_text(yaml.safe_dump(self._config), encoding="utf-8")
        (self.workdir / "log.config").write_text(
            yaml.safe_dump(_log_config(self.log_file)), encoding="utf-8"
        )
        command = [str(python), "-m", "synapse.app.homeserver", "-c", str(self._config_path)]
        keys = subprocess.run(
            [*command, "--generate-keys"], capture_output=True, text=True, check=False
        )
        if keys.returncode != 0:
            raise SynapseUnavailableError(f"synapse --generate-keys failed:\n{keys.stderr}")
        stderr = (self.workdir / "stderr.log").open("wb")
        self._process = subprocess.Popen(
            command, cwd=self.workdir, stdout=stderr, stderr=subprocess.STDOUT
        )
        stderr.close()
        try:
            wait_ready(
                self._process, f"{self.url}/health", timeout_s=STARTUP_TIMEOUT_S, interval_s=0.2
            )
        except RuntimeError:
            output = (self.workdir / "stderr.log").read_text(errors="replace")
            raise SynapseUnavailableError(
                f"synapse exited with {self._process.returncode}:\n{output[-4000:]}\n"
                f"{self.log_tail()}"
            ) from None
        except AssertionError:
            self.stop()
            raise SynapseUnavailableError(
                f"synapse did not answer /health in {STARTUP_TIMEOUT_S}s:\n{self.log_tail()}"
            ) from None

    def stop(self) -> None:
        process, self._process = self._process, None
        if process is None or process.poll() is not None:
            return
        os.kill(process.pid, signal.SIGTERM)
        try:
            process.wait(timeout=15)
        except subprocess.TimeoutExpired:
            os.kill(process.pid, signal.SIGKILL)
            process.wait(timeout=15)

    def register(self, localpart: str, *, admin: bool = False) -> Account:
        """A new user through the shared-secret admin API (nonce + HMAC-SHA1)."""
        endpoint = f"{self.url}/_synapse/admin/v1/register"
        nonce = httpx.get(endpoint, timeout=10).json()["nonce"]
        password = secrets.token_hex(12)
        mac = hmac.new(self.shared_secret.encode(), digestmod=hashlib.sha1)
        for part in (nonce, localpart, password):
            mac.update(part.encode())
            mac.update(b"\x00")
        mac.update(b"admin" if admin else b"notadmin")
        response = httpx.post(
            endpoint,
            json={
                "nonce": nonce,
                "username": localpart,
                "password": password,
                "admin": admin,
                "mac": mac.hexdigest(),
            },
            timeout=10,
        )
        response.raise_for_status()
        body = response.json()
        return Account(user_id=body["user_id"], access_token=body["access_token"])
