"""The memory's own graph: networkx's behaviour for what the memory uses, and its node-link
snapshot format, so a snapshot written while the memory was a networkx graph restores."""

from __future__ import annotations

from assistantx.core.office import load_office
from assistantx.memory.belief_graph import BeliefGraph
from assistantx.memory.graph import LongTermMemory

# What networkx 3.6's node_link_data(G, edges="edges") wrote for a desk, then a person at it
# who owns a mug (printed by networkx itself; the shape of every snapshot journaled before
# this graph replaced it).
NETWORKX_SNAPSHOT = {
    "directed": False,
    "multigraph": False,
    "graph": {},
    "nodes": [
        {"kind": "location", "name": "Desk 1", "type": "workstation", "id": "location:desk_01"},
        {"kind": "person", "name": "Lee", "available": "unknown", "lacks": [], "id": "person:lee"},
        {"kind": "item", "type": "mug", "owner": "lee", "holder": "lee", "id": "item:mug:lee"},
    ],
    "edges": [
        {"rel": "at", "source": "location:desk_01", "target": "person:lee"},
        {"rel": "owns", "source": "person:lee", "target": "item:mug:lee"},
    ],
}


def test_edges_are_undirected_and_share_their_attributes() -> None:
    g = BeliefGraph()
    g.add_edge("a", "b", rel="at")
    assert g.has_node("a") and g.has_node("b")
    assert g.edges["b", "a"] is g.edges["a", "b"]
    g.edges["a", "b"]["rel"] = "owns"
    assert g.edges["b", "a"]["rel"] == "owns"
    assert list(g.neighbors("b")) == ["a"]
    g.add_edge("b", "a", extra=1)  # the same edge: attributes updated, not a second edge
    assert len(g.edges) == 1 and g.edges["a", "b"] == {"rel": "owns", "extra": 1}


def test_add_node_updates_and_remove_node_drops_its_edges() -> None:
    g = BeliefGraph()
    g.add_node("a", kind="person")
    g.add_node("a", name="Lee")
    assert g.nodes["a"] == {"kind": "person", "name": "Lee"}
    g.add_edge("a", "b")
    g.add_edge("a", "c")
    g.remove_node("a")
    assert "a" not in g.nodes and list(g.neighbors("b")) == [] and len(g.edges) == 0
    g.add_edge("b", "c")
    g.remove_edge("c", "b")
    assert ("b", "c") not in g.edges and g.has_node("b")
    assert dict(g.nodes(data=True)) == {"b": {}, "c": {}}


def test_a_networkx_snapshot_reads_back_and_is_written_the_same() -> None:
    g = BeliefGraph.from_node_link_data(NETWORKX_SNAPSHOT)
    assert g.nodes["person:lee"]["name"] == "Lee"
    assert g.edges["location:desk_01", "person:lee"] == {"rel": "at"}
    assert g.node_link_data() == NETWORKX_SNAPSHOT


def test_the_office_memory_round_trips_through_its_snapshot() -> None:
    office = load_office()
    memory = LongTermMemory(office)
    restored = LongTermMemory.restore(office, memory.snapshot())
    assert restored.snapshot() == memory.snapshot()
    assert restored.graph.number_of_nodes() == memory.graph.number_of_nodes()
