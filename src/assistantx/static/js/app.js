// The dashboard: wires the panels to the REST API and to the live event stream (/v1/events).
// Every trace event schedules one refresh of what it may have changed; a slow poll catches
// what has no trace event (a colleague typing, the operator elsewhere), and the robot is
// polled quickly while an instruction runs so its marker moves smoothly.

import { api, office, onUnauthorized, scoped, token } from "./api.js";
import { ChatsPanel } from "./chats.js";
import { $, badge, clock, h, instructionState, keepFocus, replace } from "./dom.js";
import { showEvaluation } from "./evaluation.js";
import { LockerPanel } from "./locker.js";
import { MapView } from "./map.js";
import { readMemory } from "./memory.js";
import { PeoplePanel } from "./people.js";
import { follow } from "./stream.js";
import { renderTrace } from "./timeline.js";

const ROBOT_POLL_BUSY_MS = 400;
const ROBOT_POLL_IDLE_MS = 3000;
const SLOW_POLL_MS = 4000;
const REFRESH_DEBOUNCE_MS = 200;
const FINAL = new Set(["done", "failed", "unachievable", "cancelled"]);

const state = { memory: null, me: null, instructions: [], selected: null, stream: null, started: false, busy: false };

// -- messages to the user ------------------------------------------------------------------
const banner = $("#banner");
function showBanner(text, kind = "warning") {
  banner.textContent = text;
  banner.className = `banner${kind === "error" ? " error" : ""}`;
  banner.hidden = false;
}
function hideBanner() {
  banner.hidden = true;
}
function reportError(text) {
  showBanner(text, "error");
}
function setConnection(kind, text) {
  const el = $("#connection");
  el.dataset.state = kind;
  $("#connection-text").textContent = text;
}

// -- the token -----------------------------------------------------------------------------
const dialog = $("#token-dialog");
function askToken(reason) {
  $("#token-input").value = "";
  if (reason) showBanner(reason, "error");
  if (!dialog.open) dialog.showModal();
}
$("#token-button").addEventListener("click", () => askToken());
$("#token-cancel").addEventListener("click", () => dialog.close());
$("#token-form").addEventListener("submit", () => {
  const value = $("#token-input").value.trim();
  if (!value) return;
  token.set(value);
  hideBanner();
  start();
});
onUnauthorized(() => askToken("The token was refused. Enter a valid API token."));

// -- tabs (WAI-ARIA tabs pattern: arrow keys move between tabs) ------------------------------
const tabs = [...document.querySelectorAll('[role="tab"]')];
function selectTab(tab) {
  for (const t of tabs) {
    const selected = t === tab;
    t.setAttribute("aria-selected", String(selected));
    t.tabIndex = selected ? 0 : -1;
    document.getElementById(t.getAttribute("aria-controls")).hidden = !selected;
  }
  tab.focus();
  if (tab.id === "tab-evaluation" && state.started) showEvaluation($("#evaluation"));
}
tabs.forEach((tab, n) => {
  tab.addEventListener("click", () => selectTab(tab));
  tab.addEventListener("keydown", (event) => {
    const step = { ArrowRight: 1, ArrowLeft: -1 }[event.key];
    if (step) selectTab(tabs[(n + step + tabs.length) % tabs.length]);
    if (event.key === "Home") selectTab(tabs[0]);
    if (event.key === "End") selectTab(tabs.at(-1));
  });
});

// -- panels --------------------------------------------------------------------------------
const mapView = new MapView($("#map"));
$("#show-particles").addEventListener("change", (e) => {
  mapView.showParticles = e.target.checked;
  mapView.draw();
});
$("#show-labels").addEventListener("change", (e) => {
  mapView.showLabels = e.target.checked;
  mapView.draw();
});

const people = new PeoplePanel($("#people-table tbody"), $("#learned"), {
  onChanged: () => refreshMemory(),
  onError: reportError,
});
const chats = new ChatsPanel({
  select: $("#chat-select"),
  transcript: $("#transcript"),
  form: $("#reply-form"),
  sender: $("#reply-sender"),
  text: $("#reply-text"),
  status: $("#reply-status"),
}, { onError: reportError });
const locker = new LockerPanel($("#locker-state"), $("#codes"), {
  onChanged: () => refreshLocker(),
  onError: reportError,
  announce: (text) => { $("#robot-status").textContent = text; },
});

// -- data ----------------------------------------------------------------------------------
async function refreshMemory() {
  state.memory = readMemory(await api("/v1/memory"));
  people.render(state.memory);
  mapView.setPeople(state.memory.people);
  chats.setMemory(state.memory);
  fillRequesters();
}

// Who submits: a person's token submits as that person (the only one it may act as); the
// operator is asked to choose, never given the first name of the list, which made it easy to
// submit as someone else by mistake.
function fillRequesters() {
  const select = $("#submit-requester");
  const keep = select.value;
  const me = state.me?.person;
  const people = me ? state.memory.people.filter((p) => p.id === me) : state.memory.people;
  const choose = me ? [] : [h("option", { value: "", disabled: true }, "Choose who asks…")];
  replace(select, choose, people.map((p) => h("option", { value: p.id }, p.name)));
  select.value = me ?? keep ?? "";
  if (!select.value) select.value = "";
}

async function refreshInstructions() {
  const page = await api("/v1/instructions?limit=50");
  state.instructions = page.items;
  state.busy = page.items.some((i) => !FINAL.has(i.status));
  const list = $("#instruction-list");
  keepFocus(list, () => replace(list, page.items.length ? page.items.map((ins) => h("li", { dataset: { key: ins.id } },
    h("button", {
      type: "button",
      "aria-current": ins.id === state.selected ? "true" : "false",
      dataset: { id: ins.id, status: ins.status },
      onclick: () => select(ins.id),
    },
    h("span", { class: "meta" }, badge(instructionState(ins)), `${nameOf(ins.requester)} · ${clock(ins.created_at)}`),
    h("span", {}, ins.text))))
    : h("li", { class: "hint" }, "No instructions yet.")));
}

function nameOf(id) {
  return state.memory?.people.find((p) => p.id === id)?.name ?? id;
}

async function refreshSelected() {
  if (!state.selected) return;
  const detail = await api(`/v1/instructions/${encodeURIComponent(state.selected)}`);
  renderTrace($("#trace-header"), $("#timeline"), detail);
}

async function select(id) {
  state.selected = id;
  await Promise.all([refreshInstructions(), refreshSelected()]);
}

async function refreshLocker() {
  await locker.refresh();
}

async function refreshRobot() {
  // Every robot of the office (one, or a fleet's robots 1, 2..), each on the map.
  const robots = await api("/v1/robots");
  mapView.setRobots(robots);
  // Places by name: ids (desk_03) and instruction ids are not for people to read.
  const named = (id) => (id ? (state.memory?.places[id] ?? id.replaceAll("_", " ")) : null);
  const doing = (robot) => {
    const place = named(robot.place);
    const goal = named(robot.goal);
    return robot.moving
      ? `driving${goal ? ` to ${goal}` : ""}`
      : `at ${place ?? "an unnamed spot"}, ${robot.odometer_m.toFixed(1)} m driven`;
  };
  $("#robot-status").textContent = robots.length === 1
    ? `Robot: ${doing(robots[0])}`
    : robots.map((robot) => `${robot.name.replace(/^r/, "R")}: ${doing(robot)}`).join(" · ");
}

async function refreshAll() {
  await Promise.all([refreshInstructions(), refreshSelected(), refreshMemory(), chats.refresh(), refreshLocker(), refreshRobot(), refreshReplicas()]);
}

// Replicas on one database: each one's health and the offices it runs, refreshed with the
// page, so a watcher sees a takeover (a replica down, its offices run by another) without
// reading /metrics. Hidden without replicas, and for a colleague's token (operator only).
async function refreshReplicas() {
  const panel = $("#replicas");
  let replicas = [];
  let offices = [];
  try {
    [replicas, offices] = await Promise.all([api("/v1/replicas"), api("/v1/offices")]);
  } catch {
    replicas = [];
  }
  const names = new Map(offices.map((o) => [o.id, o.name]));
  panel.hidden = replicas.length === 0;
  replace(
    $("#replicas-table tbody"),
    ...replicas.map((r) => {
      const age = r.heartbeat_age_s == null ? "" : ` (heartbeat ${r.heartbeat_age_s.toFixed(1)} s ago)`;
      const runs = r.offices.map((id) => names.get(id) ?? "an office not yours").join(", ");
      return h(
        "tr",
        { "data-replica": r.id },
        h("td", {}, r.here ? `${r.id} (answering this page)` : r.id),
        h("td", {}, r.up ? `up${age}` : "down"),
        h("td", {}, runs || "no office"),
      );
    }),
  );
}

// Coalesce bursts of events into one refresh; never two refreshes at once.
let refreshTimer = null;
let refreshing = null;
function scheduleRefresh() {
  clearTimeout(refreshTimer);
  refreshTimer = setTimeout(async () => {
    await refreshing;
    refreshing = refreshAll().catch(handleError);
    await refreshing;
    refreshing = null;
  }, REFRESH_DEBOUNCE_MS);
}

function handleError(err) {
  if (err?.status === 401) return; // the token dialog is open
  if (err?.status === 0) return; // the stream's reconnect handles a down server
  reportError(err?.message ?? String(err));
}

// -- live stream, polling ------------------------------------------------------------------
function startStream() {
  state.stream?.stop();
  state.stream = follow("/v1/events", {
    onEvent: (message) => {
      let event;
      try {
        event = JSON.parse(message.data);
      } catch {
        return;
      }
      if (event.kind === "instruction_started" && !state.selected) state.selected = event.instruction_id;
      scheduleRefresh();
    },
    onState: (kind, detail) => {
      if (kind === "live") {
        setConnection("live", "Live");
        if (!banner.classList.contains("error")) hideBanner();
        scheduleRefresh(); // catch up on what changed while away
      } else if (kind === "connecting") {
        setConnection("reconnecting", "Connecting…");
      } else if (kind === "reconnecting") {
        const seconds = detail.delayMs ? Math.ceil(detail.delayMs / 1000) : 0;
        setConnection("down", "Disconnected");
        showBanner(`Connection to the assistant lost${detail.problem ? ` (${detail.problem})` : ""}. Reconnecting${seconds ? ` in ${seconds} s` : ""} (attempt ${detail.attempt})…`);
      } else if (kind === "unauthorized") {
        setConnection("down", "Not signed in");
        askToken("The token was refused. Enter a valid API token.");
      }
    },
  });
}

let robotTimer = null;
function pollRobot() {
  clearTimeout(robotTimer);
  refreshRobot()
    .catch(() => {})
    .finally(() => {
      robotTimer = setTimeout(pollRobot, state.busy ? ROBOT_POLL_BUSY_MS : ROBOT_POLL_IDLE_MS);
    });
}

let slowTimer = null;
function slowPoll() {
  clearTimeout(slowTimer);
  slowTimer = setTimeout(() => {
    if (!document.hidden) scheduleRefresh();
    slowPoll();
  }, SLOW_POLL_MS);
}

// -- submitting ----------------------------------------------------------------------------
$("#submit-form").addEventListener("submit", async (event) => {
  event.preventDefault();
  const requester = $("#submit-requester").value;
  const text = $("#submit-text").value.trim();
  const status = $("#submit-status");
  if (!text) return;
  status.textContent = "Submitting…";
  try {
    const created = await api("/v1/instructions", { method: "POST", body: { requester, text } });
    status.textContent = `Submitted as ${created.id}.`;
    $("#submit-text").value = "";
    state.busy = true;
    await select(created.id);
    pollRobot();
  } catch (err) {
    status.textContent = "";
    reportError(`Not submitted: ${err.message}`);
  }
});

// -- start-up ------------------------------------------------------------------------------
// Simulated durations (travel, simulated replies) may run faster than real time; say so, as
// a watcher would otherwise take the robot's speed for real. Times of day are always real.
async function showSpeedup() {
  const label = $("#speedup");
  try {
    const ready = await (await fetch(scoped("/readyz"))).json();
    const speedup = Number(ready.speedup);
    label.hidden = !(speedup > 0 && speedup !== 1);
    label.textContent = `Simulated time runs ${speedup}× faster (robot travel, simulated replies, waits); clock times are real.`;
    showReplica(ready.replica);
  } catch {
    label.hidden = true;
  }
}

// Replicas on one database: which one runs this office now. The lease's term grows at every
// takeover, so a watcher sees a failover happened even when the same page stays open.
function showReplica(replica) {
  const label = $("#replica");
  const shown = Boolean(replica) && typeof replica === "object";
  label.hidden = !shown;
  if (shown) {
    label.textContent = `Office ${replica.office} is run by replica ${replica.id} (lease term ${replica.fencing_token}).`;
  }
}

// Several offices in one deployment: the picker chooses the one the page shows (kept for the
// next visit); every API path then goes to that office's /v1/offices/ID/... One office: no
// picker, today's paths.
async function pickOffice() {
  const picker = $("#office-picker");
  const select = $("#office-select");
  const deployment = await (await fetch("/readyz")).json().catch(() => ({}));
  if (!deployment.offices) {
    office.clear();
    picker.hidden = true;
    return;
  }
  const offices = await api("/v1/offices");
  const chosen = offices.find((o) => o.id === office.get()) ?? offices[0];
  if (chosen) office.set(chosen.id);
  replace(
    select,
    ...offices.map((o) => {
      const where = o.status === "ready" || o.here ? "" : o.replica ? ` (on ${o.replica})` : " (not running)";
      return h("option", { value: o.id, selected: o.id === chosen?.id }, `${o.name}${where}`);
    }),
  );
  picker.hidden = offices.length < 2;
}
$("#office-select").addEventListener("change", (event) => {
  office.set(event.target.value);
  location.reload(); // every panel, stream and map starts over on the chosen office
});

async function start() {
  if (!token.get()) {
    showSpeedup();
    askToken();
    return;
  }
  try {
    await pickOffice();
  } catch (err) {
    handleError(err);
    if (err?.status === 401) return;
  }
  showSpeedup();
  try {
    state.me = await api("/v1/me");
    await refreshMemory();
    await mapView.load().catch((err) => reportError(`Map unavailable: ${err.message}`));
    await refreshAll();
  } catch (err) {
    handleError(err);
    if (err?.status === 401) return;
  }
  state.started = true;
  startStream();
  pollRobot();
  slowPoll();
}

start();
