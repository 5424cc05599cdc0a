/* tirenv flat: the tire's state on flat ground, at one load or at the paper's three working
 * regimes. SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>

#include "cli/cli.h"

/* The contact lengths of the paper's working regimes (Table 1 and Table 3), m: the table of
 * a tire file without a nominal load, or whose ring carries it at a contact length within
 * them (the default tire's; cli_nominal_load). Any other file with FNOMIN is tabled over its
 * own load range, tirenv_nominal_load_fractions of FNOMIN. */
static const double regimes[] = {0.28, 0.33, 0.38};

static void usage(FILE *fp)
{
    fputs("usage: tirenv flat [--load N | --contact-length M] [--model NAME] [--csv]\n"
          "                   [--tire FILE] [--set KEY=VALUE]... [--method M]\n"
          "\n"
          "The tire on flat ground: load, centre height, deflection, contact length and\n"
          "vertical stiffness. Without --load or --contact-length, a table of the tire's own\n"
          "load range, 0.5 to 1.5 times its nominal load [VERTICAL] FNOMIN, or, for a file\n"
          "without FNOMIN or whose FNOMIN the tire carries at a contact length within the\n"
          "paper's working regimes (the default tire's), those regimes, contact lengths\n"
          "0.28, 0.33 and 0.38 m. With --model ring also the largest tread compression\n"
          "(and a column tread_max_m in the CSV).\n"
          "\n"
          "options:\n",
          fp);
    cli_help_load(fp);
    cli_help_model(fp, 0, TIRENV_MODEL_NEEDS_NETWORK, " (default springs)");
    fputs("  --csv                CSV: load_N,z_flat_m,deflection_m,contact_length_m,\n"
          "                       stiffness_N_per_m\n",
          fp);
    cli_help_tire(fp, 1, "RADIAL_STIFFNESS=4.5e5 (the springs model's)");
    fputs("  -h, --help           show this help\n", fp);
}

/* What the ring adds to a flat state: its largest tread compression (m, negative for the
 * other models) and its belt-contact nodes. */
typedef struct {
    double tread_max;
    size_t belt_contacts;
} ring_extra;

/* The ring's extra at the flat state's height, from a ring of its own. */
static int ring_tread(const tirenv_model_type *type, const tirenv_tire *tire,
                      const tirenv_flat *f, ring_extra *e)
{
    e->tread_max = -1;
    if (type != tirenv_model_ring)
        return CLI_EXIT_OK;
    const double zero = 0;
    tirenv_ring *r = tirenv_ring_alloc(tire->springs.R0, &tire->ring);
    tirenv_profile *flat = tirenv_profile_alloc(1, &zero, &zero);
    double fx, fz;
    const int status = r && flat ? tirenv_ring_forces(r, flat, 0, f->z_flat, &fx, &fz, NULL, NULL, NULL)
                                 : TIRENV_ENOMEM;
    if (!status) {
        e->tread_max = tirenv_ring_tread_max(r);
        e->belt_contacts = tirenv_ring_belt_contacts(r);
    }
    tirenv_profile_free(flat);
    tirenv_ring_free(r);
    return status ? cli_fail(status, NULL) : CLI_EXIT_OK;
}

static void print_one(const char *model, const char *tire_path, const tirenv_flat *f,
                      const ring_extra *e)
{
    printf("%s model, tire %s\n", model, tire_path);
    printf("  load                %.6g N (%.4g kN)\n", f->load, f->load / 1e3);
    printf("  centre height       %.6g m\n", f->z_flat);
    printf("  deflection          %.6g m (%.4g mm)\n", f->deflection, f->deflection * 1e3);
    printf("  contact length      %.6g m\n", f->contact_length);
    printf("  vertical stiffness  %.6g N/m (%.4g kN/m)\n", f->stiffness, f->stiffness / 1e3);
    if (e->tread_max >= 0)
        printf("  tread compression   %.6g m (%.4g mm), belt contacts %zu\n", e->tread_max,
               e->tread_max * 1e3, e->belt_contacts);
}

static void print_row(int csv, const tirenv_flat *f, const ring_extra *e)
{
    if (csv)
        printf("%.9g,%.9g,%.9g,%.9g,%.9g", f->load, f->z_flat, f->deflection,
               f->contact_length, f->stiffness);
    else
        printf("%10.1f %8.3f %10.5f %10.5f %10.2f %10.4f %10.2f", f->load, f->load / 1e3,
               f->z_flat, f->deflection, f->deflection * 1e3, f->contact_length,
               f->stiffness / 1e3);
    if (e->tread_max >= 0)
        printf(csv ? ",%.9g" : " %10.2f", csv ? e->tread_max : e->tread_max * 1e3);
    putchar('\n');
}

static const char csv_header[] = "load_N,z_flat_m,deflection_m,contact_length_m,stiffness_N_per_m";

/* One flat-ground state for the load the options (or a regime's contact length) ask for. */
static int flat_at(tirenv_model *m, const cli_options *o, tirenv_flat *f)
{
    double load;
    int code = cli_load(o, m, &load);
    if (code)
        return code;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_model_flat(m, load, f, &diag);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}

int cli_flat_main(int argc, char *argv[])
{
    int csv = 0;
    const cli_opt own[] = {
        {.name = "csv", .kind = CLI_FLAG, .dst = &csv},
        {.name = NULL},
    };
    const cli_parser p = {.name = "flat", .usage = usage, .opts = own,
                          .groups = CLI_TIRE | CLI_METHOD | CLI_LOAD | CLI_MODEL};
    cli_options o;
    const int parsed = cli_parse(&p, argc, argv, &o);
    if (parsed != CLI_GO_ON)
        return parsed;
    const tirenv_model_type *type = o.type ? o.type : tirenv_model_springs;
    o.type_alone = 1;  /* the model named and no other (ring_tread: the ring's own; without
                        * --load, cli_nominal_load takes FNOMIN where no ring was derived) */
    o.runs[o.n_runs++] = type;
    /* Without --load, FNOMIN is tabled if inside the ring's regime (cli_nominal_load). */
    if (!o.have_load)
        o.reads_also = cli_model_reads(tirenv_model_ring, 0);
    tirenv_tire tire;
    int code = cli_tire(&o, &tire);
    if (code)
        return code;
    tirenv_model *m;
    if ((code = cli_model(type, &tire, &o, &m)))
        return code;
    char buf[1024];
    const char *tire_path = cli_tire_path(&o, buf, sizeof buf);

    tirenv_flat f;
    ring_extra e;
    const int ring = type == tirenv_model_ring;
    if (o.have_load || o.have_contact_length) {
        if (!(code = flat_at(m, &o, &f)) && !(code = ring_tread(type, &tire, &f, &e))) {
            if (csv) {
                printf("%s%s\n", csv_header, ring ? ",tread_max_m" : "");
                print_row(1, &f, &e);
            } else {
                print_one(tirenv_model_type_name(type), tire_path, &f, &e);
            }
        }
        tirenv_model_free(m);
        return code;
    }
    const double fnomin = cli_nominal_load(&tire);
    char what[96] = "at the paper's working regimes";
    if (fnomin > 0)
        snprintf(what, sizeof what, "at 0.5 to 1.5 times its nominal load %.6g N", fnomin);
    const size_t n = fnomin > 0 ? TIRENV_NOMINAL_LOADS : sizeof regimes / sizeof regimes[0];
    if (csv)
        printf("%s%s\n", csv_header, ring ? ",tread_max_m" : "");
    else
        printf("%s model, tire %s, %s\n"
               "%10s %8s %10s %10s %10s %10s %10s%s\n",
               tirenv_model_type_name(type), tire_path, what, "load_N", "load_kN", "z_flat_m",
               "defl_m", "defl_mm", "contact_m", "k_kN/m", ring ? "   tread_mm" : "");
    for (size_t i = 0; i < n && !code; ++i) {
        if (fnomin > 0) {
            o.have_load = 1;
            o.load = tirenv_nominal_load_fractions[i] * fnomin;
        } else {
            o.have_contact_length = 1;
            o.contact_length = regimes[i];
        }
        if (!(code = flat_at(m, &o, &f)) && !(code = ring_tread(type, &tire, &f, &e)))
            print_row(csv, &f, &e);
    }
    /* A table of rows alike but for the load, each at contact length 0, read as a model that
     * missed the regimes it was asked for: say what the loads are. */
    if (!code && !csv && !(fnomin > 0) &&
        !(tirenv_model_type_flags(type) & TIRENV_MODEL_CONTACT_LENGTH))
        printf("(the %s model does not deflect: each load is the springs model's at which the "
               "free circle's chord at its centre height is the regime's contact length, "
               "docs/models.md section 1.3)\n", tirenv_model_type_name(type));
    tirenv_model_free(m);
    return code;
}
