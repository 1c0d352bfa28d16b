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
use super::sparse::{
    block_runs, blocks_dot, cholesky_in, lower_envelope, lu_envelope, product_sparse, Pattern,
    SPARSE_FROM,
};
use super::workspace::Workspace;
use crate::linalg::{solve_in_place, PIVOT_TOL};

/// Φ(r) (3k) into `phi`, given u = W r + q, and when `jacobian` is Some its
/// generalized Jacobian (3k × 3k, row-major) written there within W's
/// block `pattern` (contact i's rows are nonzero only in its neighbours'
/// columns; the caller keeps the rest zero).
fn alart_curnier(
    p: &FrictionProblem,
    r: &[f64],
    u: &[f64],
    rho: &[f64],
    phi: &mut [f64],
    jacobian: Option<(&mut [f64], &Pattern)>,
) {
    let mut jac = jacobian;
    for (i, &mu) in p.mu.iter().enumerate() {
        let (kn, k1, k2) = (3 * i, 3 * i + 1, 3 * i + 2);
        let rh = rho[i];
        let xn = r[kn] - rh * u[kn];
        let xt = [r[k1] - rh * u[k1], r[k2] - rh * u[k2]];
        let lambda = mu * xn.max(0.0);
        let s = (xt[0] * xt[0] + xt[1] * xt[1]).sqrt();
        phi[kn] = r[kn] - xn.max(0.0);
        let sticks = s <= lambda;
        let pt = if sticks {
            xt
        } else {
            [lambda * xt[0] / s, lambda * xt[1] / s]
        };
        phi[k1] = r[k1] - pt[0];
        phi[k2] = r[k2] - pt[1];
        let Some((j, pattern)) = jac.as_mut() else {
            continue;
        };
        jacobian_rows(p, i, [xn, xt[0], xt[1]], rh, j, pattern.row(i));
    }
}

/// Contact i's three rows of ∂Φ (module docs) at x = (x_n, x_t) with
/// scaling ρ, into the 3k × 3k row-major `j`, in the columns of the
/// contact `blocks` coupled to i.
fn jacobian_rows(
    p: &FrictionProblem,
    i: usize,
    x: [f64; 3],
    rh: f64,
    j: &mut [f64],
    blocks: &[usize],
) {
    let n = p.dim();
    let mu = p.mu[i];
    let (kn, k1, k2) = (3 * i, 3 * i + 1, 3 * i + 2);
    let (xn, xt) = (x[0], [x[1], x[2]]);
    let lambda = mu * xn.max(0.0);
    let s = (xt[0] * xt[0] + xt[1] * xt[1]).sqrt();
    let sticks = s <= lambda;
    let (wn, w1, w2) = (
        &p.w[kn * n..kn * n + n],
        &p.w[k1 * n..k1 * n + n],
        &p.w[k2 * n..k2 * n + n],
    );
    let e = |d: usize, col: usize| if d == col { 1.0 } else { 0.0 };
    let columns = || blocks.iter().flat_map(|&b| 3 * b..3 * b + 3);
    for col in columns() {
        j[kn * n + col] = if xn > 0.0 { rh * wn[col] } else { e(kn, col) };
    }
    if sticks {
        for col in columns() {
            j[k1 * n + col] = rh * w1[col];
            j[k2 * n + col] = rh * w2[col];
        }
        return;
    }
    // Slide: ∂x_d = e_d − ρ W_d, ∂λ = μ ∂x_n (x_n > 0).
    let z = [xt[0] / s, xt[1] / s];
    let c = lambda / s;
    for col in columns() {
        let dl = if xn > 0.0 {
            mu * (e(kn, col) - rh * wn[col])
        } else {
            0.0
        };
        let d1 = e(k1, col) - rh * w1[col];
        let d2 = e(k2, col) - rh * w2[col];
        let zd = z[0] * d1 + z[1] * d2;
        j[k1 * n + col] = e(k1, col) - z[0] * dl - c * (d1 - z[0] * zd);
        j[k2 * n + col] = e(k2, col) - z[1] * dl - c * (d2 - z[1] * zd);
    }
}

/// The shortest step the line search tries (halving from 1): a Newton
/// direction along which ½‖Φ‖² needs a shorter step to decrease makes no
/// progress worth its trials (each one Φ), and `auto` goes back to NSGS
/// sweeps from there. At 1e-10 (34 halvings) the random spheres of
/// k = 3, 4 spent about ten trials per Newton step; 1e-4 solves the same
/// islands with 40 % fewer instructions (1e-2 left islands of 16-contact
/// stacks unsolved).
const LS_MIN: f64 = 1e-4;

fn half_squared(v: &[f64]) -> f64 {
    0.5 * v.iter().map(|x| x * x).sum::<f64>()
}

/// The Newton scalings ρ_i = 1 / W_ii,nn (1 when not positive).
#[cfg(test)]
pub fn scalings(p: &FrictionProblem) -> Vec<f64> {
    let mut ws = Workspace::default();
    ws.prepare(p, &vec![0.0; p.dim()]);
    ws.rho
}

/// The step from r into `ws.delta`: the Newton step ∂Φ Δ = −Φ (by
/// [`stick_step`] where every contact sticks, slides near the edge of its
/// cone or is free), or where ∂Φ is singular (W rank-deficient: a box on four coplanar contacts) the
/// Levenberg–Marquardt step ((∂Φᵀ∂Φ + λ I) Δ = −∂ΦᵀΦ, λ = 1e-10 of the
/// mean diagonal, a descent direction of the merit). Once the LU of ∂Φ
/// failed on an island (`ws.singular`), its later steps are LM directly.
/// Returns the merit's slope along the step, (∂ΦᵀΦ)·Δ; None when neither
/// solves.
fn step(p: &FrictionProblem, r: &[f64], ws: &mut Workspace) -> Option<f64> {
    let n = p.dim();
    if classify(p, r, ws) && stick_step(p, ws) {
        let s = slope(&ws.jac, &ws.phi, &ws.delta, &ws.pattern);
        if s < 0.0 {
            return Some(s);
        }
    }
    if !ws.singular && w_rows_dependent(p, ws) {
        ws.singular = true;
    }
    if !ws.singular {
        for (d, f) in ws.delta.iter_mut().zip(&ws.phi) {
            *d = -f;
        }
        // Large islands (reordered, `sparse::SPARSE_FROM`): within W's
        // envelope, without row exchanges (∂Φ's rows of contact i are
        // combinations of e_i's and W_i's: its pattern is W's), of which
        // only the envelope is copied (all the LU reads).
        let solved = if ws.env_first.is_empty() {
            ws.matrix.copy_from_slice(&ws.jac);
            solve_in_place(&mut ws.matrix, &mut ws.delta, n, PIVOT_TOL)
        } else {
            for (i, (&f, &l)) in ws.env_first.iter().zip(&ws.env_last).enumerate() {
                let within = i * n + f..=i * n + l;
                ws.matrix[within.clone()].copy_from_slice(&ws.jac[within]);
            }
            lu_envelope(
                &mut ws.matrix,
                &mut ws.delta,
                n,
                &ws.env_first,
                &ws.env_last,
            )
        };
        if solved && ws.delta.iter().all(|d| d.is_finite()) {
            return Some(slope(&ws.jac, &ws.phi, &ws.delta, &ws.pattern));
        }
        ws.singular = true;
    }
    // λ = 1e-10 of the mean diagonal; where rounding leaves the damped
    // matrix not positive definite to Cholesky, λ grows a thousandfold.
    // ∂Φᵀ∂Φ and −∂ΦᵀΦ once; each damping tried solves a copy of the
    // normal matrix's lower envelope (all the Cholesky reads).
    normal_system(n, ws);
    let mean = (0..n).map(|i| ws.normal[i * n + i]).sum::<f64>() / n as f64;
    let mut damping = 1e-10;
    loop {
        for (i, &f) in ws.first[..n].iter().enumerate() {
            let within = i * n + f..=i * n + i;
            ws.matrix[within.clone()].copy_from_slice(&ws.normal[within]);
        }
        let lambda = damping * mean + f64::MIN_POSITIVE;
        for i in 0..n {
            ws.matrix[i * n + i] += lambda;
        }
        ws.delta.copy_from_slice(&ws.trial);
        if cholesky_in(&mut ws.matrix, &mut ws.delta, n, None, &ws.first).is_some()
            && ws.delta.iter().all(|d| d.is_finite())
        {
            break;
        }
        damping *= 1e3;
        if damping > 1e-1 {
            return None;
        }
    }
    let s = slope(&ws.jac, &ws.phi, &ws.delta, &ws.pattern);
    (s < 0.0).then_some(s)
}

/// How far (relative) beyond the disc of radius λ a sliding x_t may lie and
/// still be taken as sticking by [`stick_step`].
const STICK_BAND: f64 = 1e-9;

/// How far (relative) beyond the disc a sliding x_t may lie for
/// [`stick_step`] to take the contact's tangential rows as the identity's:
/// the resting pyramid's contacts on the edge of their cones (s/λ − 1 of
/// 1e-9 to 2e-8 at u_t ≈ 1e-11).
const EDGE_BAND: f64 = 1e-6;

/// A sliding contact whose normal reaction is at most this fraction of the
/// island's largest is taken by [`stick_step`] as one on the edge (the
/// resting pyramid's contacts of 1e-7 to 1e-9 of the largest reaction,
/// sliding at s/λ − 1 ≈ 0.1–1.5).
const FAINT: f64 = 1e-6;

/// Sorts the contacts at r by their rows of ∂Φ (x as `alart_curnier`
/// computes it, so that the kinds are its rows'): `ws.stuck` gets the rows
/// [`stick_step`] solves through W (ascending: the three of a contact that
/// sticks with x_n > 0, the normal of one that slides with x_n > 0),
/// `ws.w_rows` every row of ∂Φ that is ρ_i times W's row (x_n > 0: the
/// normal; s ≤ λ: the tangents). True when every contact sticks with
/// x_n > 0, slides with x_n > 0 on the edge of its cone ([`EDGE_BAND`]) or
/// with a faint reaction ([`FAINT`]) on an island of at least
/// [`SPARSE_FROM`] contacts, or is free (x_n ≤ 0, x_t ≠ 0:
/// identity rows). Other slides (a box sliding on the ground) go to the
/// general step, whose rows are ∂Φ's own.
fn classify(p: &FrictionProblem, r: &[f64], ws: &mut Workspace) -> bool {
    ws.stuck.clear();
    ws.w_rows.clear();
    // Edge and faint slides only on large islands, whose LM step ((3k)³)
    // is what the stick step saves: with them on every island, the
    // frictional rain of `world_rain.rs` (4 worlds × 1,000 steps, islands
    // of mostly ≤ 16 contacts) ended 16 islands unsolved instead of 11.
    let large = p.contacts() >= SPARSE_FROM;
    let largest = (0..p.contacts()).fold(0.0f64, |m, i| m.max(r[3 * i]));
    let faint = FAINT * largest;
    let mut simple = true;
    for (i, &mu) in p.mu.iter().enumerate() {
        let rh = ws.rho[i];
        let xn = r[3 * i] - rh * ws.u[3 * i];
        let xt = [
            r[3 * i + 1] - rh * ws.u[3 * i + 1],
            r[3 * i + 2] - rh * ws.u[3 * i + 2],
        ];
        let lambda = mu * xn.max(0.0);
        let s = (xt[0] * xt[0] + xt[1] * xt[1]).sqrt();
        if xn > 0.0 {
            ws.w_rows.push(3 * i);
        }
        if s <= lambda {
            ws.w_rows.extend([3 * i + 1, 3 * i + 2]);
        }
        // A slide within rounding of the cone's edge (u_t ≈ 0 with r on the
        // boundary: a resting contact whose friction is saturated) counts
        // as sticking here; the step is then checked against the true ∂Φ
        // (its slope) and by the line search.
        if xn > 0.0 && s <= lambda * (1.0 + STICK_BAND) {
            ws.stuck.extend([3 * i, 3 * i + 1, 3 * i + 2]);
        } else if large && xn > 0.0 && (s <= lambda * (1.0 + EDGE_BAND) || r[3 * i] <= faint) {
            ws.stuck.push(3 * i);
        } else if !(xn <= 0.0 && s > 0.0) {
            simple = false;
        }
    }
    simple
}

/// Whether the rows of ∂Φ that are ρ_i W's rows (`ws.w_rows`, from
/// [`classify`]) are linearly dependent, so that ∂Φ is singular for sure:
/// W's rows R are dependent exactly where W_RR is singular (W = J M⁻¹ Jᵀ,
/// M⁻¹ ≻ 0), which a semidefinite Cholesky of W_RR ((|R|)³/6) shows by a
/// dropped pivot. The four normals of a box on four coplanar corners are
/// (rank 3): the general step then goes to Levenberg–Marquardt without
/// first paying an LU of ∂Φ that fails.
fn w_rows_dependent(p: &FrictionProblem, ws: &mut Workspace) -> bool {
    let (n, m) = (p.dim(), ws.w_rows.len());
    if m < 2 {
        return false;
    }
    // W_RR's lower triangle (all the Cholesky reads); on large islands
    // from W's envelope on (row r of W is zero left of `env_first[r]`).
    let (rows, env_first) = (&ws.w_rows, &ws.env_first);
    let from = |a: usize| {
        env_first
            .get(rows[a])
            .map_or(0, |&f| rows.partition_point(|&rb| rb < f))
    };
    for (a, &ra) in rows.iter().enumerate() {
        for b in from(a)..=a {
            ws.matrix[a * m + b] = p.w[ra * n + rows[b]];
        }
    }
    lower_envelope(&ws.matrix[..m * m], m, from, &mut ws.first);
    ws.trial[..m].fill(0.0);
    matches!(
        cholesky_in(
            &mut ws.matrix[..m * m],
            &mut ws.trial[..m],
            m,
            Some(1e-10),
            &ws.first
        ),
        Some(dropped) if dropped > 0
    )
}

/// The Newton step where every contact sticks, slides with x_n > 0 near
/// the edge or faintly ([`classify`]) or is free, x_n ≤ 0 and x_t ≠ 0 (its rows are the identity's): the resting
/// stacks and boxes of time stepping, whose W is rank-deficient (more
/// contact directions than the bodies' 6 degrees of freedom), so that ∂Φ
/// is singular and the general step pays a failed LU and then ∂Φᵀ∂Φ. The
/// rows R = `ws.stuck` ([`classify`]) are those whose ∂Φ row is ρ_i W's
/// (a sticking contact's three, a sliding one's normal); every other row
/// takes the identity's, Δ = −Φ: the free contacts' exact answer, and for
/// a sliding contact's tangents the step that puts r_t where the disc's
/// projection P_λ(x_t) is now (its true rows, −z ∂λ − (λ/‖x_t‖)(I − z zᵀ)
/// ∂x_t beside the identity, are left out: the pyramid's sliding contacts
/// carry reactions of 1e-7 of the largest, or lie on the cone's edge with
/// u_t ≈ 0). Then W_RR Δ_R = −Φ_R/ρ − W_R,¬R Δ_¬R by a semidefinite
/// Cholesky of W_RR (a pivot below 1e-10 of its diagonal dropped, its
/// unknown 0: a solution where the right side is in W_RR's range):
/// |R|³/6 multiply-adds instead of about n³. The caller checks the step's
/// slope against the true ∂Φ (a descent direction of ½‖Φ‖² or the general
/// step). Writes `ws.delta`; false when W_RR is not positive semidefinite
/// to rounding or the step is not finite.
fn stick_step(p: &FrictionProblem, ws: &mut Workspace) -> bool {
    let n = p.dim();
    // Δ = −Φ on every row first: the rows outside R keep it.
    for (d, f) in ws.delta.iter_mut().zip(&ws.phi) {
        *d = -f;
    }
    let m = ws.stuck.len();
    if m == 0 {
        return ws.delta.iter().all(|d| d.is_finite());
    }
    let (stuck, pattern, env_first) = (&ws.stuck, &ws.pattern, &ws.env_first);
    let outside = |row: &[f64], i: usize, delta: &[f64]| {
        // Σ over the columns c outside R of W_row,c Δ_c: the row times Δ
        // over i's neighbours (the bits of the whole row's `dot`) minus
        // R's columns among them (their Δ is still −Φ here).
        let blocks = pattern.row(i);
        let mut v = blocks_dot(row, blocks, delta);
        for &j in blocks {
            let from = stuck.partition_point(|&c| c < 3 * j);
            let mut within = stuck[from..]
                .iter()
                .take_while(|&&c| c < 3 * j + 3)
                .peekable();
            if within.peek().is_some() {
                v -= within.map(|&c| row[c] * delta[c]).sum::<f64>();
            }
        }
        v
    };
    // W_RR's row a: its lower triangle (all the Cholesky reads), on large
    // islands from W's envelope on (W's row is zero left of it).
    let from = |a: usize| {
        env_first
            .get(3 * (stuck[a] / 3))
            .map_or(0, |&f| stuck.partition_point(|&c| c < f))
    };
    let all_stick = m == n;
    for (a, &row) in stuck.iter().enumerate() {
        let i = row / 3;
        let w_row = &p.w[row * n..(row + 1) * n];
        let coupling = if all_stick {
            0.0
        } else {
            outside(w_row, i, &ws.delta)
        };
        ws.trial[a] = -ws.phi[row] / ws.rho[i] - coupling;
        for c in from(a)..=a {
            ws.matrix[a * m + c] = w_row[stuck[c]];
        }
    }
    lower_envelope(&ws.matrix[..m * m], m, from, &mut ws.first);
    let (matrix, trial) = (&mut ws.matrix[..m * m], &mut ws.trial[..m]);
    if cholesky_in(matrix, trial, m, Some(1e-10), &ws.first).is_none() {
        return false;
    }
    for (a, &row) in ws.stuck.iter().enumerate() {
        ws.delta[row] = ws.trial[a];
    }
    ws.delta.iter().all(|d| d.is_finite())
}

/// ∂Φᵀ∂Φ into `ws.normal` (its lower triangle within its envelope, all
/// the Cholesky reads), −∂ΦᵀΦ into `ws.trial`, and that envelope into
/// `ws.first` ([`lower_envelope`]). Sums over ∂Φ's rows in order, each
/// row over its nonzero blocks only (W's pattern: contact k/3's
/// neighbours), so that (∂Φᵀ∂Φ)_ji is zero unless contacts j/3 and i/3
/// share a neighbour: on large islands (`ws.env_first` set) the envelope
/// starts at the first neighbour of a neighbour and nothing before it is
/// touched. A contact's three rows share their blocks: each entry takes
/// their three products in one pass, in row order (the sums of one row
/// at a time, bit for bit), along the runs of consecutive blocks (so that
/// the inner loop runs over contiguous columns of a row of the lower
/// triangle). The products of zeros it adds (±0) leave a sum as it is
/// (a sum from +0 is never −0): the dense sums' bits.
fn normal_system(n: usize, ws: &mut Workspace) {
    let (pattern, large) = (&ws.pattern, !ws.env_first.is_empty());
    let reach = |i: usize| match large {
        true => {
            3 * pattern
                .row(i / 3)
                .iter()
                .map(|&b| pattern.row(b)[0])
                .min()
                .unwrap_or(i / 3)
        }
        false => 0,
    };
    for j in 0..n {
        ws.normal[j * n + reach(j)..=j * n + j].fill(0.0);
    }
    ws.trial.fill(0.0);
    for (c, rows) in ws.jac.chunks_exact(3 * n).enumerate() {
        let cols = pattern.row(c);
        let (r0, rest) = rows.split_at(n);
        let (r1, r2) = rest.split_at(n);
        ws.runs.clear();
        ws.runs.extend(block_runs(cols));
        for j in cols.iter().flat_map(|&b| 3 * b..3 * b + 3) {
            let y = [r0[j], r1[j], r2[j]];
            let out = &mut ws.normal[j * n..=j * n + j];
            for &(from, to) in &ws.runs {
                let (lo, hi) = (3 * from, (3 * to).min(j + 1));
                if lo >= hi {
                    break;
                }
                let lanes = out[lo..hi].iter_mut().zip(&r0[lo..hi]);
                for ((o, &x0), (&x1, &x2)) in lanes.zip(r1[lo..hi].iter().zip(&r2[lo..hi])) {
                    *o = ((*o + x0 * y[0]) + x1 * y[1]) + x2 * y[2];
                }
            }
        }
        for (d, row) in [r0, r1, r2].into_iter().enumerate() {
            let f = ws.phi[3 * c + d];
            if f != 0.0 {
                for col in cols.iter().flat_map(|&b| 3 * b..3 * b + 3) {
                    ws.trial[col] -= row[col] * f;
                }
            }
        }
    }
    lower_envelope(&ws.normal, n, reach, &mut ws.first);
}

/// The merit's slope along Δ: (∂ΦᵀΦ)·Δ = Φ·(∂Φ Δ).
fn slope(jac: &[f64], phi: &[f64], delta: &[f64], pattern: &Pattern) -> f64 {
    let n = phi.len();
    (0..n)
        .map(|i| phi[i] * blocks_dot(&jac[i * n..(i + 1) * n], pattern.row(i / 3), delta))
        .sum()
}

/// The longest window of a nonmonotone line search (`Workspace::window`).
const WINDOW_MAX: usize = 16;

/// Newton from `r` with `ws` prepared for `p` and `ws.u` = W r + q (see
/// [`newton`]); `ws.u` is exact for the final r.
pub(crate) fn newton_in(
    p: &FrictionProblem,
    ws: &mut Workspace,
    r: &mut [f64],
    max_steps: u64,
    tolerance: f64,
) -> (u64, f64) {
    let n = p.dim();
    ws.newton_buffers();
    alart_curnier(
        p,
        r,
        &ws.u,
        &ws.rho,
        &mut ws.phi,
        Some((&mut ws.jac, &ws.pattern)),
    );
    let mut merit = half_squared(&ws.phi);
    let mut error = ws.error(p, r);
    let mut steps = 0;
    // The last merits, for a nonmonotone line search (`ws.window` > 1).
    let mut recent = [merit; WINDOW_MAX];
    let window = ws.window.clamp(1, WINDOW_MAX);
    while steps < max_steps && !(error <= tolerance) && merit > 0.0 {
        let Some(slope) = step(p, r, ws) else {
            break;
        };
        steps += 1;
        // W Δ once: each trial's u is then u + t W Δ, O(k).
        product_sparse(p, &ws.pattern, &ws.delta, &mut ws.w_delta);
        let mut t = 1.0;
        let mut accepted = false;
        while t > LS_MIN {
            for k in 0..n {
                ws.trial[k] = r[k] + t * ws.delta[k];
                ws.trial_u[k] = ws.u[k] + t * ws.w_delta[k];
            }
            alart_curnier(p, &ws.trial, &ws.trial_u, &ws.rho, &mut ws.trial_phi, None);
            let m = half_squared(&ws.trial_phi);
            // Armijo on ½‖Φ‖² (slope −2·merit for a Newton step), against
            // the largest of the last `window` merits.
            let reference = recent[..window].iter().fold(merit, |a, &b| a.max(b));
            if m <= reference + 1e-4 * t * slope {
                accepted = true;
                break;
            }
            t *= 0.5;
        }
        if !accepted {
            break;
        }
        r.copy_from_slice(&ws.trial);
        ws.u.copy_from_slice(&ws.trial_u);
        error = ws.error(p, r);
        if error <= tolerance {
            // Converged with the updated u: check with the exact one.
            ws.refresh(p, r);
            error = ws.error(p, r);
            if error <= tolerance {
                // Done: no Φ or ∂Φ at r is read again.
                break;
            }
        }
        alart_curnier(
            p,
            r,
            &ws.u,
            &ws.rho,
            &mut ws.phi,
            Some((&mut ws.jac, &ws.pattern)),
        );
        merit = half_squared(&ws.phi);
        recent[steps as usize % window] = merit;
    }
    if !(error <= tolerance) {
        ws.refresh(p, r);
        error = ws.error(p, r);
    }
    (steps, error)
}

/// Newton from `r` until the Coulomb error is at most `tolerance`, a step
/// fails (no step, or no decrease of the merit along it), or `max_steps`
/// steps ran: (steps, error of the last r). `r` only ever moves to points
/// of smaller merit.
pub fn newton(p: &FrictionProblem, r: &mut [f64], max_steps: u64, tolerance: f64) -> (u64, f64) {
    let mut ws = Workspace::default();
    ws.prepare(p, r);
    newton_in(p, &mut ws, r, max_steps, tolerance)
}

#[cfg(test)]
#[path = "newton_tests.rs"]
mod newton_tests;

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
            let mut pattern = Pattern::default();
            pattern.build(&p);
            let phi_of = |r: &[f64], jac: Option<(&mut [f64], &Pattern)>| {
                let mut phi = vec![0.0; n];
                alart_curnier(&p, r, &p.velocity(r), &rho, &mut phi, jac);
                phi
            };
            let phi = phi_of(&r, Some((&mut jac, &pattern)));
            let h = 1e-7;
            for col in 0..n {
                let mut rp = r.clone();
                rp[col] += h;
                let fp = phi_of(&rp, None);
                let mut rm = r.clone();
                rm[col] -= h;
                let fm = phi_of(&rm, None);
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
