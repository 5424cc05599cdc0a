/* --set of a key that no model the command runs reads: said on standard error, since the run
 * would otherwise print the curve of the unchanged tire as if the key had been taken. Which
 * model reads which section of the tire file is the models' code (docs/models.md 14.2):
 *   every model           [DIMENSION] (R0; WIDTH spreads tracks over the tire)
 *   springs               [ENVELOPING_SPRINGS], [ENVELOPING_SOLVER]
 *   ring                  [ENVELOPING_RING], [OPERATING_CONDITIONS] INFLPRES, [ENVELOPING_SOLVER]
 *   cam                   [VERTICAL], [CONTACT_PATCH], [OPERATING_CONDITIONS] (PFZ1's factor)
 *   rigid, point          nothing else, unless a contact length is their load: then the
 *                         springs model's (tirenv_tir_need)
 *   nn                    the springs model as its stand-in (a network file without the law
 *                         of its tire): counted always, so that no false warning is given.
 * SPDX-License-Identifier: Apache-2.0 */
#include "cli/cli.h"

#include <ctype.h>
#include <string.h>
#include <strings.h>

/* A tire file's sections, as bits. */
enum {
    SEC_DIMENSION = 1u << 0,
    SEC_VERTICAL = 1u << 1,
    SEC_CONTACT_PATCH = 1u << 2,
    SEC_OPERATING = 1u << 3,
    SEC_SPRINGS = 1u << 4,
    SEC_RING = 1u << 5,
    SEC_SOLVER = 1u << 6
};

static const struct {
    const char *name;
    unsigned bit;
    const char *whose;  /* the models that read it, for the message */
} sections[] = {
    {"DIMENSION", SEC_DIMENSION, "every model's"},
    {"VERTICAL", SEC_VERTICAL, "the cam's"},
    {"CONTACT_PATCH", SEC_CONTACT_PATCH, "the cam's"},
    {"OPERATING_CONDITIONS", SEC_OPERATING, "the ring's and the cam's"},
    {"ENVELOPING_SPRINGS", SEC_SPRINGS, "the springs model's"},
    {"ENVELOPING_RING", SEC_RING, "the ring's"},
    {"ENVELOPING_SOLVER", SEC_SOLVER, "the springs model's and the ring's"},
};
#define N_SECTIONS (sizeof sections / sizeof sections[0])

unsigned cli_model_reads(const tirenv_model_type *type, int at_contact_length)
{
    const unsigned springs = SEC_DIMENSION | SEC_SPRINGS | SEC_SOLVER;
    if (type == tirenv_model_springs || type == tirenv_model_nn)
        return springs;
    if (type == tirenv_model_ring)
        return SEC_DIMENSION | SEC_RING | SEC_OPERATING | SEC_SOLVER;
    if (type == tirenv_model_cam)
        return SEC_DIMENSION | SEC_VERTICAL | SEC_CONTACT_PATCH | SEC_OPERATING;
    if (type == tirenv_model_rigid || type == tirenv_model_point)
        return at_contact_length ? springs : SEC_DIMENSION;
    return ~0u;  /* a model this table does not know: assumed to read everything */
}

/* The model as a noun ("the ring does not read it"). */
static const char *noun(const tirenv_model_type *type)
{
    return type == tirenv_model_springs ? "the springs model"
           : type == tirenv_model_ring  ? "the ring"
           : type == tirenv_model_cam   ? "the cam"
           : type == tirenv_model_rigid ? "the rigid disc"
           : type == tirenv_model_point ? "the point"
           : type == tirenv_model_nn    ? "the network"
                                        : tirenv_model_type_name(type);
}

/* The section of assignment's key, as tirenv_tir_set finds it (case aside, trimmed; an
 * ambiguous or unknown key was refused there), or -1. */
static int section_of(const char *assignment)
{
    const char *eq = strchr(assignment, '=');
    const char *p = assignment;
    while (isspace((unsigned char)*p))
        ++p;
    const char *end = eq ? eq : p + strlen(p);
    while (end > p && isspace((unsigned char)end[-1]))
        --end;
    const char *dot = memchr(p, '.', (size_t)(end - p));
    const char *key = dot ? dot + 1 : p;
    const size_t key_len = (size_t)(end - key), sec_len = dot ? (size_t)(dot - p) : 0;
    const char *section = NULL;
    for (size_t i = 0;; ++i) {
        const char *k = tirenv_tir_key(i, &section);
        if (!k)
            return -1;
        if (strlen(k) != key_len || strncasecmp(k, key, key_len) != 0)
            continue;
        if (dot && (strlen(section) != sec_len || strncasecmp(section, p, sec_len) != 0))
            continue;
        for (size_t s = 0; s < N_SECTIONS; ++s)
            if (strcmp(sections[s].name, section) == 0)
                return (int)s;
        return -1;
    }
}

/* "the cam does not read it", "neither A nor B reads it", "none of A, B and C reads it". */
static void none_reads(const tirenv_model_type *const runs[], size_t n_runs)
{
    if (n_runs == 1) {
        fprintf(stderr, "%s does not read it\n", noun(runs[0]));
        return;
    }
    fputs(n_runs == 2 ? "neither " : "none of ", stderr);
    for (size_t k = 0; k < n_runs; ++k) {
        const char *sep = k == 0 ? "" : n_runs == 2 ? " nor " : k + 1 < n_runs ? ", " : " and ";
        fprintf(stderr, "%s%s", sep, noun(runs[k]));
    }
    fputs(" reads it\n", stderr);
}

void cli_set_warnings(const char *const sets[], size_t n_sets,
                      const tirenv_model_type *const runs[], size_t n_runs, unsigned reads)
{
    if (n_runs == 0)
        return;  /* the command did not say what it runs: nothing said */
    for (size_t i = 0; i < n_sets; ++i) {
        const int s = section_of(sets[i]);
        if (s < 0 || (sections[s].bit & reads))
            continue;
        const size_t key_len = strcspn(sets[i], "=");
        fprintf(stderr, "tirenv: --set %.*s: [%s] is %s; ", (int)key_len, sets[i],
                sections[s].name, sections[s].whose);
        none_reads(runs, n_runs);
    }
}

/* --method sets [ENVELOPING_SOLVER] METHOD: the same warning, under its own name (the cam ran
 * with --method secant as if it had taken it). */
void cli_method_warning(const tirenv_model_type *const runs[], size_t n_runs, unsigned reads)
{
    if (n_runs == 0 || (reads & SEC_SOLVER))
        return;
    fputs("tirenv: --method: the equilibrium solver ([ENVELOPING_SOLVER] METHOD) is the "
          "springs model's and the ring's; ", stderr);
    none_reads(runs, n_runs);
}
