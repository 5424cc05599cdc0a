/* GSL's CBLAS reports a bad argument through cblas_xerbla, which in libgslcblas.a prints to
 * stderr and aborts. That object is not position independent (it addresses stderr directly),
 * so it cannot go into the FMU's shared object; this definition replaces it. GSL never passes
 * a bad argument to its own CBLAS: reaching here is a bug, and the FMU stops as CBLAS would,
 * without printing (an FMU reports through its logger, which is not reachable from here).
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include <stdlib.h>

void cblas_xerbla(int p, const char *rout, const char *form, ...);

void cblas_xerbla(int p, const char *rout, const char *form, ...)
{
    (void)p, (void)rout, (void)form;
    abort();
}
