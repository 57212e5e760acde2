/* A* over the 8-connected traversable cells of a costmap, for nav/grid_astar.py (ctypes).
 *
 * The graph is the one nav/planner.py's Dijkstra searches: a cell is a node when its cost is
 * below `inscribed`; a diagonal move needs both side cells traversable (no corner cutting);
 * an edge from u to v weighs  length * (1 + penalty * ((c_u + c_v) / 2) / (inscribed - 1)),
 * computed in that order so a path's cost is the same sum Dijkstra makes.
 *
 * Every edge weighs at least its grid length, so the octile distance times the resolution
 * never overestimates what is left; nor does the landmark bound (nav/landmarks.py: each
 * cell's cost from a few landmarks, measured by grid_distances below), less a slack for its
 * single precision. The heuristic is the larger of the two, so the first time the goal
 * leaves the queue its cost is optimal. A node whose cost improves after it left the queue
 * is queued again, so rounding in the heuristic cannot cost optimality either.
 *
 * grid_plan adds the path's cells and the planner's line-of-sight smoothing (planner.shortcut,
 * the same steps and the same samples) in the same call: done in Python, with a call per
 * step, they cost more than the search itself on a small floor.
 *
 * Built by setuptools as an extension module (PyInit below makes it importable, which is how
 * Python finds the file); the search itself is called through ctypes with numpy's buffers.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

/* A queued cell: its f = g + h, and g again in single precision, only to break ties (the
 * exact g is the cell's own): 16 bytes, so a queue step moves less. */
typedef struct {
    double f;
    float g;
    int32_t node;
} entry;

/* What a search keeps per cell, side by side in 16 bytes so a cell it reaches costs a quarter
 * of a cache line, not a line per array: the cost so far, its place in the queue (-1: not
 * queued), and in `tag` the search that wrote them (its generation, above the low 3 bits:
 * they count where it is the current one) and the move it was reached by (low 3 bits, an
 * index into DY/DX: the parent is one step back). */
typedef struct {
    double g;
    int32_t where;
    uint32_t tag;
} cell_state;
_Static_assert(sizeof(cell_state) == 16, "grid_astar.py allocates 16 bytes a cell");

static const int32_t DY[8] = {-1, -1, -1, 0, 0, 1, 1, 1};
static const int32_t DX[8] = {-1, 0, 1, -1, 1, -1, 0, 1};

/* A binary heap of open cells that knows where each cell sits (`where`), so a cell reached
 * cheaper moves up in place instead of being queued twice. */
typedef struct {
    entry *items;
    cell_state *cells;
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
        h->cells[h->items[i].node].where = (int32_t)i;
        i = parent;
    }
    h->items[i] = e;
    h->cells[e.node].where = (int32_t)i;
}

/* Queue `e`, or lower its node's entry to `e` when the node is queued already. */
static int heap_push(heap *h, entry e) {
    int32_t at = h->cells[e.node].where;
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
    h->cells[top.node].where = -1;
    entry last = h->items[--h->size];
    if (!h->size) return top;
    size_t i = 0;
    for (;;) {
        size_t child = 2 * i + 1;
        if (child >= h->size) break;
        if (child + 1 < h->size && before(&h->items[child + 1], &h->items[child])) child++;
        if (!before(&h->items[child], &last)) break;
        h->items[i] = h->items[child];
        h->cells[h->items[i].node].where = (int32_t)i;
        i = child;
    }
    h->items[i] = last;
    h->cells[last.node].where = (int32_t)i;
    return top;
}

static double octile(int32_t dy, int32_t dx) {
    double ay = fabs((double)dy), ax = fabs((double)dx);
    double lo = ay < ax ? ay : ax, hi = ay < ax ? ax : ay;
    return hi + (M_SQRT2 - 1.0) * lo;
}

/* How far a landmark's stored distance may be off, relative to the distances compared: they
 * are kept in single precision (2**-24 each) from sums in double precision. */
#define MARK_SLACK (1.0 / (1 << 22))

/* A lower bound on the cost from a cell to the goal: the octile distance (`scale`: the
 * resolution, 0 for none), and with landmarks (`here`, `there`: the cell's and the goal's
 * distances from each of `n` landmarks, negative where unreached) the landmark bound
 * |d(L, goal) - d(L, cell)|, which the triangle inequality makes no more than the path
 * between them, less a slack for the rounding of the stored distances. */
static inline double estimate(int32_t dy, int32_t dx, double scale, const float *here,
                              const float *there, int32_t n) {
    double best = scale * octile(dy, dx);
    if (here) {
        for (int32_t k = 0; k < n; k++) {
            if (here[k] < 0.0f || there[k] < 0.0f) continue;
            const double a = (double)here[k], b = (double)there[k];
            const double bound = fabs(a - b) - (a + b) * MARK_SLACK;
            if (bound > best) best = bound;
        }
    }
    return best;
}

/* Search from `start` to `goal` (flat cell indices). `cells` holds one cell_state per cell;
 * a state is valid only where its tag's generation is `generation` (a new number per search,
 * below 2**29), so a search touches only the cells it reaches instead of clearing the whole
 * grid first: on a big map with a small free area the clearing was most of the search.
 * Returns the path's cost, -1.0 when the goal cannot be reached, -2.0 when memory ran out. */
/* The cost of the move `k` from (y, x), whose cost is c_u, to its neighbour v; negative when
 * the move is not allowed (off the grid, into an inscribed cell, or a diagonal that cuts a
 * blocked corner). One definition for the A* and the landmarks' Dijkstra, so both price a
 * move to the same bits. */
static inline double step_cost(const uint8_t *costs, int32_t height, int32_t width,
                               int32_t inscribed, double penalty, const double *lengths,
                               int32_t y, int32_t x, double c_u, int k, int32_t *v_out) {
    const int32_t ny = y + DY[k], nx = x + DX[k];
    if (ny < 0 || ny >= height || nx < 0 || nx >= width) return -1.0;
    const int32_t v = ny * width + nx;
    if (costs[v] >= inscribed) return -1.0;
    if (DY[k] && DX[k] &&
        (costs[ny * width + x] >= inscribed || costs[y * width + nx] >= inscribed))
        return -1.0;
    const double mean = (c_u + (double)costs[v]) / 2.0;
    *v_out = v;
    return lengths[k] * (1.0 + penalty * mean / (double)(inscribed - 1));
}

static double grid_astar_search(const uint8_t *costs, int32_t height, int32_t width,
                         int32_t inscribed, double resolution, double penalty, int32_t start,
                         int32_t goal, cell_state *cells, uint32_t generation,
                         const float *marks, int32_t n_marks) {
    const int32_t gy = goal >= 0 ? goal / width : 0, gx = goal >= 0 ? goal % width : 0;
    const double scale = goal >= 0 ? resolution : 0.0; /* no goal: no heuristic (Dijkstra) */
    const float *goal_marks = (goal >= 0 && n_marks > 0) ? marks + (size_t)goal * n_marks : NULL;
    double lengths[8];
    for (int k = 0; k < 8; k++) lengths[k] = resolution * ((DY[k] && DX[k]) ? M_SQRT2 : 1.0);
#define TOUCH(v)                  \
    if (cells[v].tag >> 3 != generation) { \
        cells[v].tag = generation << 3;       \
        cells[v].g = INFINITY;             \
        cells[v].where = -1;               \
    }
    TOUCH(start);

    heap open = {NULL, cells, 0, 0};
    cells[start].g = 0.0;
    entry first = {estimate(start / width - gy, start % width - gx, scale,
                            goal_marks ? marks + (size_t)start * n_marks : NULL, goal_marks,
                            n_marks),
                   0.0, start};
    if (heap_push(&open, first) < 0) return -2.0;
    double found = -1.0;
    while (open.size) {
        entry e = heap_pop(&open);
        if (e.node == goal) {
            found = cells[goal].g;
            break;
        }
        const int32_t y = e.node / width, x = e.node % width;
        const double c_u = (double)costs[e.node], g_u = cells[e.node].g;
        for (int k = 0; k < 8; k++) {
            int32_t v = 0;
            const double weight =
                step_cost(costs, height, width, inscribed, penalty, lengths, y, x, c_u, k, &v);
            if (weight < 0.0) continue;
            const int32_t ny = y + DY[k], nx = x + DX[k];
            const double candidate = g_u + weight;
            TOUCH(v);
            if (candidate < cells[v].g) {
                cells[v].g = candidate;
                cells[v].tag = (generation << 3) | (uint32_t)k;
                const double h = estimate(ny - gy, nx - gx, scale,
                                          goal_marks ? marks + (size_t)v * n_marks : NULL,
                                          goal_marks, n_marks);
                entry next = {candidate + h, (float)candidate, v};
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

/* The cell `v` was reached from: one step back along the move in its tag. */
static int32_t parent_of(const cell_state *cells, int32_t width, int32_t v) {
    const uint32_t k = cells[v].tag & 7u;
    return v - DY[k] * width - DX[k];
}

/* The cells of the path a search found, from `start` to `goal`, by `parent` (flat indices).
 * Writes them to `out` when they fit in `capacity`; returns their number either way. */
static int32_t grid_path(const cell_state *cells, int32_t width, int32_t start, int32_t goal,
                         int32_t *out, int32_t capacity) {
    int32_t count = 1;
    for (int32_t v = goal; v != start; v = parent_of(cells, width, v)) count++;
    if (count > capacity) return count;
    int32_t i = count;
    for (int32_t v = goal; v != start; v = parent_of(cells, width, v)) out[--i] = v;
    out[0] = start;
    return count;
}

static int32_t clamp_cell(double v, int32_t size) {
    double cell = floor(v);
    if (cell < 0.0) cell = 0.0;
    if (cell > (double)(size - 1)) cell = (double)(size - 1);
    return (int32_t)cell;
}

/* The costs a plan searches: a box of the map's grid (all of it, or the box round its
 * traversable cells, whose costs the planner keeps as an array of their own), at row0, col0
 * of the map's full_height x full_width cells. */
typedef struct {
    const uint8_t *costs;
    int32_t height, width, row0, col0, full_height, full_width;
} view;

/* The cost under a point of the map's grid frame (cell units), clamped to the map as
 * planner.shortcut clamps it. Outside the box it is NO_INFORMATION: every cell there is
 * untraversable (at least inscribed), and the smoothing only asks whether a cost is below
 * inscribed, so the answers are the map's own. */
static int32_t cost_at(const view *w, double gx, double gy) {
    const int32_t ix = clamp_cell(gx, w->full_width) - w->col0;
    const int32_t iy = clamp_cell(gy, w->full_height) - w->row0;
    if (ix < 0 || ix >= w->width || iy < 0 || iy >= w->height) return 255;
    return (int32_t)w->costs[(int64_t)iy * w->width + ix];
}

/* Whether every sample of the segment a-b (grid frame, cell units), taken every half cell,
 * costs at most `allowed`: planner._segment_max_cost(...) <= allowed, sample for sample. */
static int segment_within(const view *w, double ax, double ay, double bx, double by,
                          int32_t allowed) {
    const double dx = bx - ax, dy = by - ay;
    int64_t n = (int64_t)ceil(hypot(dx, dy) * 2.0) + 1;
    if (n < 2) n = 2;
    for (int64_t i = 0; i < n; i++) {
        const double t = (double)i / (double)(n - 1);
        if (cost_at(w, ax + t * dx, ay + t * dy) > allowed) return 0;
    }
    return 1;
}

/* Greedy line-of-sight shortcuts over the waypoints (xs[i], ys[i]) (grid frame, cell units),
 * `along[i]` the cost under each: from each kept waypoint, a binary search for the farthest
 * one whose segment costs at most the highest cost the path met in between plus a slack of
 * 10 (capped below `inscribed`). Writes the kept waypoints' indices to `kept` (room for n)
 * and returns their number. */
static int32_t shortcut(const view *w, int32_t inscribed, const double *xs, const double *ys,
                        const int32_t *along, int32_t n, int32_t *kept) {
    int32_t count = 0;
    kept[count++] = 0;
    int32_t i = 0;
    while (i < n - 1) {
        int32_t lo = i + 1, hi = n - 1, best = lo;
        while (lo <= hi) {
            const int32_t mid = lo + (hi - lo) / 2;
            int32_t highest = along[i];
            for (int32_t j = i + 1; j <= mid; j++)
                if (along[j] > highest) highest = along[j];
            int32_t allowed = highest + 10;
            if (allowed > inscribed - 1) allowed = inscribed - 1;
            if (segment_within(w, xs[i], ys[i], xs[mid], ys[mid], allowed)) {
                best = mid;
                lo = mid + 1;
            } else {
                hi = mid - 1;
            }
        }
        kept[count++] = best;
        i = best;
    }
    return count;
}

/* The map's frame, as occupancy_map.OccupancyMap has it: the origin (m), its yaw's cosine
 * and sine (rotated: whether the yaw is not zero), the resolution (m per cell). */
typedef struct {
    double origin_x, origin_y, cos_yaw, sin_yaw, rotated, resolution;
} frame;

/* A world point (m) in the grid's frame in cell units: to_grid_frame(x, y) / resolution,
 * the same operations in the same order, so the same doubles. */
static void to_cells(const frame *f, double x, double y, double *gx, double *gy) {
    const double dx = x - f->origin_x, dy = y - f->origin_y;
    if (f->rotated == 0.0) {
        *gx = dx / f->resolution;
        *gy = dy / f->resolution;
    } else {
        *gx = (f->cos_yaw * dx + f->sin_yaw * dy) / f->resolution;
        *gy = (-f->sin_yaw * dx + f->cos_yaw * dy) / f->resolution;
    }
}

/* Smooth the path `cells` (n flat cells of the box) in place: the robot's exact start and
 * goal (world m) stand for the first and last cell, every other cell for its centre
 * (cell_to_world, on the map's grid), as planner.shortcut sees them. Leaves the kept cells
 * first in `cells`; returns their number, -1 when memory ran out. */
static int32_t smooth(const view *w, int32_t inscribed, const frame *f, const double ends[4],
                      int32_t *cells, int32_t n) {
    double *xs = malloc((size_t)n * 2 * sizeof(double));
    int32_t *along = malloc((size_t)n * 2 * sizeof(int32_t));
    if (!xs || !along) {
        free(xs);
        free(along);
        return -1;
    }
    double *ys = xs + n;
    int32_t *kept = along + n;
    for (int32_t i = 0; i < n; i++) {
        double x, y;
        if (i == 0 || i == n - 1) {
            x = ends[i == 0 ? 0 : 2];
            y = ends[i == 0 ? 1 : 3];
        } else { /* cell_to_world: the centre's world point, then back as to_cells does */
            const int32_t col = cells[i] % w->width + w->col0;
            const int32_t row = cells[i] / w->width + w->row0;
            const double cx = ((double)col + 0.5) * f->resolution;
            const double cy = ((double)row + 0.5) * f->resolution;
            if (f->rotated == 0.0) {
                x = f->origin_x + cx;
                y = f->origin_y + cy;
            } else {
                x = f->origin_x + f->cos_yaw * cx - f->sin_yaw * cy;
                y = f->origin_y + f->sin_yaw * cx + f->cos_yaw * cy;
            }
        }
        to_cells(f, x, y, &xs[i], &ys[i]);
        along[i] = cost_at(w, xs[i], ys[i]);
    }
    const int32_t count = shortcut(w, inscribed, xs, ys, along, n, kept);
    for (int32_t k = 0; k < count; k++) cells[k] = cells[kept[k]]; /* kept[k] >= k */
    free(xs);
    free(along);
    return count;
}

/* A whole plan in one call: the search (grid_astar_search's arguments, on the costs of a box
 * of the map: `box` is its row0, col0 and the map's full height and width), the path's cells
 * into `out` as flat cells of the whole map and, when `smoothing`, the planner's shortcuts
 * over them (`f`, and `ends`: the start's and the goal's world x, y). `counts` gets the
 * path's cells and the cells left first in `out` (all of them unsmoothed). When the path
 * does not fit in `capacity`, counts[1] is -1 and nothing is written (call again with room
 * for counts[0]). Returns the search's result (the cost, -1.0 no path, -2.0 out of memory). */
double grid_plan(const uint8_t *costs, int32_t height, int32_t width, int32_t inscribed,
                 double resolution, double penalty, int32_t start, int32_t goal,
                 cell_state *cells, uint32_t generation,
                 int32_t smoothing, const frame *f, const double ends[4], int32_t *out,
                 int32_t capacity, int32_t counts[2], const float *marks, int32_t n_marks,
                 const int32_t box[4]) {
    if (goal < 0) return -1.0;
    const double cost = grid_astar_search(costs, height, width, inscribed, resolution, penalty,
                                          start, goal, cells, generation, marks, n_marks);
    if (cost < 0.0) return cost;
    const int32_t n = grid_path(cells, width, start, goal, out, capacity);
    counts[0] = n;
    counts[1] = -1;
    if (n > capacity) return cost;
    counts[1] = n;
    const view w = {costs, height, width, box[0], box[1], box[2], box[3]};
    if (smoothing && n > 2) {
        counts[1] = smooth(&w, inscribed, f, ends, out, n);
        if (counts[1] < 0) return -2.0;
    }
    for (int32_t k = 0; k < counts[1]; k++) /* the box's cells as the map's */
        out[k] = (out[k] / width + w.row0) * w.full_width + out[k] % width + w.col0;
    return cost;
}

/* A plain binary heap of entries by f, for the full Dijkstra below: a cell reached cheaper
 * is queued again and its stale entries skipped when they surface (no `where` to keep up to
 * date on every move, which costs more than the duplicates when every cell is settled). */
typedef struct {
    entry *items;
    size_t size;
    size_t capacity;
} plain_heap;

static int plain_push(plain_heap *h, entry e) {
    if (h->size == h->capacity) {
        size_t capacity = h->capacity ? h->capacity * 2 : 4096;
        entry *grown = realloc(h->items, capacity * sizeof(entry));
        if (!grown) return -1;
        h->items = grown;
        h->capacity = capacity;
    }
    size_t i = h->size++;
    while (i > 0) {
        size_t parent = (i - 1) / 2;
        if (!(e.f < h->items[parent].f)) break;
        h->items[i] = h->items[parent];
        i = parent;
    }
    h->items[i] = e;
    return 0;
}

static entry plain_pop(plain_heap *h) {
    entry top = h->items[0];
    entry last = h->items[--h->size];
    size_t i = 0;
    for (;;) {
        size_t child = 2 * i + 1;
        if (child >= h->size) break;
        if (child + 1 < h->size && h->items[child + 1].f < h->items[child].f) child++;
        if (!(h->items[child].f < last.f)) break;
        h->items[i] = h->items[child];
        i = child;
    }
    if (h->size) h->items[i] = last;
    return top;
}

/* The cheapest cost from `source` to every cell (a full Dijkstra on the search's graph, the
 * same edge weights summed in the same order), in single precision into out[cell * stride]
 * (-1 where unreached or not traversable), for the landmark bounds. `cells` is the search's
 * per-cell state, of which only `g` and the generation are used. Returns the number of cells
 * reached, -2 when memory ran out. */
int32_t grid_distances(const uint8_t *costs, int32_t height, int32_t width, int32_t inscribed,
                       double resolution, double penalty, int32_t source, cell_state *cells,
                       uint32_t generation, float *out, int32_t stride) {
    double lengths[8];
    for (int k = 0; k < 8; k++) lengths[k] = resolution * ((DY[k] && DX[k]) ? M_SQRT2 : 1.0);
    const uint32_t tag = generation << 3;
    cells[source].tag = tag;
    cells[source].g = 0.0;
    plain_heap open = {NULL, 0, 0};
    entry first = {0.0, 0.0f, source};
    if (plain_push(&open, first) < 0) return -2;
    while (open.size) {
        const entry e = plain_pop(&open);
        if (e.f > cells[e.node].g) continue; /* a stale entry: reached cheaper since */
        const int32_t y = e.node / width, x = e.node % width;
        const double c_u = (double)costs[e.node], g_u = e.f;
        for (int k = 0; k < 8; k++) {
            int32_t v = 0;
            const double weight =
                step_cost(costs, height, width, inscribed, penalty, lengths, y, x, c_u, k, &v);
            if (weight < 0.0) continue;
            const double candidate = g_u + weight;
            if ((cells[v].tag >> 3) != generation) {
                cells[v].tag = tag;
                cells[v].g = INFINITY;
            }
            if (candidate < cells[v].g) {
                cells[v].g = candidate;
                entry next = {candidate, 0.0f, v};
                if (plain_push(&open, next) < 0) {
                    free(open.items);
                    return -2;
                }
            }
        }
    }
    free(open.items);
    int32_t reached = 0;
    const int64_t size = (int64_t)height * width;
    for (int64_t v = 0; v < size; v++) {
        const int fresh = (cells[v].tag >> 3) == generation;
        out[v * stride] = fresh ? (float)cells[v].g : -1.0f;
        reached += fresh;
    }
    return reached;
}

/* grid_plan called from Python directly (METH_FASTCALL), without ctypes: on a small floor
 * ctypes' own work per call (converting 19 arguments through libffi) was a third of a plan
 * whose caches a full Dijkstra had just emptied. The arguments, in order: the costs'
 * address, height, width, inscribed, resolution, penalty, start, goal, the cell states'
 * address, generation, the frame's address (0: no smoothing), the start's and the goal's
 * world x, y, the out buffer's address, its capacity, the landmark table's address and
 * columns, and the box (row0, col0, the map's height and width). Returns (cost, the path's
 * cells, the cells left in out). The GIL is released during the search, as ctypes did. */
static PyObject *py_plan(PyObject *self, PyObject *const *args, Py_ssize_t nargs) {
    (void)self;
    if (nargs != 23) {
        PyErr_SetString(PyExc_TypeError, "plan takes 23 arguments");
        return NULL;
    }
    const uint8_t *costs = PyLong_AsVoidPtr(args[0]);
    const long height = PyLong_AsLong(args[1]), width = PyLong_AsLong(args[2]);
    const long inscribed = PyLong_AsLong(args[3]);
    const double resolution = PyFloat_AsDouble(args[4]), penalty = PyFloat_AsDouble(args[5]);
    const long start = PyLong_AsLong(args[6]), goal = PyLong_AsLong(args[7]);
    cell_state *cells = PyLong_AsVoidPtr(args[8]);
    const unsigned long generation = PyLong_AsUnsignedLong(args[9]);
    const frame *f = PyLong_AsVoidPtr(args[10]);
    const double ends[4] = {PyFloat_AsDouble(args[11]), PyFloat_AsDouble(args[12]),
                            PyFloat_AsDouble(args[13]), PyFloat_AsDouble(args[14])};
    int32_t *out = PyLong_AsVoidPtr(args[15]);
    const long capacity = PyLong_AsLong(args[16]);
    const float *marks = PyLong_AsVoidPtr(args[17]);
    const long n_marks = PyLong_AsLong(args[18]);
    const int32_t box[4] = {(int32_t)PyLong_AsLong(args[19]), (int32_t)PyLong_AsLong(args[20]),
                            (int32_t)PyLong_AsLong(args[21]), (int32_t)PyLong_AsLong(args[22])};
    if (PyErr_Occurred()) return NULL;
    int32_t counts[2] = {0, 0};
    double cost;
    Py_BEGIN_ALLOW_THREADS;
    cost = grid_plan(costs, (int32_t)height, (int32_t)width, (int32_t)inscribed, resolution,
                     penalty, (int32_t)start, (int32_t)goal, cells, (uint32_t)generation,
                     f != NULL, f, ends, out, (int32_t)capacity, counts, marks,
                     (int32_t)n_marks, box);
    Py_END_ALLOW_THREADS;
    return Py_BuildValue("(dii)", cost, (int)counts[0], (int)counts[1]);
}

static PyMethodDef methods[] = {
    {"plan", (PyCFunction)(void (*)(void))py_plan, METH_FASTCALL, "grid_plan, see above"},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "_grid_astar", NULL, -1, methods};

PyMODINIT_FUNC PyInit__grid_astar(void) { return PyModule_Create(&module); }
