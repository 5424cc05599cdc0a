/* SPDX-License-Identifier: Apache-2.0 */
/* What the continuous contact carries from one position to the next (docs/models.md section
 * 4.8, A start at a new x; section 1.7), as bytes of a fixed number for a tire: the QP's
 * working set that tirenv_springs__start takes up at a new x (its span, held elements and
 * working rows between elements), and what the update at a repeated x reads of it (the
 * base's tangent, the root's state), made again on restore with K_FF's factor and the rows'
 * Schur complement, which depend on nothing else. The start reads of the base's other rows
 * only whether a ground vertex has a row between elements there
 * (tirenv_springs__cc_row_enter): for the vertex each held element's ray last ended on, a
 * flag. */
#include "model/springs_impl.h"

#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "model/model_impl.h"

enum { K_MAX = TIRENV_SPRINGS__SCHUR_MAX };

/* The flags' bits. */
enum {
    HAS_BASE = 1,    /* base_ok */
    KEPT = 2,        /* the base's working set follows (on the Schur path) */
    BASE_PINS = 4,   /* it is the closed form's pins' */
    TRI_OK = 8,      /* K_FF's factor is kept */
    PINS_VERTEX = 16, /* one of the closed form's pins is on a ground vertex */
    PRED_OK = 32,    /* the root's state follows (pred_ok) */
    PRED_HELD = 64   /* (pred_held) */
};

/* A row's fields one by one (a struct's padding would make the same state other bytes). */
enum { ROW_BYTES = 13 * 8 };

/* flags; base_z, pred_x, pred_z, pred_dz; f0, f1, k, held_vertex; per element: held, enter,
 * its row's vertex where held on one, base_w, dw, pred_w; per working row: lambda, dlambda,
 * pred_lam; the working rows */
size_t tirenv_springs__cc_carry_size(size_t N)
{
    return 1 + 4 * sizeof(double) + 4 * sizeof(uint64_t) + N * (2 + sizeof(int64_t)) +
           3 * N * sizeof(double) + 3 * K_MAX * sizeof(double) + K_MAX * ROW_BYTES;
}

static unsigned char *put_row(unsigned char *p, const tirenv_springs__cc_row *R)
{
    const uint64_t i = R->i, j = R->j;
    const int64_t id = R->id;
    const double v[10] = {R->t,      R->tau,    R->ga,    R->gb,  R->h,
                          R->dga_dz, R->dgb_dz, R->dh_dz, R->cmp, R->dcmp_dz};
    p = tirenv_model__put(p, &i, sizeof i);
    p = tirenv_model__put(p, &j, sizeof j);
    p = tirenv_model__put(p, &id, sizeof id);
    return tirenv_model__put(p, v, sizeof v);
}

static const unsigned char *get_row(const unsigned char *p, tirenv_springs__cc_row *R)
{
    uint64_t i, j;
    int64_t id;
    double v[10];
    p = tirenv_model__get(p, &i, sizeof i);
    p = tirenv_model__get(p, &j, sizeof j);
    p = tirenv_model__get(p, &id, sizeof id);
    p = tirenv_model__get(p, v, sizeof v);
    *R = (tirenv_springs__cc_row){.i = i, .j = j, .id = id, .t = v[0], .tau = v[1],
                                  .ga = v[2], .gb = v[3], .h = v[4], .dga_dz = v[5],
                                  .dgb_dz = v[6], .dh_dz = v[7], .cmp = v[8], .dcmp_dz = v[9]};
    return p;
}

/* The base's row r is one of its working rows between elements. */
static int working(const tirenv_springs__cc *c, size_t N, size_t r)
{
    for (size_t q = 0; q < c->n_schur; ++q)
        if (c->order[c->schur_pos[q]] - N == r)
            return 1;
    return 0;
}

/* Whether tirenv_springs__cc_row_enter finds vertex v's row among the base's rows, not
 * working, v not a working row's vertex. */
static int can_enter(const tirenv_springs__cc *c, size_t N, long v)
{
    if (v < 0 || tirenv_springs__long_in(c->warm_ids, c->n_warm, v))
        return 0;
    for (size_t r = 0; r < c->n_rows; ++r)
        if (c->rows[r].id == v && c->rows[r].t > 0)
            return !working(c, N, r);
    return 0;
}

/* The doubles v[f0..f1] at their elements' places in N, the others 0. */
static unsigned char *put_span(unsigned char *p, const double v[], size_t f0, size_t f1,
                               size_t N)
{
    memcpy(p + f0 * sizeof *v, v + f0, (f1 - f0 + 1) * sizeof *v);
    return p + N * sizeof *v;
}

static const unsigned char *get_span(const unsigned char *p, double v[], size_t f0, size_t f1,
                                     size_t N)
{
    memcpy(v + f0, p + f0 * sizeof *v, (f1 - f0 + 1) * sizeof *v);
    return p + N * sizeof *v;
}

void tirenv_springs__cc_carry_save(const tirenv_springs__cc *c, size_t N,
                                   const tirenv_springs__ray_memo memo[], size_t memo_a,
                                   size_t memo_b, const double dw[], int tangent,
                                   int pins_vertex, unsigned char *buf)
{
    memset(buf, 0, tirenv_springs__cc_carry_size(N));
    /* a base on the Schur path, which the start at the next x and the update at this one
     * take up; another (the banded path's) is kept only as there being one, which neither
     * takes up. warm_ids names its working rows between elements (none from the closed
     * form's pins, whose warm_ids are the last solve's, which only that solve reads). */
    const int kept = c->base_ok && c->use_schur && c->f0 <= c->f1 && c->f1 < N &&
                     c->n_schur <= K_MAX && (c->base_pins || c->n_warm == c->n_schur);
    const int pred = kept && c->pred_ok;
    const unsigned char flags = (unsigned char)(
        (c->base_ok ? HAS_BASE : 0) | (kept ? KEPT : 0) | (c->base_pins ? BASE_PINS : 0) |
        (c->tri_ok ? TRI_OK : 0) | (pins_vertex ? PINS_VERTEX : 0) | (pred ? PRED_OK : 0) |
        (pred && c->pred_held ? PRED_HELD : 0));
    const double z[4] = {c->base_z, pred ? c->pred_x : 0, pred ? c->pred_z : 0,
                         pred ? c->pred_dz : 0};
    unsigned char *p = tirenv_model__put(buf, &flags, 1);
    p = tirenv_model__put(p, z, sizeof z);
    if (!kept)
        return;
    const size_t f0 = c->f0, f1 = c->f1, k = c->n_schur;
    const uint64_t u[4] = {f0, f1, k, c->held_vertex};
    p = tirenv_model__put(p, u, sizeof u);
    unsigned char *held = p, *enter = p + N;
    p += 2 * N;
    for (size_t e = f0; e <= f1; ++e) {
        held[e] = c->wpos[e] == SIZE_MAX;
        enter[e] = held[e] && e >= memo_a && e <= memo_b && can_enter(c, N, memo[e].j);
        /* the vertex a held element's row is on (the update at this x compares it) */
        const int64_t v = held[e] && c->held_vertex > 0 && c->pin_row[e] < c->n_rows
                              ? c->rows[c->pin_row[e]].id
                              : -1;
        memcpy(p + e * sizeof v, &v, sizeof v);
    }
    p += N * sizeof(int64_t);
    /* the tangent's (the base's w, dw/dz and reactions with their d/dz) only where the
     * update at the next x may take it: at the base's own x, unless the start changed the
     * working set since (the rows it entered have no d(lambda)/dz) */
    p = tangent ? put_span(p, c->base_w + 1, f0, f1, N) : p + N * sizeof(double);
    p = tangent ? put_span(p, dw, f0, f1, N) : p + N * sizeof(double);
    p = pred ? put_span(p, c->pred_w, f0, f1, N) : p + N * sizeof(double);
    for (size_t q = 0; q < k; ++q) {
        const size_t r = c->order[c->schur_pos[q]] - N;
        const double l[3] = {tangent ? c->lambda[r] : 0, tangent ? c->dlambda[r] : 0,
                             pred ? c->pred_lam[q] : 0};
        memcpy(p + q * sizeof *l, &l[0], sizeof *l);
        memcpy(p + (K_MAX + q) * sizeof *l, &l[1], sizeof *l);
        memcpy(p + (2 * K_MAX + q) * sizeof *l, &l[2], sizeof *l);
    }
    p += 3 * K_MAX * sizeof(double);
    for (size_t q = 0; q < k; ++q)
        p = put_row(p, &c->rows[c->order[c->schur_pos[q]] - N]);
}

/* Room for n entries in *v, of which *cap there are. */
static int room(void **v, size_t *cap, size_t n, size_t size)
{
    if (n <= *cap)
        return TIRENV_OK;
    void *m = realloc(*v, n * size);
    if (!m)
        return TIRENV_ENOMEM;
    *v = m;
    *cap = n;
    return TIRENV_OK;
}

int tirenv_springs__cc_carry_restore(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                     const tirenv_springs__ray_memo memo[],
                                     const unsigned char *buf, size_t n_v, double dw[],
                                     int *pins_vertex)
{
    const size_t N = T->N;
    unsigned char flags;
    double z[4];
    const unsigned char *p = tirenv_model__get(buf, &flags, 1);
    p = tirenv_model__get(p, z, sizeof z);
    *pins_vertex = (flags & PINS_VERTEX) != 0;
    tirenv_springs__cc_forget(c);
    /* K_FF^-1 f and the rows' columns kept are another factor's (springs_root.c) */
    c->root_v_at = c->cols.at = (unsigned long long)-1;
    c->mend_at = (unsigned long long)-2;
    const int kept = (flags & KEPT) != 0;
    uint64_t u[4] = {1, 0, 0, 0};
    if (kept) {
        p = tirenv_model__get(p, u, sizeof u);
        if (!(u[0] <= u[1] && u[1] < N && u[2] <= K_MAX && u[3] <= N))
            return TIRENV_EINVAL;
    }
    const size_t f0 = u[0], f1 = u[1], k = u[2];
    const unsigned char *held = p, *enter = p + N;
    const unsigned char *pin_id = p + 2 * N;
    p += 2 * N + N * sizeof(int64_t);
    size_t n_enter = 0, n_vertex = 0;
    for (size_t e = f0; kept && e <= f1; ++e) {
        int64_t v;
        memcpy(&v, pin_id + e * sizeof v, sizeof v);
        n_enter += enter[e] != 0;
        n_vertex += held[e] && v >= 0;
        /* a held element's vertex is the ground's, or none it has now (LONG_MAX: a streamed
         * road's window moved past it, springs.c's reprofile) */
        if (held[e] && v >= (int64_t)n_v && v != LONG_MAX)
            return TIRENV_EINVAL;
    }
    /* the rows: the working ones, a row of each vertex a held element may enter, the rows
     * of the elements held on vertices, and the two the closed form's pins' rows point at */
    const size_t n_rows = k + n_enter + n_vertex + 2;
    if (tirenv_springs__cc_reserve_rows(c, n_rows, N) ||
        room((void **)&c->warm_ids, &c->cap_warm, K_MAX + 1, sizeof *c->warm_ids) ||
        room((void **)&c->dlambda, &c->cap_dl, n_rows, sizeof *c->dlambda))
        return TIRENV_ENOMEM;
    const unsigned char *l = p + 3 * N * sizeof(double);
    const unsigned char *rows = l + 3 * K_MAX * sizeof(double);
    for (size_t q = 0; q < k; ++q) {
        rows = get_row(rows, &c->rows[q]);
        const tirenv_springs__cc_row *R = &c->rows[q];
        /* (the layout the Schur path indexes by; a vertex's row, or element i's ray's) */
        if (!(R->i < N && R->j < N && (R->t > 0 ? R->j == R->i + 1 : R->j == R->i) &&
              R->id >= -(long)N && (R->id < 0 || (size_t)R->id < n_v || R->id == LONG_MAX)))
            return TIRENV_EINVAL;
        c->order[q] = N + q;
        c->schur_pos[q] = q;
        memcpy(&c->lambda[q], l + q * sizeof(double), sizeof(double));
        memcpy(&c->dlambda[q], l + (K_MAX + q) * sizeof(double), sizeof(double));
        memcpy(&c->pred_lam[q], l + (2 * K_MAX + q) * sizeof(double), sizeof(double));
        size_t m = q; /* warm_ids: the working rows' vertices, ascending */
        while (m > 0 && c->warm_ids[m - 1] > c->rows[q].id) {
            c->warm_ids[m] = c->warm_ids[m - 1];
            --m;
        }
        c->warm_ids[m] = c->rows[q].id;
    }
    /* the rows a held element may enter: tirenv_springs__cc_row_enter finds one by its vertex
     * and t > 0 alone and writes it whole before use, so i, j and t only stand in */
    size_t r = k;
    for (size_t e = f0; kept && e <= f1; ++e)
        if (enter[e])
            c->rows[r++] = (tirenv_springs__cc_row){.i = e, .j = e + 1, .t = 0.5,
                                                    .id = memo[e].j};
    /* the closed form's pins' rows, of which tirenv_springs__cc_base_pins reads only
     * whether one is a ground vertex's (then it makes no base): every element's the vertex's
     * where one was, else a ray's; on an element (t = 0), so that no search for a vertex's
     * row between elements finds them */
    const size_t ray_row = r, vertex_row = r + 1;
    c->rows[ray_row] = (tirenv_springs__cc_row){.id = -1};
    c->rows[vertex_row] = (tirenv_springs__cc_row){.id = 0};
    for (size_t e = 0; e < N; ++e)
        c->pin_row[e] = *pins_vertex ? vertex_row : ray_row;
    r += 2;
    /* the base's held elements on ground vertices, each on its vertex's row */
    for (size_t e = f0; kept && e <= f1; ++e) {
        int64_t v;
        memcpy(&v, pin_id + e * sizeof v, sizeof v);
        if (held[e] && v >= 0) {
            c->rows[r] = (tirenv_springs__cc_row){.i = e, .j = e, .id = (long)v};
            c->pin_row[e] = r++;
        }
    }
    c->n_rows = n_rows;
    c->n_warm = k;
    c->n_schur = k;
    c->n_kkt = k;
    if (!(flags & HAS_BASE))
        return TIRENV_OK;
    c->base_z = z[0];
    c->base_pins = (flags & BASE_PINS) != 0;
    if (!kept) { /* a base neither the start nor the update takes up */
        c->use_schur = 0;
        c->base_ok = 1;
        return TIRENV_OK;
    }
    c->f0 = f0;
    c->f1 = f1;
    c->n_held = 0;
    for (size_t e = f0; e <= f1; ++e) {
        c->wpos[e] = held[e] ? SIZE_MAX : 0;
        if (held[e])
            c->held[c->n_held++] = e;
    }
    c->held_vertex = u[3];
    p = get_span(p, c->base_w + 1, f0, f1, N);
    p = get_span(p, dw, f0, f1, N);
    get_span(p, c->pred_w, f0, f1, N);
    c->use_schur = 1;
    if (tirenv_springs__cc_schur_factor(c, T, 0))
        return TIRENV_OK; /* (no base: none could be made from it either) */
    c->tri_ok = (flags & TRI_OK) != 0;
    c->base_ok = 1;
    if (flags & PRED_OK) {
        c->pred_x = z[1];
        c->pred_z = z[2];
        c->pred_dz = z[3];
        c->pred_held = (flags & PRED_HELD) != 0;
        c->pred_ok = 1;
    }
    return TIRENV_OK;
}
