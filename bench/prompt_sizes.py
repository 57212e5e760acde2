"""Prompt tokens per LLM agent call, on the default office and a generated large office.

For each office the first step of "Could you get me a stapler, please?" is rendered for the
four PPDR agents and the baselines' decision prompt (with the schema outline the prompt
carries when the server enforces the schema), and a later step with a dialogue of 12 turns.
Tokens are estimated at four characters per token; with ``--base-url`` each prompt is also
sent to an OpenAI-compatible server (``max_tokens`` 1) and the prompt tokens it reports are
given. The large office copies the default one's places, item types and facilities and adds
generated people (each owning three item types, in 20 group chats).

    python bench/prompt_sizes.py [--people 1000] [--context 4096] [--base-url URL --model M]

Last stdout line: one JSON object with the sizes per office and agent, and the largest.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import random
from typing import Any

import yaml

from assistantx.adapters.model import ChatRequest, Message, OpenAICompatibleModel, estimate_tokens
from assistantx.agents.base import AgentContext
from assistantx.agents.baseline_names import BASELINES
from assistantx.agents.baselines import (
    ACTION_SPACE,
    BaselineReasoner,
    load_baseline_prompts,
)
from assistantx.agents.llm import AgentPrompts, LLMReasoner, SharedModel, schema_text
from assistantx.core.actions import Inquire, Wait
from assistantx.core.dialogue import DialogueTurn
from assistantx.core.office import DEFAULT_OFFICE, Office, parse_office
from assistantx.core.ports.messenger import ChatRef
from assistantx.core.trace import (
    ActionResult,
    Decision,
    Observation,
    Percept,
    Plan,
    SubGoal,
    Trace,
    TraceStep,
)
from assistantx.memory.focus import focus_budget
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.resolve import Resolver
from assistantx.memory.short_term import ShortTermMemory

INSTRUCTION = "Could you get me a stapler, please?"


def large_office(people: int, seed: int = 0) -> Office:
    raw: dict[str, Any] = yaml.safe_load(DEFAULT_OFFICE.read_text())
    rng = random.Random(seed)
    desks = [loc["id"] for loc in raw["locations"] if loc["kind"] == "workstation"]
    types = [t["id"] for t in raw["item_types"] if t.get("kind", "belonging") != "product"]
    extra = people - len(raw["people"])
    for n in range(extra):
        pid = f"p{n:04d}"
        owns = [{"type": t, "known": rng.random() < 0.7} for t in rng.sample(types, 3)]
        raw["people"].append(
            {
                "id": pid,
                "name": f"Person {n:04d}",
                "location": rng.choice(desks),
                "handle": f"@{pid}",
                "owns": owns,
            }
        )
    ids = [p["id"] for p in raw["people"]]
    for g in range(20):
        raw["groups"].append(
            {"id": f"team_{g:02d}", "name": f"Team {g:02d}", "members": ids[g::20]}
        )
    return parse_office(raw, where=f"<generated office of {people}>")


def contexts(office: Office) -> dict[str, AgentContext]:
    def make(step: int) -> AgentContext:
        trace = Trace(
            instruction_id="ins-b", requester="lee", text=INSTRUCTION, reasoner="llm", started_at=0
        )
        stm = ShortTermMemory(
            instruction_id="ins-b", requester="lee", text=INSTRUCTION, trace=trace
        )
        stm.embodied.robot_place = "meeting_room"
        for i in range(step):
            who = ("zhang", "wang", "gao")[i % 3]
            ask = Inquire(contact=who, question=f"Could you lend Lee your stapler? ({i})")
            stm.dialogue.append(
                DialogueTurn(
                    time=60.0 * i,
                    direction="out",
                    chat=ChatRef(kind="dm", id=who),
                    person=who,
                    text=ask.question,
                )
            )
            stm.dialogue.append(
                DialogueTurn(
                    time=60.0 * i + 20,
                    direction="in",
                    chat=ChatRef(kind="dm", id=who),
                    person=who,
                    text="Sorry, I am busy right now, maybe later.",
                )
            )
            trace.steps.append(
                TraceStep(
                    index=i,
                    started_at=60.0 * i,
                    results=[
                        ActionResult(
                            action=ask, ok=True, observation="sent", started_at=0, ended_at=0
                        ),
                        ActionResult(
                            action=Wait(timeout_s=60),
                            ok=True,
                            observation=f"{who} replied",
                            started_at=0,
                            ended_at=0,
                        ),
                    ],
                )
            )
        trace.steps.append(TraceStep(index=step, started_at=60.0 * step))
        return AgentContext(
            ltm=LongTermMemory(office), stm=stm, resolver=Resolver(office), step=step, now=0.0
        )

    return {"step 0": make(0), "step 6": make(6)}


def prompts_for(office: Office, context_tokens: int, max_tokens: int) -> dict[str, list[Message]]:
    budget = focus_budget(context_tokens, max_tokens)
    shared = SharedModel(OpenAICompatibleModel("http://127.0.0.1:9/v1", "none"))
    reasoner = LLMReasoner(shared, AgentPrompts.load(), budget=budget)
    percept = Percept(people=["lee", "zhang"], items=["stapler"], summary="lee wants a stapler")
    plan = Plan(goal="a stapler for lee", subgoals=[SubGoal(description="ask an owner")])
    decision = Decision(actions=[Wait(timeout_s=60)])
    out: dict[str, list[Message]] = {}
    for label, ctx in contexts(office).items():
        out[f"perception {label}"] = reasoner.perception_messages(ctx)
        out[f"planning {label}"] = reasoner.planning_messages(ctx, percept)
        out[f"decision {label}"] = reasoner.decision_messages(ctx, percept, plan)
        out[f"reflection {label}"] = reasoner.reflection_messages(
            ctx, percept, plan, decision, [], Observation(robot_place="meeting_room")
        )
        for name in BASELINES:
            base = BaselineReasoner(name, shared, load_baseline_prompts(name), budget=budget)
            prompt = "mobile_agent_v2_decide" if name == "mobile_agent_v2" else name
            values = {
                "memory": base.memory(ctx),
                "feedback": "(none)",
                "action_space": ACTION_SPACE,
                "output_schema": schema_text(Decision),
                "lessons": "(none yet)",
                "focus": INSTRUCTION,
                "last_judgement": "(no step judged yet)",
            }
            template = base.prompts[prompt]
            wanted = {k: v for k, v in values.items() if k in template.variables}
            out[f"{name} {label}"] = template.render(wanted)
    return out


async def server_counts(
    prompts: dict[str, list[Message]], base_url: str, model_name: str
) -> dict[str, int]:
    counts: dict[str, int] = {}
    async with OpenAICompatibleModel(base_url, model_name, max_tokens=1, timeout_s=600) as model:
        for key, messages in prompts.items():
            response = await model.complete(ChatRequest(messages=tuple(messages), agent="size"))
            counts[key] = response.usage.prompt_tokens
    return counts


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--people", type=int, default=1000)
    parser.add_argument("--context", type=int, default=4096)
    parser.add_argument("--max-tokens", type=int, default=512)
    parser.add_argument("--base-url")
    parser.add_argument("--model", default="SmolLM2-135M-Instruct")
    args = parser.parse_args()
    from assistantx.core.office import load_office

    offices = {"default": load_office(), f"generated {args.people}": large_office(args.people)}
    result: dict[str, Any] = {"context": args.context, "max_tokens": args.max_tokens}
    largest = 0
    for label, office in offices.items():
        prompts = prompts_for(office, args.context, args.max_tokens)
        sizes = {k: estimate_tokens("".join(m.content for m in v)) for k, v in prompts.items()}
        entry: dict[str, Any] = {"people": len(office.people), "estimated": sizes}
        if args.base_url:
            entry["server"] = asyncio.run(server_counts(prompts, args.base_url, args.model))
            largest = max(largest, *entry["server"].values())
        largest = max(largest, *sizes.values())
        result[label] = entry
        for key, value in sizes.items():
            served = entry.get("server", {}).get(key)
            shown = f"{value:5d} est" + (f", {served:5d} served" if served else "")
            print(f"{label:>16} {key:32} {shown}")
    result["largest_prompt_tokens"] = largest
    print(json.dumps(result))


if __name__ == "__main__":
    main()
