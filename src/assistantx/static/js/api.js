// The REST API with the bearer token kept in localStorage.

const TOKEN_KEY = "assistantx.token";
const OFFICE_KEY = "assistantx.office";

export class ApiError extends Error {
  constructor(status, message) {
    super(message);
    this.status = status;
  }
}

export const token = {
  get: () => localStorage.getItem(TOKEN_KEY) ?? "",
  set: (value) => localStorage.setItem(TOKEN_KEY, value.trim()),
  clear: () => localStorage.removeItem(TOKEN_KEY),
};

// The office the page shows, in a deployment of several (none: the single office's own paths).
export const office = {
  get: () => localStorage.getItem(OFFICE_KEY) ?? "",
  set: (value) => localStorage.setItem(OFFICE_KEY, value),
  clear: () => localStorage.removeItem(OFFICE_KEY),
};

/** The chosen office's path for an API path: "/v1/robot" → "/v1/offices/ID/robot". */
export function scoped(path) {
  const id = office.get();
  if (!id || path.startsWith("/v1/offices")) return path;
  const prefix = `/v1/offices/${encodeURIComponent(id)}`;
  if (path.startsWith("/v1/")) return `${prefix}/${path.slice(4)}`;
  if (path === "/readyz" || path === "/metrics") return `${prefix}${path}`;
  return path;
}

const unauthorizedListeners = [];

/** Called with the ApiError whenever the API answers 401 (a missing or stale token). */
export function onUnauthorized(listener) {
  unauthorizedListeners.push(listener);
}

export function authHeaders(extra = {}) {
  const value = token.get();
  return value ? { ...extra, Authorization: `Bearer ${value}` } : { ...extra };
}

/** FastAPI errors carry "detail": a string, or a list of validation errors. */
function describe(status, body) {
  const detail = body && typeof body === "object" ? body.message ?? body.detail ?? body.error : body;
  if (Array.isArray(detail)) {
    return detail.map((d) => `${(d.loc ?? []).slice(1).join(".") || "body"}: ${d.msg}`).join("; ");
  }
  if (typeof detail === "string" && detail) return detail;
  return `HTTP ${status}`;
}

/** fetch a JSON API path; throws ApiError with the server's own message on failure. */
export async function api(path, { method = "GET", body, signal } = {}) {
  const headers = authHeaders({ Accept: "application/json" });
  const init = { method, headers, signal };
  if (body !== undefined) {
    headers["Content-Type"] = "application/json";
    init.body = JSON.stringify(body);
  }
  let response;
  try {
    response = await fetch(scoped(path), init);
  } catch (err) {
    if (err.name === "AbortError") throw err;
    throw new ApiError(0, "the server cannot be reached");
  }
  const text = await response.text();
  let data = null;
  if (text) {
    try {
      data = JSON.parse(text);
    } catch {
      data = text;
    }
  }
  if (!response.ok) {
    const error = new ApiError(response.status, describe(response.status, data));
    if (response.status === 401) unauthorizedListeners.forEach((listener) => listener(error));
    throw error;
  }
  return data;
}
