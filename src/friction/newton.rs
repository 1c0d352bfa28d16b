//! Alart–Curnier semismooth Newton with a backtracking line search (as
//! Siconos' FC3D_NSN_AC): the exact solver that polishes an island to the
//! rounding of f64.
//!
//! # The equation
//! Per contact i, with u = W r + q, ρ_i > 0, x_n = r_n − ρ u_n,
//! x_t = r_t − ρ u_t and the disc radius λ = μ max(0, x_n):
//!
//! ```text
//! Φ_n = r_n − max(0, x_n),      Φ_t = r_t − P_λ(x_t)
//! ```
//!
//! P_λ the projection on the disc of radius λ. Φ = 0 exactly at a Coulomb
//! solution (Alart & Curnier 1991). Its generalized Jacobian, with
//! ∂x_n = e_n − ρ W_n (row), ∂x_t = E_t − ρ W_t:
//! - x_n > 0: ∂Φ_n = ρ W_n, else ∂Φ_n = e_n (take-off);
//! - ‖x_t‖ ≤ λ (stick): ∂Φ_t = ρ W_t;
//! - else (slide), z = x_t/‖x_t‖: ∂Φ_t = E_t − z ∂λ − (λ/‖x_t‖)(I − z zᵀ) ∂x_t,
//!   ∂λ = μ ∂x_n when x_n > 0, else 0.
//!
//! ρ_i = 1 / W_ii,nn (1 when that is not positive). The step Δ solves
//! ∂Φ Δ = −Φ (a Levenberg–Marquardt step where ∂Φ is singular); the merit
//! ½‖Φ‖² decides the step length (Armijo, halving).

use super::problem::FrictionProblem;
use super::residual::coulomb_error;
use crate::linalg::{solve_in_place, PIVOT_TOL};

/// Φ(r) (3k) and, when `jacobian` is Some, its generalized Jacobian
/// (3k × 3k, row-major) written there.
fn alart_curnier(
    p: &FrictionProblem,
    r: &[f64],
    rho: &[f64],
    jacobian: Option<&mut [f64]>,
) -> Vec<f64> {
    let n = p.dim();
    let u = p.velocity(r);
    let mut phi = vec![0.0; n];
    let mut jac = jacobian;
    for (i, &mu) in p.mu.iter().enumerate() {
        let (kn, k1, k2) = (3 * i, 3 * i + 1, 3 * i + 2);
        let rh = rho[i];
        let xn = r[kn] - rh * u[kn];
        let xt = [r[k1] - rh * u[k1], r[k2] - rh * u[k2]];
        let lambda = mu * xn.max(0.0);
        let s = xt[0].hypot(xt[1]);
        phi[kn] = r[kn] - xn.max(0.0);
        let sticks = s <= lambda;
        let pt = if sticks {
            xt
        } else {
            [lambda * xt[0] / s, lambda * xt[1] / s]
        };
        phi[k1] = r[k1] - pt[0];
        phi[k2] = r[k2] - pt[1];
        let Some(j) = jac.as_deref_mut() else {
            continue;
        };
        // Row helpers: ∂x_d = e_d − ρ W_d.
        let dx = |d: usize, col: usize| (if d == col { 1.0 } else { 0.0 }) - rh * p.w[d * n + col];
        for col in 0..n {
            j[kn * n + col] = if xn > 0.0 {
                rh * p.w[kn * n + col]
            } else if col == kn {
                1.0
            } else {
                0.0
            };
            if sticks {
                j[k1 * n + col] = rh * p.w[k1 * n + col];
                j[k2 * n + col] = rh * p.w[k2 * n + col];
            } else {
                let z = [xt[0] / s, xt[1] / s];
                let dl = if xn > 0.0 { mu * dx(kn, col) } else { 0.0 };
                let d1 = dx(k1, col);
                let d2 = dx(k2, col);
                let c = lambda / s;
                let zd = z[0] * d1 + z[1] * d2;
                let e = |d: usize| if d == col { 1.0 } else { 0.0 };
                j[k1 * n + col] = e(k1) - z[0] * dl - c * (d1 - z[0] * zd);
                j[k2 * n + col] = e(k2) - z[1] * dl - c * (d2 - z[1] * zd);
            }
        }
    }
    phi
}

fn half_squared(v: &[f64]) -> f64 {
    0.5 * v.iter().map(|x| x * x).sum::<f64>()
}

/// The Newton scalings ρ_i = 1 / W_ii,nn (1 when not positive).
pub fn scalings(p: &FrictionProblem) -> Vec<f64> {
    (0..p.contacts())
        .map(|i| {
            let d = p.at(3 * i, 3 * i);
            if d > 0.0 && d.is_finite() {
                1.0 / d
            } else {
                1.0
            }
        })
        .collect()
}

/// The step from r: the Newton step ∂Φ Δ = −Φ, or where ∂Φ is singular
/// (W rank-deficient: a box on four coplanar contacts) the
/// Levenberg–Marquardt step ((∂Φᵀ∂Φ + λ I) Δ = −∂ΦᵀΦ, λ = 1e-10 of
/// the mean diagonal, a descent direction of the merit). Returns the step
/// and the merit's slope along it, (∂ΦᵀΦ)·Δ; None when neither solves.
fn step(jac: &[f64], phi: &[f64], n: usize) -> Option<(Vec<f64>, f64)> {
    let slope = |delta: &[f64]| -> f64 {
        // (∂ΦᵀΦ)·Δ = Φ·(∂Φ Δ).
        (0..n)
            .map(|i| phi[i] * (0..n).map(|j| jac[i * n + j] * delta[j]).sum::<f64>())
            .sum()
    };
    let mut a = jac.to_vec();
    let mut delta: Vec<f64> = phi.iter().map(|v| -v).collect();
    if solve_in_place(&mut a, &mut delta, n, PIVOT_TOL) && delta.iter().all(|d| d.is_finite()) {
        let s = slope(&delta);
        return Some((delta, s));
    }
    let mut normal = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            normal[i * n + j] = (0..n).map(|k| jac[k * n + i] * jac[k * n + j]).sum();
        }
    }
    let mean = (0..n).map(|i| normal[i * n + i]).sum::<f64>() / n as f64;
    let lambda = 1e-10 * mean + f64::MIN_POSITIVE;
    for i in 0..n {
        normal[i * n + i] += lambda;
    }
    let mut delta: Vec<f64> = (0..n)
        .map(|j| -(0..n).map(|k| jac[k * n + j] * phi[k]).sum::<f64>())
        .collect();
    if !solve_in_place(&mut normal, &mut delta, n, 0.0) || delta.iter().any(|d| !d.is_finite()) {
        return None;
    }
    let s = slope(&delta);
    (s < 0.0).then_some((delta, s))
}

/// Newton from `r` until the Coulomb error is at most `tolerance`, a step
/// fails (no step, or no decrease of the merit along it), or `max_steps`
/// steps ran: (steps, error of the last r). `r` only ever moves to points
/// of smaller merit.
pub fn newton(p: &FrictionProblem, r: &mut [f64], max_steps: u64, tolerance: f64) -> (u64, f64) {
    let n = p.dim();
    let rho = scalings(p);
    let mut jac = vec![0.0; n * n];
    let mut phi = alart_curnier(p, r, &rho, Some(&mut jac));
    let mut merit = half_squared(&phi);
    let mut error = coulomb_error(p, r);
    let mut steps = 0;
    let mut trial = vec![0.0; n];
    while steps < max_steps && !(error <= tolerance) && merit > 0.0 {
        let Some((delta, slope)) = step(&jac, &phi, n) else {
            break;
        };
        steps += 1;
        let mut t = 1.0;
        let mut accepted = false;
        while t > 1e-10 {
            for k in 0..n {
                trial[k] = r[k] + t * delta[k];
            }
            let m = half_squared(&alart_curnier(p, &trial, &rho, None));
            // Armijo on ½‖Φ‖² (slope −2·merit for a Newton step).
            if m <= merit + 1e-4 * t * slope {
                accepted = true;
                break;
            }
            t *= 0.5;
        }
        if !accepted {
            break;
        }
        r.copy_from_slice(&trial);
        phi = alart_curnier(p, r, &rho, Some(&mut jac));
        merit = half_squared(&phi);
        error = coulomb_error(p, r);
    }
    (steps, error)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_jacobian_matches_finite_differences_away_from_kinks() {
        let mut rng = crate::generate::Rng::new(11);
        for _ in 0..200 {
            let k = rng.int(1, 4);
            let n = 3 * k;
            let a: Vec<f64> = (0..n * n).map(|_| rng.range(-1.0, 1.0)).collect();
            let w: Vec<f64> = (0..n * n)
                .map(|e| {
                    (0..n)
                        .map(|m| a[e / n * n + m] * a[e % n * n + m])
                        .sum::<f64>()
                        + if e / n == e % n { 0.1 } else { 0.0 }
                })
                .collect();
            let q: Vec<f64> = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
            let mu: Vec<f64> = (0..k).map(|_| rng.range(0.0, 1.0)).collect();
            let p = FrictionProblem::new(w, q, mu).unwrap();
            let r: Vec<f64> = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
            let rho = scalings(&p);
            let mut jac = vec![0.0; n * n];
            let phi = alart_curnier(&p, &r, &rho, Some(&mut jac));
            let h = 1e-7;
            for col in 0..n {
                let mut rp = r.clone();
                rp[col] += h;
                let fp = alart_curnier(&p, &rp, &rho, None);
                let mut rm = r.clone();
                rm[col] -= h;
                let fm = alart_curnier(&p, &rm, &rho, None);
                for row in 0..n {
                    let fd = (fp[row] - fm[row]) / (2.0 * h);
                    let one_sided = (fp[row] - phi[row]) / h;
                    // At a kink the two one-sided slopes differ: skip those.
                    if (fd - one_sided).abs() > 1e-4 {
                        continue;
                    }
                    assert!(
                        (fd - jac[row * n + col]).abs() < 1e-5,
                        "row {row} col {col}: {fd} vs {}",
                        jac[row * n + col]
                    );
                }
            }
        }
    }
}
