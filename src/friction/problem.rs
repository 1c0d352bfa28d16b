//! One island's frictional contact problem: W, q and μ.

use crate::lcp::all_finite;
use crate::Error;

/// The frictional contact problem of one island of k contacts: find r with
/// u = W r + q and, per contact, the Coulomb conditions of the module docs.
/// Entries are interleaved per contact (3i normal, 3i + 1 and 3i + 2 the
/// tangents), as in Siconos' FrictionContact3D files.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FrictionProblem {
    /// W, 3k × 3k, row-major: `w[i * 3k + j]`. Used as given (Siconos' W
    /// need not be exactly symmetric).
    pub w: Vec<f64>,
    /// The free velocity, 3k.
    pub q: Vec<f64>,
    /// The friction coefficient of each contact, k, each finite and ≥ 0.
    pub mu: Vec<f64>,
}

impl FrictionProblem {
    /// Builds a problem, checking shapes and values (see [`Self::validate`]).
    ///
    /// # Errors
    /// Those of [`Self::validate`], naming the item "problem".
    pub fn new(w: Vec<f64>, q: Vec<f64>, mu: Vec<f64>) -> Result<Self, Error> {
        let p = FrictionProblem { w, q, mu };
        p.validate("problem")?;
        Ok(p)
    }

    /// The number of contacts k.
    #[inline]
    pub fn contacts(&self) -> usize {
        self.mu.len()
    }

    /// The dimension 3k.
    #[inline]
    pub fn dim(&self) -> usize {
        self.q.len()
    }

    /// W_ij.
    #[inline]
    pub fn at(&self, i: usize, j: usize) -> f64 {
        self.w[i * self.dim() + j]
    }

    /// u = W r + q.
    pub fn velocity(&self, r: &[f64]) -> Vec<f64> {
        let n = self.dim();
        (0..n)
            .map(|i| {
                let row = &self.w[i * n..(i + 1) * n];
                self.q[i] + row.iter().zip(r).map(|(a, b)| a * b).sum::<f64>()
            })
            .collect()
    }

    /// Checks that q has 3k entries for the k coefficients, W is 3k × 3k,
    /// every entry is finite and every μ ≥ 0. `item` names the problem
    /// (rendered only when a check fails: pass `format_args!("problem {i}")`).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `item` and the first field at fault (`mu`,
    /// `q`, `W`, or the entry at fault, e.g. `mu[2]` or `W[0][1]`).
    pub fn validate(&self, item: impl std::fmt::Display) -> Result<(), Error> {
        let k = self.mu.len();
        if k == 0 {
            return Err(Error::invalid(item, "mu", "no contacts (k = 0)"));
        }
        if self.q.len() != 3 * k {
            return Err(Error::invalid(
                item,
                "q",
                format!(
                    "has {} entries, expected 3k = {} for {k} contacts",
                    self.q.len(),
                    3 * k
                ),
            ));
        }
        let n = 3 * k;
        if self.w.len() != n * n {
            return Err(Error::invalid(
                item,
                "W",
                format!("has {} entries, expected (3k)² = {}", self.w.len(), n * n),
            ));
        }
        // The common answer (every entry finite, every μ ≥ 0) without
        // stopping early: this runs on every island of every batch.
        if all_finite(&self.w)
            && all_finite(&self.q)
            && all_finite(&self.mu)
            && self.mu.iter().fold(true, |ok, m| ok & (*m >= 0.0))
        {
            return Ok(());
        }
        if let Some(i) = self.mu.iter().position(|m| !m.is_finite() || *m < 0.0) {
            return Err(Error::invalid(
                item,
                format!("mu[{i}]"),
                format!("{} is not a finite number ≥ 0", self.mu[i]),
            ));
        }
        if let Some(i) = self.q.iter().position(|v| !v.is_finite()) {
            return Err(Error::invalid(
                item,
                format!("q[{i}]"),
                "not a finite number",
            ));
        }
        if let Some(e) = self.w.iter().position(|v| !v.is_finite()) {
            return Err(Error::invalid(
                item,
                format!("W[{}][{}]", e / n, e % n),
                "not a finite number",
            ));
        }
        Ok(())
    }
}
