/* A* over the 8-connected traversable cells of a costmap, for nav/grid_astar.py (ctypes).
 *
 * The graph is the one nav/planner.py's Dijkstra searches: a cell is a node when its cost is
 * below `inscribed`; a diagonal move needs both side cells traversable (no corner cutting);
 * an edge from u to v weighs  length * (1 + penalty * ((c_u + c_v) / 2) / (inscribed - 1)),
 * computed in that order so a path's cost is the same sum Dijkstra makes.
 *
 * Every edge weighs at least its grid length, so the octile distance times the resolution
 * never overestimates what is left: the first time the goal leaves the queue its cost is
 * optimal. A node whose cost improves after it left the queue is queued again, so rounding
 * in the heuristic cannot cost optimality either.
 *
 * Built by setuptools as an extension module (PyInit below makes it importable, which is how
 * Python finds the file); the search itself is called through ctypes with numpy's buffers.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

typedef struct {
    double f;
    double g;
    int32_t node;
} entry;

/* A binary heap of open cells that knows where each cell sits (`where`, -1: not queued), so
 * a cell reached cheaper moves up in place instead of being queued twice. */
typedef struct {
    entry *items;
    int32_t *where;
    size_t size;
    size_t capacity;
} heap;

/* Lower f first; among equal f the deeper entry (higher g), which heads straight for the goal. */
static int before(const entry *a, const entry *b) {
    if (a->f != b->f) return a->f < b->f;
    return a->g > b->g;
}

static void sift_up(heap *h, size_t i, entry e) {
    while (i > 0) {
        size_t parent = (i - 1) / 2;
        if (!before(&e, &h->items[parent])) break;
        h->items[i] = h->items[parent];
        h->where[h->items[i].node] = (int32_t)i;
        i = parent;
    }
    h->items[i] = e;
    h->where[e.node] = (int32_t)i;
}

/* Queue `e`, or lower its node's entry to `e` when the node is queued already. */
static int heap_push(heap *h, entry e) {
    int32_t at = h->where[e.node];
    if (at >= 0) {
        sift_up(h, (size_t)at, e);
        return 0;
    }
    if (h->size == h->capacity) {
        size_t capacity = h->capacity ? h->capacity * 2 : 1024;
        entry *grown = realloc(h->items, capacity * sizeof(entry));
        if (!grown) return -1;
        h->items = grown;
        h->capacity = capacity;
    }
    sift_up(h, h->size++, e);
    return 0;
}

static entry heap_pop(heap *h) {
    entry top = h->items[0];
    h->where[top.node] = -1;
    entry last = h->items[--h->size];
    if (!h->size) return top;
    size_t i = 0;
    for (;;) {
        size_t child = 2 * i + 1;
        if (child >= h->size) break;
        if (child + 1 < h->size && before(&h->items[child + 1], &h->items[child])) child++;
        if (!before(&h->items[child], &last)) break;
        h->items[i] = h->items[child];
        h->where[h->items[i].node] = (int32_t)i;
        i = child;
    }
    h->items[i] = last;
    h->where[last.node] = (int32_t)i;
    return top;
}

static double octile(int32_t dy, int32_t dx) {
    double ay = fabs((double)dy), ax = fabs((double)dx);
    double lo = ay < ax ? ay : ax, hi = ay < ax ? ax : ay;
    return hi + (M_SQRT2 - 1.0) * lo;
}

/* Search from `start` to `goal` (flat cell indices). `g` (doubles), `parent` and `where`
 * (int32) hold one entry per cell; they are valid for a cell only where `stamp` equals
 * `generation` (a new number per search), so a search touches only the cells it reaches
 * instead of clearing the whole grid first: on a big map with a small free area the
 * clearing was most of the search. Returns the path's cost, -1.0 when the goal cannot
 * be reached, -2.0 when memory ran out. */
double grid_astar(const uint8_t *costs, int32_t height, int32_t width, int32_t inscribed,
                  double resolution, double penalty, int32_t start, int32_t goal, double *g,
                  int32_t *parent, int32_t *where, uint32_t *stamp, uint32_t generation) {
    static const int32_t DY[8] = {-1, -1, -1, 0, 0, 1, 1, 1};
    static const int32_t DX[8] = {-1, 0, 1, -1, 1, -1, 0, 1};
    const int32_t gy = goal / width, gx = goal % width;
    double lengths[8];
    for (int k = 0; k < 8; k++) lengths[k] = resolution * ((DY[k] && DX[k]) ? M_SQRT2 : 1.0);
#define TOUCH(v)                  \
    if (stamp[v] != generation) { \
        stamp[v] = generation;    \
        g[v] = INFINITY;          \
        where[v] = -1;            \
    }
    TOUCH(start);

    heap open = {NULL, where, 0, 0};
    g[start] = 0.0;
    parent[start] = -1;
    entry first = {resolution * octile(start / width - gy, start % width - gx), 0.0, start};
    if (heap_push(&open, first) < 0) return -2.0;
    double found = -1.0;
    while (open.size) {
        entry e = heap_pop(&open);
        if (e.node == goal) {
            found = e.g;
            break;
        }
        const int32_t y = e.node / width, x = e.node % width;
        const double c_u = (double)costs[e.node];
        for (int k = 0; k < 8; k++) {
            const int32_t ny = y + DY[k], nx = x + DX[k];
            if (ny < 0 || ny >= height || nx < 0 || nx >= width) continue;
            const int32_t v = ny * width + nx;
            if (costs[v] >= inscribed) continue;
            if (DY[k] && DX[k] &&
                (costs[ny * width + x] >= inscribed || costs[y * width + nx] >= inscribed))
                continue;
            const double mean = (c_u + (double)costs[v]) / 2.0;
            const double weight = lengths[k] * (1.0 + penalty * mean / (double)(inscribed - 1));
            const double candidate = e.g + weight;
            TOUCH(v);
            if (candidate < g[v]) {
                g[v] = candidate;
                parent[v] = e.node;
                entry next = {candidate + resolution * octile(ny - gy, nx - gx), candidate, v};
                if (heap_push(&open, next) < 0) {
                    free(open.items);
                    return -2.0;
                }
            }
        }
    }
    free(open.items);
    return found;
#undef TOUCH
}

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "_grid_astar", NULL, -1, NULL};

PyMODINIT_FUNC PyInit__grid_astar(void) { return PyModule_Create(&module); }
