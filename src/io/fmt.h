/* Private to the library and its tests: the number formatter's fast path alone.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_DATA_FMT_H
#define TIRENV_DATA_FMT_H

/* tirenv_fmt_g without the snprintf fallback: 1 with buf written as printf("%.*g") would,
 * or 0 where the fast path cannot decide (also for 0, inf, nan and precision outside 1..17),
 * buf then undefined. */
int tirenv_fmt__g_fast(double x, int precision, char *buf);

#endif
