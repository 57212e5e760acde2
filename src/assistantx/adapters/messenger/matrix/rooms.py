"""Which room is what, for the bot: configured group rooms, each person's DM room, and the
rules for invites.

- An invite is accepted from an office person, or into a configured group's room (including a
  group whose room only came to exist after start-up: its alias is resolved again). Anyone
  else's invite is answered politely once and left; the bot never stays in their rooms.
- A person's DM room is recorded in the store (so it survives restarts) when they invite the
  bot into a direct chat, when they write in a room where only they and the bot are, or when
  the bot creates one. It is forgotten when they leave it.
- Private content only ever goes to a room where the person is joined or invited and nobody
  but the bot's own accounts is joined besides them, and that is not end-to-end encrypted
  (the bot cannot encrypt, and plain text in a room its people believe encrypted would
  mislead them); otherwise a new DM is created. An encrypted room is never adopted as a DM.
"""

from __future__ import annotations

import logging
from collections.abc import Mapping
from typing import Any

from assistantx.adapters.messenger.matrix.client import MatrixClient, MatrixError
from assistantx.adapters.messenger.matrix.config import MatrixConfig
from assistantx.adapters.messenger.matrix.normalize import Rooms
from assistantx.adapters.messenger.matrix.store import EventStore
from assistantx.core.errors import UnreachableContactError

logger = logging.getLogger(__name__)

_GONE = frozenset({"leave", "ban"})


class RoomDirectory:
    """The bot's knowledge of rooms; ``rooms`` is shared with the normalizer."""

    def __init__(self, config: MatrixConfig, store: EventStore, rooms: Rooms) -> None:
        self.config = config
        self.store = store
        self.rooms = rooms
        self._own = config.own_user_ids()
        self._not_dm: set[str] = set()  # rooms checked and found shared (not asked again)
        self._forgotten: list[str] = []  # people who left their DM, to persist
        self._encrypted: set[str] = set()  # encryption, once on, cannot be turned off

    # -- loading -----------------------------------------------------------------------------
    async def load(self) -> None:
        for person, room_id in (await self.store.dm_rooms()).items():
            if person in self.config.people:
                self.rooms.dms[room_id] = person

    def dm_of(self, person: str) -> str | None:
        for room_id, owner in self.rooms.dms.items():
            if owner == person:
                return room_id
        return None

    async def set_dm(self, person: str, room_id: str | None) -> None:
        for known in [r for r, owner in self.rooms.dms.items() if owner == person]:
            del self.rooms.dms[known]
        if room_id is not None:
            self.rooms.dms[room_id] = person
            self._not_dm.discard(room_id)
        await self.store.set_dm_room(person, room_id)

    # -- groups ------------------------------------------------------------------------------
    async def resolve_group(self, client: MatrixClient, group: str) -> str:
        """The room id of a configured group (an alias is resolved on the homeserver)."""
        for room_id, known in self.rooms.groups.items():
            if known == group:
                return room_id
        target = self.config.groups.get(group)
        if target is None:
            raise UnreachableContactError(
                f"group {group!r} has no Matrix room in the configuration"
            )
        room_id = await client.resolve_alias(target) if target.startswith("#") else target
        self.rooms.groups[room_id] = group
        return room_id

    async def group_of(self, client: MatrixClient, room_id: str) -> str | None:
        """The configured group ``room_id`` belongs to; resolves groups not resolved yet."""
        if room_id in self.rooms.groups:
            return self.rooms.groups[room_id]
        for group in self.config.groups:
            if group in self.rooms.groups.values():
                continue
            try:
                if await self.resolve_group(client, group) == room_id:
                    return group
            except MatrixError as exc:
                logger.debug("group %s not resolvable yet: %s", group, exc)
        return None

    # -- what arrives ------------------------------------------------------------------------
    async def observe(self, client: MatrixClient, room_id: str, event: Mapping[str, Any]) -> None:
        """Learn from one event before its batch is normalized: people leaving their DM, the
        DM rooms people write in, groups joined later, and which sent events asked questions.
        Call ``flush`` after the batch."""
        kind = event.get("type")
        sender = event.get("sender")
        if kind == "m.room.member":
            self._member_change(room_id, event)
            return
        if not isinstance(sender, str) or sender in self._own:
            return
        await self._learn_targets(event)
        person = self.config.person_of(sender)
        known = room_id in self.rooms.groups or room_id in self.rooms.dms
        if person is None or known or room_id in self._not_dm or kind != "m.room.message":
            return
        if await self.group_of(client, room_id) is not None:
            return
        if await self.is_private(client, room_id, sender, joined_only=True):
            logger.info("room %s is %s's DM", room_id, person)
            await self.set_dm(person, room_id)
        else:
            self._not_dm.add(room_id)

    def _member_change(self, room_id: str, event: Mapping[str, Any]) -> None:
        content = event.get("content")
        user = event.get("state_key")
        if not isinstance(content, dict) or not isinstance(user, str):
            return
        person = self.config.person_of(user)
        if person is None:
            return  # the bot, a stranger: nobody's DM ends with them leaving
        if content.get("membership") in _GONE and self.rooms.dms.get(room_id) == person:
            logger.info("%s left their DM room %s", person, room_id)
            del self.rooms.dms[room_id]
            self._forgotten.append(person)

    async def flush(self) -> None:
        """Write what the batch's events made forgotten (people who left their DM)."""
        forgotten, self._forgotten = self._forgotten, []
        for person in forgotten:
            if self.dm_of(person) is None:
                await self.store.set_dm_room(person, None)

    async def _learn_targets(self, event: Mapping[str, Any]) -> None:
        content = event.get("content")
        if not isinstance(content, dict):
            return
        relation = content.get("m.relates_to")
        if not isinstance(relation, dict):
            return
        target = relation.get("event_id")
        reply = relation.get("m.in_reply_to")
        if isinstance(reply, dict):
            target = reply.get("event_id")
        if isinstance(target, str) and target not in self.rooms.questions:
            question = await self.store.question_of(target)
            if question is not None:
                self.rooms.questions[target] = question

    # -- privacy -----------------------------------------------------------------------------
    async def is_private(
        self, client: MatrixClient, room_id: str, user_id: str, *, joined_only: bool = False
    ) -> bool:
        """Only ``user_id`` and the bot's own accounts are in ``room_id``, and ``user_id`` is
        joined (or, unless ``joined_only``, invited)."""
        try:
            joined = set(await client.joined_members(room_id))
            membership = "join" if user_id in joined else await client.membership(room_id, user_id)
        except MatrixError as exc:
            if exc.status is not None and 400 <= exc.status < 500:
                return False  # not in the room any more, or never was
            raise
        allowed = {"join"} if joined_only else {"join", "invite"}
        if membership not in allowed or joined - self._own - {user_id}:
            return False
        return not await self.is_encrypted(client, room_id)

    async def is_encrypted(self, client: MatrixClient, room_id: str) -> bool:
        """Whether ``room_id`` has end-to-end encryption on (its ``m.room.encryption`` state)."""
        if room_id in self._encrypted:
            return True
        if await client.state_event(room_id, "m.room.encryption") is None:
            return False
        logger.info("room %s is end-to-end encrypted: no private content goes there", room_id)
        self._encrypted.add(room_id)
        return True
