// The people panel: where everyone is, whether the assistant believes them available (the
// operator toggles it), what it knows they own, and what it learned during the run.

import { api } from "./api.js";
import { clock, h, keepFocus, replace } from "./dom.js";
import { describeUpdate } from "./timeline.js";

export class PeoplePanel {
  constructor(tbody, learnedList, { onChanged, onError }) {
    this.tbody = tbody;
    this.learnedList = learnedList;
    this.onChanged = onChanged;
    this.onError = onError;
  }

  render(memory) {
    this.renderRows(memory);
    this.renderLearned(memory);
  }

  renderRows(memory) {
    // A row is redrawn only when what it shows changed: a refresh that swapped identical rows
    // would pull a toggle out from under a pointer that is about to press it.
    const kept = new Map([...this.tbody.children].map((row) => [row.dataset.key, row]));
    const rows = memory.people.map((person) => {
      const place = memory.places[person.place] ?? person.place ?? "—";
      const shown = JSON.stringify([person.name, place, person.available, person.items]);
      const old = kept.get(person.id);
      if (old && old.dataset.shown === shown) return old;
      return h("tr", { dataset: { person: person.id, key: person.id, shown } },
        h("th", { scope: "row" }, person.name),
        h("td", {}, place),
        h("td", {}, this.toggle(person)),
        h("td", {}, person.items.length ? person.items.join(", ") : "—"));
    });
    const same = rows.length === this.tbody.children.length && rows.every((row, i) => row === this.tbody.children[i]);
    if (!same) keepFocus(this.tbody, () => replace(this.tbody, rows));
  }

  renderLearned(memory) {
    const learned = memory.updates.filter((u) => u.changed !== false).slice(-50).reverse();
    replace(this.learnedList, learned.length
      ? learned.map((applied) => h("li", {},
        h("strong", {}, describeUpdate(applied.update)),
        applied.instruction_id ? ` (${applied.instruction_id}, ${clock(applied.time)})` : ` (operator, ${clock(applied.time)})`,
        h("span", { class: "evidence" }, `evidence: ${applied.update.evidence}`)))
      : h("li", { class: "hint" }, "Nothing learned yet."));
  }

  toggle(person) {
    const state = person.available === true ? "available" : person.available === false ? "unavailable" : "unknown";
    // A toggle button: pressed = available. Unknown shows as not pressed, styled apart.
    return h("button", {
      type: "button",
      class: `switch ${state === "unknown" ? "unknown" : ""}`,
      "aria-pressed": person.available === true ? "true" : "false",
      "aria-label": `${person.name} is ${state}; set ${person.available === true ? "unavailable" : "available"}`,
      onclick: (event) => this.set(person, person.available !== true, event.currentTarget),
    }, state);
  }

  async set(person, available, button) {
    button.disabled = true;
    try {
      await api(`/v1/people/${encodeURIComponent(person.id)}`, {
        method: "PATCH",
        body: { available, evidence: "set by the operator on the dashboard" },
      });
      await this.onChanged();
      // A change that altered nothing leaves the row as it was, so its button is enabled again.
      button.disabled = false;
      // Keep keyboard focus on the same person's toggle after the table is redrawn.
      this.tbody.querySelector(`tr[data-person="${CSS.escape(person.id)}"] button`)?.focus();
    } catch (err) {
      button.disabled = false;
      this.onError(`Could not change ${person.name}: ${err.message}`);
    }
  }
}
