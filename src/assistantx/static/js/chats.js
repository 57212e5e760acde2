// The built-in messenger's transcripts (DMs and groups), and a box to answer as a person, so
// someone can play a colleague in the demo. A reply answers the chat's latest open question.

import { api } from "./api.js";
import { clock, h, keepScrolledToEnd, replace } from "./dom.js";

const chatKey = (chat) => `${chat.kind}/${chat.id}`;

export class ChatsPanel {
  constructor({ select, transcript, form, sender, text, status }, { onError }) {
    Object.assign(this, { select, transcript, form, sender, text, status, onError });
    this.chats = [];
    this.memory = null;
    this.messages = [];
    this.selected = null;
    select.addEventListener("change", () => this.choose(select.value));
    form.addEventListener("submit", (event) => {
      event.preventDefault();
      this.send();
    });
  }

  setMemory(memory) {
    this.memory = memory;
    this.fillSenders();
  }

  nameOf(id) {
    if (id === "assistant") return "Assistant";
    return this.memory?.people.find((p) => p.id === id)?.name ?? id;
  }

  chatLabel(chat) {
    if (chat.kind === "dm") return `DM: ${this.nameOf(chat.id)}`;
    return `Group: ${this.memory?.groups[chat.id]?.name ?? chat.id}`;
  }

  async refresh() {
    const chats = await api("/v1/chats");
    chats.sort((a, b) => b.last_time - a.last_time);
    this.chats = chats;
    const keys = chats.map(chatKey);
    if (!this.selected || !keys.includes(this.selected)) this.selected = keys[0] ?? null;
    const previous = this.select.value;
    replace(this.select, chats.length
      ? chats.map((c) => h("option", { value: chatKey(c), selected: chatKey(c) === this.selected }, `${this.chatLabel(c)} (${c.messages})`))
      : h("option", { value: "" }, "No chats yet"));
    this.select.value = this.selected ?? "";
    if (previous !== this.select.value) this.fillSenders();
    await this.load();
  }

  async choose(key) {
    this.selected = key;
    this.messages = [];
    this.fillSenders();
    await this.load();
  }

  /** The people who may write in the selected chat: the DM's person, or a group's members. */
  fillSenders() {
    if (!this.memory) return;
    const [kind, id] = (this.selected ?? "").split("/");
    let ids = this.memory.people.map((p) => p.id);
    if (kind === "dm") ids = [id];
    else if (kind === "group") ids = this.memory.groups[id]?.members ?? ids;
    const keep = this.sender.value;
    replace(this.sender, ids.map((pid) => h("option", { value: pid }, this.nameOf(pid))));
    if (ids.includes(keep)) this.sender.value = keep;
  }

  async load() {
    if (!this.selected) {
      replace(this.transcript, h("li", { class: "hint" }, "No messages yet."));
      return;
    }
    const [kind, id] = this.selected.split("/");
    const messages = await api(`/v1/chats/${kind}/${encodeURIComponent(id)}?limit=500`);
    this.messages = messages;
    keepScrolledToEnd(this.transcript, () => replace(this.transcript, messages.map((m) => this.item(m))));
  }

  item(m) {
    const fromAssistant = m.direction === "out";
    const attachments = (m.attachments ?? []).map((a) => h("span", { class: "hint" }, ` [attached: ${a.name ?? a.item ?? "file"}]`));
    return h("li", { class: `msg ${fromAssistant ? "assistant" : "person"}`, dataset: { seq: m.seq } },
      h("span", { class: "who" }, `${this.nameOf(m.sender)} · ${clock(m.time)}${m.question_id ? " · question" : ""}`),
      h("span", { class: "text" }, m.text), attachments);
  }

  /** The newest question the assistant asked in this chat that nobody answered yet. */
  openQuestion() {
    const answered = new Set(this.messages.filter((m) => m.in_reply_to).map((m) => m.in_reply_to));
    const asked = this.messages.filter((m) => m.direction === "out" && m.question_id && !answered.has(m.question_id));
    return asked.at(-1)?.question_id ?? null;
  }

  async send() {
    const text = this.text.value.trim();
    if (!text || !this.selected) return;
    const [kind, id] = this.selected.split("/");
    const body = { sender: this.sender.value, text };
    if (kind === "group") body.group = id;
    const question = this.openQuestion();
    if (question) body.in_reply_to = question;
    this.status.textContent = "Sending…";
    try {
      await api("/v1/messages", { method: "POST", body });
      this.text.value = "";
      this.status.textContent = `Sent as ${this.nameOf(body.sender)}.`;
      await this.load();
    } catch (err) {
      this.status.textContent = "";
      this.onError(`Message not sent: ${err.message}`);
    }
  }
}
