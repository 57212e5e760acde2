"""The application-service registration file the homeserver loads (``app_service_config_files``).

The bot's own user is claimed exclusively, so nobody else can register it and every event in
a room it is in is pushed to us.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import yaml

from assistantx.adapters.messenger.matrix.config import MatrixConfig
from assistantx.core.errors import MessengerError


def registration(config: MatrixConfig) -> dict[str, Any]:
    """The registration as a mapping (the homeserver's YAML schema)."""
    if config.appservice_url is None:
        raise MessengerError("a registration needs appservice_url (where to push transactions)")
    bot_regex = "^" + re.escape(config.bot_user_id) + "$"
    return {
        "id": config.appservice_id,
        "url": config.appservice_url,
        "as_token": config.as_token.get_secret_value(),
        "hs_token": config.hs_token.get_secret_value(),
        "sender_localpart": config.sender_localpart,
        "namespaces": {
            "users": [{"exclusive": True, "regex": bot_regex}],
            "aliases": [],
            "rooms": [],
        },
        # The assistant answers people; the homeserver's per-user limits would throttle it.
        "rate_limited": False,
    }


def write_registration(config: MatrixConfig, path: Path | str) -> Path:
    """Write the registration YAML (mode 0600: it holds both tokens)."""
    path = Path(path)
    text = yaml.safe_dump(registration(config), sort_keys=False)
    path.write_text(text, encoding="utf-8")
    path.chmod(0o600)
    return path
