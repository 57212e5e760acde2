"""Backoff delays and Retry-After parsing."""

from __future__ import annotations

from email.utils import formatdate

import pytest

from assistantx.adapters.model import RetryPolicy, parse_retry_after
from assistantx.adapters.model._retry import is_retryable_status

NOW = 1_750_000_000.0


@pytest.mark.parametrize(
    ("value", "expected"),
    [
        ("3", 3.0),
        (" 0.25 ", 0.25),
        ("-5", 0.0),
        (None, None),
        ("", None),
        ("soon", None),
        ("nan", None),
        (formatdate(NOW + 30, usegmt=True), 30.0),
        (formatdate(NOW - 30, usegmt=True), 0.0),
    ],
)
def test_parse_retry_after(value: str | None, expected: float | None) -> None:
    assert parse_retry_after(value, now=NOW) == expected


def test_backoff_grows_exponentially_with_full_jitter() -> None:
    policy = RetryPolicy(base_delay_s=1.0, max_delay_s=8.0, seed=1)
    for index, ceiling in enumerate([1.0, 2.0, 4.0, 8.0, 8.0, 8.0]):
        delay = policy.delay_s(index)
        assert 0.0 <= delay <= ceiling


def test_backoff_is_reproducible_from_the_seed() -> None:
    first = [RetryPolicy(seed=5).delay_s(i) for i in range(4)]
    again = [RetryPolicy(seed=5).delay_s(i) for i in range(4)]
    other = [RetryPolicy(seed=6).delay_s(i) for i in range(4)]
    assert first == again
    assert first != other


def test_retry_after_replaces_backoff_up_to_the_cap() -> None:
    policy = RetryPolicy(base_delay_s=1.0, retry_after_cap_s=10.0)
    assert policy.delay_s(3, retry_after_s=2.5) == 2.5
    assert policy.delay_s(0, retry_after_s=600.0) == 10.0


def test_invalid_policy_rejected() -> None:
    with pytest.raises(ValueError, match="max_retries"):
        RetryPolicy(max_retries=-1)
    with pytest.raises(ValueError, match="delays"):
        RetryPolicy(base_delay_s=-1)


@pytest.mark.parametrize(
    ("status", "retry"),
    [
        (429, True),
        (500, True),
        (503, True),
        (408, True),
        (400, False),
        (401, False),
        (404, False),
        (422, False),
    ],
)
def test_retryable_statuses(status: int, retry: bool) -> None:
    assert is_retryable_status(status) is retry
