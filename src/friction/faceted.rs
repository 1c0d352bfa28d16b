//! A finite pivoting start for small islands where the methods driven by
//! the residual stall: Lemke's algorithm ([`crate::cpu::lemke`]) on the
//! LCP of the island with each friction cone replaced by an inscribed
//! pyramid of [`FACETS`] faces (Stewart & Trinkle 1996; Anitescu & Potra
//! 1997), whose answer is then polished into an exact Coulomb answer by
//! Newton (`solve::hybrid`).
//!
//! Why: a pile whose W is singular and whose q lies outside W's range by
//! 1e-11–1e-9 of ‖q‖ can rest on all its contacts only to rounding; the
//! exact answer lifts or slides a contact on a residual of that size, so
//! NSGS, Newton and PROX take tiny steps toward it. Lemke moves from basis
//! to basis instead: its answer is a basic solution, where a dependent
//! contact is out of the basis (r = 0: lifted) rather than loaded to
//! rounding, and the contacts it leaves sliding, sticking and lifted are
//! those of a nearby Coulomb answer.
//!
//! The LCP, for k contacts with unknowns x_i = (r_n,i, β_i1, …, β_im) and
//! slacks λ_i: r_i = G_i x_i with G_i = [[1, 0], [0, D]], D's columns the m
//! unit directions d_j = (cos 2πj/m, sin 2πj/m) in the tangent plane, so
//! that u = W G x + q and
//! - 0 ≤ r_n,i ⟂ u_n,i ≥ 0,
//! - 0 ≤ β_ij ⟂ λ_i + d_j · u_t,i ≥ 0,
//! - 0 ≤ λ_i ⟂ μ_i r_n,i − Σ_j β_ij ≥ 0:
//!
//! M = [[Gᵀ W G, E], [μ̂ − Eᵀ, 0]], q' = (Gᵀ q, 0), with E_(β_ij, λ_i) = 1
//! and μ̂_(λ_i, r_n,i) = μ_i. M is copositive-plus (Gᵀ W G ⪰ 0, the other
//! blocks skew up to μ̂ ≥ 0), so Lemke's path ends on a solution
//! (Cottle–Pang–Stone 1992, §4.4). Since ‖Σ_j β_ij d_j‖ ≤ Σ_j β_ij ≤ μ_i
//! r_n,i, the answer's r lies in the round cones.

use super::problem::FrictionProblem;
use crate::cpu::lemke::{lemke, LemkeSettings};
use crate::lcp::{Lcp, Status};

/// Faces of the pyramid that replaces each friction cone: a sliding
/// contact's direction is then within π/8 of the Coulomb one.
pub(crate) const FACETS: usize = 8;

/// The most contacts of an island given a faceted start: its LCP has
/// k(2 + [`FACETS`]) unknowns (240 at 24), and Lemke's pivots cost
/// O(that²) each (24: two piles of 17 and 19 contacts in `rain:32`, 4
/// worlds × 1,000 steps, were left unsolved at 16).
pub(crate) const FACETED_MAX: usize = 24;

/// The faceted LCP's answer as reactions, into `r` (3k, interleaved), and
/// its slacks λ (k: a contact's sliding speed along the pyramid; 0 where
/// it sticks) into `slide`: (the pivots Lemke took, whether it found an
/// answer: r is left as it was where its path did not end on a solution
/// within `max_pivots` pivots).
pub(crate) fn faceted_start(
    p: &FrictionProblem,
    r: &mut [f64],
    slide: &mut [f64],
    max_pivots: u64,
) -> (u64, bool) {
    let lcp = faceted_lcp(p);
    let sol = lemke(
        &lcp,
        &LemkeSettings {
            max_pivots,
            ..LemkeSettings::default()
        },
    );
    let pivots = sol.counters.pivots;
    if sol.status != Status::Solved || !sol.z.iter().all(|v| v.is_finite()) {
        return (pivots, false);
    }
    let directions = directions();
    let x = 1 + FACETS;
    for i in 0..p.contacts() {
        let xi = &sol.z[x * i..x * (i + 1)];
        let t = xi[1..]
            .iter()
            .zip(&directions)
            .fold([0.0; 2], |t, (b, d)| [t[0] + b * d[0], t[1] + b * d[1]]);
        r[3 * i..3 * i + 3].copy_from_slice(&[xi[0], t[0], t[1]]);
    }
    slide.copy_from_slice(&sol.z[x * p.contacts()..]);
    (pivots, true)
}

/// The unit directions d_j of the pyramid's edges in a contact's tangent
/// plane.
fn directions() -> [[f64; 2]; FACETS] {
    std::array::from_fn(|j| {
        let a = std::f64::consts::TAU * j as f64 / FACETS as f64;
        [a.cos(), a.sin()]
    })
}

/// The faceted LCP of `p` (module docs), row-major.
fn faceted_lcp(p: &FrictionProblem) -> Lcp {
    let (k, n) = (p.contacts(), p.dim());
    let x = 1 + FACETS;
    let nx = k * x;
    let size = nx + k;
    let d = directions();
    // G's column c of contact i as its three entries (rows 3i..3i + 3).
    let g = |c: usize| -> [f64; 3] {
        match c {
            0 => [1.0, 0.0, 0.0],
            _ => [0.0, d[c - 1][0], d[c - 1][1]],
        }
    };
    // W G, n × nx.
    let mut wg = vec![0.0; n * nx];
    for row in 0..n {
        for i in 0..k {
            let w = &p.w[row * n + 3 * i..row * n + 3 * i + 3];
            for c in 0..x {
                let gc = g(c);
                wg[row * nx + i * x + c] = w[0] * gc[0] + w[1] * gc[1] + w[2] * gc[2];
            }
        }
    }
    let mut m = vec![0.0; size * size];
    let mut q = vec![0.0; size];
    for i in 0..k {
        for c in 0..x {
            let gc = g(c);
            let row = i * x + c;
            for col in 0..nx {
                m[row * size + col] = (0..3).map(|a| gc[a] * wg[(3 * i + a) * nx + col]).sum();
            }
            q[row] = (0..3).map(|a| gc[a] * p.q[3 * i + a]).sum();
            if c > 0 {
                m[row * size + nx + i] = 1.0;
                m[(nx + i) * size + row] = -1.0;
            }
        }
        m[(nx + i) * size + i * x] = p.mu[i];
    }
    Lcp { m, q }
}

/// The kind of a contact in [`polish`]'s active set.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// r = 0 (no unknowns).
    Lifted,
    /// u = 0 (unknowns r, three).
    Sticking,
    /// u_n = 0, r_t = −μ r_n (cos θ, sin θ) and u_t along (cos θ, sin θ)
    /// (unknowns r_n and θ): the slide's direction as an angle, so that a
    /// slide at 1e-11 m/s is as well posed as one at 1 m/s.
    Sliding,
}

/// Gauss–Newton steps of [`polish`] per active set.
const POLISH_STEPS: u64 = 20;

/// Active sets [`polish`] tries from each start (the faceted one, then
/// each correction of [`reclassify`]).
const POLISH_ROUNDS: usize = 3;

/// The thresholds (times ‖q‖) above which a contact's faceted slack λ
/// counts as sliding in [`polish`]'s first active sets, tried in turn:
/// the faceted answer's slacks at rest are 1e-18–1e-14 of ‖q‖, its slides
/// at the rounding of a degenerate pile 1e-11–1e-9, real slides larger.
const SLIDE_THRESHOLDS: [f64; 3] = [1e-14, 1e-10, 1e-6];

/// From the faceted answer (`r`, slacks `slide`): for each of the active
/// sets of [`SLIDE_THRESHOLDS`] (lifted where r_n = 0, sliding where λ is
/// above the threshold, sticking otherwise), damped Gauss–Newton on the
/// set's equations (see [`Kind`]); where its best iterate is short of
/// `tolerance`, the set corrected where that iterate contradicts it
/// ([`reclassify`]) and again, at most [`POLISH_ROUNDS`] sets in all; where
/// every such set falls short, the neighbours of the best one
/// ([`neighbours`]). Writes into `r` the first r found whose Coulomb error
/// is at most `tolerance` (else r is left as it was): (steps, that error
/// or the best error seen).
pub(crate) fn polish(
    p: &FrictionProblem,
    r: &mut [f64],
    slide: &[f64],
    max_steps: u64,
    tolerance: f64,
) -> (u64, f64) {
    let q_norm = super::residual::norm(&p.q);
    let mut search = Search::new(p, max_steps, tolerance);
    for t in SLIDE_THRESHOLDS {
        let mut kinds: Vec<Kind> = (0..p.contacts())
            .map(|i| match (r[3 * i] > 0.0, slide[i] > t * q_norm) {
                (false, _) => Kind::Lifted,
                (true, true) => Kind::Sliding,
                (true, false) => Kind::Sticking,
            })
            .collect();
        let mut from = r.to_vec();
        for _ in 0..POLISH_ROUNDS {
            let Some(x) = search.try_set(&kinds, &from) else {
                break;
            };
            if search.solved() {
                r.copy_from_slice(&x);
                return search.outcome();
            }
            if !reclassify(p, &x, &mut kinds) {
                break;
            }
            from = x;
        }
    }
    if let Some(x) = neighbours(&mut search) {
        r.copy_from_slice(&x);
    }
    search.outcome()
}

/// The state of [`polish`]'s search over active sets: the steps used of
/// the cap, the best Coulomb error seen, and the active set and r of the
/// best iterate.
struct Search<'a> {
    p: &'a FrictionProblem,
    used: u64,
    max_steps: u64,
    tolerance: f64,
    best: f64,
    best_set: Option<(Vec<Kind>, Vec<f64>)>,
}

impl<'a> Search<'a> {
    fn new(p: &'a FrictionProblem, max_steps: u64, tolerance: f64) -> Self {
        Search {
            p,
            used: 0,
            max_steps,
            tolerance,
            best: f64::INFINITY,
            best_set: None,
        }
    }

    /// Gauss–Newton on `kinds` from `from` within the steps left: its best
    /// r, or None where no step is left. Records the best set.
    fn try_set(&mut self, kinds: &[Kind], from: &[f64]) -> Option<Vec<f64>> {
        if self.used >= self.max_steps || self.solved() {
            return None;
        }
        let steps = POLISH_STEPS.min(self.max_steps - self.used);
        let (k, e, x) = gauss_newton(self.p, kinds, from, steps, self.tolerance);
        self.used += k;
        if e < self.best {
            self.best = e;
            self.best_set = Some((kinds.to_vec(), x.clone()));
        }
        Some(x)
    }

    /// Whether the best r is within the tolerance.
    fn solved(&self) -> bool {
        self.best <= self.tolerance
    }

    /// (steps used, the best error).
    fn outcome(&self) -> (u64, f64) {
        (self.used, self.best)
    }
}

/// Contacts whose kind [`neighbours`] changes: the [`FLIPPED`] of largest
/// residual in the best set's r.
const FLIPPED: usize = 4;

/// The neighbours of the best active set of `search` (its r short of the
/// tolerance): each of its [`FLIPPED`] contacts of largest Coulomb residual
/// (‖r_i − P_K(r_i − ũ_i)‖, the contact's part of the error; ties in
/// index order) given each other kind ([`flips`]), Gauss–Newton on each
/// set from the best r with the flipped contact's reaction restarted
/// ([`restart`]). A contact on the edge between sticking and
/// sliding, or loaded only to rounding, is where the faceted answer's
/// rounding picks the wrong side, and where the set's own correction sees
/// nothing to correct. Again around the best set found, while that lowers
/// the error, at most [`NEIGHBOUR_ROUNDS`] rounds (a flip can make a
/// second one needed). The first r within the tolerance, else None.
fn neighbours(search: &mut Search) -> Option<Vec<f64>> {
    for _ in 0..NEIGHBOUR_ROUNDS {
        let base = search.best;
        if let Some(x) = neighbours_of_best(search) {
            return Some(x);
        }
        if !(search.best < base) {
            break;
        }
    }
    None
}

/// Rounds of [`neighbours`]: each from the best set the last one found,
/// while that lowers the error.
const NEIGHBOUR_ROUNDS: usize = 3;

/// One round of [`neighbours`] around the best set so far.
fn neighbours_of_best(search: &mut Search) -> Option<Vec<f64>> {
    let (kinds, x) = search.best_set.clone()?;
    let p = search.p;
    let u = p.velocity(&x);
    let worst = worst_contacts(p, &x, &u, FLIPPED);
    for &c in &worst {
        for &k in flips(kinds[c]) {
            let (mut set, mut from) = (kinds.clone(), x.clone());
            set[c] = k;
            restart(p, c, k, &u, &mut from);
            let found = search.try_set(&set, &from)?;
            if search.solved() {
                return Some(found);
            }
        }
    }
    None
}

/// The kinds a contact of kind `k` is tried as by [`neighbours`]: the two
/// others, and a sliding one sliding again from the edge of its cone
/// against its velocity ([`restart`]: Gauss–Newton's equations hold as
/// well where the slide runs along its friction as against it, and a
/// sliding contact found running along it is the wrong root).
fn flips(k: Kind) -> &'static [Kind] {
    match k {
        Kind::Lifted => &[Kind::Sticking, Kind::Sliding],
        Kind::Sticking => &[Kind::Sliding, Kind::Lifted],
        Kind::Sliding => &[Kind::Sliding, Kind::Sticking, Kind::Lifted],
    }
}

/// Contact `c`'s reaction in `r`, restarted for kind `k` with u = W r + q
/// at the best r: sliding, on the edge of its cone against its tangential
/// velocity (r_t = −μ r_n u_t/‖u_t‖: a sticking contact's u_t, the residual
/// of an inconsistent set, points where it would slide; kept where u_t = 0
/// or r_n ≤ 0); lifted, zero; sticking, as it is.
fn restart(p: &FrictionProblem, c: usize, k: Kind, u: &[f64], r: &mut [f64]) {
    let (rn, ut) = (r[3 * c], [u[3 * c + 1], u[3 * c + 2]]);
    let speed = ut[0].hypot(ut[1]);
    match k {
        Kind::Sliding if speed > 0.0 && rn > 0.0 => {
            let edge = p.mu[c] * rn / speed;
            r[3 * c + 1] = -edge * ut[0];
            r[3 * c + 2] = -edge * ut[1];
        }
        Kind::Lifted => r[3 * c..3 * c + 3].fill(0.0),
        _ => {}
    }
}

/// The (at most) `count` contacts of largest Coulomb residual at r (u = W
/// r + q), the largest first, ties in index order.
fn worst_contacts(p: &FrictionProblem, r: &[f64], u: &[f64], count: usize) -> Vec<usize> {
    let mut diff = vec![0.0; p.dim()];
    super::residual::coulomb_error_into(p, r, u, 1.0, &mut diff);
    let part = |i: usize| super::residual::norm(&diff[3 * i..3 * i + 3]);
    let mut order: Vec<usize> = (0..p.contacts()).collect();
    order.sort_by(|&a, &b| part(b).total_cmp(&part(a)));
    order.truncate(count);
    order
}

/// Corrects `kinds` where r contradicts them: a lifted contact approaching
/// (u_n < 0) sticks, a loaded one pulling (r_n < 0) lifts, a sticking one
/// outside its cone slides, a sliding one whose velocity runs along its
/// friction (u_t · r_t > 0) sticks. Whether any kind changed.
fn reclassify(p: &FrictionProblem, r: &[f64], kinds: &mut [Kind]) -> bool {
    let u = p.velocity(r);
    let mut changed = false;
    for (i, kind) in kinds.iter_mut().enumerate() {
        let (ri, ui) = (&r[3 * i..3 * i + 3], &u[3 * i..3 * i + 3]);
        let new = match *kind {
            Kind::Lifted if ui[0] < 0.0 => Kind::Sticking,
            Kind::Lifted => Kind::Lifted,
            _ if ri[0] < 0.0 => Kind::Lifted,
            Kind::Sticking if ri[1].hypot(ri[2]) > p.mu[i] * ri[0] => Kind::Sliding,
            Kind::Sliding if ui[1] * ri[1] + ui[2] * ri[2] > 0.0 => Kind::Sticking,
            k => k,
        };
        changed |= new != *kind;
        *kind = new;
    }
    changed
}

/// The reactions of the unknowns `x` of the active set `kinds`.
fn reactions(p: &FrictionProblem, kinds: &[Kind], x: &[f64], r: &mut [f64]) {
    let mut c = 0;
    for (i, kind) in kinds.iter().enumerate() {
        let ri = match kind {
            Kind::Lifted => [0.0; 3],
            Kind::Sticking => {
                c += 3;
                [x[c - 3], x[c - 2], x[c - 1]]
            }
            Kind::Sliding => {
                c += 2;
                let (rn, th) = (x[c - 2], x[c - 1]);
                [rn, -p.mu[i] * rn * th.cos(), -p.mu[i] * rn * th.sin()]
            }
        };
        r[3 * i..3 * i + 3].copy_from_slice(&ri);
    }
}

/// The equations of `kinds` at x (r and u = W r + q given) into `f`, and
/// when `jac` is Some their Jacobian (rows of f × unknowns, row-major).
fn equations(
    p: &FrictionProblem,
    kinds: &[Kind],
    x: &[f64],
    u: &[f64],
    f: &mut [f64],
    jac: Option<&mut [f64]>,
) {
    let n = p.dim();
    let m = x.len();
    // ∂r/∂x: for each unknown, the contact it moves and its 3 entries;
    // the rows of f: (a linear form on u_i, the contact, the θ column and
    // the form's derivative in θ where it depends on θ).
    let mut columns = Vec::with_capacity(m);
    let mut rows: Vec<([f64; 3], usize, Option<(usize, [f64; 3])>)> = Vec::with_capacity(m);
    let mut c = 0;
    for (i, kind) in kinds.iter().enumerate() {
        match kind {
            Kind::Lifted => {}
            Kind::Sticking => {
                for a in 0..3 {
                    let mut e = [0.0; 3];
                    e[a] = 1.0;
                    columns.push((i, e));
                    rows.push((e, i, None));
                }
                c += 3;
            }
            Kind::Sliding => {
                let (rn, th, mu) = (x[c], x[c + 1], p.mu[i]);
                let (s, co) = th.sin_cos();
                columns.push((i, [1.0, -mu * co, -mu * s]));
                columns.push((i, [0.0, mu * rn * s, -mu * rn * co]));
                rows.push(([1.0, 0.0, 0.0], i, None));
                rows.push(([0.0, -s, co], i, Some((c + 1, [0.0, -co, -s]))));
                c += 2;
            }
        }
    }
    for (row, (e, i, _)) in rows.iter().enumerate() {
        f[row] = (0..3).map(|a| e[a] * u[3 * i + a]).sum();
    }
    if let Some(jac) = jac {
        for (row, (e, i, dth)) in rows.iter().enumerate() {
            for (col, (j, d)) in columns.iter().enumerate() {
                // e · (W_ij d)
                jac[row * m + col] = (0..3)
                    .map(|a| {
                        let w = &p.w[(3 * i + a) * n + 3 * j..(3 * i + a) * n + 3 * j + 3];
                        e[a] * (w[0] * d[0] + w[1] * d[1] + w[2] * d[2])
                    })
                    .sum();
            }
            if let Some((col, de)) = dth {
                jac[row * m + col] += (0..3).map(|a| de[a] * u[3 * i + a]).sum::<f64>();
            }
        }
    }
}

/// Levenberg–Marquardt damping of [`gauss_newton`], relative to the mean
/// diagonal of JᵀJ: small, so that the step is nearly the least-squares
/// one of smallest norm where J is singular (the degenerate piles).
const DAMPING: f64 = 1e-14;

/// Steps without a smaller Coulomb error after which [`gauss_newton`]
/// stops (the set's equations are inconsistent there, or solved to
/// rounding; the error of a full Gauss–Newton step on a degenerate pile
/// swings by 1e3 from step to step before it falls).
const STALL: u64 = 8;

/// Damped Gauss–Newton for the active set `kinds` from the reactions
/// `r0`, full steps (a degenerate pile's equations are inconsistent at the
/// 1e-10 of ‖q‖ that its answer turns on: a line search on their residual
/// stalls where the Coulomb error still falls), at most `steps` steps,
/// until the Coulomb error is at most `tolerance`: (steps, the smallest
/// Coulomb error seen, its r).
fn gauss_newton(
    p: &FrictionProblem,
    kinds: &[Kind],
    r0: &[f64],
    steps: u64,
    tolerance: f64,
) -> (u64, f64, Vec<f64>) {
    let u0 = p.velocity(r0);
    let mut x = Vec::new();
    for (i, kind) in kinds.iter().enumerate() {
        let (ri, ui) = (&r0[3 * i..3 * i + 3], &u0[3 * i..3 * i + 3]);
        match kind {
            Kind::Lifted => {}
            Kind::Sticking => x.extend_from_slice(ri),
            // The slide's direction: against r_t, or along u_t where r_t = 0.
            Kind::Sliding if ri[1] == 0.0 && ri[2] == 0.0 => {
                x.extend_from_slice(&[ri[0].max(0.0), ui[2].atan2(ui[1])])
            }
            Kind::Sliding => x.extend_from_slice(&[ri[0], (-ri[2]).atan2(-ri[1])]),
        }
    }
    let m = x.len();
    let mut r = r0.to_vec();
    reactions(p, kinds, &x, &mut r);
    let mut best_r = r.clone();
    let mut best = super::residual::coulomb_error(p, &r);
    if m == 0 {
        return (0, best, best_r);
    }
    let (mut f, mut jac) = (vec![0.0; m], vec![0.0; m * m]);
    let (mut normal, mut step) = (vec![0.0; m * m], vec![0.0; m]);
    let mut u = p.velocity(&r);
    let (mut done, mut since) = (0, 0);
    while done < steps && since < STALL && best > tolerance {
        done += 1;
        equations(p, kinds, &x, &u, &mut f, Some(&mut jac));
        // (JᵀJ + δ I) step = −Jᵀ f.
        for a in 0..m {
            for b in 0..m {
                normal[a * m + b] = (0..m).map(|row| jac[row * m + a] * jac[row * m + b]).sum();
            }
            step[a] = -(0..m).map(|row| jac[row * m + a] * f[row]).sum::<f64>();
        }
        let mean = (0..m).map(|a| normal[a * m + a]).sum::<f64>() / m as f64;
        for a in 0..m {
            normal[a * m + a] += DAMPING * mean;
        }
        if !crate::linalg::solve_in_place(&mut normal, &mut step, m, 0.0)
            || !step.iter().all(|v| v.is_finite())
        {
            break;
        }
        for a in 0..m {
            x[a] += step[a];
        }
        reactions(p, kinds, &x, &mut r);
        u = p.velocity(&r);
        let e = super::residual::FrictionResiduals::of_velocity(p, &r, &u).coulomb_error;
        since += 1;
        if e < best {
            best = e;
            best_r.copy_from_slice(&r);
            since = 0;
        }
    }
    (done, best, best_r)
}

#[cfg(test)]
#[path = "faceted_tests.rs"]
mod faceted_tests;
