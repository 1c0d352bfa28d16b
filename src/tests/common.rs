//! Helpers shared by the integration tests: where the conformance data lies,
//! solver shorthands, the scale-aware comparisons the tests report with, and
//! the GPU tests' adapter (every skip goes through [`skip`]).
#![allow(dead_code)]

use crate::settings::{Backend, Method, Settings};
use crate::tests::reference::solve;
use crate::{Lcp, LcpSolution};

pub use super::skip::{dat_files, fc3d_dir, siconos_dir, skip, Lack};

/// Default settings of `method` on the CPU.
pub fn settings(method: Method) -> Settings {
    Settings::new(Backend::Cpu, method)
}

/// Enumeration visiting every basis.
pub fn all_solutions_settings() -> Settings {
    Settings {
        all_solutions: true,
        ..settings(Method::Enumeration)
    }
}

/// Solves with `method`'s default settings; panics on an `Error` (the tests
/// only hand solvers problems they accept).
pub fn run(lcp: &Lcp, method: Method) -> LcpSolution {
    solve(lcp, &settings(method)).unwrap_or_else(|e| panic!("{}: {e}", method.name()))
}

/// The algorithms the reference solves with.
pub const METHODS: [Method; 3] = [Method::Enumeration, Method::Lemke, Method::Pgs];

/// ‖v‖∞.
pub fn inf_norm(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

/// max_i |a_i − b_i|.
pub fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
}

/// ‖M‖∞: the largest absolute row sum.
pub fn matrix_inf_norm(lcp: &Lcp) -> f64 {
    let n = lcp.n();
    (0..n)
        .map(|i| (0..n).map(|j| lcp.at(i, j).abs()).sum::<f64>())
        .fold(0.0, f64::max)
}

/// The scale of w for solutions of size up to `zmax`: ‖q‖∞ + ‖M‖∞·zmax, the
/// size of the terms whose sum is w. Differences in w are measured against it.
pub fn w_scale(lcp: &Lcp, zmax: f64) -> f64 {
    (inf_norm(&lcp.q) + matrix_inf_norm(lcp) * zmax).max(f64::MIN_POSITIVE)
}

/// Relative difference of two w vectors of `lcp` whose z are `za`, `zb`:
/// max|wa − wb| / (‖q‖∞ + ‖M‖∞ · max(‖za‖∞, ‖zb‖∞)).
pub fn w_rel_diff(lcp: &Lcp, za: &[f64], wa: &[f64], zb: &[f64], wb: &[f64]) -> f64 {
    max_diff(wa, wb) / w_scale(lcp, inf_norm(za).max(inf_norm(zb)))
}

/// Relative difference of two z vectors: max|za − zb| / max(‖za‖∞, ‖zb‖∞)
/// (0 when both are zero).
pub fn z_rel_diff(za: &[f64], zb: &[f64]) -> f64 {
    let s = inf_norm(za).max(inf_norm(zb));
    if s == 0.0 {
        0.0
    } else {
        max_diff(za, zb) / s
    }
}

/// Is the symmetric part of M positive definite, with the smallest Cholesky
/// pivot at least `rel_tol` times the largest diagonal entry? Then the LCP's
/// solution is unique. (For the symmetric matrices of contact islands this is
/// M itself.)
pub fn is_positive_definite(lcp: &Lcp, rel_tol: f64) -> bool {
    let n = lcp.n();
    let mut a: Vec<f64> = (0..n * n)
        .map(|k| 0.5 * (lcp.m[k] + lcp.at(k % n, k / n)))
        .collect();
    let dmax = (0..n).map(|i| a[i * n + i]).fold(0.0f64, f64::max);
    if dmax.is_nan() || dmax <= 0.0 {
        return false;
    }
    for j in 0..n {
        let mut d = a[j * n + j];
        for k in 0..j {
            d -= a[j * n + k] * a[j * n + k];
        }
        if d.is_nan() || d <= rel_tol * dmax {
            return false;
        }
        let l = d.sqrt();
        a[j * n + j] = l;
        for i in j + 1..n {
            let mut s = a[i * n + j];
            for k in 0..j {
                s -= a[i * n + k] * a[j * n + k];
            }
            a[i * n + j] = s / l;
        }
    }
    true
}

/// A GPU context at `precision` for the GPU tests (the environment's
/// adapter choice, `LCPBATCH_GPU_*`). None, after a [`skip`], when f64 is
/// asked of an adapter without SHADER_F64 ([`Lack::F64`]), or when there is
/// no adapter at all ([`Lack::Adapter`]; the error says how to install one).
pub fn gpu_context(precision: crate::gpu::Precision) -> Option<crate::gpu::GpuContext> {
    use crate::gpu::{GpuContext, GpuOptions, Precision};
    let mut o = GpuOptions::from_env().expect("GPU environment variables");
    o.precision = precision;
    match GpuContext::new(&o) {
        Ok(c) => Some(c),
        Err(e) if precision == Precision::F64 && e.to_string().contains("SHADER_F64") => {
            skip(Lack::F64, &format!("the f64 run: {e}"));
            None
        }
        Err(e) => {
            skip(Lack::Adapter, &format!("no GPU adapter ({e})"));
            None
        }
    }
}

/// The environment's GPU settings at f64 where its adapter has SHADER_F64,
/// else (after a [`skip`] of the f64 part, [`Lack::F64`]) at f32; None
/// (see [`gpu_context`]) without an adapter.
pub fn gpu_settings_or_skip() -> Option<crate::GpuSettings> {
    use crate::gpu::Precision;
    let mut g = crate::GpuSettings::from_env().expect("GPU environment variables");
    let ctx = gpu_context(Precision::Auto)?;
    if ctx.precision() != Precision::F64 {
        skip(
            Lack::F64,
            &format!(
                "the f64 part: adapter `{}` has no SHADER_F64 (its GPU runs are in {})",
                ctx.adapter_info().name,
                ctx.precision().name()
            ),
        );
    }
    g.precision = ctx.precision();
    Some(g)
}

/// The non-symmetric M of the 3×3 Lemke walk-through (`tests/seeds.rs`;
/// zero diagonal: no principal pivot order from the empty basis) with
/// q = (−3, 6, −1), (−3, 6, 1) and (1, 1, 1).
pub fn seed_002_problems() -> Vec<Lcp> {
    [[-3.0, 6.0, -1.0], [-3.0, 6.0, 1.0], [1.0, 1.0, 1.0]]
        .iter()
        .map(|q| {
            Lcp::new(
                vec![0.0, -1.0, 2.0, 2.0, 0.0, -2.0, -1.0, 1.0, 0.0],
                q.to_vec(),
            )
            .unwrap()
        })
        .collect()
}

/// Fixed-seed physical islands of at most `max_n` contacts: `count` random
/// islands of 1…max_n contacts (mass ratios 1, 1e2, 1e4 in turn), a box
/// resting on 4 coplanar contacts, the chain of four coupled bodies
/// ([`crate::generate::seed_chain`]) and 10 demo worlds; then
/// [`seed_002_problems`].
pub fn physical_islands(seed: u64, count: usize, max_n: usize) -> Vec<Lcp> {
    use crate::generate::{box_on_ground, demo_world, random_island, seed_chain, Rng};
    let mut rng = Rng::new(seed);
    let mut scenes = vec![box_on_ground(1.0, 0.5), seed_chain(0.3)];
    for k in 0..count {
        scenes.push(random_island(
            &mut rng,
            1 + k % max_n,
            [1.0, 1e2, 1e4][k % 3],
        ));
    }
    for _ in 0..10 {
        scenes.push(demo_world(&mut rng));
    }
    let mut lcps: Vec<Lcp> = scenes
        .iter()
        .flat_map(|s| crate::tests::reference::build(s, "scene").unwrap().2)
        .filter(|l| l.n() <= max_n)
        .collect();
    lcps.extend(seed_002_problems());
    lcps
}
