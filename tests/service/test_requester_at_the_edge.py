"""The requester's name is resolved once, by the route that takes it: a name a person types
("Mr Lee", "LEE") is journaled as the person's id, and an unknown or misspelt one gets one line
(422) and journals nothing. Below the route (admission, the Assistant) nobody resolves it again.
Against a real uvicorn server."""

from __future__ import annotations

import httpx
import pytest

from service.server import OPERATOR

OP = {"Authorization": f"Bearer {OPERATOR}"}


@pytest.mark.parametrize("name", ["lee", "LEE", "Mr Lee", "  lee  "])
async def test_a_name_is_journaled_as_the_persons_id(api: httpx.AsyncClient, name: str) -> None:
    r = await api.post("/v1/instructions", json={"requester": name, "text": "hi"}, headers=OP)
    assert r.status_code == 202, r.text
    assert r.json()["requester"] == "lee"
    listed = await api.get("/v1/instructions", params={"requester": name}, headers=OP)
    assert [i["requester"] for i in listed.json()["items"]] == ["lee"]


@pytest.mark.parametrize(
    ("name", "starts", "suggests"),
    [
        ("nobody", "Unknown person 'nobody'.", None),
        ("wnag", "Unknown person 'wnag'. Did you mean", "'wang'"),
    ],
)
async def test_an_unknown_requester_gets_one_line_and_nothing_is_journaled(
    api: httpx.AsyncClient, name: str, starts: str, suggests: str | None
) -> None:
    r = await api.post("/v1/instructions", json={"requester": name, "text": "hi"}, headers=OP)
    assert r.status_code == 422
    message = r.json()["message"]
    assert message.startswith(starts), message
    assert "\n" not in message
    if suggests is not None:
        assert suggests in message
    assert (await api.get("/v1/instructions", headers=OP)).json()["items"] == []
