// Small DOM helpers. Text always goes in through textContent, never innerHTML, so nothing the
// API returns (messages, instructions, names) can inject markup into the page.

/** Create an element: h("li", {class: "x", onclick: fn}, "text", child, ...). */
export function h(tag, attrs = {}, ...children) {
  const el = document.createElement(tag);
  for (const [name, value] of Object.entries(attrs)) {
    if (value === undefined || value === null || value === false) continue;
    if (name.startsWith("on") && typeof value === "function") {
      el.addEventListener(name.slice(2), value);
    } else if (name === "class") {
      el.className = value;
    } else if (name === "dataset") {
      Object.assign(el.dataset, value);
    } else {
      el.setAttribute(name, value === true ? "" : String(value));
    }
  }
  append(el, children);
  return el;
}

function append(el, children) {
  for (const child of children.flat()) {
    if (child === undefined || child === null || child === false) continue;
    el.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
}

/** Replace all children of el. */
export function replace(el, ...children) {
  el.replaceChildren();
  append(el, children);
}

export function $(selector) {
  const el = document.querySelector(selector);
  if (!el) throw new Error(`dashboard: no element ${selector}`);
  return el;
}

/** A status/outcome badge with a class the stylesheet colours. */
export function badge(text, kind = text) {
  return h("span", { class: `badge ${kind ?? ""}` }, text ?? "—");
}

/**
 * The one state an instruction is in, for its badge: while it runs, its status; once it ended,
 * "cancelled" when it was cancelled (its trace then ends as failed, which is not news), else
 * its outcome. Never two badges that disagree.
 */
export function instructionState(ins) {
  if (ins.status === "cancelled") return "cancelled";
  return ins.outcome ?? ins.status;
}

/** Seconds (Unix time) as a local clock time. */
export function clock(seconds) {
  if (typeof seconds !== "number") return "";
  return new Date(seconds * 1000).toLocaleTimeString([], { hour12: false });
}

/** "1.2 s", "340 ms". */
export function duration(seconds) {
  if (typeof seconds !== "number" || !Number.isFinite(seconds)) return "";
  return seconds < 1 ? `${Math.round(seconds * 1000)} ms` : `${seconds.toFixed(1)} s`;
}

/** Keep a scrollable list pinned to its end if the user had not scrolled away. */
export function keepScrolledToEnd(el, update) {
  const atEnd = el.scrollHeight - el.scrollTop - el.clientHeight < 24;
  update();
  if (atEnd) el.scrollTop = el.scrollHeight;
}

/**
 * Re-render a container without losing keyboard focus: if focus was on a control inside an
 * element marked with data-key, the same control of the re-rendered element gets it back.
 * (A background refresh must never throw a keyboard user back to the top of the page.)
 */
export function keepFocus(container, update) {
  const active = document.activeElement;
  const keyed = active && container.contains(active) ? active.closest("[data-key]") : null;
  const key = keyed?.dataset.key;
  const tag = active?.tagName;
  update();
  if (key === undefined) return;
  const again = container.querySelector(`[data-key="${CSS.escape(key)}"]`);
  const target = again && (again.tagName === tag ? again : again.querySelector(tag.toLowerCase()));
  target?.focus();
}
