/* tirenv's, not the Reference FMUs': fmusim's --solver cvode without SUNDIALS. The interop test
 * drives a co-simulation FMU, which brings its own solver, so fmusim is built without CVode
 * (Debian's libsundials-dev pulls in MPI, PETSc and a Fortran compiler); asking for it fails
 * here with a message instead of at link time. SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>

#include "FMICVode.h"

FMISolver *FMICVodeCreate(const FMISolverParameters *solverFunctions)
{
    (void)solverFunctions;
    fprintf(stderr, "fmusim: built for tirenv's tests without SUNDIALS: no --solver cvode\n");
    return NULL;
}

void FMICVodeFree(FMISolver *solver)
{
    (void)solver;
}

FMISolverStatus FMICVodeStep(FMISolver *solver, double nextTime, double *timeReached,
                             bool *stateEvent)
{
    (void)solver, (void)nextTime, (void)timeReached, (void)stateEvent;
    return FMISolverError;
}

FMISolverStatus FMICVodeReset(FMISolver *solver, double time)
{
    (void)solver, (void)time;
    return FMISolverError;
}
