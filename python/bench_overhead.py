"""The Python call's overhead over the Rust call, on one batch.

Times, on the same 20,000 problems of n = 8 and the same solver (device,
pipelines, threads):

- python: ``Solver.solve(M, q)`` end to end (argument checks, copying the
  arrays into the library's problems, the chunks, the result arrays);
- rust: the library's ``Solver::solve_lcps`` on the whole batch, timed in
  Rust around the call with the problems already built
  (``NativeSolver.time_solve_lcps``, there for this script), and its
  ``Solver::solve_dense`` on the same arrays read in place
  (``time_solve_lcps(..., dense=True)``). The figures over "the Rust call"
  take whichever of the two has the lower median in the run (the fastest
  call a Rust user has for the data); both are printed.

Runs alternate (python, rust, python, …) so that a noisy machine hits both
alike. Three figures, target ≤ 10%: the ratio of the medians, the ratio of
the minimums (the least disturbed runs), and the time each Python call spent
outside the library (its wall time less the library's own total, measured
inside the same call: the least noisy of the three) over the Rust call.

    python python/bench_overhead.py [--problems 20000] [--n 8] [--repeats 9] [--backend cpu] [--threads 0]

With ``--grad``: the differentiable solve of the adapters instead, solve
plus gradient of L = c·z with respect to M and q on the same batch:

- jax: ``jax.jit(jax.value_and_grad(L))`` through ``lcpbatch.jax.solve``
  (two host callbacks per call);
- torch (where installed): ``lcpbatch.torch.solve`` and ``torch.autograd.grad``;
- rust: the library's ``Solver::solve_lcps`` plus its ``lcp_vjp_batch`` on
  the same batch, each timed in Rust with its problems already built
  (``time_solve_lcps``, ``time_lcp_vjp``), and their dense twins reading
  the arrays in place (``Solver::solve_dense``, ``lcp_vjp_dense_into``:
  ``dense=True``); the solve and the VJP each the faster by median in
  the run.

And each adapter's forward alone (the solve, with what a backward needs
kept) against the Rust solve alone. ``--threads 1``: the solver on one
thread (with ``--torch-threads 1``, the one-thread figures). Beside wall
time, the process's CPU seconds of each call (medians; the Rust calls' as a
call of two less a call of one): on one thread the same measure, and the
one a loaded machine disturbs least.

Each adapter is also timed on the same loss with the solve replaced by a
framework op of the same shapes (z = q + M[..., 0]): the framework's own
cost of the loss and its gradient, which any differentiable z pays. The
figures "net" take it off: the adapter's own overhead. On a loaded machine
PyTorch's intra-op threads compete with the solver's (use
``--torch-threads 1`` to see the adapter without that).

Target: each adapter ≤ 10% over the Rust calls (ratios of medians and of
minimums).

With ``--grad --ab PACKAGE``: old and new in one process, paired, the
steadier comparison on a loaded machine (see ``ab_overhead``):

    PYTHONPATH=/tmp/old python -P python/bench_overhead.py --grad --ab lcpbatch_old --threads 1

Where both builds have the XLA FFI handlers, JAX refuses a second
registration of the same names: in the old copy's ``jax.py``, register
them and call them as ``"old_" + name``.
"""

from __future__ import annotations

import argparse
import collections
import importlib
import json
import statistics
import time
from typing import Dict, List, Tuple

import numpy as np

import lcpbatch


def batch(problems: int, n: int, seed: int = 0):
    """Random positive definite M = A Aᵀ + I (contact-like: one solution each)."""
    rng = np.random.default_rng(seed)
    A = rng.standard_normal((problems, n, n))
    M = A @ A.transpose(0, 2, 1) + np.eye(n)
    q = rng.standard_normal((problems, n)) * 3
    return M, q


def adapters(M, q, c, settings: dict, torch_threads: int, package: str = "lcpbatch"):
    """The solve + gradient of each adapter installed, and the same loss's
    gradient without the solve (the framework's own cost), as pairs of
    functions of no argument that return when the gradient is ready, and
    the forward alone (the solve, its graph recorded for a backward).
    ``package``: the lcpbatch build whose adapters are timed (``--ab``)."""
    calls = {}
    try:
        import jax
        import jax.numpy as jnp
    except ImportError:
        print("jax not installed: no jax timing")
    else:
        lcp_jax = importlib.import_module(f"{package}.jax")

        jax.config.update("jax_enable_x64", True)
        Mj, qj, cj = jnp.asarray(M), jnp.asarray(q), jnp.asarray(c)
        step = jax.jit(jax.value_and_grad(
            lambda M, q: jnp.sum(cj * lcp_jax.solve(M, q, **settings)[0]), argnums=(0, 1)))
        base = jax.jit(jax.value_and_grad(lambda M, q: jnp.sum(cj * (q + M[..., 0])), argnums=(0, 1)))
        forward = jax.jit(lambda M, q: lcp_jax.solve(M, q, **settings))
        calls["jax"] = (lambda: jax.block_until_ready(step(Mj, qj)),
                        lambda: jax.block_until_ready(base(Mj, qj)),
                        lambda: jax.block_until_ready(forward(Mj, qj)))
    try:
        import torch
    except ImportError:
        print("torch not installed: no torch timing")
    else:
        lcp_torch = importlib.import_module(f"{package}.torch")

        if torch_threads > 0:
            torch.set_num_threads(torch_threads)
        Mt, qt, ct = (torch.tensor(a) for a in (M, q, c))
        Mt.requires_grad_(True)
        qt.requires_grad_(True)

        def torch_step():
            z, _ = lcp_torch.solve(Mt, qt, **settings)
            return torch.autograd.grad((ct * z).sum(), (Mt, qt))

        def torch_base():
            return torch.autograd.grad((ct * (qt + Mt[..., 0])).sum(), (Mt, qt))

        calls["torch"] = (torch_step, torch_base, lambda: lcp_torch.solve(Mt, qt, **settings))
    return calls


def timed(f) -> Tuple[float, float]:
    """The wall and process CPU seconds of one call of ``f``."""
    t, p = time.perf_counter(), time.process_time()
    f()
    return time.perf_counter() - t, time.process_time() - p


RUST_CALLS = {"solve": ("solve_lcps", "solve_dense"), "vjp": ("vjp_batch", "vjp_dense")}


def rust_round(s, M, q, z, c, parts=("solve", "vjp")) -> Tuple[Dict[str, float], Dict[str, float]]:
    """One round of the Rust calls: the wall seconds of the library's solve
    and VJP, each timed in Rust with its problems built (``solve_lcps``,
    ``vjp_batch``) or on the arrays in place (``solve_dense``,
    ``vjp_dense``), and the process CPU seconds of each (a call of two less
    a call of one: the building cancels)."""
    native = lcpbatch._native
    calls = {"solve_lcps": lambda k: s._native.time_solve_lcps(M, q, k),
             "solve_dense": lambda k: s._native.time_solve_lcps(M, q, k, dense=True),
             "vjp_batch": lambda k: native.time_lcp_vjp(M, q, z, c, k),
             "vjp_dense": lambda k: native.time_lcp_vjp(M, q, z, c, k, dense=True)}
    calls = {key: f for key, f in calls.items() if any(key in RUST_CALLS[p] for p in parts)}
    wall = {key: f(1)[0] for key, f in calls.items()}
    cpu = {}
    for key, f in calls.items():
        p = time.process_time()
        f(2)
        p2 = time.process_time()
        f(1)
        cpu[key] = (p2 - p) - (time.process_time() - p2)
    return wall, cpu


def fastest(wall: Dict, cpu: Dict, out: Dict, calls: Dict = RUST_CALLS) -> None:
    """Per part (solve, VJP) the Rust call with the lower median wall time
    in the run, filed under ``wall["rust", part]``, and the one with the
    lower median CPU time, under ``cpu["rust", part]`` (the baselines);
    every call's medians into ``out``."""
    med = statistics.median
    for part, keys in calls.items():
        for key in keys:
            out[f"rust_{key}_s_median"] = med(wall["rust", key])
            out[f"rust_cpu_{key}_s_median"] = med(cpu["rust", key])
        for kind, d in (("", wall), ("cpu_", cpu)):
            best = min(keys, key=lambda k: med(d["rust", k]))
            out[f"rust_{kind}{part}_baseline"] = best
            d["rust", part] = d["rust", best]


def ab_overhead(args: argparse.Namespace) -> None:
    """``--grad --ab PACKAGE``: this lcpbatch's adapters and another build's
    (importable as PACKAGE, e.g. an old build's package folder copied as
    ``lcpbatch_old`` onto PYTHONPATH), called in turns in one process: per
    iteration each adapter's solve + grad of both builds, the forward of
    both, the framework's own loss and gradient, and the Rust calls, the two
    builds' order reversed every other iteration. Per build: the medians
    over iterations of each iteration's wall-time overheads (net of the
    framework's own, over the Rust solve + VJP; the forward over the Rust
    solve), the process CPU overheads (medians of CPU seconds), and the
    paired saving, old less new, per iteration (medians)."""
    M, q = batch(args.problems, args.n)
    c = np.random.default_rng(1).standard_normal(q.shape)
    settings = dict(backend=args.backend, threads=args.threads)
    s = lcpbatch.Solver(**settings)
    z = s.solve(M, q).z
    sides = {"new": adapters(M, q, c, settings, args.torch_threads),
             "old": adapters(M, q, c, settings, args.torch_threads, args.ab)}
    names = [name for name in sides["new"] if name in sides["old"]]
    for calls in sides.values():
        for fs in calls.values():
            for f in fs:
                f()  # warm-up: compilation, the cached solver, thread pool
    wall: Dict[Tuple[str, ...], List[float]] = collections.defaultdict(list)
    cpu: Dict[Tuple[str, ...], List[float]] = collections.defaultdict(list)
    for i in range(args.repeats):
        order = ("new", "old") if i % 2 == 0 else ("old", "new")
        for name in names:
            for k, part in ((0, "step"), (2, "forward")):
                for side in order:
                    w, p = timed(sides[side][name][k])
                    wall[side, name, part].append(w)
                    cpu[side, name, part].append(p)
            w, p = timed(sides["new"][name][1])
            wall["base", name].append(w)
            cpu["base", name].append(p)
        w, p = rust_round(s, M, q, z, c)
        for key in w:
            wall["rust", key].append(w[key])
            cpu["rust", key].append(p[key])
    med = statistics.median
    out = {"problems": args.problems, "n": args.n, "device": s.device, "repeats": args.repeats, "old": args.ab}
    fastest(wall, cpu, out)
    rs, rv = med(cpu["rust", "solve"]), med(cpu["rust", "vjp"])
    for name in names:
        for side in ("new", "old"):
            net = [(t - b) / (a + v) - 1 for t, b, a, v in zip(wall[side, name, "step"], wall["base", name],
                                                               wall["rust", "solve"], wall["rust", "vjp"])]
            fw = [t / a - 1 for t, a in zip(wall[side, name, "forward"], wall["rust", "solve"])]
            out[f"{name}_{side}_net_overhead_wall"] = med(net)
            out[f"{name}_{side}_forward_overhead_wall"] = med(fw)
            out[f"{name}_{side}_net_overhead_cpu"] = (med(cpu[side, name, "step"]) - med(cpu["base", name])) / (rs + rv) - 1
            out[f"{name}_{side}_forward_overhead_cpu"] = med(cpu[side, name, "forward"]) / rs - 1
        for part in ("step", "forward"):
            for kind, d in (("wall", wall), ("cpu", cpu)):
                saved = [o - n for o, n in zip(d["old", name, part], d["new", name, part])]
                out[f"{name}_{part}_saved_ms_{kind}"] = 1e3 * med(saved)
    print(json.dumps(out, indent=2))
    for name in names:
        for side in ("old", "new"):
            x = {k: 100 * out[f"{name}_{side}_{k}"] for k in ("net_overhead_wall", "net_overhead_cpu",
                                                           "forward_overhead_wall", "forward_overhead_cpu")}
            print(f"lcpbatch.{name}, {side} ({args.ab if side == 'old' else 'lcpbatch'}): solve + grad net "
                  f"{x['net_overhead_wall']:+.1f}% wall / {x['net_overhead_cpu']:+.1f}% CPU over the Rust solve + "
                  f"VJP; forward {x['forward_overhead_wall']:+.1f}% / {x['forward_overhead_cpu']:+.1f}% over the "
                  f"Rust solve")
        print(f"lcpbatch.{name}: paired saving per call, old less new (medians of {args.repeats}): solve + grad "
              f"{out[f'{name}_step_saved_ms_wall']:.2f} ms wall, {out[f'{name}_step_saved_ms_cpu']:.2f} ms CPU; "
              f"forward {out[f'{name}_forward_saved_ms_wall']:.2f} ms wall, "
              f"{out[f'{name}_forward_saved_ms_cpu']:.2f} ms CPU (Rust {1e3 * rs:.1f} + {1e3 * rv:.1f} ms CPU)")
    print(rust_line(out))


def rust_line(out: Dict) -> str:
    """The Rust calls' medians, and which is each part's baseline."""
    calls = ", ".join(f"{key} {1e3 * out[f'rust_{key}_s_median']:.1f} ms ({1e3 * out[f'rust_cpu_{key}_s_median']:.1f} "
                      f"CPU)" for keys in RUST_CALLS.values() for key in keys)
    return (f"Rust medians: {calls}; baselines (wall) {out['rust_solve_baseline']}, {out['rust_vjp_baseline']}, "
            f"(CPU) {out['rust_cpu_solve_baseline']}, {out['rust_cpu_vjp_baseline']}")


def grad_overhead(args: argparse.Namespace) -> None:
    M, q = batch(args.problems, args.n)
    c = np.random.default_rng(1).standard_normal(q.shape)
    settings = dict(backend=args.backend, threads=args.threads)
    s = lcpbatch.Solver(**settings)
    z = s.solve(M, q).z
    calls = adapters(M, q, c, settings, args.torch_threads)
    for fs in calls.values():
        for f in fs:
            f()  # warm-up: compilation, the cached solver, thread pool
    times = {name: [] for name in calls}
    bases = {name: [] for name in calls}
    forwards = {name: [] for name in calls}
    cpu = {(name, k): [] for name in calls for k in range(3)}
    rust_wall: Dict = collections.defaultdict(list)
    rust_cpu: Dict = collections.defaultdict(list)
    for _ in range(args.repeats):
        for name, fs in calls.items():
            for k, (f, into) in enumerate(zip(fs, (times, bases, forwards))):
                wall, seconds = timed(f)
                into[name].append(wall)
                cpu[name, k].append(seconds)
        wall, seconds = rust_round(s, M, q, z, c)
        for key in wall:
            rust_wall["rust", key].append(wall[key])
            rust_cpu["rust", key].append(seconds[key])
    out = {"problems": args.problems, "n": args.n, "device": s.device, "repeats": args.repeats,
           "torch_threads": args.torch_threads}
    fastest(rust_wall, rust_cpu, out)
    rust_solve = rust_wall["rust", "solve"]
    rust = [a + v for a, v in zip(rust_solve, rust_wall["rust", "vjp"])]
    out.update({"rust_solve_plus_vjp_s_median": statistics.median(rust), "rust_solve_plus_vjp_s_min": min(rust),
                "rust_solve_s_median": statistics.median(rust_solve), "rust_solve_s_min": min(rust_solve),
                "rust_cpu_solve_s_median": statistics.median(rust_cpu["rust", "solve"]),
                "rust_cpu_vjp_s_median": statistics.median(rust_cpu["rust", "vjp"])})
    for name, ts in times.items():
        out[f"{name}_s_median"] = statistics.median(ts)
        out[f"{name}_s_min"] = min(ts)
        out[f"{name}_overhead_of_medians"] = statistics.median(ts) / statistics.median(rust) - 1.0
        out[f"{name}_overhead_of_minimums"] = min(ts) / min(rust) - 1.0
        out[f"{name}_framework_s_median"] = statistics.median(bases[name])
        net = [t - b for t, b in zip(ts, bases[name])]
        out[f"{name}_net_overhead_of_medians"] = statistics.median(net) / statistics.median(rust) - 1.0
        out[f"{name}_net_overhead_of_minimums"] = min(net) / min(rust) - 1.0
        fw = forwards[name]
        out[f"{name}_forward_s_median"] = statistics.median(fw)
        out[f"{name}_forward_overhead_of_medians"] = statistics.median(fw) / statistics.median(rust_solve) - 1.0
        out[f"{name}_forward_overhead_of_minimums"] = min(fw) / min(rust_solve) - 1.0
        # Process CPU seconds, medians: the figures that a loaded machine
        # disturbs least (equal to wall time only on one thread: --threads 1
        # and, for torch, --torch-threads 1).
        med = {k: statistics.median(cpu[name, k]) for k in range(3)}
        rs, rv = out["rust_cpu_solve_s_median"], out["rust_cpu_vjp_s_median"]
        out[f"{name}_cpu_net_overhead"] = (med[0] - med[1]) / (rs + rv) - 1.0
        out[f"{name}_cpu_forward_overhead"] = med[2] / rs - 1.0
    print(json.dumps(out, indent=2))
    for name in times:
        print(f"overhead of lcpbatch.{name} solve + grad over the Rust solve + VJP ({args.problems} problems, "
              f"n = {args.n}, {s.device}): medians {100 * out[f'{name}_overhead_of_medians']:+.1f}%, "
              f"minimums {100 * out[f'{name}_overhead_of_minimums']:+.1f}%; net of the framework's own "
              f"{1e3 * out[f'{name}_framework_s_median']:.1f} ms: medians "
              f"{100 * out[f'{name}_net_overhead_of_medians']:+.1f}%, minimums "
              f"{100 * out[f'{name}_net_overhead_of_minimums']:+.1f}% "
              f"({1e3 * out['rust_solve_plus_vjp_s_median']:.1f} ms Rust median of {args.repeats})")
        print(f"overhead of the lcpbatch.{name} forward alone over the Rust solve: medians "
              f"{100 * out[f'{name}_forward_overhead_of_medians']:+.1f}%, minimums "
              f"{100 * out[f'{name}_forward_overhead_of_minimums']:+.1f}% "
              f"({1e3 * out['rust_solve_s_median']:.1f} ms Rust median)")
        print(f"process CPU seconds, medians, lcpbatch.{name}: solve + grad net "
              f"{100 * out[f'{name}_cpu_net_overhead']:+.1f}% over the Rust solve + VJP, forward "
              f"{100 * out[f'{name}_cpu_forward_overhead']:+.1f}% over the Rust solve "
              f"({1e3 * out['rust_cpu_solve_s_median']:.1f} + {1e3 * out['rust_cpu_vjp_s_median']:.1f} ms)")
    print(rust_line(out))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--problems", type=int, default=20_000)
    ap.add_argument("--n", type=int, default=8)
    ap.add_argument("--repeats", type=int, default=9)
    ap.add_argument("--backend", default="cpu")
    ap.add_argument("--solver", default="auto")
    ap.add_argument("--threads", type=int, default=0, help="the solver's threads (0: every core)")
    ap.add_argument("--grad", action="store_true", help="time the adapters' solve + gradient")
    ap.add_argument("--torch-threads", type=int, default=0,
                    help="torch.set_num_threads for --grad (0: PyTorch's default)")
    ap.add_argument("--ab", metavar="PACKAGE",
                    help="with --grad: pair this build's adapters with another build's, importable as PACKAGE, "
                         "called in turns in one process")
    args = ap.parse_args()
    if args.grad:
        (ab_overhead if args.ab else grad_overhead)(args)
        return

    M, q = batch(args.problems, args.n)
    s = lcpbatch.Solver(backend=args.backend, method=args.solver, threads=args.threads)
    s.solve(M, q)  # warm-up: pipelines, thread pool, page faults
    python, python_cpu, inside = [], [], []
    wall: Dict = collections.defaultdict(list)
    cpu: Dict = collections.defaultdict(list)
    for _ in range(args.repeats):
        t, p = time.perf_counter(), time.process_time()
        r = s.solve(M, q)
        python.append(time.perf_counter() - t)
        python_cpu.append(time.process_time() - p)
        inside.append(r.report.timings["total"])
        w, p = rust_round(s, M, q, None, None, parts=("solve",))
        for key in w:
            wall["rust", key].append(w[key])
            cpu["rust", key].append(p[key])
    rusts: Dict = {}
    fastest(wall, cpu, rusts, {"solve": RUST_CALLS["solve"]})
    baseline, rust = rusts["rust_solve_baseline"], wall["rust", "solve"]
    py_med, rs_med = statistics.median(python), statistics.median(rust)
    cpu_overhead = statistics.median(python_cpu) / statistics.median(cpu["rust", "solve"]) - 1.0
    outside = statistics.median(p - i for p, i in zip(python, inside))
    out = {
        "problems": args.problems,
        "n": args.n,
        "device": s.device,
        "solver": args.solver,
        "repeats": args.repeats,
        "python_call_s_median": py_med,
        "rust_call_s_median": rs_med,
        "rust_call": baseline,
        **rusts,
        "python_cpu_s_median": statistics.median(python_cpu),
        "cpu_overhead_of_medians": cpu_overhead,
        "python_call_s_min": min(python),
        "rust_call_s_min": min(rust),
        "outside_library_s_median": outside,
        "overhead_of_medians": py_med / rs_med - 1.0,
        "overhead_of_minimums": min(python) / min(rust) - 1.0,
        "overhead_outside_library": outside / rs_med,
        "statuses": r.report.statuses,
    }
    print(json.dumps(out, indent=2))
    print(f"overhead of the Python call over the Rust call ({args.problems} problems, n = {args.n}, "
          f"{s.device}): medians {100 * out['overhead_of_medians']:+.1f}%, minimums "
          f"{100 * out['overhead_of_minimums']:+.1f}%, time outside the library "
          f"{1e3 * outside:.2f} ms = {100 * out['overhead_outside_library']:.1f}% of the Rust call "
          f"({1e3 * rs_med:.1f} ms median of {args.repeats}, {baseline}; solve_lcps "
          f"{1e3 * out['rust_solve_lcps_s_median']:.1f} ms, solve_dense {1e3 * out['rust_solve_dense_s_median']:.1f} ms)")
    print(f"process CPU seconds, medians: the Python call {1e3 * out['python_cpu_s_median']:.1f} ms, "
          f"{100 * cpu_overhead:+.1f}% over the Rust call ({rusts['rust_cpu_solve_baseline']}; solve_lcps "
          f"{1e3 * out['rust_cpu_solve_lcps_s_median']:.1f} ms, solve_dense {1e3 * out['rust_cpu_solve_dense_s_median']:.1f} ms)")


if __name__ == "__main__":
    main()
