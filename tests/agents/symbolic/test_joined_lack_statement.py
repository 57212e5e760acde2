"""A statement of two joined clauses is context, not a request (blind round 67's class: "<a
time> and <a colleague> has no <thing>. Please take my <thing> to her" took a colleague's
thing to the speaker): a clause that asks nothing, joined by "and"/"but"/"so" to a colleague's
lack of a thing ("has no", "hasn't got", "is without", "has lost"), is told; the request is the
sentence after it. A lack said beside a request of its own asks as before."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.stage_crew import stage_crew

_frame = frame_reader(stage_crew, "kit")


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        (
            "Sound check is at 2 and Zoë has no headset. Please take my headset to her.",
            "headset",
            "zoe",
        ),
        (
            "Dress rehearsal is at 2 and Zoë has no headset. Please take my headset to her.",
            "headset",
            "zoe",
        ),
        (
            "Morning. Sound check is at 2 and Zoë Marsh hasn't got a headset. "
            "Please take my headset to her.",
            "headset",
            "zoe",
        ),
        (
            "Sound check is at 2 but Zoë has lost her headset. Please take my headset to her.",
            "headset",
            "zoe",
        ),
        (
            "Sound check's at 2 so Zoë is without a headset. Could you bring her mine?",
            "headset",
            "zoe",
        ),
        (
            "Hi all. Dress rehearsal starts at 2 and Ana's got no charger. "
            "take her my charger please",
            "charger",
            "ana",
        ),
        ("Soundcheck at 2 and Sam has no mug. bring him my mug pls", "mug", "sam"),
        (
            "Sound check is at 2 and she has no headset. Please take my headset to Zoë.",
            "headset",
            "zoe",
        ),
    ],
)
def test_a_joined_statement_of_a_colleagues_lack_is_context(
    text: str, item: str, recipient: str
) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, "kit", recipient)
    ], frame


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("Zoë has no headset, can you bring her one?", "zoe"),
        ("I have no pen, could you get me one?", "kit"),
        ("Sound check is at 2, can you bring Zoë a headset?", "zoe"),
    ],
)
def test_a_lack_beside_its_own_request_still_asks(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert [t.recipient for t in frame.tasks] == [recipient], frame
    assert frame.tasks[0].owner is None, frame
