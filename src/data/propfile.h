/* Private to the library: the property-file engine behind the .tir tire file and the .veh
 * vehicle file. A format is a schema (a table of keys with where each value goes in a struct,
 * its sections, a physical check); the engine reads, overrides (--set) and writes it, so the
 * formats share one syntax and one set of error messages.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TIRENV_PROPFILE_H
#define TIRENV_PROPFILE_H

#include <stddef.h>
#include <stdio.h>

#include "tirenv/error.h"

/* How a key's value is parsed and where it goes. */
typedef enum {
    TIRENV_PROPFILE_REAL,  /* a finite double at offset */
    TIRENV_PROPFILE_COUNT, /* a positive integer, stored as size_t at offset */
    TIRENV_PROPFILE_NAME,  /* one of names[], stored as its index (an int or an enum of int's
                            * size) at offset */
    TIRENV_PROPFILE_UNIT,  /* one of names[] (the first is written); stores nothing */
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
} tirenv_propfile__key;

/* Table entries. The macro parameters avoid the member names: a parameter called key would
 * replace the designator .key too. */
#define TIRENV_PROPFILE_KEY(type, sec, name, what, member, text)                               \
    {.section = (sec), .key = (name), .kind = (what), .offset = offsetof(type, member),        \
     .comment = (text)}
#define TIRENV_PROPFILE_UNIT_KEY(name, text, ...)                                              \
    {.section = "UNITS", .key = (name), .kind = TIRENV_PROPFILE_UNIT, .comment = (text),       \
     .names = {__VA_ARGS__}}

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
} tirenv_propfile__schema;

/* Reads path over *obj (only the keys present change), then checks the result; *obj changes
 * only if everything passes. Errors name file, line, column (when it helps) and key. */
int tirenv_propfile__read(const tirenv_propfile__schema *s, const char *path, void *obj,
                          tirenv_diag *diag);

/* Applies "KEY=VALUE" or "SECTION.KEY=VALUE" (not [UNITS] keys), parsed as in a file, then
 * checks; *obj changes only if both pass. A key in several sections needs its section.
 * Relative paths stay relative to the working directory. Errors name file "--set". */
int tirenv_propfile__set(const tirenv_propfile__schema *s, void *obj, const char *assignment,
                         tirenv_diag *diag);

/* Checks *obj and writes it atomically (tirenv_outfile) with every key and its comment. A
 * relative path is written as an absolute one when the file goes to another directory than
 * the working one, so that reading the file back names the same file. */
int tirenv_propfile__write(const tirenv_propfile__schema *s, const char *path,
                           const void *obj, tirenv_diag *diag);

#endif
