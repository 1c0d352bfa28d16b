//! The buffers of the exact Coulomb solvers ([`super::nsgs`],
//! [`super::newton`]), sized once per island and reused across the islands
//! one thread solves, so that no sweep or Newton step allocates; and the
//! velocity u = W r + q they keep current instead of recomputing it.

use std::cell::RefCell;

use super::local::Block;
use super::problem::FrictionProblem;
use super::prox::ProxScratch;
use super::residual::{coulomb_error_into, norm};
use super::sparse::{envelope, velocity_sparse, Pattern, SPARSE_FROM};

/// Per-island state and scratch of the exact solvers. [`Workspace::prepare`]
/// sizes it for a problem; every buffer then has the problem's dimension.
#[derive(Debug, Default)]
pub struct Workspace {
    /// u = W r + q of the current r (kept current by the solvers).
    pub(crate) u: Vec<f64>,
    /// The Coulomb error's vector r − P_K(r − ũ), 3k.
    pub(crate) diff: Vec<f64>,
    /// The contacts' 3×3 diagonal blocks of W.
    pub(crate) blocks: Vec<Block>,
    /// The Newton scalings ρ_i = 1 / W_ii,nn.
    pub(crate) rho: Vec<f64>,
    /// ‖q‖ (a term of the error's normalisation).
    pub(crate) q_norm: f64,
    /// Φ(r) of the Alart–Curnier equation, 3k.
    pub(crate) phi: Vec<f64>,
    /// Its generalized Jacobian, 3k × 3k (zero outside W's block pattern).
    pub(crate) jac: Vec<f64>,
    /// The Newton step Δ, 3k.
    pub(crate) delta: Vec<f64>,
    /// W Δ, 3k: the velocity's change along the step (line search in O(k)).
    pub(crate) w_delta: Vec<f64>,
    /// A trial r and its u and Φ, 3k each.
    pub(crate) trial: Vec<f64>,
    pub(crate) trial_u: Vec<f64>,
    pub(crate) trial_phi: Vec<f64>,
    /// The matrix of a linear solve (destroyed by it), 3k × 3k.
    pub(crate) matrix: Vec<f64>,
    /// ∂Φᵀ∂Φ of a Levenberg–Marquardt step, 3k × 3k.
    pub(crate) normal: Vec<f64>,
    /// The rows a Newton step solves through W (`newton::stick_step`),
    /// ascending: a sticking contact's three, a sliding one's normal.
    pub(crate) stuck: Vec<usize>,
    /// The rows of ∂Φ that are ρ_i W's rows (`newton::classify`).
    pub(crate) w_rows: Vec<usize>,
    /// A contact's runs of consecutive neighbour blocks (first, last + 1)
    /// (`newton::normal_system`).
    pub(crate) runs: Vec<(usize, usize)>,
    /// A Cholesky factor's envelope (`sparse::cholesky_in`).
    pub(crate) first: Vec<usize>,
    /// The best r seen (hybrid rounds), 3k.
    pub(crate) best: Vec<f64>,
    /// The start r (hybrid's Newton restart), 3k.
    pub(crate) start: Vec<f64>,
    /// W's nonzero blocks (products and sweeps over them only).
    pub(crate) pattern: Pattern,
    /// Those blocks' copy by block column (`nsgs::gather_columns`), for the
    /// NSGS sweeps on islands of at least `sparse::SPARSE_FROM` contacts.
    pub(crate) columns: Vec<Block>,
    /// W's envelope (`sparse::envelope`), on islands of at least
    /// `sparse::SPARSE_FROM` contacts (else empty: dense LU).
    pub(crate) env_first: Vec<usize>,
    pub(crate) env_last: Vec<usize>,
    /// The LU of ∂Φ failed on this island (W rank-deficient, as for a box on
    /// four coplanar corners): later steps go to Levenberg–Marquardt directly.
    pub(crate) singular: bool,
    /// Newton's line search compares a trial's merit with the largest of
    /// the last `window` merits (nonmonotone, Grippo–Lampariello–Lucidi);
    /// 0 or 1: with the current one (monotone Armijo, the default).
    pub(crate) window: usize,
    /// `jac`, `matrix` and `normal` are sized for the prepared problem
    /// ([`Workspace::newton_buffers`]).
    pub(crate) newton_ready: bool,
    /// PROX's inner problem and workspace (`prox::prox_in`), kept between
    /// calls.
    pub(crate) prox: Option<Box<ProxScratch>>,
}

thread_local! {
    static WORKSPACE: RefCell<Workspace> = RefCell::new(Workspace::default());
}

/// Runs `f` with this thread's workspace (a fresh one when it is in use
/// already, as by a local solve's fallback inside a sweep).
pub fn with_workspace<T>(f: impl FnOnce(&mut Workspace) -> T) -> T {
    let mut f = Some(f);
    let out = WORKSPACE.with(|cell| {
        cell.try_borrow_mut()
            .ok()
            .map(|mut ws| (f.take().expect("called once"))(&mut ws))
    });
    match out {
        Some(v) => v,
        None => (f.take().expect("not called yet"))(&mut Workspace::default()),
    }
}

impl Workspace {
    /// Sizes every buffer for `p`, computes its blocks, scalings and ‖q‖,
    /// and u = W r + q for the start `r`.
    pub fn prepare(&mut self, p: &FrictionProblem, r: &[f64]) {
        self.prepare_with(p, r, false);
    }

    /// [`Workspace::prepare`], where `patterned` says that `self.pattern`
    /// is W's pattern already (not built again).
    pub(crate) fn prepare_with(&mut self, p: &FrictionProblem, r: &[f64], patterned: bool) {
        let n = p.dim();
        for v in [
            &mut self.u,
            &mut self.diff,
            &mut self.phi,
            &mut self.delta,
            &mut self.w_delta,
            &mut self.trial,
            &mut self.trial_u,
            &mut self.trial_phi,
            &mut self.best,
            &mut self.start,
        ] {
            v.clear();
            v.resize(n, 0.0);
        }
        // The 3k × 3k buffers wait for the first Newton step
        // ([`Workspace::newton_buffers`]): NSGS alone never reads them
        // (on 570 contacts, 70 MB).
        self.newton_ready = false;
        if !patterned {
            self.pattern.build(p);
        }
        if p.contacts() >= SPARSE_FROM {
            envelope(&self.pattern, &mut self.env_first, &mut self.env_last);
        } else {
            self.env_first.clear();
            self.env_last.clear();
        }
        self.refit(p, r);
    }

    /// What [`Workspace::prepare`] computes from W's diagonal and q: the
    /// diagonal blocks, the scalings ρ_i = 1 / W_ii,nn (1 when not
    /// positive), ‖q‖, and u = W r + q. Alone, for a problem whose W
    /// differs from the prepared one's on the diagonal only (PROX's
    /// W + αI for another α): W's pattern, its envelope and every
    /// buffer's size stay.
    pub(crate) fn refit(&mut self, p: &FrictionProblem, r: &[f64]) {
        self.blocks.clear();
        self.blocks
            .extend((0..p.contacts()).map(|i| diagonal_block(p, i)));
        self.rho.clear();
        self.rho.extend((0..p.contacts()).map(|i| {
            let d = p.at(3 * i, 3 * i);
            if d > 0.0 && d.is_finite() {
                1.0 / d
            } else {
                1.0
            }
        }));
        self.q_norm = norm(&p.q);
        self.singular = false;
        self.refresh(p, r);
    }

    /// Sizes the Newton step's 3k × 3k buffers for the problem of the last
    /// [`Workspace::prepare`], once after it: ∂Φ cleared on large islands
    /// within W's envelope (it is written only within W's pattern, and read
    /// only within the envelope: the LU's copy; the products and ∂Φᵀ∂Φ read
    /// the pattern), the others written in full before they are read (sized,
    /// not cleared). A buffer kept from an island of this size is not
    /// written outside the envelope (on 570 contacts, 23 MB a call).
    pub(crate) fn newton_buffers(&mut self) {
        if self.newton_ready {
            return;
        }
        let n = self.u.len();
        for v in [&mut self.matrix, &mut self.normal, &mut self.jac] {
            v.resize(n * n, 0.0);
        }
        // Below `SPARSE_FROM` contacts the pattern lists every block and
        // ∂Φ is written in full: it needs no clearing.
        for (i, (&f, &l)) in self.env_first.iter().zip(&self.env_last).enumerate() {
            self.jac[i * n + f..=i * n + l].fill(0.0);
        }
        self.newton_ready = true;
    }

    /// Swaps the Newton step's 3k × 3k buffers (`jac`, `matrix`, `normal`)
    /// and whether they are ready with `other`'s: PROX's inner workspace
    /// borrows the outer one's, idle while PROX runs, and gives them back.
    /// Both workspaces' problems have one dimension and one block pattern
    /// (W and W + αI), so that ∂Φ's zeros outside it hold for either.
    pub(crate) fn lend_newton_buffers(&mut self, other: &mut Workspace) {
        std::mem::swap(&mut self.jac, &mut other.jac);
        std::mem::swap(&mut self.matrix, &mut other.matrix);
        std::mem::swap(&mut self.normal, &mut other.normal);
        std::mem::swap(&mut self.newton_ready, &mut other.newton_ready);
    }

    /// u = W r + q recomputed exactly (the sweeps update it incrementally):
    /// the bits of [`velocity_into`]. Islands below `SPARSE_FROM` contacts
    /// list every block in their pattern, so their rows are taken whole by
    /// [`dot`] (vectorised; the block walk of `velocity_sparse` over every
    /// block was 15% of a resting 4-box stack's step); larger ones over W's
    /// nonzero blocks.
    pub fn refresh(&mut self, p: &FrictionProblem, r: &[f64]) {
        if p.contacts() < SPARSE_FROM {
            velocity_into(p, r, &mut self.u);
        } else {
            velocity_sparse(p, &self.pattern, r, &mut self.u);
        }
    }

    /// The Coulomb error of r with the current u (the same number as
    /// [`super::coulomb_error`] when u is exact).
    pub fn error(&mut self, p: &FrictionProblem, r: &[f64]) -> f64 {
        coulomb_error_into(p, r, &self.u, self.q_norm, &mut self.diff)
    }
}

/// Contact i's 3×3 diagonal block of W.
pub fn diagonal_block(p: &FrictionProblem, i: usize) -> Block {
    block_at(p, i, i)
}

/// W's 3×3 block (j, i): the rows of contact j, the columns of contact i.
#[inline]
pub fn block_at(p: &FrictionProblem, j: usize, i: usize) -> Block {
    let n = p.dim();
    std::array::from_fn(|a| {
        let at = (3 * j + a) * n + 3 * i;
        [p.w[at], p.w[at + 1], p.w[at + 2]]
    })
}

/// u = W r + q into `u` (rows by [`dot`]; the solvers' final u and error
/// are computed by it too, so that their checks and the reported status
/// agree bit for bit).
pub fn velocity_into(p: &FrictionProblem, r: &[f64], u: &mut [f64]) {
    let n = p.dim();
    for (i, ui) in u.iter_mut().enumerate() {
        *ui = p.q[i] + dot(&p.w[i * n..(i + 1) * n], r);
    }
}

/// a · b (over the shorter length) with four running sums, which the
/// compiler keeps in vector registers (a single running sum is one long
/// chain of dependent additions).
#[inline]
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
    let len = a.len().min(b.len());
    let (a, b) = (&a[..len], &b[..len]);
    let mut s = [0.0f64; 4];
    let (ca, cb) = (a.chunks_exact(4), b.chunks_exact(4));
    let (ta, tb) = (ca.remainder(), cb.remainder());
    for (x, y) in ca.zip(cb) {
        for k in 0..4 {
            s[k] += x[k] * y[k];
        }
    }
    let tail: f64 = ta.iter().zip(tb).map(|(x, y)| x * y).sum();
    (s[0] + s[1]) + (s[2] + s[3]) + tail
}

/// [`dot`] of each of the R `rows` with `x` (each as long as `x`), in one
/// pass that loads x once for all R: each row's bits are [`dot`]'s (the
/// same four running sums and tail), R independent chains of additions
/// instead of one.
#[inline]
pub fn dots<const R: usize>(rows: [&[f64]; R], x: &[f64]) -> [f64; R] {
    let len = x.len();
    let body = len - len % 4;
    let mut s = [[0.0f64; 4]; R];
    for c in (0..body).step_by(4) {
        let xc = &x[c..c + 4];
        for (sr, row) in s.iter_mut().zip(&rows) {
            let rc = &row[c..c + 4];
            for k in 0..4 {
                sr[k] += rc[k] * xc[k];
            }
        }
    }
    std::array::from_fn(|r| {
        let tail: f64 = rows[r][body..len]
            .iter()
            .zip(&x[body..])
            .map(|(a, b)| a * b)
            .sum();
        let sr = s[r];
        (sr[0] + sr[1]) + (sr[2] + sr[3]) + tail
    })
}

/// W x into `out` (the change of u = W r + q when r moves by x).
#[cfg(test)]
pub fn velocity_into_linear(p: &FrictionProblem, x: &[f64], out: &mut [f64]) {
    let n = p.dim();
    for (i, o) in out.iter_mut().enumerate() {
        *o = dot(&p.w[i * n..(i + 1) * n], x);
    }
}
