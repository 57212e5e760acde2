"""Property-based tests of the Matrix event normalizer (issue 24, "fuzzing as a habit"): any
JSON value, shaped like a Matrix event or not, gives a list of messages and answers or the one
documented error (``MalformedEventError``), and every message it gives can be stored."""

from __future__ import annotations

from typing import Any

import yaml
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from adapters.messenger.test_matrix_units import CONFIG_YAML
from assistantx.adapters.messenger.matrix import EventNormalizer, MatrixConfig
from assistantx.adapters.messenger.matrix.normalize import AutoReply, MalformedEventError
from assistantx.core.ports.messenger import InboundMessage

CONFIG = MatrixConfig.model_validate(yaml.safe_load(CONFIG_YAML))
DM, GROUP, OTHER = "!dm:office.test", "!group:office.test", "!else:office.test"

# Any text JSON can carry, lone UTF-16 surrogates included (JSON allows them, UTF-8 does not).
any_text = st.text(st.characters(exclude_categories=()), max_size=30)
scalars = st.none() | st.booleans() | st.integers() | st.floats() | any_text
json_values = st.recursive(
    scalars,
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(any_text, inner, max_size=4),
    max_leaves=12,
)


def maybe(strategy: st.SearchStrategy[Any]) -> st.SearchStrategy[Any]:
    """A plausible value most of the time, anything JSON now and then."""
    return st.one_of(strategy, strategy, json_values)


people = st.sampled_from([*CONFIG.people.values(), "@eve:else.where", CONFIG.bot_user_id])
kinds = st.sampled_from(
    ["m.room.message", "m.reaction", "m.room.encrypted", "m.room.member", "m.sticker"]
)
msgtypes = st.sampled_from(["m.text", "m.emote", "m.notice", "m.image", "m.file", "m.video"])
event_ids = st.sampled_from(["$q", "$told", "$e1"]) | any_text
relations = st.fixed_dictionaries(
    {},
    optional={
        "rel_type": maybe(st.sampled_from(["m.replace", "m.annotation"])),
        "event_id": maybe(event_ids),
        "key": maybe(st.sampled_from(["👍", "👎🏽", "❤️"]) | any_text),
        "m.in_reply_to": maybe(st.fixed_dictionaries({"event_id": maybe(event_ids)})),
    },
)
contents = st.fixed_dictionaries(
    {},
    optional={
        "msgtype": maybe(msgtypes),
        "body": maybe(any_text | st.just("> <@lee:office.test> quoted\n\nreply")),
        "url": maybe(st.sampled_from(["mxc://office.test/abc", "https://x"]) | any_text),
        "filename": maybe(any_text),
        "info": maybe(st.fixed_dictionaries({}, optional={"mimetype": maybe(any_text)})),
        "membership": maybe(st.sampled_from(["join", "leave", "invite", "ban"])),
        "m.relates_to": maybe(relations),
    },
)
events = st.fixed_dictionaries(
    {},
    optional={
        "type": maybe(kinds),
        "event_id": maybe(event_ids),
        "sender": maybe(people),
        "state_key": maybe(people),
        "origin_server_ts": maybe(st.integers() | st.floats()),
        "content": maybe(contents),
        "unsigned": json_values,
    },
)


def normalizer(*, strict: bool) -> EventNormalizer:
    made = EventNormalizer(CONFIG, {GROUP: "printing"})
    made.rooms.strict = strict
    made.rooms.dms[DM] = "lee"
    made.rooms.questions.update({"$q": "ins-7:s0a0", "$told": ""})
    return made


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    event=events | json_values,
    room=st.sampled_from([DM, GROUP, OTHER]),
    strict=st.booleans(),
)
# Found by this test: a msgtype that is a list (unhashable) raised TypeError.
@example(
    event={
        "type": "m.room.message",
        "event_id": "$e",
        "sender": "@lee:office.test",
        "content": {"msgtype": [], "body": "hi"},
    },
    room=DM,
    strict=False,
)
def test_any_event_gives_items_or_the_documented_error(event: Any, room: str, strict: bool) -> None:
    try:
        items = normalizer(strict=strict).interpret(room, event)
    except MalformedEventError:
        return
    for item in items:
        assert isinstance(item, InboundMessage | AutoReply)
        if isinstance(item, InboundMessage):
            item.model_dump_json()  # what the store writes: it must never fail later
        else:
            item.text.encode("utf-8")
