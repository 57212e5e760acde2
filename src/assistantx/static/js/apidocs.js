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

// A body schema's fields (name, type, required, description) and its first example, so the
// page shows what to send rather than only the model's name.
function bodyDetails(schema, spec) {
  const name = schema.$ref?.split("/").pop();
  const model = name ? spec.components?.schemas?.[name] : schema;
  if (!model?.properties) return null;
  const required = new Set(model.required ?? []);
  const fields = Object.entries(model.properties).map(([field, s]) =>
    h("li", {}, h("code", {}, field), ` (${schemaName(s)}${required.has(field) ? ", required" : ""})`,
      s.description ? ` — ${s.description}` : ""));
  const example = model.examples?.[0];
  const shown = [h("ul", { class: "fields" }, fields)];
  if (example) shown.push(h("p", {}, "Example:"), h("pre", { class: "example" }, JSON.stringify(example, null, 2)));
  return shown;
}

function operation(path, method, op, spec) {
  const params = (op.parameters ?? []).map((p) =>
    h("li", {}, h("code", {}, p.name), ` (${p.in}${p.required ? ", required" : ""}) `, schemaName(p.schema), p.description ? ` — ${p.description}` : ""));
  const body = op.requestBody?.content?.["application/json"]?.schema;
  const responses = Object.entries(op.responses ?? {}).map(([code, r]) => h("li", {}, h("code", {}, code), ` ${r.description ?? ""}`));
  return h("section", { class: "panel operation", dataset: { method, path } },
    h("h3", {}, h("span", { class: `badge method-${method}` }, method.toUpperCase()), " ", h("code", {}, path)),
    op.summary ? h("p", {}, h("strong", {}, op.summary)) : null,
    op.description ? h("p", { class: "description" }, op.description) : null,
    params.length ? [h("h4", {}, "Parameters"), h("ul", {}, params)] : null,
    body ? [h("h4", {}, "Body (JSON, Content-Type: application/json)"), h("p", {}, h("code", {}, schemaName(body))), ...(bodyDetails(body, spec) ?? [])] : null,
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
      for (const [method, op] of Object.entries(methods)) sections.push(operation(path, method, op, spec));
    }
    replace(target, h("p", {}, `${spec.info?.title ?? "API"} ${spec.info?.version ?? ""} — ${spec.info?.description ?? ""}`), sections);
    target.dataset.ready = String(sections.length);
  } catch (err) {
    replace(target, h("p", { role: "alert" }, `Cannot load /openapi.json: ${err.message}`));
  }
}

main();
