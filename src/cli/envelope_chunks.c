/* SPDX-License-Identifier: Apache-2.0 */
/* One sweep on several threads (envelope_chunks.h). A model instance is not thread-safe, so
 * every thread has its own, set on the same (read-only) profiles; the cold state saved from
 * the caller's model right after it was set is restored before every chunk, so that no chunk
 * depends on which thread ran it, nor on what that thread ran before. A model set on several
 * tracks has no state to save (tirenv_model_state_save is for one track): each chunk sets its
 * model on the tracks again, which leaves it as cold as the first set did. A streamed sweep
 * (envelope_stream.c) gives each chunk tracks of its own, windows of the road: its model is
 * set on them, then (one track) restored to the cold state. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/envelope_chunks.h"

enum { CLI_CHUNK_SAID = 1024 }; /* bytes of a model's warnings kept */

struct cli_chunks {
    size_t jobs;
    tirenv_model **models;  /* one a thread; models[0] is the caller's */
    double *x;              /* CLI_CHUNK positions a thread */
    void *cold;             /* the state each chunk starts from */
    size_t cold_size;
    double x_from, dx;      /* m */
    size_t n;               /* positions in the sweep */
    size_t n_tracks;        /* > 1: the chunks start by setting the tracks again */
    const tirenv_profile *const *tracks;
    double load;            /* N */
    /* the call under way */
    const tirenv_profile *const *windows;  /* NULL, or item i's tracks at [i * n_tracks] */
    size_t c0;
    tirenv_point *pt;
    int (*side)(void *side_ctx, tirenv_diag *diag);  /* item 0 if not NULL */
    void *side_ctx;
    char (*said)[CLI_CHUNK_SAID]; /* [n_said], each chunk's warnings in the call under way */
    size_t n_said;
    char warnings[CLI_CHUNK_SAID]; /* the first chunk's that had any (cli_chunks_warnings) */
};

void cli_chunks_free(cli_chunks *c)
{
    if (!c)
        return;
    for (size_t w = 1; c->models && w < c->jobs; ++w)
        tirenv_model_free(c->models[w]);
    free(c->models);
    free(c->x);
    free(c->cold);
    free(c->said);
    free(c);
}

static int no_memory(tirenv_diag *diag)
{
    return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
}

int cli_chunks_open(tirenv_model *m, const tirenv_model_type *type, const cli_options *o,
                    size_t n_tracks, const tirenv_profile *const tracks[], double load,
                    double x_from, double dx, size_t n, size_t jobs, cli_chunks **out,
                    tirenv_diag *diag)
{
    *out = NULL;
    const size_t n_chunks = n / CLI_CHUNK + (n % CLI_CHUNK != 0);
    if (jobs < 1)
        jobs = 1;
    if (jobs > n_chunks)
        jobs = n_chunks ? n_chunks : 1;
    cli_chunks *c = calloc(1, sizeof *c);
    if (!c)
        return no_memory(diag);
    c->jobs = jobs;
    c->x_from = x_from;
    c->dx = dx;
    c->n = n;
    c->n_tracks = n_tracks;
    c->tracks = tracks;
    c->load = load;
    c->cold_size = n_tracks > 1 ? 0 : tirenv_model_state_size(m);
    c->models = calloc(jobs, sizeof *c->models);
    c->x = malloc(jobs * CLI_CHUNK * sizeof *c->x);
    c->cold = malloc(c->cold_size ? c->cold_size : 1);
    int status = c->models && c->x && c->cold ? TIRENV_OK : no_memory(diag);
    if (!status) {
        c->models[0] = m;
        if (n_tracks <= 1)
            status = tirenv_model_state_save(m, c->cold, c->cold_size, diag);
    }
    for (size_t w = 1; w < jobs && !status; ++w) {
        if (cli_model(type, tirenv_model_tire(m), o, &c->models[w]))
            status = tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "a model for thread %zu",
                                  w);
        else
            status = tirenv_model_set_tracks(c->models[w], n_tracks, tracks, NULL, load, diag);
    }
    if (status) {
        cli_chunks_free(c);
        return status;
    }
    *out = c;
    return TIRENV_OK;
}

size_t cli_chunks_round(const cli_chunks *c)
{
    return 4 * c->jobs;
}

/* One chunk: item i of the call is the sweep's chunk c0 + i. */
static int chunk(void *ctx, size_t item, size_t worker, tirenv_diag *diag)
{
    cli_chunks *c = ctx;
    if (c->side) {
        if (item == 0)
            return c->side(c->side_ctx, diag);
        --item;
    }
    const size_t k0 = (c->c0 + item) * CLI_CHUNK;
    const size_t n = c->n - k0 < CLI_CHUNK ? c->n - k0 : CLI_CHUNK;
    double *x = c->x + worker * CLI_CHUNK;
    for (size_t k = 0; k < n; ++k)
        x[k] = c->x_from + (double)(k0 + k) * c->dx;
    tirenv_model *m = c->models[worker];
    const tirenv_profile *const *tracks = c->windows ? c->windows + item * c->n_tracks
                                                     : c->tracks;
    int status = TIRENV_OK;
    if (c->windows || c->n_tracks > 1)
        status = tirenv_model_set_tracks(m, c->n_tracks, tracks, NULL, c->load, diag);
    if (!status && c->n_tracks == 1)
        status = tirenv_model_state_restore(m, c->cold, c->cold_size, diag);
    if (!status)
        status = tirenv_model_envelope(m, n, x, c->pt + item * CLI_CHUNK, NULL, diag);
    if (!status)
        snprintf(c->said[item], sizeof c->said[item], "%s", tirenv_model_warnings(m));
    /* A window is freed after its round: the model must not point at it then. */
    if (c->windows)
        tirenv_model_set_profile(m, NULL, NULL);
    return status;
}

int cli_chunks_run(cli_chunks *c, size_t c0, size_t n_c, tirenv_point pt[], size_t *n_out,
                   int (*side)(void *side_ctx, tirenv_diag *diag), void *side_ctx,
                   tirenv_diag *diag)
{
    return cli_chunks_run_on(c, c0, n_c, NULL, pt, n_out, side, side_ctx, diag);
}

int cli_chunks_run_on(cli_chunks *c, size_t c0, size_t n_c,
                      const tirenv_profile *const windows[], tirenv_point pt[], size_t *n_out,
                      int (*side)(void *side_ctx, tirenv_diag *diag), void *side_ctx,
                      tirenv_diag *diag)
{
    c->windows = windows;
    c->side = side;
    c->side_ctx = side_ctx;
    const size_t n_chunks = c->n / CLI_CHUNK + (c->n % CLI_CHUNK != 0);
    if (c0 >= n_chunks) {
        *n_out = 0;
        return side ? side(side_ctx, diag) : TIRENV_OK;
    }
    if (n_c > n_chunks - c0)
        n_c = n_chunks - c0;
    if (n_c > c->n_said) {
        void *said = realloc(c->said, n_c * sizeof *c->said);
        if (!said)
            return no_memory(diag);
        c->said = said;
        c->n_said = n_c;
    }
    c->c0 = c0;
    c->pt = pt;
    const size_t end = (c0 + n_c) * CLI_CHUNK;
    *n_out = (end < c->n ? end : c->n) - c0 * CLI_CHUNK;
    const int status = tirenv_parallel_for(n_c + (side != NULL), c->jobs, chunk, NULL, c, diag);
    for (size_t i = 0; !status && !c->warnings[0] && i < n_c; ++i)
        memcpy(c->warnings, c->said[i], sizeof c->warnings);
    return status;
}

const char *cli_chunks_warnings(const cli_chunks *c)
{
    return c->warnings;
}
