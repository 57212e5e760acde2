"""Reading a pushed request body with a size cap (the Matrix appservice's pushes)."""

from assistantx.adapters.messenger.webhooks.body import BodyTooLargeError, read_capped_body

__all__ = ["BodyTooLargeError", "read_capped_body"]
