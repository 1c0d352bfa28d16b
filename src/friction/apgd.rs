//! APGD for the cone complementarity problem (see [`super::projected`]):
//! accelerated projected gradient descent with Nesterov/FISTA momentum, the
//! step by backtracking on the Lipschitz estimate, gradient restarts and the
//! best iterate kept (Mazhar, Heyn, Negrut, Tasora 2015). The CPU twin of
//! the entry point `apgd` of `shaders/friction_projected.wgsl`.

use super::cone::project_on_cone;
use super::problem::FrictionProblem;
use super::projected::{start, stop_measure, sum_squares, velocity_into, Run, MAX_BACKTRACKS};

/// APGD's first Lipschitz estimate: ‖W e‖ / ‖e‖ for e = (1, …, 1) (at most
/// the largest eigenvalue; backtracking raises it), else the largest |W_rr|,
/// else 1.
pub(crate) fn first_lipschitz(problem: &FrictionProblem) -> f64 {
    let n = problem.dim();
    let mut s2 = 0.0;
    for r in 0..n {
        let mut s = 0.0;
        for j in 0..n {
            s += problem.w[r * n + j];
        }
        s2 += s * s;
    }
    let l = (s2 / n as f64).sqrt();
    if l > 0.0 && l.is_finite() {
        return l;
    }
    let d = (0..n).fold(0.0f64, |m, r| m.max(problem.w[r * n + r].abs()));
    if d > 0.0 && d.is_finite() {
        d
    } else {
        1.0
    }
}

/// APGD's state between iterations (what the shader keeps in its buffers
/// between rounds).
pub(crate) struct ApgdState {
    /// x_k, u(x_k), y_k, u(y_k), the best iterate.
    pub(crate) x: Vec<f64>,
    pub(crate) ux: Vec<f64>,
    pub(crate) y: Vec<f64>,
    pub(crate) uy: Vec<f64>,
    pub(crate) best: Vec<f64>,
    pub(crate) theta: f64,
    pub(crate) lipschitz: f64,
    pub(crate) best_err: f64,
}

/// Accelerated projected gradient descent (see the module docs).
pub(crate) fn apgd(
    problem: &FrictionProblem,
    r0: Option<&[f64]>,
    max_iterations: u32,
    tolerance: f64,
) -> Run {
    let n = problem.dim();
    let q2 = sum_squares(&problem.q);
    let x = start(problem, r0);
    let mut ux = vec![0.0; n];
    velocity_into(problem, &x, &mut ux);
    let err = stop_measure(problem, &x, &ux, q2);
    let mut s = ApgdState {
        y: x.clone(),
        uy: ux.clone(),
        best: x.clone(),
        x,
        ux,
        theta: 1.0,
        lipschitz: first_lipschitz(problem),
        best_err: err,
    };
    let mut run = Run {
        r: Vec::new(),
        iterations: 0,
        restarts: 0,
        failed: !err.is_finite(),
    };
    let mut xn = vec![0.0; n];
    let mut un = vec![0.0; n];
    while !run.failed && s.best_err > tolerance && run.iterations < max_iterations {
        match apgd_iteration(problem, &mut s, &mut xn, &mut un, q2) {
            None => run.failed = true,
            Some(restarted) => {
                run.iterations += 1;
                run.restarts += restarted as u32;
            }
        }
    }
    run.r = s.best;
    run
}

/// The backtracking test: dᵀW d ≤ L‖d‖² (`curvature`, `d2`), or a step
/// that rounding decides: L‖d‖ ≤ 16 ε ‖∇f(y)‖ (`g2` = ‖∇f(y)‖²). There
/// dᵀW d is computed from u(x_new) − u(y), whose cancellation error
/// (about ε‖u‖‖d‖) exceeds L‖d‖² however large L grows, so doubling L
/// would never end; the iterate is then stationary to working precision.
#[inline]
pub(crate) fn accept_step(curvature: f64, d2: f64, g2: f64, lipschitz: f64, eps: f64) -> bool {
    let noise = 16.0 * eps;
    curvature <= lipschitz * d2 || lipschitz * lipschitz * d2 <= noise * noise * g2
}

/// One APGD iteration from `s`, with scratch `xn`, `un` (3k): the step by
/// backtracking, the momentum, the best iterate, the gradient restart.
/// Some(restarted), or None when the step or the iterate is not finite or L
/// was doubled [`MAX_BACKTRACKS`] times.
#[allow(clippy::needless_range_loop, reason = "mirrors the WGSL loops")]
pub(crate) fn apgd_iteration(
    problem: &FrictionProblem,
    s: &mut ApgdState,
    xn: &mut [f64],
    un: &mut [f64],
    q2: f64,
) -> Option<bool> {
    let k = problem.contacts();
    let mut doublings = 0;
    loop {
        // x_new = P_K(y − ∇f(y) / L), ∇f(y) = u(y).
        let t = 1.0 / s.lipschitz;
        for i in 0..k {
            let c = 3 * i;
            let p = project_on_cone(
                [
                    s.y[c] - t * s.uy[c],
                    s.y[c + 1] - t * s.uy[c + 1],
                    s.y[c + 2] - t * s.uy[c + 2],
                ],
                problem.mu[i],
            );
            xn[c..c + 3].copy_from_slice(&p);
        }
        velocity_into(problem, xn, un);
        // f quadratic: f(x_new) − f(y) − ∇f(y)·d = ½ dᵀW d, W d = u(x_new) − u(y).
        let (mut curvature, mut d2, mut g2) = (0.0, 0.0, 0.0);
        for r in 0..3 * k {
            let d = xn[r] - s.y[r];
            curvature += d * (un[r] - s.uy[r]);
            d2 += d * d;
            g2 += s.uy[r] * s.uy[r];
        }
        if accept_step(curvature, d2, g2, s.lipschitz, f64::EPSILON) {
            break;
        }
        s.lipschitz *= 2.0;
        doublings += 1;
        if doublings >= MAX_BACKTRACKS || !s.lipschitz.is_finite() {
            return None;
        }
    }
    let err = stop_measure(problem, xn, un, q2);
    if !err.is_finite() {
        return None;
    }
    if err < s.best_err {
        s.best_err = err;
        s.best.copy_from_slice(xn);
    }
    let th = s.theta;
    let th_new = 0.5 * (th * (th * th + 4.0).sqrt() - th * th);
    let beta = th * (1.0 - th) / (th * th + th_new);
    // Gradient restart (O'Donoghue–Candès): ∇f(y)·(x_new − x) > 0.
    let mut g_dot = 0.0;
    for r in 0..3 * k {
        g_dot += s.uy[r] * (xn[r] - s.x[r]);
    }
    let restart = g_dot > 0.0;
    for r in 0..3 * k {
        if restart {
            s.y[r] = xn[r];
            s.uy[r] = un[r];
        } else {
            // y = x_new + β (x_new − x); u(y) by linearity from u(x_new), u(x).
            s.y[r] = xn[r] + beta * (xn[r] - s.x[r]);
            s.uy[r] = un[r] + beta * (un[r] - s.ux[r]);
        }
        s.x[r] = xn[r];
        s.ux[r] = un[r];
    }
    s.theta = if restart { 1.0 } else { th_new };
    s.lipschitz *= 0.9;
    Some(restart)
}
