// The API reference at /docs, drawn from the service's own /openapi.json with nothing loaded
// from elsewhere (the stock Swagger UI comes from a CDN and stays blank offline).

import { h, replace } from "./dom.js";

function schemaName(schema) {
  if (!schema) return "";
  if (schema.$ref) return schema.$ref.split("/").pop();
  if (schema.type === "array") return `${schemaName(schema.items)}[]`;
  if (schema.anyOf) return schema.anyOf.map(schemaName).join(" | ");
  return schema.type ?? "";
}

function operation(path, method, op) {
  const params = (op.parameters ?? []).map((p) =>
    h("li", {}, h("code", {}, p.name), ` (${p.in}${p.required ? ", required" : ""}) `, schemaName(p.schema), p.description ? ` — ${p.description}` : ""));
  const body = op.requestBody?.content?.["application/json"]?.schema;
  const responses = Object.entries(op.responses ?? {}).map(([code, r]) => h("li", {}, h("code", {}, code), ` ${r.description ?? ""}`));
  return h("section", { class: "panel operation", dataset: { method, path } },
    h("h3", {}, h("span", { class: `badge method-${method}` }, method.toUpperCase()), " ", h("code", {}, path)),
    op.summary ? h("p", {}, h("strong", {}, op.summary)) : null,
    op.description ? h("p", { class: "description" }, op.description) : null,
    params.length ? [h("h4", {}, "Parameters"), h("ul", {}, params)] : null,
    body ? [h("h4", {}, "Body"), h("p", {}, h("code", {}, schemaName(body)))] : null,
    responses.length ? [h("h4", {}, "Responses"), h("ul", {}, responses)] : null);
}

async function main() {
  const target = document.getElementById("apidocs");
  try {
    const response = await fetch("/openapi.json");
    if (!response.ok) throw new Error(`HTTP ${response.status}`);
    const spec = await response.json();
    const sections = [];
    for (const [path, methods] of Object.entries(spec.paths ?? {})) {
      for (const [method, op] of Object.entries(methods)) sections.push(operation(path, method, op));
    }
    replace(target, h("p", {}, `${spec.info?.title ?? "API"} ${spec.info?.version ?? ""} — ${spec.info?.description ?? ""}`), sections);
    target.dataset.ready = String(sections.length);
  } catch (err) {
    replace(target, h("p", { role: "alert" }, `Cannot load /openapi.json: ${err.message}`));
  }
}

main();
