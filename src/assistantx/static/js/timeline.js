// One instruction's trace as a timeline: per step its perception, plan, actions with their
// results, the reflection's verdict and reason, memory updates, and the agents' token use and
// latency. Renders the Trace model (src/assistantx/trace.py) as the API returns it.

import { badge, clock, duration, h, instructionState, keepScrolledToEnd, replace } from "./dom.js";

/** "inform(contact=lee, content=…)" from an action object. */
export function describeAction(action) {
  if (!action) return "";
  const { type, ...args } = action;
  const parts = Object.entries(args)
    .filter(([, v]) => v !== null && v !== undefined && v !== "")
    .map(([k, v]) => `${k}=${typeof v === "string" ? v : JSON.stringify(v)}`);
  return `${type}(${parts.join(", ")})`;
}

function percept(p) {
  if (!p) return null;
  const focus = [
    p.people?.length && `people: ${p.people.join(", ")}`,
    p.items?.length && `items: ${p.items.join(", ")}`,
    p.places?.length && `places: ${p.places.join(", ")}`,
    p.groups?.length && `groups: ${p.groups.join(", ")}`,
  ].filter(Boolean);
  return [h("dt", {}, "Perception"), h("dd", {}, p.summary || "", focus.length ? h("div", { class: "hint" }, focus.join(" · ")) : null)];
}

function plan(p) {
  if (!p) return null;
  return [
    h("dt", {}, "Plan"),
    h("dd", {}, h("div", {}, p.goal),
      h("ul", {}, p.subgoals.map((s) => h("li", {}, s.done ? "☑ " : "☐ ", s.description)))),
  ];
}

function actions(step) {
  const results = step.results ?? [];
  if (results.length) {
    return [
      h("dt", {}, "Actions"),
      h("dd", {}, h("ul", {}, results.map((r) =>
        h("li", { class: r.ok ? "result-ok" : "result-fail" },
          h("code", {}, describeAction(r.action)), " → ", r.observation || r.error || (r.ok ? "ok" : "failed"),
          r.refused ? " (refused)" : "")))),
    ];
  }
  if (step.decision?.actions?.length) {
    return [
      h("dt", {}, "Actions"),
      h("dd", {}, h("ul", {}, step.decision.actions.map((a) => h("li", {}, h("code", {}, describeAction(a)), " …")))),
    ];
  }
  return null;
}

function reflection(r) {
  if (!r) return null;
  return [h("dt", {}, "Reflection"), h("dd", {}, badge(r.verdict === "Y" ? "Y — as expected" : "N — not as expected", r.verdict), " ", r.reason)];
}

function learned(applied) {
  if (!applied?.length) return null;
  return [
    h("dt", {}, "Memory"),
    h("dd", {}, h("ul", {}, applied.map((a) => h("li", {}, describeUpdate(a.update), a.changed ? "" : " (already known)")))),
  ];
}

function feedback(step) {
  if (!step.feedback?.length) return null;
  return [h("dt", {}, "Feedback"), h("dd", {}, h("ul", {}, step.feedback.map((f) => h("li", {}, f))))];
}

/** An update in words, e.g. "zhang is unavailable". */
export function describeUpdate(u) {
  if (!u) return "";
  if (u.kind === "availability") {
    const state = u.available === true ? "available" : u.available === false ? "unavailable" : "of unknown availability";
    return `${u.person} is ${state}`;
  }
  if (u.kind === "ownership") return `${u.person} ${u.owns ? "owns" : "does not own"} a ${u.item_type}`;
  if (u.kind === "item_location") return `${u.item} is with ${u.holder}`;
  return JSON.stringify(u);
}

function usage(calls) {
  if (!calls?.length) return null;
  const text = calls.map((c) => {
    const tokens = c.prompt_tokens || c.completion_tokens
      ? ` ${c.prompt_tokens}+${c.completion_tokens} tok${c.estimated ? " (est.)" : ""}` : "";
    return `${c.agent}${c.model ? ` [${c.model}]` : ""}:${tokens} ${duration(c.latency_s)}`;
  });
  return h("p", { class: "usage" }, text.join(" · "));
}

function stepItem(step) {
  const verdict = step.reflection?.verdict;
  return h("li", { class: `step${verdict ? ` verdict-${verdict}` : ""}`, dataset: { step: step.index } },
    h("h3", {}, `Step ${step.index}`, h("span", { class: "hint" }, clock(step.started_at)),
      step.ended_at == null ? badge("running") : null),
    h("dl", {}, percept(step.percept), plan(step.plan), actions(step), reflection(step.reflection),
      learned(step.applied), feedback(step),
      step.queue?.length ? [h("dt", {}, "Queued"), h("dd", {}, `waiting for ${step.queue.join(", ")}`)] : null),
    usage(step.calls));
}

/** One badge: "running"/"queued" while it runs, then "outcome: done" (or failed,
 * unachievable), or "cancelled" — never cancelled and failed side by side. */
function stateBadge(instruction) {
  const state = instructionState(instruction);
  const ended = instruction.status !== "queued" && instruction.status !== "running";
  const text = ended && state !== "cancelled" ? `outcome: ${state}` : state;
  return h("span", { class: `badge ${state}`, id: "trace-state" }, text);
}

/** Render an instruction (with .trace) into the header and timeline elements. */
export function renderTrace(headerEl, timelineEl, instruction) {
  const trace = instruction.trace;
  const total = trace?.usage;
  replace(headerEl,
    h("p", {}, h("strong", {}, instruction.requester), ": ", instruction.text),
    h("p", { class: "row" }, stateBadge(instruction),
      trace?.reasoner ? h("span", { class: "hint" }, `reasoner ${trace.reasoner}`) : null),
    instruction.summary || trace?.summary ? h("p", { id: "trace-summary" }, instruction.summary || trace.summary) : null,
    total && total.calls ? h("p", { class: "usage" },
      `${total.calls} agent calls · ${total.prompt_tokens} prompt + ${total.completion_tokens} completion tokens · ${duration(total.latency_s)} in agents`) : null);
  const steps = trace?.steps ?? [];
  // Follow new steps as they arrive, unless the reader scrolled back to an earlier one.
  keepScrolledToEnd(timelineEl, () =>
    replace(timelineEl, steps.length ? steps.map(stepItem) : h("li", { class: "hint" }, "No steps yet.")));
}
