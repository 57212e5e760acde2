"""How fast the real server is here and now, and the time budgets sized from it.

On a 2-core machine shared with other jobs the same server reads a prompt at 6 to 300 tokens
per second; fixed budgets either wait ten minutes for a hung call or fail a slow but healthy
one. The tests measure the server first (one call that reads a long prompt and writes one
token, one that reads a short prompt and writes a few dozen) and give each call a budget of a
few times what it should take at that speed, capped so that no call waits minutes.
"""

from __future__ import annotations

from dataclasses import dataclass

from assistantx.adapters.model import ChatRequest, Message, OpenAICompatibleModel, RetryPolicy
from assistantx.adapters.model import estimate_tokens as four_chars_per_token

# the four-characters estimate runs about 20% under this model's own token counts
_ESTIMATE_UNDER = 1.3
_MARGIN = 3.0  # a budget is this many times the expected time, plus _SLACK_S
_SLACK_S = 5.0
CALL_CAP_S = 90.0  # no call ever waits longer than this, however slow the server measured
# a call a test needs answered never gets less than this: the speed is measured once, on free
# text, while the suite's other worker comes and goes; a grammar-constrained answer (the grammar
# is compiled in Python per schema) under that load took over 10 s where 2 s were expected
MUST_FINISH_FLOOR_S = 45.0


@dataclass(frozen=True)
class ServerSpeed:
    prompt_tps: float  # prompt tokens read per second
    generate_tps: float  # completion tokens written per second

    def expected_s(self, prompt_tokens: int, completion_tokens: int) -> float:
        return prompt_tokens / self.prompt_tps + completion_tokens / self.generate_tps

    def budget_s(self, prompt_tokens: int, completion_tokens: int) -> float:
        """A call's budget: a few times its expected time, never over ``CALL_CAP_S``."""
        expected = self.expected_s(prompt_tokens, completion_tokens)
        return min(CALL_CAP_S, _MARGIN * expected + _SLACK_S)

    def must_finish_budget_s(self, prompt_tokens: int, completion_tokens: int) -> float:
        """The budget of a call whose answer the test needs: ``budget_s`` with a floor of
        ``MUST_FINISH_FLOOR_S``, so a load swing after the measurement fails nothing healthy."""
        floor = max(self.budget_s(prompt_tokens, completion_tokens), MUST_FINISH_FLOOR_S)
        return min(CALL_CAP_S, floor)

    def fits(self, prompt_tokens: int, completion_tokens: int, within_s: float) -> bool:
        """Whether such a call should finish within ``within_s`` at the measured speed."""
        return self.expected_s(prompt_tokens, completion_tokens) * 1.5 <= within_s


def prompt_tokens(messages: tuple[Message, ...] | list[Message]) -> int:
    """The model's count of a prompt, from its text (the estimate, corrected)."""
    text = "".join(m.content for m in messages)
    return int(four_chars_per_token(text) * _ESTIMATE_UNDER) + 8 * len(messages)


async def measure(base_url: str, model_name: str) -> ServerSpeed:
    """Two small calls: prompt reading speed, then writing speed."""
    reading = ChatRequest(
        messages=(Message(role="user", content="office robot memory line. " * 60),),
        agent="speed-read",
    )
    writing = ChatRequest(
        messages=(Message(role="user", content="Count from one to twenty in words."),),
        agent="speed-write",
    )
    async with _client(base_url, model_name, max_tokens=1) as model:
        read = await model.complete(reading)
    prompt_tps = read.usage.prompt_tokens / max(read.latency_s, 0.01)
    async with _client(base_url, model_name, max_tokens=32) as model:
        written = await model.complete(writing)
    writing_s = written.latency_s - written.usage.prompt_tokens / prompt_tps
    generate_tps = written.usage.completion_tokens / max(writing_s, 0.01)
    return ServerSpeed(prompt_tps=max(prompt_tps, 0.5), generate_tps=max(generate_tps, 0.5))


def _client(base_url: str, model_name: str, *, max_tokens: int) -> OpenAICompatibleModel:
    return OpenAICompatibleModel(
        base_url,
        model_name,
        max_tokens=max_tokens,
        timeout_s=CALL_CAP_S,
        call_budget_s=CALL_CAP_S,
        retry=RetryPolicy(max_retries=0),
    )
