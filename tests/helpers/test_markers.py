"""never_selects: a folder is left uncollected only when no test carrying its marker could
be selected by the `-m` expression, whatever other markers the test has."""

from __future__ import annotations

import pytest

from helpers.markers import never_selects


@pytest.mark.parametrize(
    ("markexpr", "deselected"),
    [
        ("not synapse and not browser and not slow", True),
        ("not synapse", True),
        ("", False),
        ("synapse", False),
        ("slow", False),  # a synapse test marked slow is selected
        ("not slow", False),
        ("not (synapse and slow)", False),  # a synapse test without slow is selected
        ("browser and not synapse", True),
        ("browser or not synapse", False),  # a synapse test marked browser is selected
    ],
)
def test_a_folder_is_skipped_only_when_none_of_its_tests_can_be_selected(
    markexpr: str, deselected: bool
) -> None:
    assert never_selects(markexpr, "synapse") is deselected
