"""/docs works with no internet (every asset it loads comes from the service itself), and
/metrics names the embedded reasoner's agent calls as what they are, not LLM calls."""

from __future__ import annotations

import re
from pathlib import Path

from helpers.instructions import ended
from service.test_dashboard import serve


async def test_docs_load_only_local_assets(tmp_path: Path) -> None:
    async with serve(tmp_path) as client:
        page = await client.get("/docs", headers={"Authorization": ""})
        assert page.status_code == 200
        assert page.headers["content-type"].startswith("text/html")
        assets = re.findall(r'(?:src|href)="([^"]+)"', page.text)
        assert any(a.endswith(".js") for a in assets), assets
        for asset in assets:
            if asset == "data:,":  # the empty inline favicon
                continue
            assert asset.startswith("/"), f"{asset} is not served by the assistant"
            got = await client.get(asset, headers={"Authorization": ""})
            assert got.status_code == 200, asset
        # The page's script draws the reference from the service's own schema.
        script = (await client.get("/js/apidocs.js")).text
        assert "/openapi.json" in script and "http" not in script.replace("HTTP ", "")
        schema = (await client.get("/openapi.json", headers={"Authorization": ""})).json()
        assert "/v1/instructions" in schema["paths"]
        assert (await client.get("/redoc")).status_code == 404  # ReDoc would need a CDN too


def _samples(text: str, name: str) -> dict[str, float]:
    return {
        labels: float(value)
        for labels, value in re.findall(rf"^{name}_count(\{{[^}}]*\}}) (\S+)$", text, re.M)
    }


async def test_metrics_report_the_embedded_reasoner_as_agent_calls(tmp_path: Path) -> None:
    async with serve(tmp_path, people="simulated", reasoner_builder=None) as client:
        created = await client.post(
            "/v1/instructions", json={"requester": "lee", "text": "Bring me a stapler"}
        )
        assert created.status_code == 202, created.text
        record = await ended(client, created.json()["id"])
        assert record["status"] not in ("queued", "running")
        text = (await client.get("/metrics")).text
    agents = _samples(text, "assistantx_agent_call_latency_seconds")
    embedded = {k: v for k, v in agents.items() if 'backend="embedded"' in k}
    assert embedded and all(v > 0 for v in embedded.values()), agents
    assert not any('backend="llm"' in k for k in agents)
    assert _samples(text, "assistantx_llm_call_latency_seconds") == {}
