"""A small client for the Matrix client-server API over httpx: only what the assistant uses.

It speaks the wire protocol and knows nothing of people, groups or agents. Requests that the
homeserver throttles (429, honouring ``retry_after_ms``), fails with a 5xx, or that time out
are retried with exponential backoff by the shared retrying transport
(:mod:`assistantx.core.http_retry`, see :func:`retrying_http`); every other failure raises
``MatrixError`` with the homeserver's ``errcode``. Retrying a send is safe because the
caller passes a stable transaction id (the homeserver answers a repeated ``txnId`` with the
first event id).

An application service acts as one of its users by adding ``user_id`` to each request
(identity assertion); ``as_user`` returns such a view sharing the connection pool.
"""

from __future__ import annotations

import logging
from types import TracebackType
from typing import Any, Self
from urllib.parse import quote

import httpx

from assistantx.core.errors import MessengerClosedError, MessengerError
from assistantx.core.http_retry import RetryingTransport, RetryPolicy, header_retry_after

logger = logging.getLogger(__name__)

JSON = dict[str, Any]


class MatrixError(MessengerError):
    """The homeserver refused a request, or could not be reached after retries."""

    def __init__(self, message: str, *, status: int | None = None, errcode: str | None = None):
        self.status = status
        self.errcode = errcode
        super().__init__(message)


def matrix_policy(max_retries: int = 5, base_delay_s: float = 0.25) -> RetryPolicy:
    """The homeserver's retries: up to 30 s between tries, timeouts retried, unseeded."""
    return RetryPolicy(
        max_retries=max_retries,
        base_delay_s=base_delay_s,
        max_delay_s=30.0,
        retry_after_cap_s=30.0,
        seed=None,
    )


def matrix_retry_after(response: httpx.Response) -> float | None:
    """A throttled request's wait: the body's ``retry_after_ms``, else ``Retry-After``."""
    try:
        body = response.json()
        retry_after_ms = float(body.get("retry_after_ms", 0)) if isinstance(body, dict) else 0.0
    except ValueError:
        retry_after_ms = 0.0
    if retry_after_ms > 0:
        return retry_after_ms / 1000
    return header_retry_after(response)


def retrying_http(retry: RetryPolicy | None = None, timeout_s: float = 30.0) -> httpx.AsyncClient:
    """An httpx client whose transport retries as a homeserver needs."""
    transport = RetryingTransport(retry or matrix_policy(), retry_after=matrix_retry_after)
    return httpx.AsyncClient(timeout=timeout_s, transport=transport)


def _path_part(value: str) -> str:
    return quote(value, safe="")


class MatrixClient:
    """One access token (and optionally an asserted user) on one homeserver."""

    def __init__(
        self,
        homeserver_url: str,
        access_token: str,
        *,
        user_id: str | None = None,
        timeout_s: float = 30.0,
        retry: RetryPolicy | None = None,
        http: httpx.AsyncClient | None = None,
    ) -> None:
        self._base = homeserver_url.rstrip("/")
        self._token = access_token
        self._user_id = user_id
        self._retry = retry or matrix_policy()
        self._owns_http = http is None
        # a client passed in retries as it was built (``retrying_http``); ours does
        self._http = http or retrying_http(self._retry, timeout_s)

    def as_user(self, user_id: str) -> MatrixClient:
        """A view that asserts ``user_id`` (application services only); shares the pool."""
        return MatrixClient(
            self._base, self._token, user_id=user_id, retry=self._retry, http=self._http
        )

    async def aclose(self) -> None:
        if self._owns_http:
            await self._http.aclose()

    async def __aenter__(self) -> Self:
        return self

    async def __aexit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        await self.aclose()

    # -- the transport ------------------------------------------------------------------

    async def request(
        self,
        method: str,
        path: str,
        *,
        params: dict[str, str | int] | None = None,
        json: JSON | None = None,
        content: bytes | None = None,
        headers: dict[str, str] | None = None,
        timeout_s: float | None = None,
    ) -> httpx.Response:
        """Send (the transport retries); returns a 2xx response or raises ``MatrixError``."""
        query: dict[str, str | int] = dict(params or {})
        if self._user_id is not None:
            query["user_id"] = self._user_id
        all_headers = {"Authorization": f"Bearer {self._token}", **(headers or {})}
        timeout = httpx.USE_CLIENT_DEFAULT if timeout_s is None else httpx.Timeout(timeout_s)
        url = self._base + path
        if self._http.is_closed:  # stopping: httpx would raise a bare RuntimeError
            raise MessengerClosedError(f"{method} {path}: the homeserver connection is closed")
        try:
            response = await self._http.request(
                method,
                url,
                params=query,
                json=json,
                content=content,
                headers=all_headers,
                timeout=timeout,
            )
        except httpx.TransportError as exc:  # after the transport's retries
            raise MatrixError(f"{method} {path}: {exc!r}") from exc
        if not response.is_success:
            raise _error_from(method, path, response)
        return response

    async def _json(self, method: str, path: str, **kwargs: Any) -> JSON:
        response = await self.request(method, path, **kwargs)
        try:
            body = response.json()
        except ValueError as exc:
            raise MatrixError(f"{method} {path}: answer is not JSON") from exc
        if not isinstance(body, dict):
            raise MatrixError(f"{method} {path}: answer is not a JSON object")
        return body

    async def _found(self, method: str, path: str) -> JSON | None:
        """``_json``, or None where the homeserver answers ``M_NOT_FOUND``."""
        try:
            return await self._json(method, path)
        except MatrixError as exc:
            if exc.errcode == "M_NOT_FOUND":
                return None
            raise

    # -- the API ------------------------------------------------------------------------

    async def whoami(self) -> str:
        body = await self._json("GET", "/_matrix/client/v3/account/whoami")
        return str(body["user_id"])

    async def sync(self, *, since: str | None, timeout_ms: int, filter_json: str | None) -> JSON:
        params: dict[str, str | int] = {"timeout": timeout_ms}
        if since is not None:
            params["since"] = since
        if filter_json is not None:
            params["filter"] = filter_json
        # The long poll holds the connection open for timeout_ms; give the read some slack.
        return await self._json(
            "GET", "/_matrix/client/v3/sync", params=params, timeout_s=timeout_ms / 1000 + 30
        )

    async def room_messages(
        self, room_id: str, *, from_token: str | None, direction: str = "b", limit: int = 100
    ) -> JSON:
        """A page of a room's events; ``from_token`` None starts at the newest (dir ``b``)."""
        params: dict[str, str | int] = {"dir": direction, "limit": limit}
        if from_token is not None:
            params["from"] = from_token
        return await self._json(
            "GET", f"/_matrix/client/v3/rooms/{_path_part(room_id)}/messages", params=params
        )

    async def join(self, room_id_or_alias: str) -> str:
        body = await self._json(
            "POST", f"/_matrix/client/v3/join/{_path_part(room_id_or_alias)}", json={}
        )
        return str(body["room_id"])

    async def invite(self, room_id: str, user_id: str) -> None:
        await self._json(
            "POST",
            f"/_matrix/client/v3/rooms/{_path_part(room_id)}/invite",
            json={"user_id": user_id},
        )

    async def leave(self, room_id: str) -> None:
        """Leave a room, or decline an invite to it."""
        await self._json("POST", f"/_matrix/client/v3/rooms/{_path_part(room_id)}/leave", json={})

    async def membership(self, room_id: str, user_id: str) -> str | None:
        """``user_id``'s membership in ``room_id`` (join, invite, leave, ban), None if never."""
        path = (
            f"/_matrix/client/v3/rooms/{_path_part(room_id)}/state/m.room.member/"
            f"{_path_part(user_id)}"
        )
        body = await self._found("GET", path)
        if body is None:
            return None
        value = body.get("membership")
        return value if isinstance(value, str) else None

    async def joined_rooms(self) -> list[str]:
        body = await self._json("GET", "/_matrix/client/v3/joined_rooms")
        return [str(room) for room in body.get("joined_rooms", [])]

    async def joined_members(self, room_id: str) -> list[str]:
        body = await self._json(
            "GET", f"/_matrix/client/v3/rooms/{_path_part(room_id)}/joined_members"
        )
        return list(body.get("joined", {}))

    async def create_room(
        self,
        *,
        invite: list[str] | None = None,
        is_direct: bool = False,
        preset: str = "private_chat",
        name: str | None = None,
        alias_localpart: str | None = None,
    ) -> str:
        payload: JSON = {"preset": preset, "is_direct": is_direct, "invite": invite or []}
        if name is not None:
            payload["name"] = name
        if alias_localpart is not None:
            payload["room_alias_name"] = alias_localpart
        body = await self._json("POST", "/_matrix/client/v3/createRoom", json=payload)
        return str(body["room_id"])

    async def resolve_alias(self, alias: str) -> str:
        body = await self._json("GET", f"/_matrix/client/v3/directory/room/{_path_part(alias)}")
        return str(body["room_id"])

    async def get_account_data(self, user_id: str, data_type: str) -> JSON | None:
        path = f"/_matrix/client/v3/user/{_path_part(user_id)}/account_data/{_path_part(data_type)}"
        return await self._found("GET", path)

    async def set_account_data(self, user_id: str, data_type: str, content: JSON) -> None:
        path = f"/_matrix/client/v3/user/{_path_part(user_id)}/account_data/{_path_part(data_type)}"
        await self._json("PUT", path, json=content)

    async def send_event(self, room_id: str, event_type: str, content: JSON, *, txn_id: str) -> str:
        """Send once per ``txn_id``: the homeserver answers a repeat with the first event id."""
        path = (
            f"/_matrix/client/v3/rooms/{_path_part(room_id)}/send/"
            f"{_path_part(event_type)}/{_path_part(txn_id)}"
        )
        body = await self._json("PUT", path, json=content)
        return str(body["event_id"])

    async def state_event(self, room_id: str, event_type: str, state_key: str = "") -> JSON | None:
        """The content of one state event of ``room_id``, None when the room has none."""
        path = (
            f"/_matrix/client/v3/rooms/{_path_part(room_id)}/state/{_path_part(event_type)}/"
            f"{_path_part(state_key)}"
        )
        return await self._found("GET", path)

    async def read_receipt(self, room_id: str, event_id: str) -> None:
        """Mark ``event_id`` (and everything before it) read."""
        path = (
            f"/_matrix/client/v3/rooms/{_path_part(room_id)}/receipt/m.read/{_path_part(event_id)}"
        )
        await self._json("POST", path, json={})

    async def typing(self, user_id: str, room_id: str, *, typing: bool, timeout_ms: int) -> None:
        """Show (or stop showing) ``user_id`` typing in ``room_id``, for at most ``timeout_ms``."""
        path = f"/_matrix/client/v3/rooms/{_path_part(room_id)}/typing/{_path_part(user_id)}"
        body: JSON = {"typing": typing}
        if typing:
            body["timeout"] = timeout_ms
        await self._json("PUT", path, json=body)

    async def upload(self, data: bytes, *, content_type: str, filename: str) -> str:
        """Store ``data`` in the media repository; returns its ``mxc://`` URI."""
        body = await self._json(
            "POST",
            "/_matrix/media/v3/upload",
            params={"filename": filename},
            content=data,
            headers={"Content-Type": content_type},
        )
        return str(body["content_uri"])

    async def download(self, mxc_uri: str) -> bytes:
        """Fetch media by ``mxc://server/id`` (authenticated media endpoint)."""
        server, media_id = parse_mxc(mxc_uri)
        response = await self.request(
            "GET",
            f"/_matrix/client/v1/media/download/{_path_part(server)}/{_path_part(media_id)}",
        )
        return response.content


def parse_mxc(uri: str) -> tuple[str, str]:
    """``mxc://server/media_id`` → (server, media_id); anything else is a ``MatrixError``."""
    prefix = "mxc://"
    if not uri.startswith(prefix) or uri.count("/") != 3:
        raise MatrixError(f"not an mxc:// URI: {uri!r}")
    server, media_id = uri[len(prefix) :].split("/")
    if not server or not media_id:
        raise MatrixError(f"not an mxc:// URI: {uri!r}")
    return server, media_id


def _error_from(method: str, path: str, response: httpx.Response) -> MatrixError:
    errcode: str | None = None
    detail = response.text[:200]
    try:
        body = response.json()
    except ValueError:
        body = None
    if isinstance(body, dict):
        errcode = body.get("errcode")
        detail = str(body.get("error", detail))
    return MatrixError(
        f"{method} {path}: {response.status_code} {errcode or ''} {detail}".strip(),
        status=response.status_code,
        errcode=errcode,
    )
