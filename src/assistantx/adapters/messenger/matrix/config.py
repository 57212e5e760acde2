"""Who the assistant is on a Matrix homeserver, and who the office's people and groups are there.

Loaded from a YAML file (``load_matrix_config``) whose keys are the fields of ``MatrixConfig``::

    homeserver_url: http://127.0.0.1:8008
    server_name: office.example
    as_token: "..."            # the application service's token towards the homeserver
    hs_token: "..."            # the homeserver's token towards us (checked on every push)
    sender_localpart: assistant
    mode: push                 # push (application service), pull (/sync), or both
    pull_user_id: "@assistant-sync:office.example"
    pull_access_token: "..."
    people: {lee: "@lee:office.example"}
    groups: {printing: "#printing:office.example"}
"""

from __future__ import annotations

from pathlib import Path
from typing import Literal, Self

import yaml
from pydantic import BaseModel, Field, SecretStr, ValidationError, model_validator

from assistantx.core.errors import MessengerError

MatrixMode = Literal["push", "pull", "both"]


class MatrixConfig(BaseModel):
    model_config = {"frozen": True, "extra": "forbid"}

    homeserver_url: str = Field(description="client-server API base, e.g. http://127.0.0.1:8008")
    server_name: str = Field(description="the homeserver's name, the part after ':' in user ids")
    as_token: SecretStr = Field(description="application service token (we → homeserver)")
    hs_token: SecretStr = Field(description="homeserver token (homeserver → us), checked on push")
    appservice_id: str = Field(default="assistantx", description="id in the registration file")
    appservice_url: str | None = Field(
        default=None, description="where the homeserver pushes transactions (None: no push)"
    )
    sender_localpart: str = Field(default="assistant", description="the bot user's localpart")
    mode: MatrixMode = "push"
    pull_user_id: str | None = Field(default=None, description="ordinary account that /syncs")
    pull_access_token: SecretStr | None = None
    people: dict[str, str] = Field(default_factory=dict, description="person id → @user:server")
    groups: dict[str, str] = Field(
        default_factory=dict, description="group id → !room:server or #alias:server"
    )
    accept_unknown_senders: bool = Field(
        default=False,
        description="deliver messages from Matrix users not in `people` (sender = Matrix id)",
    )
    sync_timeout_s: float = Field(default=30.0, gt=0, description="/sync long-poll timeout")
    request_timeout_s: float = Field(default=30.0, gt=0)
    max_retries: int = Field(default=5, ge=0, description="retries on 429, 5xx and timeouts")

    @model_validator(mode="after")
    def _check(self) -> Self:
        if self.mode in ("pull", "both") and not (self.pull_user_id and self.pull_access_token):
            raise ValueError(f"mode {self.mode!r} needs pull_user_id and pull_access_token")
        for person, user in self.people.items():
            if not user.startswith("@") or ":" not in user:
                raise ValueError(f"people.{person}: {user!r} is not a Matrix user id")
        for group, room in self.groups.items():
            if room[:1] not in ("!", "#") or ":" not in room:
                raise ValueError(f"groups.{group}: {room!r} is not a room id or alias")
        seen: dict[str, str] = {}
        for person, user in self.people.items():
            if user in seen:
                raise ValueError(f"people.{person} and people.{seen[user]} share {user}")
            seen[user] = person
        return self

    @property
    def bot_user_id(self) -> str:
        """The application service's own user, which sends in push and both modes."""
        return f"@{self.sender_localpart}:{self.server_name}"

    @property
    def push_enabled(self) -> bool:
        return self.mode in ("push", "both")

    @property
    def pull_enabled(self) -> bool:
        return self.mode in ("pull", "both")

    def person_of(self, user_id: str) -> str | None:
        for person, user in self.people.items():
            if user == user_id:
                return person
        return None

    def own_user_ids(self) -> frozenset[str]:
        """Users whose messages are the assistant's own and never count as inbound."""
        ids = {self.bot_user_id}
        if self.pull_user_id:
            ids.add(self.pull_user_id)
        return frozenset(ids)


def load_matrix_config(path: Path | str) -> MatrixConfig:
    """Read a YAML file; a bad file raises ``MessengerError`` naming the file and the problem."""
    path = Path(path)
    try:
        raw = yaml.safe_load(path.read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError) as exc:
        raise MessengerError(f"{path}: cannot read Matrix config: {exc}") from exc
    if not isinstance(raw, dict):
        raise MessengerError(f"{path}: a Matrix config must be a mapping")
    try:
        return MatrixConfig.model_validate(raw)
    except ValidationError as exc:
        problems = "; ".join(
            f"{'.'.join(str(part) for part in error['loc']) or 'config'}: {error['msg']}"
            for error in exc.errors(include_url=False, include_input=False)
        )
        # Not chained: pydantic's own message repeats the input, tokens included.
        raise MessengerError(f"{path}: invalid Matrix config: {problems}") from None
