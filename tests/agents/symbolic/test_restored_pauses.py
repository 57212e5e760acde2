"""A pause left out in chat between two clauses is put back, so the message is read as it is
with its comma (reading/restored_pauses.py). Found by dropping the one comma of 1,682
single-sentence messages of the probe corpus: 157 were read differently without it (the
request lost as "Noted. I did nothing.", a thing of the reason fetched too, a correction that
withdrew everything). Each case below was read wrongly before."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.restored_pauses import restored_pauses
from assistantx.core.office import load_office
from helpers.reading import frame_reader

_read = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("who", "text", "item", "owner", "to"),
    [
        (
            "dang",
            "my phone's on 3% can i borrow zhou's charger cable",
            "data_cable",
            "zhou",
            "dang",
        ),
        ("wang", "Zhou needs a stapler can you bring him mine", "stapler", "wang", "zhou"),
        ("zhou", "take my mug over to Sun she's got nothing to drink from", "cup", "zhou", "sun"),
        ("lee", "Zhang's stapler is broken get me another one", "stapler", None, "lee"),
        ("lin", "tray's empty again can u bring me some a4", "paper", None, "lin"),
        (
            "zheng",
            "can u bring me a pen no wait a stapler need to clip the handouts",
            "stapler",
            None,
            "zheng",
        ),
    ],
)
def test_a_message_without_its_comma_is_read_as_with_it(
    who: str, text: str, item: str, owner: str | None, to: str
) -> None:
    frame = _read(text, who)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, to)
    ], frame


_COMMANDS = {"bring", "get", "print", "send", "give", "take", "grab", "find", "sign", "cut"}


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("my phone's on 3% can i borrow a cable", "my phone's on 3%, can i borrow a cable"),
        (
            "Zhang's stapler is broken get me another one",
            "Zhang's stapler is broken, get me another one",
        ),
        ("bring me a pen the one on my desk is dead", "bring me a pen, the one on my desk is dead"),
        ("can u grab me a hairnet forgot mine", "can u grab me a hairnet, forgot mine"),
        ("bring me a torch no wait a lamp", "bring me a torch, no wait a lamp"),
        ("take it to Miles pls he's on parcels", "take it to Miles pls, he's on parcels"),
        ("a pen please my biro just died", "a pen please, my biro just died"),
        (
            "need to cut ribbon anyone got something sharp",
            "need to cut ribbon, anyone got something sharp",
        ),
        ("take my paper to sun her tray is empty", "take my paper to sun, her tray is empty"),
        ("Dang needs some wipes he spilled his tea", "Dang needs some wipes, he spilled his tea"),
        # must not change: bound to the clause before, a relative clause, a subject's verb,
        # a name said first, a question, a command's own object
        ("I wonder if you could bring me a pen", "I wonder if you could bring me a pen"),
        (
            "print the slides i just sent and give them to Wang",
            "print the slides i just sent and give them to Wang",
        ),
        (
            "the glass I had cut for the frame has cracked",
            "the glass I had cut for the frame has cracked",
        ),
        ("Otto could you bring me your ruler", "Otto could you bring me your ruler"),
        (
            "is the edger playing up or did robin fix it?",
            "is the edger playing up or did robin fix it?",
        ),
        ("Bay 2 is shut and I can't find my stapler", "Bay 2 is shut and I can't find my stapler"),
        ("I will probably need an umbrella", "I will probably need an umbrella"),
        (
            "ice to the desk please the milk samples need to stay cold",
            "ice to the desk please, the milk samples need to stay cold",
        ),
        ("hairnet pls mine ripped", "hairnet pls mine ripped"),
        ("bring me a pen, she's waiting", "bring me a pen, she's waiting"),
        ("any chance someone has a cable?", "any chance someone has a cable?"),
        ("please I need a pen", "please I need a pen"),
    ],
)
def test_the_rewrite(text: str, read: str) -> None:
    assert restored_pauses(text, _COMMANDS) == read
