"""The undirected, attributed graph the long-term memory keeps: nodes and edges with a dict
of attributes each, and node-link JSON for snapshots.

It offers the part of networkx's ``Graph`` the memory uses, spelled the same way
(``nodes(data=True)``, ``nodes[n]``, ``edges[u, v]``, ``neighbors``, ``add_node``,
``add_edge``, ``remove_node``, ``remove_edge``, ``has_node``), and reads and writes the same
node-link format (``{"directed", "multigraph", "graph", "nodes": [{"id", ...}], "edges":
[{"source", "target", ...}]}``), so snapshots written before it restore unchanged. networkx
itself cost a third of a CPU-second to import in every command that shows the office.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

Attributes = dict[str, Any]


class NodeView:
    """``graph.nodes``: iterate node names, ``nodes[n]`` for the attributes, ``nodes(data=True)``
    for (name, attributes) pairs."""

    def __init__(
        self,
        adjacency: dict[str, dict[str, Attributes]],
        attrs: dict[str, Attributes],
    ) -> None:
        self._adjacency = adjacency
        self._attrs = attrs

    def __call__(self, data: bool = False) -> Iterator[Any]:
        return iter(self._attrs.items()) if data else iter(self._attrs)

    def __getitem__(self, node: str) -> Attributes:
        return self._attrs[node]

    def __iter__(self) -> Iterator[str]:
        return iter(self._attrs)

    def __contains__(self, node: object) -> bool:
        return node in self._attrs

    def __len__(self) -> int:
        return len(self._attrs)


class EdgeView:
    """``graph.edges[u, v]``: the attributes of the edge between u and v (either order)."""

    def __init__(self, adjacency: dict[str, dict[str, Attributes]]) -> None:
        self._adjacency = adjacency

    def __getitem__(self, pair: tuple[str, str]) -> Attributes:
        u, v = pair
        return self._adjacency[u][v]

    def __contains__(self, pair: object) -> bool:
        if not isinstance(pair, tuple) or len(pair) != 2:
            return False
        u, v = pair
        return u in self._adjacency and v in self._adjacency[u]

    def __len__(self) -> int:
        return sum(len(nbrs) for nbrs in self._adjacency.values()) // 2

    def __iter__(self) -> Iterator[tuple[str, str]]:
        seen: set[str] = set()
        for u, nbrs in self._adjacency.items():
            for v in nbrs:
                if v not in seen:
                    yield u, v
            seen.add(u)


class BeliefGraph:
    def __init__(self) -> None:
        self._attrs: dict[str, Attributes] = {}
        self._adjacency: dict[str, dict[str, Attributes]] = {}
        self.nodes = NodeView(self._adjacency, self._attrs)
        self.edges = EdgeView(self._adjacency)

    def add_node(self, node: str, **attrs: Any) -> None:
        """Add ``node``, or update its attributes when it is there."""
        if node not in self._attrs:
            self._attrs[node] = {}
            self._adjacency[node] = {}
        self._attrs[node].update(attrs)

    def add_edge(self, u: str, v: str, **attrs: Any) -> None:
        """Join u and v (adding either when missing), or update the edge's attributes."""
        for node in (u, v):
            if node not in self._attrs:
                self.add_node(node)
        data = self._adjacency[u].get(v)
        if data is None:
            data = {}
            self._adjacency[u][v] = data
            self._adjacency[v][u] = data  # one dict for both directions
        data.update(attrs)

    def remove_node(self, node: str) -> None:
        for other in self._adjacency.pop(node):
            if other != node:
                del self._adjacency[other][node]
        del self._attrs[node]

    def remove_edge(self, u: str, v: str) -> None:
        del self._adjacency[u][v]
        if u != v:
            del self._adjacency[v][u]

    def has_node(self, node: str) -> bool:
        return node in self._attrs

    def neighbors(self, node: str) -> Iterator[str]:
        return iter(self._adjacency[node])

    def number_of_nodes(self) -> int:
        return len(self._attrs)

    # -- node-link JSON (networkx's format) ----------------------------------------------
    def node_link_data(self) -> dict[str, Any]:
        return {
            "directed": False,
            "multigraph": False,
            "graph": {},
            "nodes": [{**attrs, "id": node} for node, attrs in self._attrs.items()],
            "edges": [{**self.edges[u, v], "source": u, "target": v} for u, v in self.edges],
        }

    @classmethod
    def from_node_link_data(cls, data: dict[str, Any]) -> BeliefGraph:
        if data.get("directed") or data.get("multigraph"):
            raise ValueError("the memory graph is undirected and simple")
        graph = cls()
        for entry in data["nodes"]:
            attrs = {k: v for k, v in entry.items() if k != "id"}
            graph.add_node(entry["id"], **attrs)
        for entry in data["edges"]:
            attrs = {k: v for k, v in entry.items() if k not in ("source", "target")}
            graph.add_edge(entry["source"], entry["target"], **attrs)
        return graph
