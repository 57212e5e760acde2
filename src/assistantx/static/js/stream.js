// Server-Sent Events over fetch: EventSource cannot send an Authorization header, and a token
// in the URL ends up in access logs, so the stream is read with fetch and parsed here
// (the text/event-stream format of the HTML standard). Reconnects by itself with exponential
// backoff and jitter, resuming with Last-Event-ID so no event is missed or repeated.

import { authHeaders, scoped } from "./api.js";

const MIN_DELAY_MS = 500;
const MAX_DELAY_MS = 15000;

/** Parse text/event-stream chunks; calls dispatch({event, data, id}) per complete event. */
export class EventStreamParser {
  constructor(dispatch) {
    this.dispatch = dispatch;
    this.buffer = "";
    this.reset();
    this.retryMs = null;
  }

  reset() {
    this.event = "";
    this.data = [];
    this.id = null;
  }

  push(chunk) {
    this.buffer += chunk;
    const lines = this.buffer.split(/\r\n|\r|\n/);
    this.buffer = lines.pop(); // an incomplete last line waits for the next chunk
    for (const line of lines) this.line(line);
  }

  line(line) {
    if (line === "") {
      if (this.data.length) {
        this.dispatch({ event: this.event || "message", data: this.data.join("\n"), id: this.id });
      }
      this.reset();
      return;
    }
    if (line.startsWith(":")) return; // a comment: the server's keep-alive
    const colon = line.indexOf(":");
    const field = colon < 0 ? line : line.slice(0, colon);
    let value = colon < 0 ? "" : line.slice(colon + 1);
    if (value.startsWith(" ")) value = value.slice(1);
    if (field === "event") this.event = value;
    else if (field === "data") this.data.push(value);
    else if (field === "id" && !value.includes("\0")) this.id = value;
    else if (field === "retry" && /^\d+$/.test(value)) this.retryMs = Number(value);
  }
}

/**
 * Follow an SSE endpoint until stop() is called.
 *   onEvent({event, data, id})      every event (data is the raw string)
 *   onState(state, detail)          "connecting" | "live" | "reconnecting" | "unauthorized"
 */
export function follow(url, { onEvent, onState }) {
  let lastEventId = null;
  let attempt = 0;
  let controller = null;
  let stopped = false;
  let timer = null;

  async function connect() {
    if (stopped) return;
    controller = new AbortController();
    onState(attempt === 0 ? "connecting" : "reconnecting", { attempt });
    const headers = authHeaders({ Accept: "text/event-stream", "Cache-Control": "no-cache" });
    if (lastEventId !== null) headers["Last-Event-ID"] = lastEventId;
    const parser = new EventStreamParser((message) => {
      if (message.id !== null) lastEventId = message.id;
      onEvent(message);
    });
    let problem;
    try {
      const response = await fetch(scoped(url), { headers, signal: controller.signal, cache: "no-store" });
      if (response.status === 401 || response.status === 403) {
        onState("unauthorized", { status: response.status });
        return; // waits for a new token: the app calls restart()
      }
      if (!response.ok || !response.body) throw new Error(`HTTP ${response.status}`);
      attempt = 0;
      onState("live", {});
      const reader = response.body.pipeThrough(new TextDecoderStream()).getReader();
      for (;;) {
        const { value, done } = await reader.read();
        if (done) break;
        parser.push(value);
      }
      problem = "the server closed the stream";
    } catch (err) {
      if (stopped || err.name === "AbortError") return;
      problem = err.message || String(err);
    }
    if (stopped) return;
    attempt += 1;
    const base = parser.retryMs ?? MIN_DELAY_MS;
    const delay = Math.min(MAX_DELAY_MS, base * 2 ** (attempt - 1)) * (0.75 + Math.random() * 0.5);
    onState("reconnecting", { attempt, delayMs: delay, problem });
    timer = setTimeout(connect, delay);
  }

  connect();
  return {
    stop() {
      stopped = true;
      clearTimeout(timer);
      controller?.abort();
    },
    /** Connect again now (after a new token), keeping the resume position. */
    restart() {
      clearTimeout(timer);
      controller?.abort();
      attempt = 0;
      stopped = false;
      connect();
    },
  };
}
