//! The exact Coulomb solve of one contact: given its 3×3 block W (normal
//! first, then t₁, t₂) and its free velocity q (the island's q plus the
//! other contacts' reactions), find r with u = W r + q, r ∈ K,
//! ũ = u + μ‖u_t‖ e_n ∈ K*, r·ũ = 0. The local solver of [`super::nsgs`].
//!
//! Three cases, tried in order (Siconos' enumerative local solver):
//! - **take-off**: r = 0, valid when q_n ≥ 0;
//! - **stick**: u = 0, r = −W⁻¹ q, valid when r ∈ K;
//! - **slide** in direction d = (cos θ, sin θ): r = r_n (1, −μ d), u_n = 0,
//!   u_t = α d with α > 0. From u_n = 0,
//!   r_n = −q_n / a(θ), a(θ) = W_nn − μ W_nt·d (needs a > 0, q_n < 0), and
//!   a(θ) u_t = g(θ) = −q_n (W_tn − μ W_tt d) + a(θ) q_t must be parallel to
//!   d: f(θ) = d⊥·g(θ) = 0 with g·d > 0. f is a trigonometric polynomial of
//!   degree 2 (at most four roots); they are bracketed on a grid of
//!   [`SLIDE_SAMPLES`] angles (close pairs through the extrema of f) and
//!   refined by the Illinois method to machine precision. First, though,
//!   Newton's method on f (f' from the same sine and cosine) from a guess
//!   of the direction (the current reaction's, the stick solution's or the
//!   free tangential velocity's) finds the slide in a few steps; the grid
//!   decides where it does not converge to a valid slide.
//!
//! Where several slide directions are valid (an anisotropic block), the one
//! closest to the current reaction is taken. When no case holds to rounding
//! (a tangent double root the grid misses, a singular block), a few hundred
//! De Saxcé fixed-point steps r ← P_K(r − ρ ũ) and Alart–Curnier Newton on
//! the contact alone give the best local answer.

use super::cone::project_on_cone;

/// Grid of angles on which the slide condition's roots are bracketed.
pub const SLIDE_SAMPLES: usize = 24;

/// A contact's 3×3 block of W, rows normal, t₁, t₂.
pub type Block = [[f64; 3]; 3];

/// The exact local solution r of one contact (see the module docs);
/// `current` is the reaction before (it picks among several slides).
pub fn solve_contact(w: &Block, q: [f64; 3], mu: f64, current: [f64; 3]) -> [f64; 3] {
    if q[0] >= 0.0 {
        return [0.0; 3];
    }
    if mu == 0.0 {
        return match w[0][0] > 0.0 {
            true => [-q[0] / w[0][0], 0.0, 0.0],
            false => fallback(w, q, mu, current),
        };
    }
    let stuck = stick(w, q);
    if let Some(r) = stuck {
        if r[0] >= 0.0 && (r[1] * r[1] + r[2] * r[2]).sqrt() <= mu * r[0] {
            return r;
        }
    }
    // A guess of the slide direction: the current reaction's, else the
    // stick solution's (both oppose the slide), else the free tangential
    // velocity's (the slide's direction when W_tn and μ W_tt are small:
    // a cold start whose stick solution pulls).
    let guess = [current, stuck.unwrap_or([0.0; 3])]
        .into_iter()
        .find(|r| r[0] > 0.0 && (r[1] != 0.0 || r[2] != 0.0))
        .map(|r| (-r[2]).atan2(-r[1]))
        .or_else(|| (q[1] != 0.0 || q[2] != 0.0).then(|| q[2].atan2(q[1])));
    guess
        .and_then(|theta| slide_near(w, q, mu, theta))
        .or_else(|| slide(w, q, mu, current))
        .unwrap_or_else(|| fallback(w, q, mu, current))
}

/// r = −W⁻¹ q by Cramer's rule, None when W is singular to rounding.
fn stick(w: &Block, q: [f64; 3]) -> Option<[f64; 3]> {
    let c0 = [
        w[1][1] * w[2][2] - w[1][2] * w[2][1],
        w[1][2] * w[2][0] - w[1][0] * w[2][2],
        w[1][0] * w[2][1] - w[1][1] * w[2][0],
    ];
    let det = w[0][0] * c0[0] + w[0][1] * c0[1] + w[0][2] * c0[2];
    let scale = w.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    if !(det.abs() > 1e-13 * scale * scale * scale) {
        return None;
    }
    // Inverse = adjugate / det; the adjugate's rows are the cofactors' columns.
    let inv = [
        [
            c0[0],
            w[0][2] * w[2][1] - w[0][1] * w[2][2],
            w[0][1] * w[1][2] - w[0][2] * w[1][1],
        ],
        [
            c0[1],
            w[0][0] * w[2][2] - w[0][2] * w[2][0],
            w[0][2] * w[1][0] - w[0][0] * w[1][2],
        ],
        [
            c0[2],
            w[0][1] * w[2][0] - w[0][0] * w[2][1],
            w[0][0] * w[1][1] - w[0][1] * w[1][0],
        ],
    ];
    let mut r = [0.0; 3];
    for (ri, row) in r.iter_mut().zip(&inv) {
        *ri = -(row[0] * q[0] + row[1] * q[1] + row[2] * q[2]) / det;
    }
    Some(r)
}

/// The slide condition at angle θ: (f, a, g·d) of the module docs.
#[inline]
fn slide_condition(w: &Block, q: [f64; 3], mu: f64, theta: f64) -> (f64, f64, f64) {
    let (s, c) = theta.sin_cos();
    let a = w[0][0] - mu * (w[0][1] * c + w[0][2] * s);
    let g1 = -q[0] * (w[1][0] - mu * (w[1][1] * c + w[1][2] * s)) + a * q[1];
    let g2 = -q[0] * (w[2][0] - mu * (w[2][1] * c + w[2][2] * s)) + a * q[2];
    (-s * g1 + c * g2, a, c * g1 + s * g2)
}

/// The reaction of a slide at angle θ (q_n < 0, a(θ) > 0).
fn slide_reaction(w: &Block, q: [f64; 3], mu: f64, theta: f64) -> [f64; 3] {
    let (s, c) = theta.sin_cos();
    let a = w[0][0] - mu * (w[0][1] * c + w[0][2] * s);
    let rn = -q[0] / a;
    [rn, -mu * rn * c, -mu * rn * s]
}

/// A valid slide found by Newton's method on f from the angle `theta` (the
/// fast path: from a guess near the answer, quadratic convergence in a few
/// steps, one `sin_cos` each, f' from the same sine and cosine); None when
/// it does not converge to a valid slide, and the grid decides. The answer
/// is the last angle evaluated, once the step it gives is at rounding
/// level (no evaluation beyond it).
fn slide_near(w: &Block, q: [f64; 3], mu: f64, theta: f64) -> Option<[f64; 3]> {
    let wmax = w.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut x = theta;
    for _ in 0..30 {
        let (s, c) = x.sin_cos();
        // f = d⊥·g and its derivative (module docs), d = (c, s).
        let a = w[0][0] - mu * (w[0][1] * c + w[0][2] * s);
        let da = -mu * (w[0][2] * c - w[0][1] * s);
        let g1 = -q[0] * (w[1][0] - mu * (w[1][1] * c + w[1][2] * s)) + a * q[1];
        let g2 = -q[0] * (w[2][0] - mu * (w[2][1] * c + w[2][2] * s)) + a * q[2];
        let dg1 = q[0] * mu * (w[1][2] * c - w[1][1] * s) + da * q[1];
        let dg2 = q[0] * mu * (w[2][2] * c - w[2][1] * s) + da * q[2];
        let f = -s * g1 + c * g2;
        let df = -c * g1 - s * dg1 - s * g2 + c * dg2;
        let step = f / df;
        if !step.is_finite() || step.abs() > 1.0 {
            return None;
        }
        if step.abs() <= 4.0 * f64::EPSILON * x.abs().max(1.0) {
            // Converged: |f| at rounding level of its terms (q_n W and a q_t).
            let along = c * g1 + s * g2;
            let size = (q[0].abs() * wmax * (1.0 + mu) + a.abs() * q[1].hypot(q[2]))
                .max(f64::MIN_POSITIVE);
            let valid = a > 0.0 && along > 0.0 && f.abs() <= 1e-13 * size;
            let rn = -q[0] / a;
            return valid.then_some([rn, -mu * rn * c, -mu * rn * s]);
        }
        x -= step;
    }
    None
}

/// The valid slide closest to `current`, None when none is found.
///
/// Roots are bracketed by sign changes on the grid; a pair of close roots
/// inside one cell shows as a local extremum of f pointing towards zero,
/// which a golden-section search locates and which then splits the cell in
/// two brackets.
fn slide(w: &Block, q: [f64; 3], mu: f64, current: [f64; 3]) -> Option<[f64; 3]> {
    let step = std::f64::consts::TAU / SLIDE_SAMPLES as f64;
    let f = |t: f64| slide_condition(w, q, mu, t).0;
    let samples: [f64; SLIDE_SAMPLES + 1] = std::array::from_fn(|i| f(i as f64 * step));
    let mut best: Option<([f64; 3], f64)> = None;
    let mut consider = |theta: f64| {
        let (_, a, along) = slide_condition(w, q, mu, theta);
        if !(a > 0.0 && along > 0.0) {
            return;
        }
        let r = slide_reaction(w, q, mu, theta);
        let dist = (0..3).map(|k| (r[k] - current[k]).powi(2)).sum::<f64>();
        if best.is_none_or(|(_, d)| dist < d) {
            best = Some((r, dist));
        }
    };
    let mut root_in = |lo: f64, hi: f64, f_lo: f64, f_hi: f64| {
        if f_lo == 0.0 {
            consider(lo);
        } else if (f_lo < 0.0) != (f_hi < 0.0) {
            consider(illinois(f, lo, hi, f_lo, f_hi));
        }
    };
    for i in 0..SLIDE_SAMPLES {
        let (lo, hi) = (i as f64 * step, (i + 1) as f64 * step);
        root_in(lo, hi, samples[i], samples[i + 1]);
        // A local extremum at sample i + 1 turned towards zero: maybe two
        // roots in (lo, hi + step).
        let next = samples[(i + 2) % SLIDE_SAMPLES];
        let (a, b, c) = (samples[i], samples[i + 1], next);
        let sign = b.signum();
        if (a < 0.0) == (b < 0.0)
            && (c < 0.0) == (b < 0.0)
            && sign * b < sign * a
            && sign * b < sign * c
        {
            let m = golden_min(|t| sign * f(t), lo, hi + step);
            let fm = f(m);
            if (fm < 0.0) != (b < 0.0) {
                root_in(lo, m, a, fm);
                root_in(m, hi + step, fm, c);
            }
        }
    }
    best.map(|(r, _)| r)
}

/// The minimiser of g on [lo, hi] by golden-section search (g unimodal there).
fn golden_min(g: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    let mut x1 = hi - ratio * (hi - lo);
    let mut x2 = lo + ratio * (hi - lo);
    let (mut g1, mut g2) = (g(x1), g(x2));
    for _ in 0..60 {
        if g1 < g2 {
            hi = x2;
            x2 = x1;
            g2 = g1;
            x1 = hi - ratio * (hi - lo);
            g1 = g(x1);
        } else {
            lo = x1;
            x1 = x2;
            g1 = g2;
            x2 = lo + ratio * (hi - lo);
            g2 = g(x2);
        }
        if g1.min(g2) < 0.0 {
            return if g1 < g2 { x1 } else { x2 };
        }
    }
    0.5 * (lo + hi)
}

/// A root of f in [lo, hi] with f(lo) = f_lo and f(hi) = f_hi of opposite
/// signs, by the Illinois variant of regula falsi (bracketing, superlinear),
/// ending with bisection steps once the secant stalls.
fn illinois(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64, mut f_lo: f64, mut f_hi: f64) -> f64 {
    let mut side = 0i8;
    let mut best = if f_lo.abs() < f_hi.abs() {
        (lo, f_lo.abs())
    } else {
        (hi, f_hi.abs())
    };
    for it in 0..200 {
        let secant = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        // Every fourth step bisects, so that the bracket shrinks for sure.
        let x = if it % 4 == 3 || !(secant > lo && secant < hi) {
            0.5 * (lo + hi)
        } else {
            secant
        };
        if !(x > lo && x < hi) {
            break;
        }
        let fx = f(x);
        if fx.abs() < best.1 {
            best = (x, fx.abs());
        }
        if fx == 0.0 {
            break;
        }
        if (fx < 0.0) == (f_lo < 0.0) {
            lo = x;
            f_lo = fx;
            if side == -1 {
                f_hi *= 0.5;
            }
            side = -1;
        } else {
            hi = x;
            f_hi = fx;
            if side == 1 {
                f_lo *= 0.5;
            }
            side = 1;
        }
    }
    best.0
}

/// The fallback when no case holds: De Saxcé's fixed point
/// r ← P_K(r − ρ ũ), ρ = 1 / W_nn (or 1), from `current`, then
/// Alart–Curnier Newton on the contact alone.
fn fallback(w: &Block, q: [f64; 3], mu: f64, current: [f64; 3]) -> [f64; 3] {
    let mut r = fixed_point(w, q, mu, current);
    if let Ok(p) =
        super::FrictionProblem::new(w.iter().flatten().copied().collect(), q.to_vec(), vec![mu])
    {
        super::newton::newton(&p, &mut r, 50, 0.0);
    }
    r
}

/// De Saxcé's fixed point r ← P_K(r − ρ ũ), ρ = 1 / W_nn (or 1), from
/// `current`, 300 steps.
fn fixed_point(w: &Block, q: [f64; 3], mu: f64, current: [f64; 3]) -> [f64; 3] {
    let rho = if w[0][0] > 0.0 { 1.0 / w[0][0] } else { 1.0 };
    let mut r = current;
    for _ in 0..300 {
        let u: [f64; 3] =
            std::array::from_fn(|i| q[i] + w[i][0] * r[0] + w[i][1] * r[1] + w[i][2] * r[2]);
        let un = u[0] + mu * u[1].hypot(u[2]);
        r = project_on_cone([r[0] - rho * un, r[1] - rho * u[1], r[2] - rho * u[2]], mu);
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::friction::{coulomb_error, FrictionProblem};

    fn problem(w: &Block, q: [f64; 3], mu: f64) -> FrictionProblem {
        FrictionProblem::new(w.iter().flatten().copied().collect(), q.to_vec(), vec![mu]).unwrap()
    }

    #[test]
    fn every_case_of_one_contact_is_exact_on_random_blocks() {
        let mut rng = crate::generate::Rng::new(3);
        let mut cases = [0usize; 3];
        for _ in 0..3000 {
            // W = A Aᵀ + δ I: symmetric positive definite, anisotropic.
            let a: [[f64; 3]; 3] =
                std::array::from_fn(|_| std::array::from_fn(|_| rng.range(-1.0, 1.0)));
            let w: Block = std::array::from_fn(|i| {
                std::array::from_fn(|j| {
                    (0..3).map(|k| a[i][k] * a[j][k]).sum::<f64>() + if i == j { 0.05 } else { 0.0 }
                })
            });
            let q = [
                rng.range(-2.0, 1.0),
                rng.range(-2.0, 2.0),
                rng.range(-2.0, 2.0),
            ];
            let mu = rng.range(0.0, 1.2);
            let r = solve_contact(&w, q, mu, [0.0; 3]);
            let e = coulomb_error(&problem(&w, q, mu), &r);
            assert!(e < 1e-12, "W {w:?} q {q:?} μ {mu}: r {r:?} error {e:e}");
            let kind = if r == [0.0; 3] {
                0
            } else if r[1].hypot(r[2]) < mu * r[0] * (1.0 - 1e-9) {
                1
            } else {
                2
            };
            cases[kind] += 1;
        }
        assert!(
            cases.iter().all(|&c| c > 100),
            "take-off, stick, slide: {cases:?}"
        );
    }

    #[test]
    fn a_unit_mass_sliding_gets_the_seeds_disc_impulse() {
        // W = I, approaching at 10 (γ_n = 10), sliding v_T = (3, −4) fast
        // enough to keep sliding, μ = 0.5: γ_T = −μ γ_n v_T/‖v_T‖ = (−3, 4).
        let w = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let r = solve_contact(&w, [-10.0, 30.0, -40.0], 0.5, [0.0; 3]);
        let want = [10.0, -3.0, 4.0];
        for k in 0..3 {
            assert!((r[k] - want[k]).abs() < 1e-12, "{r:?}");
        }
    }
}
