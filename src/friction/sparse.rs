//! The block sparsity of an island's W: contacts couple only through the
//! bodies they share, so that W = J M⁻¹ Jᵀ has a nonzero 3 × 3 block (i, j)
//! only where contacts i and j share a dynamic body. A pile of 570
//! contacts has a few dozen neighbours per contact, not 570.
//!
//! What uses it: the products W x of the exact solvers (O(nonzeros), the
//! same bits as the dense [`super::workspace::dot`]: see
//! [`row_dot`]); the NSGS sweep's update of u; and on islands of at least
//! [`SPARSE_FROM`] contacts, a reordering of the contacts (reverse
//! Cuthill–McKee on the contact graph, [`bandwidth_order`]) that gathers
//! W's nonzeros near the diagonal, so that the Newton step's factorisations
//! (the Cholesky [`cholesky_in`], the LU [`lu_envelope`]) work within an
//! envelope instead of on a dense 3k × 3k matrix, and every matrix a step
//! builds (∂Φ's copy, W_RR, W_SS, ∂Φᵀ∂Φ) is written within it only: a
//! Newton step on 570 contacts touches no O((3k)²) array.

use super::problem::FrictionProblem;
use super::workspace::{dot, dots};

/// Islands of at least this many contacts are solved in the contact order
/// of [`bandwidth_order`], their Newton steps factored within W's envelope
/// ([`lu_envelope`]). Below it the dense factorisations are cheap (3k ≤ 93:
/// under 0.3 M multiply-adds) and the answers stay those of the natural
/// order, bit for bit.
pub const SPARSE_FROM: usize = 32;

/// The nonzero 3 × 3 blocks of W, by block row (compressed rows): block
/// (i, j) is listed where W's block (i, j) or (j, i) has a nonzero entry
/// (a symmetric pattern), and (i, i) always; columns ascending. Below
/// [`SPARSE_FROM`] contacts every block is listed (the dense loops, as
/// before, at no cost of finding the zeros).
#[derive(Debug, Default)]
pub struct Pattern {
    /// Row i's blocks are `cols[start[i]..start[i + 1]]`.
    pub start: Vec<usize>,
    /// The block columns.
    pub cols: Vec<usize>,
    /// Scratch: the k × k nonzero flags.
    flags: Vec<bool>,
}

impl Pattern {
    /// The pattern of `p`'s W, in place (O((3k)²), once per island).
    pub fn build(&mut self, p: &FrictionProblem) {
        let (k, n) = (p.contacts(), p.dim());
        self.flags.clear();
        self.flags.resize(k * k, k < SPARSE_FROM);
        for row in (0..n).filter(|_| k >= SPARSE_FROM) {
            let i = row / 3;
            let w = &p.w[row * n..(row + 1) * n];
            for j in 0..k {
                if !self.flags[i * k + j] && w[3 * j..3 * j + 3].iter().any(|&v| v != 0.0) {
                    self.flags[i * k + j] = true;
                    self.flags[j * k + i] = true;
                }
            }
        }
        self.start.clear();
        self.cols.clear();
        self.start.push(0);
        for i in 0..k {
            self.flags[i * k + i] = true;
            let row = &self.flags[i * k..(i + 1) * k];
            self.cols
                .extend(row.iter().enumerate().filter(|(_, &f)| f).map(|(j, _)| j));
            self.start.push(self.cols.len());
        }
    }

    /// `other`'s pattern into this one, reusing its buffers (the pattern
    /// of a problem whose W has `other`'s nonzero blocks: PROX's W + αI).
    pub fn copy_from(&mut self, other: &Pattern) {
        self.start.clone_from(&other.start);
        self.cols.clone_from(&other.cols);
    }

    /// Contact i's neighbours (itself included), ascending.
    #[inline]
    pub fn row(&self, i: usize) -> &[usize] {
        &self.cols[self.start[i]..self.start[i + 1]]
    }

    /// This pattern with its contacts in `order` (as [`permuted`] reorders
    /// the problem), in place: what [`Pattern::build`] gives for the
    /// reordered problem, without reading its W again.
    pub fn permute(&mut self, order: &[usize]) {
        let mut position = vec![0; order.len()];
        for (a, &i) in order.iter().enumerate() {
            position[i] = a;
        }
        let (start, cols) = (
            std::mem::take(&mut self.start),
            std::mem::take(&mut self.cols),
        );
        self.start.push(0);
        for &i in order {
            let from = self.cols.len();
            self.cols
                .extend(cols[start[i]..start[i + 1]].iter().map(|&j| position[j]));
            self.cols[from..].sort_unstable();
            self.start.push(self.cols.len());
        }
    }
}

/// W's row `row` (of p) times x over the row's nonzero blocks: the same
/// bits as [`super::workspace::dot`] over the whole row, whose four running
/// sums (entry c in sum c mod 4) and tail (the last n mod 4 entries, in
/// order) it keeps; the products it skips are W's zeros, ±0, which leave
/// a running sum that starts at +0 as it is.
#[inline]
pub fn row_dot(p: &FrictionProblem, pattern: &Pattern, row: usize, x: &[f64]) -> f64 {
    let n = p.dim();
    blocks_dot(&p.w[row * n..(row + 1) * n], pattern.row(row / 3), x)
}

/// `w` · x (both 3k long) where w is zero outside the contact `blocks`:
/// the bits of [`super::workspace::dot`] (see [`row_dot`]).
#[inline]
pub fn blocks_dot(w: &[f64], blocks: &[usize], x: &[f64]) -> f64 {
    let n = w.len();
    if 3 * blocks.len() == n {
        // Every block (islands below `SPARSE_FROM`): the whole row, by the
        // vectorised `dot` (the same sums in the same order).
        return dot(w, x);
    }
    let body = n - n % 4;
    let mut s = [0.0f64; 4];
    // Along the runs of consecutive blocks (contiguous columns): entry c
    // still goes to sum c mod 4, in ascending c, four lanes at a time
    // where a run covers an aligned quadruple.
    for (from, to) in block_runs(blocks) {
        let (lo, hi) = (3 * from, (3 * to).min(body));
        if lo >= hi {
            break;
        }
        let aligned = (lo.next_multiple_of(4)).min(hi);
        let quads = aligned + (hi - aligned) / 4 * 4;
        for c in lo..aligned {
            s[c % 4] += w[c] * x[c];
        }
        for (wc, xc) in w[aligned..quads]
            .chunks_exact(4)
            .zip(x[aligned..quads].chunks_exact(4))
        {
            for k in 0..4 {
                s[k] += wc[k] * xc[k];
            }
        }
        for c in quads..hi {
            s[c % 4] += w[c] * x[c];
        }
    }
    let tail: f64 = w[body..].iter().zip(&x[body..]).map(|(a, b)| a * b).sum();
    (s[0] + s[1]) + (s[2] + s[3]) + tail
}

/// The runs of consecutive blocks in the ascending `blocks`: (first,
/// last + 1) of each.
pub(crate) fn block_runs(blocks: &[usize]) -> impl Iterator<Item = (usize, usize)> + '_ {
    let mut at = 0;
    std::iter::from_fn(move || {
        let from = *blocks.get(at)?;
        let mut to = from + 1;
        at += 1;
        while blocks.get(at) == Some(&to) {
            to += 1;
            at += 1;
        }
        Some((from, to))
    })
}

/// u = W r + q over W's nonzero blocks (the bits of
/// [`super::workspace::velocity_into`]).
pub fn velocity_sparse(p: &FrictionProblem, pattern: &Pattern, r: &[f64], u: &mut [f64]) {
    for (row, ui) in u.iter_mut().enumerate() {
        *ui = p.q[row] + row_dot(p, pattern, row, r);
    }
}

/// W x over W's nonzero blocks (the bits of
/// [`super::workspace::velocity_into_linear`]).
pub fn product_sparse(p: &FrictionProblem, pattern: &Pattern, x: &[f64], out: &mut [f64]) {
    for (row, o) in out.iter_mut().enumerate() {
        *o = row_dot(p, pattern, row, x);
    }
}

/// A contact order that keeps W's nonzero blocks near the diagonal:
/// reverse Cuthill–McKee (each connected part from a contact of least
/// degree, neighbours by increasing degree, the whole order reversed).
/// `order[a]` is the contact at position a.
pub fn bandwidth_order(pattern: &Pattern) -> Vec<usize> {
    let k = pattern.start.len() - 1;
    let degree = |i: usize| pattern.row(i).len();
    let mut seen = vec![false; k];
    let mut order = Vec::with_capacity(k);
    let mut by_degree: Vec<usize> = (0..k).collect();
    by_degree.sort_by_key(|&i| (degree(i), i));
    let mut next = Vec::new();
    for &root in &by_degree {
        if seen[root] {
            continue;
        }
        seen[root] = true;
        let mut head = order.len();
        order.push(root);
        while head < order.len() {
            let i = order[head];
            head += 1;
            next.clear();
            next.extend(pattern.row(i).iter().copied().filter(|&j| !seen[j]));
            next.sort_by_key(|&j| (degree(j), j));
            for &j in &next {
                seen[j] = true;
                order.push(j);
            }
        }
    }
    order.reverse();
    order
}

/// The problem with its contacts in `order` (`order[a]`: the original
/// contact at position a): W' = P W Pᵀ, q' = P q, μ' = P μ. `pattern` is
/// the reordered problem's ([`Pattern::permute`]d already); W's blocks
/// outside it (zeros) are left at zero.
pub fn permuted(p: &FrictionProblem, order: &[usize], pattern: &Pattern) -> FrictionProblem {
    let n = p.dim();
    let mut w = vec![0.0; n * n];
    for (a, &i) in order.iter().enumerate() {
        for d in 0..3 {
            let (from, to) = ((3 * i + d) * n, (3 * a + d) * n);
            for &b in pattern.row(a) {
                let j = order[b];
                w[to + 3 * b..to + 3 * b + 3].copy_from_slice(&p.w[from + 3 * j..from + 3 * j + 3]);
            }
        }
    }
    FrictionProblem {
        w,
        q: gather(&p.q, order),
        mu: order.iter().map(|&i| p.mu[i]).collect(),
    }
}

/// x's contact blocks in `order` (x' = P x).
pub fn gather(x: &[f64], order: &[usize]) -> Vec<f64> {
    order
        .iter()
        .flat_map(|&i| [x[3 * i], x[3 * i + 1], x[3 * i + 2]])
        .collect()
}

/// x' = P x back in the original order (x = Pᵀ x').
pub fn scatter(x: &[f64], order: &[usize]) -> Vec<f64> {
    let mut out = vec![0.0; x.len()];
    for (a, &i) in order.iter().enumerate() {
        out[3 * i..3 * i + 3].copy_from_slice(&x[3 * a..3 * a + 3]);
    }
    out
}

/// The envelope of a symmetric block pattern, per scalar row i of 3k:
/// `first[i]`, the first column of row i's block neighbours (the first
/// nonzero of row i left of the diagonal, and of column i above it), and
/// `last[i]`, the last row (or column) whose `first` is at most i.
pub fn envelope(pattern: &Pattern, first: &mut Vec<usize>, last: &mut Vec<usize>) {
    let k = pattern.start.len() - 1;
    first.clear();
    first.extend((0..3 * k).map(|i| 3 * pattern.row(i / 3)[0].min(i / 3)));
    last.clear();
    last.extend(0..3 * k);
    for (i, &f) in first.iter().enumerate() {
        for l in &mut last[f..i] {
            *l = (*l).max(i);
        }
    }
}

/// Solves A x = b (A n × n row-major, overwritten by its LU factors; x
/// holds b on entry) by Gaussian elimination without row exchanges, within
/// the envelope `first`/`last` of [`envelope`] (every nonzero of A in it;
/// the factors have no fill outside it): multiply-adds about n times the
/// envelope's width squared. False when a pivot is at most 1e-13 times the
/// largest entry of its row of U, or not finite (the caller solves otherwise: there
/// are no row exchanges to avoid a small pivot).
pub fn lu_envelope(
    a: &mut [f64],
    x: &mut [f64],
    n: usize,
    first: &[usize],
    last: &[usize],
) -> bool {
    for k in 0..n {
        let end = last[k];
        let (upper, lower) = a.split_at_mut((k + 1) * n);
        let row_k = &upper[k * n..];
        let scale = row_k[k..=end].iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let pivot = row_k[k];
        if !(pivot.abs() > 1e-13 * scale) || !pivot.is_finite() {
            return false;
        }
        let row_k = &row_k[k + 1..=end];
        for i in k + 1..=end {
            if first[i] > k {
                continue;
            }
            let row_i = &mut lower[(i - k - 1) * n..(i - k) * n];
            let l = row_i[k] / pivot;
            row_i[k] = l;
            if l != 0.0 {
                for (t, &v) in row_i[k + 1..=end].iter_mut().zip(row_k) {
                    *t -= l * v;
                }
            }
        }
    }
    for i in 0..n {
        let row = &a[i * n..(i + 1) * n];
        let s: f64 = (first[i]..i).map(|c| row[c] * x[c]).sum();
        x[i] -= s;
    }
    for i in (0..n).rev() {
        let row = &a[i * n..(i + 1) * n];
        let s: f64 = (i + 1..=last[i]).map(|c| row[c] * x[c]).sum();
        x[i] = (x[i] - s) / row[i];
    }
    x.iter().all(|v| v.is_finite())
}

/// The envelope of the lower triangle of the n × n row-major `a`, into
/// `env` (2n): `env[i]`, row i's first nonzero left of the diagonal (i
/// where there is none), looked for from `start(i)` on (`a`'s row i is
/// zero before it, and need not be written there); `env[n + i]`, the last
/// row k ≥ i whose first nonzero is at most column i. L has no entry
/// outside it (no fill there), so that [`cholesky_in`] skips those zeros:
/// O(rows × envelope width) instead of O(n²) to find it where `start` is
/// the envelope of a block pattern (0 for a dense search).
pub(crate) fn lower_envelope(
    a: &[f64],
    n: usize,
    start: impl Fn(usize) -> usize,
    env: &mut Vec<usize>,
) {
    env.clear();
    env.extend((0..n).map(|i| (start(i)..i).find(|&j| a[i * n + j] != 0.0).unwrap_or(i)));
    env.extend(0..n);
    for k in 0..n {
        let first = env[k];
        for c in first..k {
            env[n + c] = k;
        }
    }
}

/// Solves A x = b for a symmetric positive definite A (n × n, row-major,
/// overwritten by its Cholesky factor L in the lower triangle) by
/// A = L Lᵀ within its envelope `env` ([`lower_envelope`]): A's lower
/// triangle is read there only (rows i, columns `env[i]..=i`), about n
/// times the envelope's width squared / 2 multiply-adds (n³/6 dense, half
/// of LU's). `x` holds b on entry.
/// None when a pivot is not positive (A not positive definite to
/// rounding); else the number of pivots dropped (below).
///
/// With `drop` = Some(ρ), A may be positive *semi*definite: a pivot at most
/// ρ times its diagonal entry (a column dependent on the ones before, to
/// rounding) is dropped, its unknown set to 0 and its column of L zeroed,
/// which gives a solution of A x = b when b is in A's range.
pub(crate) fn cholesky_in(
    a: &mut [f64],
    x: &mut [f64],
    n: usize,
    drop: Option<f64>,
    env: &[usize],
) -> Option<usize> {
    let (first, last) = env.split_at(n);
    let mut dropped = 0;
    for j in 0..n {
        let fj = first[j];
        let row_j = &a[j * n + fj..j * n + j];
        let diagonal = a[j * n + j];
        let d = diagonal - dot(row_j, row_j);
        let drops = match drop {
            Some(rho) => !(d > rho * diagonal),
            None if !(d > 0.0) => return None,
            None => false,
        };
        if drops {
            dropped += 1;
            a[j * n + j] = 0.0;
            for i in j + 1..=last[j] {
                a[i * n + j] = 0.0;
            }
            continue;
        }
        let d = d.sqrt();
        a[j * n + j] = d;
        let inv = 1.0 / d;
        // Rows below with the same envelope start (a contact's three, as
        // a rule) up to four at a time: one pass over L's row j for all
        // (`dots`: each row's sum the bits of `dot`).
        let mut i = j + 1;
        while i <= last[j] {
            let f = first[i];
            if f > j {
                i += 1;
                continue; // L_ij = A_ij = 0
            }
            let mut g = 1;
            while g < 4 && i + g <= last[j] && first[i + g] == f {
                g += 1;
            }
            let s = f.max(fj);
            let (upper, lower) = a.split_at_mut(i * n);
            let lj = &upper[j * n + s..j * n + j];
            let row = |r: usize| &lower[r * n + s..r * n + j];
            let sums: [f64; 4] = match g {
                1 => [dot(row(0), lj), 0.0, 0.0, 0.0],
                2 => {
                    let [a, b] = dots([row(0), row(1)], lj);
                    [a, b, 0.0, 0.0]
                }
                3 => {
                    let [a, b, c] = dots([row(0), row(1), row(2)], lj);
                    [a, b, c, 0.0]
                }
                _ => dots([row(0), row(1), row(2), row(3)], lj),
            };
            for (r, sum) in sums.iter().enumerate().take(g) {
                let at = r * n + j;
                lower[at] = (lower[at] - sum) * inv;
            }
            i += g;
        }
    }
    // L y = b, then Lᵀ x = y (a dropped unknown is 0).
    for i in 0..n {
        let fi = first[i];
        let d = dot(&a[i * n + fi..i * n + i], &x[fi..i]);
        let p = a[i * n + i];
        x[i] = if p == 0.0 { 0.0 } else { (x[i] - d) / p };
    }
    for i in (0..n).rev() {
        let p = a[i * n + i];
        if p == 0.0 {
            x[i] = 0.0;
            continue;
        }
        let mut v = x[i];
        for k in i + 1..=last[i] {
            if first[k] <= i {
                v -= a[k * n + i] * x[k];
            }
        }
        x[i] = v / p;
    }
    Some(dropped)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::friction::workspace::{velocity_into, velocity_into_linear};

    /// A random island: bodies in a chain, each contact between two
    /// neighbouring bodies, W = J M⁻¹ Jᵀ with random directions.
    pub(crate) fn chain_problem(seed: u64, k: usize) -> FrictionProblem {
        let mut rng = crate::generate::Rng::new(seed);
        let bodies = k + 1;
        // Each contact: two bodies, a random 3 × 6 Jacobian block per body.
        let contacts: Vec<(usize, [[f64; 6]; 3], [[f64; 6]; 3])> = (0..k)
            .map(|_| {
                let a = rng.int(0, bodies - 2);
                let mut jac =
                    || std::array::from_fn(|_| std::array::from_fn(|_| rng.range(-1.0, 1.0)));
                (a, jac(), jac())
            })
            .collect();
        let n = 3 * k;
        let mut w = vec![0.0; n * n];
        for (i, (a, ja, jb)) in contacts.iter().enumerate() {
            for (j, (b, ka, kb)) in contacts.iter().enumerate() {
                for (x, y) in [(a, b), (&(a + 1), &(b + 1)), (a, &(b + 1)), (&(a + 1), b)] {
                    if x != y {
                        continue;
                    }
                    let left = if x == a { ja } else { jb };
                    let right = if y == b { ka } else { kb };
                    for d in 0..3 {
                        for e in 0..3 {
                            w[(3 * i + d) * n + 3 * j + e] +=
                                (0..6).map(|m| left[d][m] * right[e][m]).sum::<f64>();
                        }
                    }
                }
            }
        }
        let q = (0..n).map(|_| rng.range(-1.0, 1.0)).collect();
        let mu = (0..k).map(|_| rng.range(0.1, 1.0)).collect();
        FrictionProblem::new(w, q, mu).unwrap()
    }

    #[test]
    fn sparse_products_give_the_dense_bits() {
        for (seed, k) in [(1, 5), (2, 16), (3, 37), (4, 60)] {
            let p = chain_problem(seed, k);
            let mut pattern = Pattern::default();
            pattern.build(&p);
            assert!(
                k < SPARSE_FROM || pattern.cols.len() < k * k / 2,
                "k = {k}: sparse"
            );
            let r: Vec<f64> = (0..p.dim()).map(|i| (i as f64 * 0.37).sin()).collect();
            let (mut dense, mut sparse) = (vec![0.0; p.dim()], vec![0.0; p.dim()]);
            velocity_into(&p, &r, &mut dense);
            velocity_sparse(&p, &pattern, &r, &mut sparse);
            assert_eq!(dense.map_bits(), sparse.map_bits(), "k = {k}");
            velocity_into_linear(&p, &r, &mut dense);
            product_sparse(&p, &pattern, &r, &mut sparse);
            assert_eq!(dense.map_bits(), sparse.map_bits(), "k = {k}");
        }
    }

    trait Bits {
        fn map_bits(&self) -> Vec<u64>;
    }
    impl Bits for Vec<f64> {
        fn map_bits(&self) -> Vec<u64> {
            self.iter().map(|v| v.to_bits()).collect()
        }
    }

    #[test]
    fn the_envelope_lu_solves_a_reordered_island() {
        let p = chain_problem(7, 40);
        let mut pattern = Pattern::default();
        pattern.build(&p);
        let order = bandwidth_order(&pattern);
        let mut sorted = order.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..40).collect::<Vec<_>>(), "a permutation");
        // The permuted pattern is the reordered problem's, and the
        // reordered W has every entry of W (zeros outside the pattern).
        pattern.permute(&order);
        let pp = permuted(&p, &order, &pattern);
        let mut built = Pattern::default();
        built.build(&pp);
        assert_eq!((&pattern.start, &pattern.cols), (&built.start, &built.cols));
        let n = pp.dim();
        for (a, &i) in order.iter().enumerate() {
            for (b, &j) in order.iter().enumerate() {
                for (d, e) in (0..3).flat_map(|d| (0..3).map(move |e| (d, e))) {
                    let want = p.w[(3 * i + d) * n + 3 * j + e];
                    assert_eq!(pp.w[(3 * a + d) * n + 3 * b + e].to_bits(), want.to_bits());
                }
            }
        }
        let (mut first, mut last) = (Vec::new(), Vec::new());
        envelope(&pattern, &mut first, &mut last);
        // W + I (nonsymmetric by a random lower part within the pattern).
        let mut a = pp.w.clone();
        for i in 0..n {
            a[i * n + i] += 1.0;
            for j in first[i]..i {
                a[i * n + j] *= 1.5;
            }
        }
        let x_true: Vec<f64> = (0..n).map(|i| (i as f64).cos()).collect();
        let mut x: Vec<f64> = (0..n)
            .map(|i| (0..n).map(|j| a[i * n + j] * x_true[j]).sum())
            .collect();
        let mut lu = a.clone();
        assert!(lu_envelope(&mut lu, &mut x, n, &first, &last));
        for (got, want) in x.iter().zip(&x_true) {
            assert!((got - want).abs() < 1e-8, "{got} vs {want}");
        }
        // The order narrows the envelope of this chain.
        let width = |first: &[usize]| (0..n).map(|i| i - first[i]).max().unwrap();
        let mut natural = Pattern::default();
        natural.build(&p);
        let (mut f0, mut l0) = (Vec::new(), Vec::new());
        envelope(&natural, &mut f0, &mut l0);
        assert!(
            width(&first) < width(&f0),
            "{} vs {}",
            width(&first),
            width(&f0)
        );
        // And gather / scatter are inverse.
        assert_eq!(scatter(&gather(&p.q, &order), &order), p.q);
    }
}
