"""Persistence: the service's journal and the SQLite helper every store shares."""
