// The evaluation tab: the newest run's summary table (from its summary.md, whose tables and
// headings are rendered here without any HTML from the file) and its charts.

import { api, authHeaders, scoped } from "./api.js";
import { h, replace } from "./dom.js";

function cells(line) {
  return line.trim().replace(/^\|/, "").replace(/\|$/, "").split("|").map((c) => c.trim().replace(/\*\*/g, ""));
}

/** A small Markdown subset: headings, pipe tables, paragraphs. Anything else stays text. */
export function renderMarkdown(text) {
  const out = [];
  const lines = text.split(/\r?\n/);
  for (let i = 0; i < lines.length; i++) {
    const line = lines[i];
    const heading = /^(#{1,4})\s+(.*)$/.exec(line);
    if (heading) {
      out.push(h(`h${Math.min(6, heading[1].length + 2)}`, {}, heading[2]));
    } else if (line.trim().startsWith("|") && /^\s*\|?[\s:|-]+\|?\s*$/.test(lines[i + 1] ?? "")) {
      const head = cells(line);
      const body = [];
      i += 2;
      while (i < lines.length && lines[i].trim().startsWith("|")) body.push(cells(lines[i++]));
      i -= 1;
      out.push(h("p", { class: "scroll-hint", hidden: true }, "The table is wider than the screen: scroll it sideways →"));
      out.push(h("div", { class: "table-wrap" }, h("table", {},
        h("thead", {}, h("tr", {}, head.map((c) => h("th", { scope: "col" }, c)))),
        h("tbody", {}, body.map((row) => h("tr", {}, row.map((c, n) => (n === 0 ? h("th", { scope: "row" }, c) : h("td", {}, c)))))))));
    } else if (line.trim()) {
      out.push(h("p", {}, line.replace(/[*`_]/g, "")));
    }
  }
  return out;
}

/** What each metric means (DESIGN §5), shown above the table and under each chart. */
export const METRICS = {
  SR: ["success rate", "tasks whose outcome is right: every goal milestone holds and the requester was told (for an unachievable task: the assistant said it cannot be done, and why)"],
  CR: ["completion rate", "goal milestones reached, out of the milestones in the goal"],
  RR: ["redundancy rate", "redundant actions per action of the shortest successful sequence: repeats with nothing new in between, actions aimed at someone known to be away, or reaching nothing relevant; lower is better, 0 is none"],
  CTA: ["cyber task accuracy", "messages, questions, file forwards and QR codes that were valid, grounded in memory and not redundant, out of all of them"],
  RTA: ["real-world task accuracy", "drives and hand-over waits that were valid, grounded and not redundant, out of all of them"],
};

function glossary() {
  return h("dl", { class: "metric-glossary", "aria-label": "What the metrics mean" },
    Object.entries(METRICS).flatMap(([key, [name, text]]) => [h("dt", {}, h("abbr", { title: name }, key)), h("dd", {}, `${name}: ${text}.`)]));
}

function caption(file) {
  const key = file.toUpperCase();
  if (!METRICS[key]) return file.replace(/[_-]+/g, " ");
  return `${key} — ${METRICS[key][0]} by level (%)`;
}

async function chart(url) {
  const response = await fetch(scoped(url), { headers: authHeaders() });
  if (!response.ok) throw new Error(`HTTP ${response.status}`);
  return URL.createObjectURL(await response.blob());
}

/** Show each table's scroll hint only while the table is wider than its box (a phone). */
function markOverflow(container) {
  for (const wrap of container.querySelectorAll(".table-wrap")) {
    const hint = wrap.previousElementSibling;
    if (hint?.classList.contains("scroll-hint")) hint.hidden = wrap.scrollWidth <= wrap.clientWidth + 1;
  }
}

let watching = null;

export async function showEvaluation(container) {
  replace(container, h("p", { class: "hint" }, "Loading…"));
  let run;
  try {
    run = await api("/v1/evaluation/latest");
  } catch (err) {
    replace(container, h("p", {}, err.status === 404 ? `No evaluation yet: ${err.message}. Run "assistantx eval".` : `Cannot load the evaluation: ${err.message}`));
    return;
  }
  const figures = await Promise.all(run.charts.map(async (url) => {
    const name = decodeURIComponent(url.split("/").pop()).replace(/\.png$/, "").replace(/[_-]+/g, " ");
    try {
      return h("figure", {}, h("img", { src: await chart(url), alt: `Chart: ${name}` }), h("figcaption", {}, caption(name)));
    } catch (err) {
      return h("figure", {}, h("figcaption", {}, `${caption(name)}: ${err.message}`));
    }
  }));
  replace(container,
    h("p", { class: "hint" }, `Run ${run.run}, written ${new Date(run.modified * 1000).toLocaleString()}`),
    h("h3", {}, "What the metrics mean"), glossary(),
    run.markdown ? renderMarkdown(run.markdown) : h("pre", {}, JSON.stringify(run.summary, null, 2)),
    figures.length ? [h("h3", {}, "Charts"), h("div", { class: "charts" }, figures)] : null);
  markOverflow(container);
  watching?.disconnect();
  watching = new ResizeObserver(() => markOverflow(container));
  watching.observe(container);
}
