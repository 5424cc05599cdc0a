/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: .tir tire property files (MF-Tyre's layout; docs/formats.md section 2). */
#ifndef TIRENV_TIR_H
#define TIRENV_TIR_H

#include "tirenv/decls.h"
#include "tirenv/error.h"
#include "tirenv/model.h"
#include "tirenv/tire.h"

#include <stddef.h>

TIRENV_BEGIN_DECLS

/* Reads a .tir file (sections in brackets, KEY = value, '$' comments, [UNITS] in SI) into
 * *tire, overriding only the keys present. Keys this library knows (see data/tires/default.tir)
 * are checked; sections it does not know are skipped so that MF-Tyre files load unchanged.
 * Errors name file, line and key. On failure *tire is unchanged. */
int tirenv_tir_read(const char *path, tirenv_tire *tire, tirenv_diag *diag);

/* Applies one "KEY=VALUE" override (KEY as in the .tir file, e.g. RADIAL_STIFFNESS=1.6e6),
 * as the --set option does. On failure *tire is unchanged, and diag names the file "--set"
 * (line 0: no file was read) and the key as its field. */
int tirenv_tir_set(tirenv_tire *tire, const char *assignment, tirenv_diag *diag);

/* Writes *tire as a .tir file (atomically: all or nothing). */
int tirenv_tir_write(const char *path, const tirenv_tire *tire, tirenv_diag *diag);
/* Writes *tire as tirenv_tir_write does, with note (lines separated by '\n') as '!' comment
 * lines after the [MDI_HEADER] keys in place of tirenv's own preamble: no tirenv version, for
 * files that must stay the same bytes across versions (a data set's tire.tir). */
int tirenv_tir_write_noted(const char *path, const tirenv_tire *tire, const char *note,
                           tirenv_diag *diag);

/* What a tire key holds: a real number (SI), a count, or a name (METHOD). */
typedef enum { TIRENV_TIR_REAL, TIRENV_TIR_COUNT, TIRENV_TIR_NAME } tirenv_tir_kind;

/* The keys tirenv_tir_set and tirenv_tir_get take, in the order a .tir file is written: the
 * i-th key's name (and, if section is not NULL, its [SECTION]); NULL past the last. Static
 * strings. */
const char *tirenv_tir_key(size_t i, const char **section);

/* The value of key ("KEY" or "SECTION.KEY", as tirenv_tir_set takes it) in *tire as text into
 * buf (n bytes, 64 always suffice), exactly as tirenv_tir_write writes it: the shortest text
 * that reads back to the same double (SI units), a count, or a name unquoted; *kind (if not
 * NULL) says which. An unknown key is TIRENV_EINVAL with the known keys in the message (diag's
 * file "get", line 0, its field the key); on any failure buf (if n > 0) holds "". */
int tirenv_tir_get(const tirenv_tire *tire, const char *key, char *buf, size_t n,
                   tirenv_tir_kind *kind, tirenv_diag *diag);

/* The models of a tire file that tirenv_tir_derive may derive (docs/models.md section 14). */
enum {
    TIRENV_TIR_SPRINGS = 1u << 0, /* [ENVELOPING_SPRINGS]: c_r and c_b */
    TIRENV_TIR_RING = 1u << 1,    /* [ENVELOPING_RING]: t_r, EI, T, k_f, k_t */
    TIRENV_TIR_CAM = 1u << 2,     /* [CONTACT_PATCH] Q_RA1 and Q_RA2: the cam's patch */
    TIRENV_TIR_VERTICAL = 1u << 3, /* [VERTICAL] Q_FZ2 (or Q_FZ1): the cam's vertical law */
    TIRENV_TIR_ONLY = 1u << 4      /* in tirenv_tir_derive's need: the caller uses the models
                                    * named there and no other */
};

/* What a tire file says of its own tire besides tirenv's keys, and what tirenv_tir_derive
 * made of it. */
typedef struct {
    double fnomin;         /* [VERTICAL] FNOMIN: nominal load, N; 0 if the file has none */
    double rho_nominal;    /* the file's deflection at FNOMIN and INFLPRES, m, by its law (with
                            * Q_FZ2 where derived); 0 if unknown */
    unsigned own;          /* TIRENV_TIR_* of the enveloping sections the file has (and
                            * TIRENV_TIR_VERTICAL: it gives Q_FZ2 or a Q_FZ1 other than 0) */
    unsigned derived;      /* TIRENV_TIR_* of the models derived from its MF-Tyre keys */
    double pretension_ratio; /* the derived ring's added BELT_PRETENSION over k_f*R^2, - */
    double cam_ring_deflection;     /* largest |cam - ring|/ring at 0.5 to 1.5 FNOMIN, */
    double cam_ring_contact_length; /* deflection and contact length; NAN if not compared */
    char note[1024];       /* which values were derived from which keys, or why a model
                            * could not be; "" when the file has every section */
} tirenv_tir_origin;

/* After tirenv_tir_read(path, tire): for each enveloping model whose section the file lacks,
 * derives its parameters from the file's MF-Tyre keys (UNLOADED_RADIUS, FNOMIN,
 * VERTICAL_STIFFNESS, PFZ1/INFLPRES/NOMPRES, Q_FZ1/Q_FZ2, RIM_RADIUS or WIDTH and
 * ASPECT_RATIO) so that its flat-ground deflection at FNOMIN is the file's, and says so in
 * origin->note. Where it derives the ring of a file whose vertical law is VERTICAL_STIFFNESS
 * alone (no Q_FZ1, Q_FZ2), the cam's Q_FZ2 is identified on that ring with VERTICAL_STIFFNESS
 * its tangent at FNOMIN, and the file's deflection is that law's (docs/models.md 14.2). A
 * derived ring of a file with its own Q_RA1, Q_RA2 is searched on that contact law and the
 * vertical law together (a softening carcass on the shear-coupled tread, said in the note),
 * and a springs model derived on that ring has a sidewall in series (SIDEWALL_STIFFNESS,
 * SIDEWALL_PRELOAD, said in the note).
 * need (TIRENV_TIR_* bits): the models that must describe this tire; one that can be neither
 * read nor derived is TIRENV_EINVAL naming the missing key, where the others
 * keep *tire's values with a note. With TIRENV_TIR_ONLY | TIRENV_TIR_CAM (the caller uses the
 * cam alone), a file whose cam laws are all its own (Q_RA1, Q_RA2 and a vertical law with
 * Q_FZ2 or Q_FZ1) has no ring or springs model derived: its ring and springs keep *tire's
 * values, said in the note. With TIRENV_TIR_ONLY and without TIRENV_TIR_SPRINGS (the ring or
 * the cam alone), a file with a contact law of its own (Q_RA1, Q_RA2), whose ring is searched
 * on its laws alone, has no springs model derived on that ring: its springs keep *tire's
 * values, said in the note. origin (may be NULL): where each model's values came from. On
 * failure *tire is unchanged. */
int tirenv_tir_derive(const char *path, tirenv_tire *tire, unsigned need,
                      tirenv_tir_origin *origin, tirenv_diag *diag);

/* tirenv_tir_read then tirenv_tir_derive on the bytes of one read of path: what a caller
 * does that may be given a pipe or /dev/stdin, which cannot be read twice. On failure *tire
 * is unchanged. */
int tirenv_tir_read_derive(const char *path, tirenv_tire *tire, unsigned need,
                           tirenv_tir_origin *origin, tirenv_diag *diag);

/* tirenv_tir_derive's need for a caller that runs a model of type on a tire file (the one rule
 * the CLI, the FMU and the Python module follow, docs/models.md 14.2): TIRENV_TIR_RING for the
 * ring, TIRENV_TIR_SPRINGS for the springs model, TIRENV_TIR_CAM for the cam, with
 * TIRENV_TIR_ONLY for the ring or the cam alone (the caller uses that model of the tire and no
 * other); 0 for the
 * rigid disc and the point, which do not deflect, for the network, whose load turns into its
 * contact length by its own file's law (14.3), and for NULL. A contact length given to the
 * rigid disc or the point, or to a network whose file records no law, takes the springs
 * model's load: the caller that gives one adds TIRENV_TIR_SPRINGS. */
unsigned tirenv_tir_need(const tirenv_model_type *type, int alone);

/* One key of a .tir file to set by tirenv_tir_update. */
typedef struct {
    const char *section;   /* e.g. "ENVELOPING_SPRINGS" */
    const char *key;       /* e.g. "RADIAL_STIFFNESS" */
    double value;          /* SI; written with 6 significant digits */
} tirenv_tir_value;

/* Sets the n values[] in the .tir file at path in place, keeping every other line, comment
 * and column (the file must state its [UNITS] in SI or not at all: its values are not
 * converted): a key present has its value replaced, a missing one is added after its
 * section's header, a missing section at the end. note (lines separated by '\n') replaces
 * the '!' block between "! tirenv identify: begin" and "! tirenv identify: end" lines, or
 * is added with them after the [MDI_HEADER] keys. The file is replaced atomically (or not
 * at all) and must then read back with tirenv_tir_read. */
int tirenv_tir_update(const char *path, size_t n, const tirenv_tir_value values[],
                      const char *note, tirenv_diag *diag);

TIRENV_END_DECLS
#endif
