/* Siconos' own FrictionContact3D solvers on Siconos .dat files, timed
 * around the fc3d_driver call alone: the same-machine yardstick of
 * `lcpbatch bench --friction --fc3d-dir DIR` (BENCHMARKS.md). Built and
 * run by benches/siconos_fc3d.sh against Debian's libsiconos-numerics-dev
 * (4.4.0); never a test dependency.
 *
 * Usage: siconos_fc3d FILE SOLVER [MAX_ITER]   (SOLVER: NSN_AC, NSGS, PROX)
 * Prints one line: file, solver, info (0 = converged), iterations, error,
 * wall seconds, CPU seconds (user + system, the process). From r = 0,
 * tolerance 1e-8, as in ../shared/conformance/siconos-fc3d-large. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <FrictionContactProblem.h>
#include <Friction_cst.h>
#include <NonSmoothDrivers.h>
#include <SolverOptions.h>

static double seconds(clockid_t clock) {
  struct timespec t;
  clock_gettime(clock, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: %s FILE NSN_AC|NSGS|PROX [MAX_ITER]\n", argv[0]);
    return 2;
  }
  int id;
  if (!strcmp(argv[2], "NSN_AC")) id = SICONOS_FRICTION_3D_NSN_AC;
  else if (!strcmp(argv[2], "NSGS")) id = SICONOS_FRICTION_3D_NSGS;
  else if (!strcmp(argv[2], "PROX")) id = SICONOS_FRICTION_3D_PROX;
  else {
    fprintf(stderr, "%s: unknown solver %s\n", argv[0], argv[2]);
    return 2;
  }
  FrictionContactProblem *p = frictionContact_new_from_filename(argv[1]);
  if (!p) {
    fprintf(stderr, "%s: cannot read %s\n", argv[0], argv[1]);
    return 1;
  }
  int n = 3 * p->numberOfContacts;
  double *r = calloc(n, sizeof(double)), *u = calloc(n, sizeof(double));
  SolverOptions *o = solver_options_create(id);
  o->dparam[SICONOS_DPARAM_TOL] = 1e-8;
  o->iparam[SICONOS_IPARAM_MAX_ITER] = argc > 3 ? atoi(argv[3]) : 100000;
  double w0 = seconds(CLOCK_MONOTONIC), c0 = seconds(CLOCK_PROCESS_CPUTIME_ID);
  int info = fc3d_driver(p, r, u, o);
  double c1 = seconds(CLOCK_PROCESS_CPUTIME_ID), w1 = seconds(CLOCK_MONOTONIC);
  printf("%s %s info=%d it=%d error=%.3e wall=%.4f cpu=%.4f\n", argv[1], argv[2], info,
         o->iparam[SICONOS_IPARAM_ITER_DONE], o->dparam[SICONOS_DPARAM_RESIDU], w1 - w0, c1 - c0);
  solver_options_delete(o);
  frictionContactProblem_free(p);
  free(r);
  free(u);
  return 0;
}
