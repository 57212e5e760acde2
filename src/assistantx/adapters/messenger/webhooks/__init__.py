"""Inbound webhooks of other messengers (Slack Events API, Telegram Bot API) as APIRouters."""

from assistantx.adapters.messenger.webhooks.body import BodyTooLargeError, read_capped_body
from assistantx.adapters.messenger.webhooks.slack import (
    SlackSignatureError,
    create_slack_router,
    slack_signature,
    verify_slack_request,
)
from assistantx.adapters.messenger.webhooks.telegram import (
    create_telegram_router,
    verify_telegram_secret,
)

__all__ = [
    "BodyTooLargeError",
    "SlackSignatureError",
    "create_slack_router",
    "create_telegram_router",
    "read_capped_body",
    "slack_signature",
    "verify_slack_request",
    "verify_telegram_secret",
]
