/* Private to the library: the property-file engine behind the .tir tire file and the .veh
 * vehicle file. A format is a schema (a table of keys with where each value goes in a struct,
 * its sections, a physical check); the engine reads, overrides (--set) and writes it, so the
 * formats share one syntax and one set of error messages.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_PROPFILE_H
#define TIRENV_PROPFILE_H

#include <stddef.h>
#include <stdio.h>

#include "formats/units.h"
#include "tirenv/error.h"

/* How a key's value is parsed and where it goes. */
typedef enum {
    TIRENV_PROPFILE_REAL,  /* a finite double at offset */
    TIRENV_PROPFILE_COUNT, /* a positive integer, stored as size_t at offset */
    TIRENV_PROPFILE_NAME,  /* one of names[], stored as its index (an int or an enum of int's
                            * size) at offset */
    TIRENV_PROPFILE_UNIT,  /* one of names[] (the first is written), or with converts any
                            * unit of its quantity that formats/units.c knows; stores nothing,
                            * but converts the file's REAL values to SI */
    TIRENV_PROPFILE_PATH   /* a file path, quoted or not, stored as a string in a char array
                            * of size bytes at offset; a relative path read from a file is
                            * taken relative to that file's directory */
} tirenv_propfile__kind;

typedef struct {
    const char *section;
    const char *key;
    tirenv_propfile__kind kind;
    size_t offset;           /* into the schema's struct; unused for UNIT */
    const char *comment;     /* unit and meaning, written after the value */
    size_t size;             /* PATH: capacity of the char array, '\0' included */
    const char *names[4];    /* NAME: the names of values 0, 1...; UNIT: accepted spellings */
    const char *noun;        /* NAME: what the names are, for messages ("method") */
    int converts;            /* UNIT: any unit of quantity `unit` is read and converted */
    tirenv_unit_kind unit;   /* UNIT: the quantity this key sets the unit of */
    /* REAL: the value's dimension as exponents of the [UNITS] quantities (N/m/rad: length -1,
     * force 1, angle -1); a value read from a file is converted to SI with them. */
    signed char dim[TIRENV_UNIT_KINDS];
    unsigned given;          /* a bit set in the schema's given field when the key has a
                              * value from a file or --set; 0: not tracked */
    int omit_zero;           /* REAL: written only when not 0, for a key whose 0 means "none"
                              * (MF-Tyre's Q_FZ1, PFZ1), so that files without it stay as
                              * they were */
    int omit_nan;            /* REAL: written only when not NAN, for a key whose absence
                              * means "none given" (VERTICAL_DAMPING, TIRE_STIFFNESS) */
} tirenv_propfile__key;

/* Table entries. The macro parameters avoid the member names: a parameter called key would
 * replace the designator .key too. */
#define TIRENV_PROPFILE_KEY(type, sec, name, what, member, text)                               \
    {.section = (sec), .key = (name), .kind = (what), .offset = offsetof(type, member),        \
     .comment = (text)}
#define TIRENV_PROPFILE_UNIT_KEY(name, text, ...)                                              \
    {.section = "UNITS", .key = (name), .kind = TIRENV_PROPFILE_UNIT, .comment = (text),       \
     .names = {__VA_ARGS__}}

/* A [UNITS] key whose every unit of the quantity is read, and values converted to SI. */
#define TIRENV_PROPFILE_CONVERTED_UNIT(name, text, si, quantity)                               \
    {.section = "UNITS", .key = (name), .kind = TIRENV_PROPFILE_UNIT, .comment = (text),       \
     .names = {si}, .converts = 1, .unit = (quantity)}

/* The [UNITS] section of MF-Tyre and Adams files, converted to SI. */
#define TIRENV_PROPFILE_CONVERTED_UNITS                                                        \
    TIRENV_PROPFILE_CONVERTED_UNIT("LENGTH", "lengths in m", "meter", TIRENV_UNIT_LENGTH),     \
    TIRENV_PROPFILE_CONVERTED_UNIT("FORCE", "forces in N", "newton", TIRENV_UNIT_FORCE),       \
    TIRENV_PROPFILE_CONVERTED_UNIT("ANGLE", "angles in rad", "radians", TIRENV_UNIT_ANGLE),    \
    TIRENV_PROPFILE_CONVERTED_UNIT("MASS", "masses in kg", "kg", TIRENV_UNIT_MASS),            \
    TIRENV_PROPFILE_CONVERTED_UNIT("TIME", "times in s", "second", TIRENV_UNIT_TIME),          \
    TIRENV_PROPFILE_CONVERTED_UNIT("PRESSURE", "pressures in Pa", "pascal", TIRENV_UNIT_PRESSURE)

/* The [UNITS] section of an SI-only file: any other unit is refused rather than converted. */
#define TIRENV_PROPFILE_SI_UNITS                                                               \
    TIRENV_PROPFILE_UNIT_KEY("LENGTH", "lengths in m", "meter"),                               \
    TIRENV_PROPFILE_UNIT_KEY("FORCE", "forces in N", "newton"),                                \
    TIRENV_PROPFILE_UNIT_KEY("ANGLE", "angles in rad", "radians", "rad"),                      \
    TIRENV_PROPFILE_UNIT_KEY("MASS", "masses in kg", "kg"),                                    \
    TIRENV_PROPFILE_UNIT_KEY("TIME", "times in s", "second", "sec")

/* In a strict section an unknown key is an error (a typo); in a lenient one, shared with
 * another program's format, it is skipped. */
typedef struct {
    const char *name;
    int strict;
} tirenv_propfile__section;

typedef struct {
    const tirenv_propfile__key *keys;
    size_t n_keys;
    const tirenv_propfile__section *sections; /* in the order they are written */
    size_t n_sections;
    /* An unknown section whose name starts with this is a typo and an error; any other
     * unknown section belongs to another program and is skipped. "" makes every unknown
     * section an error. */
    const char *own_prefix;
    const char *first_section; /* suggested when text comes before any section */
    size_t size;               /* of the struct the keys' offsets point into */
    /* The physical check on a whole struct: TIRENV_OK, or a status with diag->field set to
     * the offending key ("KEY", or "SECTION.KEY" where the key is in several sections). */
    int (*check)(const void *obj, tirenv_diag *diag);
    /* Writes what comes before the first section (a header, comments). */
    void (*preamble)(FILE *fp);
    /* Where the keys' given bits are kept (an unsigned in the struct), and all of them: a
     * file read clears them, then sets those of the keys it has; --set sets its key's. */
    size_t given_offset;
    unsigned given_mask;     /* 0: nothing tracked */
} tirenv_propfile__schema;

/* Reads path over *obj (only the keys present change), converting REAL values to SI by the
 * file's [UNITS], then checks the result; *obj changes only if everything passes. A file
 * that sets none of the keys is an error (an empty file is not a tire), and so is a key of
 * the schema met in another section the schema reads (it would be ignored there). Errors
 * name file, line, column (when it helps) and key. */
int tirenv_propfile__read(const tirenv_propfile__schema *s, const char *path, void *obj,
                          tirenv_diag *diag);
/* tirenv_propfile__read that also returns, on success, the bytes read (*text, *len bytes,
 * malloc'd, the caller frees; NULL on failure): the file is read once, and a second schema
 * reads the same bytes by tirenv_propfile__read_text, which a pipe or /dev/stdin needs. */
int tirenv_propfile__read_kept(const tirenv_propfile__schema *s, const char *path, void *obj,
                               char **text, size_t *len, tirenv_diag *diag);
/* tirenv_propfile__read on len bytes of text read from path before (errors name path). */
int tirenv_propfile__read_text(const tirenv_propfile__schema *s, const char *path,
                               const char *text, size_t len, void *obj, tirenv_diag *diag);

/* Applies "KEY=VALUE" or "SECTION.KEY=VALUE" (not [UNITS] keys), parsed as in a file, then
 * checks; *obj changes only if both pass. A key in several sections needs its section.
 * Relative paths stay relative to the working directory. Errors name file "--set". */
int tirenv_propfile__set(const tirenv_propfile__schema *s, void *obj, const char *assignment,
                         tirenv_diag *diag);

/* Checks *obj and writes it atomically (tirenv_outfile) with every key (but an omit_zero key
 * at 0) and its comment. A
 * relative path is written as an absolute one when the file goes to another directory than
 * the working one, so that reading the file back names the same file. */
int tirenv_propfile__write(const tirenv_propfile__schema *s, const char *path,
                           const void *obj, tirenv_diag *diag);

/* The same with header (if not NULL) written in place of the schema's preamble. */
int tirenv_propfile__write_headed(const tirenv_propfile__schema *s, const char *path,
                                  const void *obj, const char *header, tirenv_diag *diag);

/* The settable keys (not [UNITS]) of s, in table order: the i-th one's key and (if section
 * is not NULL) section, or NULL past the last. */
const char *tirenv_propfile__key_at(const tirenv_propfile__schema *s, size_t i,
                                    const char **section);

/* The value of "KEY" or "SECTION.KEY" in *obj as text into buf (n bytes), as the writer
 * writes it: the shortest text that reads back to the same double, a count, a name unquoted,
 * a path; *kind (if not NULL) its kind. An unknown or ambiguous key, or a buffer too small,
 * is an error naming the key (file "get"). */
int tirenv_propfile__get(const tirenv_propfile__schema *s, const void *obj, const char *field,
                         char *buf, size_t n, tirenv_propfile__kind *kind, tirenv_diag *diag);

/* ---- What the RDF road and OpenCRG header readers share with this engine ------------ */

/* Where the text being parsed came from, so that an error names file, line and column. */
typedef struct {
    const char *file;   /* name for messages */
    size_t line;        /* 1-based, or 0 for none */
    const char *base;   /* start of the line: columns count from here; NULL for no column */
    tirenv_diag *diag;
} tirenv_propfile__where;

/* Records TIRENV_EPARSE at w's file and line for field, with the column of at when both at
 * and w->base are set. */
int tirenv_propfile__fail(const tirenv_propfile__where *w, const char *at, const char *field,
                          const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* s without white space at either end (the end cut in place). */
char *tirenv_propfile__trim(char *s);

/* A finite number that fills text (trimmed): strtod with an end check. Errors name key and
 * point at the offending character. */
int tirenv_propfile__real(const tirenv_propfile__where *w, const char *key, const char *text,
                          double *out);

#endif
