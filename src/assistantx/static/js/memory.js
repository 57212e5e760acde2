// The assistant's belief from GET /v1/memory (node-link graph + applied updates), reshaped for
// the people table, the map and the chat pickers.

const bare = (node) => node.slice(node.indexOf(":") + 1);

/**
 * {people: [{id, name, place, available: true|false|null, observedAt, items: [type], groups}],
 *  groups: {id: {name, members}}, places: {id: name}, updates: [AppliedUpdate]}
 */
export function readMemory(snapshot) {
  const { nodes, edges } = snapshot.graph;
  const byId = new Map(nodes.map((n) => [n.id, n]));
  const people = new Map();
  const groups = {};
  const places = {};
  for (const node of nodes) {
    if (node.kind === "person") {
      people.set(node.id, {
        id: bare(node.id),
        name: node.name ?? bare(node.id),
        place: null,
        available: node.available === "available" ? true : node.available === "unavailable" ? false : null,
        observedAt: node.observed_at ?? null,
        items: [],
        groups: [],
      });
    } else if (node.kind === "group") {
      groups[bare(node.id)] = { name: node.name ?? bare(node.id), members: [] };
    } else if (node.kind === "location") {
      places[bare(node.id)] = node.name ?? bare(node.id);
    }
  }
  for (const { source, target, rel } of edges) {
    const [personNode, other] = people.has(source) ? [source, target] : [target, source];
    const person = people.get(personNode);
    if (!person) continue;
    const node = byId.get(other);
    if (rel === "at" && node?.kind === "location") person.place = bare(other);
    else if (rel === "owns" && node?.kind === "item") person.items.push(node.type);
    else if (rel === "member" && node?.kind === "group") {
      person.groups.push(bare(other));
      groups[bare(other)]?.members.push(person.id);
    }
  }
  const list = [...people.values()];
  list.forEach((p) => p.items.sort());
  list.sort((a, b) => a.name.localeCompare(b.name));
  return { people: list, groups, places, updates: snapshot.updates ?? [] };
}
