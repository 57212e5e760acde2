// The locker: door and lock state, what it holds, the codes recent instructions issued, and
// the operator's stand-in for a person at the locker (scan a code, shut the door).

import { api } from "./api.js";
import { badge, h, keepFocus, replace } from "./dom.js";

export class LockerPanel {
  constructor(stateList, codesList, { onChanged, onError, announce }) {
    Object.assign(this, { stateList, codesList, onChanged, onError, announce });
  }

  async refresh() {
    const [status, codes] = await Promise.all([
      api("/v1/locker"),
      api("/v1/locker/codes").catch((err) => (err.status === 403 ? null : Promise.reject(err))),
    ]);
    replace(this.stateList,
      h("dt", {}, "Door"), h("dd", { id: "locker-door" }, badge(status.door, status.door === "open" ? "unachievable" : "")),
      h("dt", {}, "Lock"), h("dd", {}, status.locked ? "locked" : "released"),
      h("dt", {}, "Active codes"), h("dd", {}, String(status.active_codes)),
      h("dt", {}, "Contents"), h("dd", {}, status.contents?.length ? status.contents.join(", ") : "empty"),
      status.door === "open" ? [h("dt", {}, ""), h("dd", {}, h("button", { type: "button", class: "secondary", onclick: () => this.close() }, "Close door"))] : null);
    if (codes === null) {
      replace(this.codesList, h("li", { class: "hint" }, "Codes are shown to the operator."));
      return;
    }
    keepFocus(this.codesList, () => replace(this.codesList, codes.length ? codes.map((code) => h("li", { dataset: { code: code.code_id, key: code.code_id } },
      h("span", { class: "what" }, `${code.person_name}: ${code.task}`),
      badge(code.state, { used: "done", scanned: "running", revoked: "failed" }[code.state] ?? "queued"),
      code.scannable && code.state === "issued"
        ? h("button", { type: "button", onclick: (e) => this.scan(code, e.currentTarget), "aria-label": `Scan ${code.person_name}'s code to ${code.task}` }, "Scan")
        : null))
      : h("li", { class: "hint" }, "No codes issued yet.")));
  }

  async scan(code, button) {
    button.disabled = true;
    try {
      const event = await api("/v1/locker/scan", { method: "POST", body: { code_id: code.code_id } });
      this.announce(event.kind === "code_accepted"
        ? `Locker accepted ${code.person_name}'s code: the door is open.`
        : `Locker rejected the code (${event.reason ?? "rejected"}).`);
      await this.onChanged();
    } catch (err) {
      button.disabled = false;
      this.onError(`Scan failed: ${err.message}`);
    }
  }

  async close() {
    try {
      await api("/v1/locker/close", { method: "POST" });
      this.announce("The locker's door is closed.");
      await this.onChanged();
    } catch (err) {
      this.onError(`Could not close the door: ${err.message}`);
    }
  }
}
