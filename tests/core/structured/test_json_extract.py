"""Finding the JSON object in what a model wrote."""

from __future__ import annotations

import pytest

from assistantx.core.structured import extract_json_object
from assistantx.core.structured._json_extract import remove_trailing_commas


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ('{"a": 1}', {"a": 1}),
        ('  \n{"a": 1}\n', {"a": 1}),
        ('```json\n{"a": 1}\n```', {"a": 1}),
        ('```\n{"a": 1}\n```', {"a": 1}),
        ('Here you go: {"a": {"b": [1, 2]}} -- done', {"a": {"b": [1, 2]}}),
        ('{"a": [1, 2,], "b": {"c": 3,},}', {"a": [1, 2], "b": {"c": 3}}),
        ('<think>maybe {"a": 0}? no.</think>{"a": 1}', {"a": 1}),
        ('Braces in strings: {"s": "a } b { c", "t": "q\\"}"}', {"s": "a } b { c", "t": 'q"}'}),
        ('{not json} then {"a": 1}', {"a": 1}),
        ('{"text": "a, ]"}', {"text": "a, ]"}),
    ],
)
def test_extracts(text: str, expected: dict[str, object]) -> None:
    assert extract_json_object(text) == expected


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("", "empty"),
        ("   ", "empty"),
        ("I'd rather not.", "no JSON object found"),
        ("[1, 2, 3]", "got an array"),
        ('"just a string"', "got a string"),
        ('{"a": 1, "b": ', "not valid JSON"),
    ],
)
def test_failures_say_why(text: str, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        extract_json_object(text)


def test_trailing_commas_inside_strings_are_kept() -> None:
    assert remove_trailing_commas('{"a": ",}", "b": [1,]}') == '{"a": ",}", "b": [1]}'


@pytest.mark.parametrize(
    "text",
    [
        # cut off at the token limit: the complete inner action is not the answer
        '{"thought": "go", "actions": [{"type": "wait", "timeout_s": 60}',
        'Sure: {"plan": {"goal": "x"}, "broken": }',
    ],
)
def test_an_object_nested_in_a_broken_one_is_never_the_answer(text: str) -> None:
    with pytest.raises(ValueError, match="not valid JSON"):
        extract_json_object(text)


def test_raw_line_breaks_inside_strings_are_read() -> None:
    text = '{"summary": "line one\nline two\ttabbed"}'
    assert extract_json_object(text) == {"summary": "line one\nline two\ttabbed"}
