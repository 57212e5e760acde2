"""``LiveMemo``: values kept for the keys of the last call only (issue 26's flat memory)."""

from __future__ import annotations

from assistantx.service.live_memo import LiveMemo


def _counting() -> tuple[LiveMemo[str, str], list[str]]:
    made: list[str] = []

    def make(key: str) -> str:
        made.append(key)
        return key.upper()

    return LiveMemo(make), made


def test_each_value_is_made_from_its_key_in_the_order_asked() -> None:
    memo, _ = _counting()
    assert memo.values(["b", "a", "c"]) == ["B", "A", "C"]


def test_a_key_of_the_last_call_is_not_made_again() -> None:
    memo, made = _counting()
    memo.values(["a", "b"])
    assert memo.values(["b", "c"]) == ["B", "C"]
    assert made == ["a", "b", "c"]


def test_a_key_missing_from_the_last_call_is_forgotten_and_made_again() -> None:
    memo, made = _counting()
    memo.values(["a"])
    memo.values(["b"])  # "a" is no longer held
    memo.values(["a"])
    assert made == ["a", "b", "a"]


def test_a_key_asked_twice_in_one_call_is_made_once() -> None:
    memo, made = _counting()
    assert memo.values(["a", "a"]) == ["A", "A"]
    assert made == ["a"]


def test_its_size_follows_the_last_call_not_every_key_ever_seen() -> None:
    memo, _ = _counting()
    for n in range(5_000):
        memo.values([f"code-{n}", f"code-{n + 1}"])
    assert len(memo) == 2
    assert memo.values([]) == []
    assert len(memo) == 0
