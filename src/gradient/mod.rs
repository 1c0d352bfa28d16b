//! Gradients through the exact contact solve: vector–Jacobian products of
//! an LCP's solution with respect to its data (M, q), one island at a time
//! or a batch on every core, and through assembly to the bodies and
//! contacts of a frictionless scene ([`scene_vjp`]).
//!
//! # The derivative of an LCP's solution
//! At a solution z of w = M z + q ≥ 0, z ≥ 0, zᵀw = 0, split the rows into
//! the active set α (z_α > 0, w_α = 0) and the inactive set β (z_β = 0,
//! w_β ≥ 0). Where α is the same for every nearby (M, q) and M_αα is
//! nonsingular, the solution is the smooth function
//!
//! ```text
//! z_α = −M_αα⁻¹ q_α,   z_β = 0,   w_α = 0,   w_β = M_βα z_α + q_β.
//! ```
//!
//! For a loss L(z, w) with g = ∂L/∂z and h = ∂L/∂w (h = 0 when not given),
//! perturb (M, q) by (dM, dq):
//!
//! ```text
//! dz_β = 0,   dw_α = 0,
//! dz_α = −M_αα⁻¹ (dM_αα z_α + dq_α) = −M_αα⁻¹ (dM z + dq)_α      (z_β = 0)
//! dw_β = (dM z + dq)_β + M_βα dz_α
//! dL = gᵀdz + hᵀdw = (g_α + M_βαᵀ h_β)ᵀ dz_α + h_βᵀ (dM z + dq)_β.
//! ```
//!
//! With u solving M_ααᵀ u = v, v = g_α + M_βαᵀ h_β (one small solve per
//! island), (g_α + M_βαᵀ h_β)ᵀ dz_α = −uᵀ (dM z + dq)_α. So with
//! r_α = −u and r_β = h_β, dL = rᵀ (dM z + dq), that is
//!
//! ```text
//! ∂L/∂q = r,   ∂L/∂M_ij = r_i z_j   (0 in the columns j ∈ β, where z_j = 0).
//! ```
//!
//! h_α does not enter: w_α is 0 for every nearby problem. The inactive rows
//! pass ∂L/∂w straight to q (w_β = … + q_β) and, through M_βα, back into the
//! active solve.
//!
//! # Degenerate and undefined points
//! With a scale τ (below), row i is active when z_i > τ_z, inactive when
//! w_i > τ_w, and *degenerate* when both z_i ≤ τ_z and w_i ≤ τ_w (a contact
//! that touches without pushing). A degenerate row is treated as inactive:
//! the result is the derivative along perturbations that keep it inactive
//! (a valid one-sided derivative), flagged [`Derivative::OneSided`]. The
//! derivative is [`Derivative::Undefined`], and both ∂L/∂M and ∂L/∂q are
//! set to zero (the choice documented here: no least-squares guess), when
//!
//! * M_αα is singular to the solvers' own test ([`crate::Settings::pivot_tol`]'s
//!   default 1e-13: a pivot of M_ααᵀ under 1e-13 times its column's largest
//!   entry), so z_α is not locally unique;
//! * z is not a solution within τ: z_i < −τ_z, w_i < −τ_w, or both
//!   z_i > τ_z and w_i > τ_w.
//!
//! # The scale τ
//! With the tolerance t (a relative number, e.g. [`crate::Settings::tolerance`]),
//! m = max |M_ij|, τ_w = t · max(‖q‖∞, m ‖z‖∞) (w's size: the terms whose
//! sum it is) and τ_z = τ_w / m (impulses that change w by τ_w), or
//! t ‖z‖∞ when M = 0. Scaling M, q or z by a constant changes no verdict.
//!
//! See also [`Report::lcp_vjps`] for a solved batch, and [`scene_vjp`] for
//! the bodies and contacts of a scene.

use std::fmt;
use std::str::FromStr;

use crate::cpu::batch::{parallel_fill, parallel_map};
use crate::lcp::validate_parts;
use crate::linalg::{solve_in_place, PIVOT_TOL};
use crate::short_vec::ShortVec;
use crate::{Error, Lcp, Report, Settings};

mod scene;
pub use scene::{scene_vjp, BodyGradient, ContactGradient, SceneGradient};

/// How an island's derivative is to be read.
#[non_exhaustive]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Derivative {
    /// The solution is differentiable here: every row strictly active or
    /// strictly inactive, M_αα nonsingular. The gradient is exact.
    Exact,
    /// A degenerate row (z_i and w_i both 0 within τ), or several solutions
    /// ([`crate::Status::MultipleSolutions`]): the gradient is that of the
    /// branch with those rows inactive (or the solver's chosen solution),
    /// exact along perturbations that keep it; see the module docs.
    OneSided,
    /// No derivative: M_αα singular, or z not a solution (or the island's
    /// status not a solution). ∂L/∂M and ∂L/∂q are zero.
    Undefined,
}

impl Derivative {
    /// Every kind, from the best to the worst.
    pub const ALL: [Derivative; 3] = [
        Derivative::Exact,
        Derivative::OneSided,
        Derivative::Undefined,
    ];

    /// The snake_case name: `exact`, `one_sided`, `undefined`.
    pub fn name(&self) -> &'static str {
        match self {
            Derivative::Exact => "exact",
            Derivative::OneSided => "one_sided",
            Derivative::Undefined => "undefined",
        }
    }

    /// The worse of the two (Exact < OneSided < Undefined).
    pub(crate) fn worst(self, other: Derivative) -> Derivative {
        let rank = |d: Derivative| Derivative::ALL.iter().position(|&x| x == d);
        if rank(other) > rank(self) {
            other
        } else {
            self
        }
    }
}

impl fmt::Display for Derivative {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Derivative {
    type Err = Error;
    /// The kind of [`Derivative::name`]; an error listing the names otherwise.
    fn from_str(s: &str) -> Result<Self, Error> {
        crate::settings::from_name("derivative", s, &Derivative::ALL, |d| d.name())
    }
}

/// One island's vector–Jacobian product.
#[non_exhaustive]
#[derive(Clone, Debug)]
pub struct LcpGradient {
    /// ∂L/∂M, row-major n×n: entry i·n + j is ∂L/∂M_ij.
    pub m: Vec<f64>,
    /// ∂L/∂q, n entries.
    pub q: Vec<f64>,
    /// How to read it (zeros when [`Derivative::Undefined`]).
    pub derivative: Derivative,
}

impl LcpGradient {
    /// Zero gradient of an n-row island, flagged undefined.
    fn undefined(n: usize) -> Self {
        LcpGradient {
            m: vec![0.0; n * n],
            q: vec![0.0; n],
            derivative: Derivative::Undefined,
        }
    }
}

/// One island: given its LCP, a solution z (w = M z + q is recomputed
/// here), ∂L/∂z and optionally ∂L/∂w, the gradient ∂L/∂M, ∂L/∂q (module
/// docs: the formula, its derivation and the degenerate cases).
/// `tolerance` is the relative t of the scale τ (e.g. 1e-8, the default
/// [`Settings::tolerance`]). Allocates the two outputs, and index lists
/// only beyond [`crate::short_vec::SHORT_INLINE`] rows.
///
/// # Errors
/// [`Error::Invalid`] naming "island 0" and the field: the LCP's own checks
/// ([`Lcp::validate`]), `z`, `dz` or `dw` of the wrong length or with an
/// entry not finite, `tolerance` not in [0, 1).
pub fn lcp_vjp(
    lcp: &Lcp,
    z: &[f64],
    dz: &[f64],
    dw: Option<&[f64]>,
    tolerance: f64,
) -> Result<LcpGradient, Error> {
    check_tolerance(tolerance)?;
    island_vjp(0, lcp, z, dz, dw, tolerance)
}

/// [`lcp_vjp`] for a batch, on every core (the CPU path's thread pool),
/// results in the batch's order. `z`, `dz` and `dw` (when given) hold one
/// slice per island.
///
/// # Errors
/// [`Error::Invalid`]: "batch" and the field when `z`, `dz` or `dw` does not
/// have one entry per LCP; else the first island's error in the order of
/// the batch ("island i" and the field, as [`lcp_vjp`]).
pub fn lcp_vjp_batch(
    lcps: &[Lcp],
    z: &[&[f64]],
    dz: &[&[f64]],
    dw: Option<&[&[f64]]>,
    tolerance: f64,
) -> Result<Vec<LcpGradient>, Error> {
    check_tolerance(tolerance)?;
    check_count("z", z.len(), lcps.len())?;
    check_count("dz", dz.len(), lcps.len())?;
    if let Some(dw) = dw {
        check_count("dw", dw.len(), lcps.len())?;
    }
    parallel_map(lcps.len(), threads(), |i| {
        island_vjp(i, &lcps[i], z[i], dz[i], dw.map(|d| d[i]), tolerance)
    })
    .into_iter()
    .collect()
}

/// [`lcp_vjp_batch`] of a dense batch of B islands of one size n, held as
/// flat row-major arrays (`m` B·n·n, `q`, `z`, `dz`, `dw` B·n), written
/// into the caller's `out_m` (B·n·n) and `out_q` (B·n): nothing allocated
/// per island. The same gradients and errors as [`lcp_vjp_batch`] on the
/// same problems; returns each island's [`Derivative`].
///
/// # Errors
/// As [`lcp_vjp_batch`]; "batch" and the field when n is 0 or an array's
/// length is not that of B islands of size n (B = `q.len() / n`).
#[allow(clippy::too_many_arguments)]
pub fn lcp_vjp_dense_into(
    n: usize,
    m: &[f64],
    q: &[f64],
    z: &[f64],
    dz: &[f64],
    dw: Option<&[f64]>,
    tolerance: f64,
    out_m: &mut [f64],
    out_q: &mut [f64],
) -> Result<Vec<Derivative>, Error> {
    check_tolerance(tolerance)?;
    if n == 0 {
        return Err(Error::invalid("batch", "q", "empty problems (n = 0)"));
    }
    let b = q.len() / n;
    check_count("q", q.len(), b * n)?;
    check_count("M", m.len(), b * n * n)?;
    check_count("z", z.len(), b * n)?;
    check_count("dz", dz.len(), b * n)?;
    if let Some(dw) = dw {
        check_count("dw", dw.len(), b * n)?;
    }
    check_count("out_m", out_m.len(), b * n * n)?;
    check_count("out_q", out_q.len(), b * n)?;
    let mut slots: Vec<(&mut [f64], &mut [f64], Result<Derivative, Error>)> = out_m
        .chunks_exact_mut(n * n)
        .zip(out_q.chunks_exact_mut(n))
        .map(|(gm, gq)| (gm, gq, Ok(Derivative::Exact)))
        .collect();
    parallel_fill(&mut slots, threads(), |i, (gm, gq, r)| {
        let rows = i * n..(i + 1) * n;
        *r = island_vjp_into(
            i,
            &m[i * n * n..(i + 1) * n * n],
            &q[rows.clone()],
            &z[rows.clone()],
            &dz[rows.clone()],
            dw.map(|d| &d[rows]),
            tolerance,
            gm,
            gq,
        );
    });
    slots.into_iter().map(|(_, _, r)| r).collect()
}

impl Report {
    /// [`lcp_vjp_batch`] at the report's solutions: `lcps` are the problems
    /// this report solved (one per [`Report::islands`], in order; for a
    /// scene batch, the islands' LCPs), z is each island's reported z.
    /// An island whose status is not a solution gets a zero gradient
    /// flagged [`Derivative::Undefined`]; one with
    /// [`crate::Status::MultipleSolutions`] is at least
    /// [`Derivative::OneSided`] (another solution may win nearby). A report
    /// does not keep its settings: the scale τ uses the default
    /// [`Settings::tolerance`] (1e-8).
    ///
    /// # Errors
    /// As [`lcp_vjp_batch`], "batch" and `lcps` when there is not one LCP
    /// per island, "island i" and `lcps` when an LCP's size is not the
    /// island's.
    pub fn lcp_vjps(
        &self,
        lcps: &[Lcp],
        dz: &[&[f64]],
        dw: Option<&[&[f64]]>,
    ) -> Result<Vec<LcpGradient>, Error> {
        let n = self.islands.len();
        check_count("lcps", lcps.len(), n)?;
        check_count("dz", dz.len(), n)?;
        if let Some(dw) = dw {
            check_count("dw", dw.len(), n)?;
        }
        let tolerance = Settings::default().tolerance;
        parallel_map(n, threads(), |i| {
            let island = &self.islands[i];
            let (lcp, z) = (&lcps[i], &island.solution.z[..]);
            if lcp.n() != z.len() {
                return Err(Error::invalid(
                    format_args!("island {i}"),
                    "lcps",
                    format!("has {} rows, the island {}", lcp.n(), z.len()),
                ));
            }
            let mut g = island_vjp(i, lcp, z, dz[i], dw.map(|d| d[i]), tolerance)?;
            match island.status() {
                crate::Status::Solved => {}
                crate::Status::MultipleSolutions => {
                    g.derivative = g.derivative.worst(Derivative::OneSided)
                }
                _ => g = LcpGradient::undefined(lcp.n()),
            }
            Ok(g)
        })
        .into_iter()
        .collect()
    }
}

/// Every core the OS reports (as the solver's default `threads`).
fn threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

fn check_tolerance(tolerance: f64) -> Result<(), Error> {
    if (0.0..1.0).contains(&tolerance) {
        Ok(())
    } else {
        Err(Error::invalid(
            "gradient",
            "tolerance",
            format!("{tolerance} is not in [0, 1)"),
        ))
    }
}

/// `got` entries where `want` are expected, else an error naming the field.
fn check_count(field: &str, got: usize, want: usize) -> Result<(), Error> {
    if got == want {
        Ok(())
    } else {
        Err(Error::invalid(
            "batch",
            field,
            format!("has {got} entries, expected {want}"),
        ))
    }
}

/// `v` has `n` finite entries, else an error naming `item` and the field.
fn check_vector(item: impl fmt::Display, field: &str, v: &[f64], n: usize) -> Result<(), Error> {
    if v.len() != n {
        return Err(Error::invalid(
            item,
            field,
            format!("has {} entries, expected {n}", v.len()),
        ));
    }
    match v.iter().position(|x| !x.is_finite()) {
        None => Ok(()),
        Some(k) => Err(Error::invalid(
            item,
            format!("{field}[{k}]"),
            "not a finite number",
        )),
    }
}

/// One island's product (module docs), island `i` named in errors.
fn island_vjp(
    i: usize,
    lcp: &Lcp,
    z: &[f64],
    dz: &[f64],
    dw: Option<&[f64]>,
    tolerance: f64,
) -> Result<LcpGradient, Error> {
    let n = lcp.n();
    let (mut gm, mut gq) = (vec![0.0; n * n], vec![0.0; n]);
    let derivative = island_vjp_into(i, &lcp.m, &lcp.q, z, dz, dw, tolerance, &mut gm, &mut gq)?;
    Ok(LcpGradient {
        m: gm,
        q: gq,
        derivative,
    })
}

/// [`island_vjp`] of the problem M (`m`, row-major n×n), q, written into
/// `gm` (n×n) and `gq` (n): zeros where the derivative is undefined.
#[allow(clippy::too_many_arguments)]
fn island_vjp_into(
    i: usize,
    m: &[f64],
    q: &[f64],
    z: &[f64],
    dz: &[f64],
    dw: Option<&[f64]>,
    tolerance: f64,
    gm: &mut [f64],
    gq: &mut [f64],
) -> Result<Derivative, Error> {
    validate_parts(m, q, format_args!("island {i}"))?;
    let n = q.len();
    let item = format_args!("island {i}");
    check_vector(item, "z", z, n)?;
    check_vector(item, "dz", dz, n)?;
    if let Some(dw) = dw {
        check_vector(item, "dw", dw, n)?;
    }
    let h = |r: usize| dw.map_or(0.0, |d| d[r]);
    // The scale τ (module docs).
    let inf = |v: &[f64]| v.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    let (m_max, z_max) = (inf(m), inf(z));
    let tau_w = tolerance * inf(q).max(m_max * z_max);
    let tau_z = if m_max > 0.0 {
        tau_w / m_max
    } else {
        tolerance * z_max
    };
    // Classify the rows: the active set α in increasing order.
    let mut derivative = Derivative::Exact;
    let mut active: ShortVec<bool> = ShortVec::from_elem(false, n);
    let mut alpha: ShortVec<usize> = ShortVec::new();
    for r in 0..n {
        let row = &m[r * n..(r + 1) * n];
        let w = q[r] + row.iter().zip(z).map(|(a, b)| a * b).sum::<f64>();
        let (on, open) = (z[r] > tau_z, w > tau_w);
        if z[r] < -tau_z || w < -tau_w || (on && open) {
            return Ok(undefined(gm, gq));
        }
        if on {
            active[r] = true;
            alpha.push(r);
        } else if !open {
            derivative = Derivative::OneSided;
        }
    }
    // M_ααᵀ into the output m, v = g_α + M_βαᵀ h_β into the output q.
    let k = alpha.len();
    for (a, &ca) in alpha.iter().enumerate() {
        for (b, &cb) in alpha.iter().enumerate() {
            gm[a * k + b] = m[cb * n + ca];
        }
        let back: f64 = (0..n)
            .filter(|&r| !active[r])
            .map(|r| m[r * n + ca] * h(r))
            .sum();
        gq[a] = dz[ca] + back;
    }
    if !solve_in_place(&mut gm[..k * k], &mut gq[..k], k, PIVOT_TOL) {
        return Ok(undefined(gm, gq));
    }
    // r in place, from the last row down: u_j sits at j ≤ α_j, so each u_j
    // is read before its slot is written.
    let mut j = k;
    for r in (0..n).rev() {
        gq[r] = if active[r] {
            j -= 1;
            -gq[j]
        } else {
            h(r)
        };
    }
    // ∂L/∂M = r zᵀ over the active columns.
    for r in 0..n {
        for c in 0..n {
            gm[r * n + c] = if active[c] { gq[r] * z[c] } else { 0.0 };
        }
    }
    Ok(derivative)
}

/// Zeros in `gm` and `gq`: an undefined island's gradient.
fn undefined(gm: &mut [f64], gq: &mut [f64]) -> Derivative {
    gm.fill(0.0);
    gq.fill(0.0);
    Derivative::Undefined
}
