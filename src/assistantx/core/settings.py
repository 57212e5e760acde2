"""One settings object, read from ``ASSISTANTX_*`` environment variables.

Nothing else in the code base reads ``os.environ``. Secrets are ``SecretStr`` so they are
masked in reprs and logs. Components take the fields they need as arguments.

The lock's keys follow one precedence rule in ``assistantx serve`` and ``assistantx
lock-sim`` alike (``assistantx.adapters.lock.protocol.keys.load_lock_keys``): ``--key-file`` /
``ASSISTANTX_LOCK_KEY_FILE`` (must exist) wins over ``ASSISTANTX_LOCK_SHARED_KEY``; with
neither, the service generates ``DATA_DIR/lock-keys.json`` once and keeps using it.
"""

from __future__ import annotations

from pathlib import Path
from typing import Literal

from pydantic import Field, SecretStr, field_validator
from pydantic_settings import BaseSettings, SettingsConfigDict

from assistantx.core.office import DEFAULT_OFFICE

DEFAULT_SIM_SPEEDUP = 10.0


class Settings(BaseSettings):
    model_config = SettingsConfigDict(env_prefix="ASSISTANTX_", extra="ignore", frozen=True)

    # -- the office and the data directory ---------------------------------------------
    office: Path = Field(default=DEFAULT_OFFICE, description="office YAML file")
    data_dir: Path = Field(default=Path("data"), description="journal, snapshots, keys")
    offices: Path | None = Field(
        default=None,
        description="deployment YAML naming several offices (default: one, ASSISTANTX_OFFICE)",
    )
    database_url: SecretStr | None = Field(
        default=None,
        description="postgresql://user:password@host:port/db: the journal, surveys and Matrix"
        " state on PostgreSQL; unset: SQLite in the data folder",
    )
    lease_ttl_s: float = Field(
        default=9.0,
        gt=0,
        description="with a database URL: how long the office's lease lasts unrenewed (a"
        " standby replica takes over a killed one after at most this long)",
    )
    replica_id: str | None = Field(
        default=None, description="this replica's name in the leases (default: host-pid-random)"
    )
    results_dir: Path = Field(default=Path("results"), description="evaluation run folders")

    # -- the reasoner ---------------------------------------------------------------------
    llm_base_url: str | None = Field(default=None, description="OpenAI-compatible /v1 URL")
    llm_model: str = "gpt-4o-mini"
    llm_api_key: SecretStr | None = None
    llm_timeout_s: float = 60.0
    llm_temperature: float = 0.0
    llm_seed: int | None = 0
    llm_max_retries: int = Field(default=4, description="HTTP retries on 429/5xx/timeouts")
    llm_output_retries: int = Field(default=2, description="retries on invalid model output")
    llm_structured_output: Literal[
        "auto", "json_schema", "json_object_schema", "json_object", "prompt"
    ] = Field(
        default="auto",
        description="how a schema reaches the server: auto tries json_schema, then llama.cpp's "
        "json_object+schema, then JSON mode, then the prompt alone",
    )
    llm_max_tokens: int = Field(default=1024, gt=0, description="completion cap per call")
    llm_call_budget_s: float = Field(
        default=120.0, gt=0, description="wall-clock budget of one call, streaming included"
    )
    llm_stream: bool = Field(default=True, description="stream, so a timeout stops generation")
    llm_context_tokens: int = Field(
        default=8192, gt=0, description="the server's context; prompts are fitted to it"
    )
    instruction_wall_s: float = Field(
        default=900.0, gt=0, description="wall-clock bound of one instruction (not sim time)"
    )
    reasoner: Literal["auto", "symbolic", "llm", "hybrid", "cascade"] = "auto"

    # -- the loop -----------------------------------------------------------------------
    max_steps: int = 30
    journal_retention_days: float = Field(
        default=90.0,
        ge=0,
        description="finished instructions' traces compacted after this many days (0: never);"
        " outcomes and messages are kept",
    )
    instruction_deadline_s: float = 3600.0  # real seconds from its start (not sped up)

    # -- the service --------------------------------------------------------------------
    host: str = "127.0.0.1"
    port: int = 8000
    operator_token: SecretStr | None = None
    tokens: SecretStr | None = Field(
        default=None,
        description='person tokens: JSON {"token": "person"} or CSV "token:person,..."',
    )
    max_body_bytes: int = Field(default=64 * 1024, gt=0, description="larger bodies get 413")
    instructions_per_minute: int = Field(
        default=20, ge=0, description="instructions one person may start per minute (0: any)"
    )
    people: Literal["simulated", "human"] = Field(
        default="simulated", description="who answers: the SimOffice's people or real people"
    )
    sim_unavailable: str = Field(default="", description="CSV of simulated people who are away")
    sim_reply_delay_s: float = Field(default=20.0, ge=0, description="simulated reply delay")
    sim_handover_delay_s: float = Field(default=30.0, ge=0, description="time to the locker")
    speedup: float | None = Field(
        default=None,
        gt=0,
        description="how many times faster simulated durations (robot travel, simulated"
        " colleagues' replies, waits) pass than real time; timestamps stay real. Default: 10"
        " with simulated people, 1 with ASSISTANTX_PEOPLE=human (people need real time to"
        " answer)",
    )
    reasoner_builder: str | None = Field(
        default=None, description="'module:builder' of a custom reasoner factory (tests, plugins)"
    )

    # -- the robot base ------------------------------------------------------------------
    robot: Literal["navigator", "sim"] = Field(
        default="navigator", description="navigator (map, planner, AMCL) or sim (kinematic)"
    )
    map: Path | None = Field(default=None, description="ROS map YAML (default: maps/office.yaml)")
    map_anchors: Path | None = Field(default=None, description="default: MAP's .anchors.yaml")
    robot_localize: bool = Field(default=True, description="AMCL on (False: kinematic paths)")
    robots: int = Field(
        default=1, ge=1, le=3, description="robot bases serving the office (each with a locker)"
    )

    # -- the smart lock ------------------------------------------------------------------
    lock: Literal["local", "tcp"] = Field(
        default="local", description="local (in-process) or tcp (LOCK_HOST:LOCK_PORT)"
    )
    lock_host: str = "127.0.0.1"
    lock_port: int = 7420
    lock_id: str = "locker-1"
    lock_shared_key: SecretStr | None = Field(default=None, description="link + code keys")
    lock_key_file: Path | None = Field(default=None, description="JSON keys; wins over the secret")
    lock_code_expiry_min: float = Field(default=15.0, gt=0, description="QR code lifetime")

    # -- the messenger -------------------------------------------------------------------
    messenger: Literal["builtin", "matrix"] = Field(
        default="builtin", description="builtin (REST + web page) or matrix (a homeserver)"
    )
    matrix_config: Path | None = Field(default=None, description="Matrix YAML (MatrixConfig)")
    matrix_store: Path | None = Field(
        default=None, description="Matrix inbound event store (default: DATA_DIR/matrix.sqlite3)"
    )

    @field_validator("database_url")
    @classmethod
    def _a_postgres_url(cls, value: SecretStr | None) -> SecretStr | None:
        if value is None or not value.get_secret_value().strip():
            return None
        if not value.get_secret_value().startswith(("postgresql://", "postgres://")):
            raise ValueError("ASSISTANTX_DATABASE_URL must start with postgresql://")
        return value

    @property
    def database(self) -> str | None:
        """The PostgreSQL URL of the journal, or None for SQLite in the data folder."""
        return self.database_url.get_secret_value() if self.database_url else None

    @property
    def llm_enabled(self) -> bool:
        return bool(self.llm_base_url)

    @property
    def effective_speedup(self) -> float:
        """The stated speed-up, else 10 with simulated people and 1 with real ones."""
        if self.speedup is not None:
            return self.speedup
        return 1.0 if self.people == "human" else DEFAULT_SIM_SPEEDUP

    @property
    def effective_reasoner(self) -> Literal["symbolic", "llm", "hybrid", "cascade"]:
        if self.reasoner == "auto":
            return "llm" if self.llm_enabled else "symbolic"
        return self.reasoner
