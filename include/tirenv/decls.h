/* tirenv: how every public header opens and closes its declarations: C linkage for C++
 * callers, and default symbol visibility, so that a shared library built with
 * -fvisibility=hidden exports exactly what the public headers declare and nothing private.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_DECLS_H
#define TIRENV_DECLS_H

#if defined(__GNUC__)
#define TIRENV_VISIBLE_PUSH _Pragma("GCC visibility push(default)")
#define TIRENV_VISIBLE_POP _Pragma("GCC visibility pop")
#else
#define TIRENV_VISIBLE_PUSH
#define TIRENV_VISIBLE_POP
#endif

#ifdef __cplusplus
#define TIRENV_BEGIN_DECLS extern "C" { TIRENV_VISIBLE_PUSH
#define TIRENV_END_DECLS TIRENV_VISIBLE_POP }
#else
#define TIRENV_BEGIN_DECLS TIRENV_VISIBLE_PUSH
#define TIRENV_END_DECLS TIRENV_VISIBLE_POP
#endif

#endif
