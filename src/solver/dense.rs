//! A dense batch solved where it lies ([`Solver::solve_dense`]): M
//! (B × n × n) and q (B × n) row-major in two slices, as NumPy, JAX and
//! PyTorch hold a batch, without one [`Lcp`] built per problem.
//!
//! The CPU path reads the batch through [`Problems`], the view its LCP
//! phase takes of either kind of batch: each problem is checked on the
//! slices and copied, just before its solve, into a problem kept per
//! thread (n² + n numbers, in the cache the solve then reads), since the
//! per-island solvers take an [`Lcp`]. The GPU path builds the problems
//! (its upload reads them), so a dense batch there costs what
//! [`Solver::solve_lcps`] costs.

use std::borrow::Cow;
use std::cell::RefCell;

use super::Solver;
use crate::lcp::validate_parts;
use crate::{Error, Lcp, Report};

/// An LCP batch as the solver's LCP phase reads it: problems built, or a
/// dense batch of one size in two row-major slices.
#[derive(Clone, Copy)]
pub(super) enum Problems<'a> {
    /// One [`Lcp`] per problem.
    Built(&'a [Lcp]),
    /// B problems of size `n` > 0: `m` holds B·n² entries, `q` B·n.
    Dense {
        /// The problems' size.
        n: usize,
        /// M of every problem, one after the other, row-major.
        m: &'a [f64],
        /// q of every problem, one after the other.
        q: &'a [f64],
    },
}

thread_local! {
    /// The problem a thread copies each dense problem into for its solve
    /// (see [`Problems::with`]), kept for the thread's life.
    static SCRATCH: RefCell<Lcp> = const { RefCell::new(Lcp { m: Vec::new(), q: Vec::new() }) };
}

impl Problems<'_> {
    /// How many problems.
    pub(super) fn len(&self) -> usize {
        match self {
            Problems::Built(l) => l.len(),
            Problems::Dense { n, q, .. } => q.len() / n,
        }
    }

    /// Every problem's size, in order.
    pub(super) fn sizes(&self) -> impl ExactSizeIterator<Item = usize> + '_ {
        (0..self.len()).map(|i| self.n(i))
    }

    /// Problem i's size.
    pub(super) fn n(&self, i: usize) -> usize {
        match self {
            Problems::Built(l) => l[i].n(),
            Problems::Dense { n, .. } => *n,
        }
    }

    /// Problem i's M (row-major) and q.
    fn parts(&self, i: usize) -> (&[f64], &[f64]) {
        match self {
            Problems::Built(l) => (&l[i].m, &l[i].q),
            Problems::Dense { n, m, q } => (&m[i * n * n..(i + 1) * n * n], &q[i * n..(i + 1) * n]),
        }
    }

    /// [`Lcp::validate`] of problem i, named `item` in the error.
    pub(super) fn validate(&self, i: usize, item: impl std::fmt::Display) -> Result<(), Error> {
        let (m, q) = self.parts(i);
        validate_parts(m, q, item)
    }

    /// `f` of problem i: the caller's [`Lcp`], or for a dense batch this
    /// thread's kept problem holding a copy of it (allocated once per
    /// thread and size; `f` must not call `with` again).
    pub(super) fn with<R>(&self, i: usize, f: impl FnOnce(&Lcp) -> R) -> R {
        match self {
            Problems::Built(l) => f(&l[i]),
            Problems::Dense { .. } => {
                let (m, q) = self.parts(i);
                SCRATCH.with_borrow_mut(|lcp| {
                    lcp.m.clear();
                    lcp.m.extend_from_slice(m);
                    lcp.q.clear();
                    lcp.q.extend_from_slice(q);
                    f(lcp)
                })
            }
        }
    }

    /// The problems as [`Lcp`]s (built here for a dense batch: the GPU
    /// path's upload reads them).
    pub(super) fn built(&self) -> Cow<'_, [Lcp]> {
        match self {
            Problems::Built(l) => Cow::Borrowed(l),
            Problems::Dense { .. } => (0..self.len())
                .map(|i| {
                    let (m, q) = self.parts(i);
                    Lcp {
                        m: m.to_vec(),
                        q: q.to_vec(),
                    }
                })
                .collect(),
        }
    }
}

impl Solver {
    /// Solves a dense batch of LCPs of one size `n`, read where it lies:
    /// `m` holds B row-major n×n matrices one after the other (B·n²
    /// entries), `q` the B vectors (B·n), as a C-ordered array of shape
    /// (B, n, n) and one of (B, n) hold them. The same checks, statuses,
    /// answers and report as [`Solver::solve_lcps`] on the same problems
    /// built as [`Lcp`]s, without building them (on the CPU path; the GPU
    /// path builds them for its upload).
    ///
    /// # Errors
    /// [`Error::Invalid`] (item `batch`) where n = 0 or the slices do not
    /// hold B whole problems; then those of [`Solver::solve_lcps`], naming
    /// the problem by its index in the batch (`problem 3: field
    /// ``M[0][1]``: not a finite number`).
    pub fn solve_dense(&mut self, n: usize, m: &[f64], q: &[f64]) -> Result<Report, Error> {
        let problems = dense(n, m, q)?;
        self.solve_lcps_warm(problems, None)
    }

    /// [`Solver::solve_dense`] with the caller's contact ids, `n` per
    /// problem one after the other (B·n, as an array of q's shape holds
    /// them): with `settings.warm_start` each problem starts from the
    /// basis its contacts had in the last call, as with
    /// [`Solver::solve_lcps_keyed`].
    ///
    /// # Errors
    /// Those of [`Solver::solve_dense`], and [`Error::Invalid`] (item
    /// `ids`) where `ids` has not B·n entries.
    pub fn solve_dense_keyed(
        &mut self,
        n: usize,
        m: &[f64],
        q: &[f64],
        ids: &[u64],
    ) -> Result<Report, Error> {
        let problems = dense(n, m, q)?;
        if ids.len() != q.len() {
            return Err(Error::invalid(
                "ids",
                "len",
                format!(
                    "{} ids for {} problems of n = {n} (expected {})",
                    ids.len(),
                    problems.len(),
                    q.len()
                ),
            ));
        }
        let keys: Vec<&[u64]> = ids.chunks_exact(n).collect();
        self.solve_lcps_warm(problems, Some(&keys))
    }
}

/// The dense batch `m`, `q` of size `n`, its shapes checked.
fn dense<'a>(n: usize, m: &'a [f64], q: &'a [f64]) -> Result<Problems<'a>, Error> {
    if n == 0 {
        return Err(Error::invalid(
            "batch",
            "n",
            "n = 0: every problem needs at least one row",
        ));
    }
    if q.len() % n != 0 {
        return Err(Error::invalid(
            "batch",
            "q",
            format!("has {} entries, not a multiple of n = {n}", q.len()),
        ));
    }
    if m.len() != q.len() * n {
        return Err(Error::invalid(
            "batch",
            "M",
            format!(
                "has {} entries, expected B·n² = {} (B = {}, n = {n})",
                m.len(),
                q.len() * n,
                q.len() / n
            ),
        ));
    }
    Ok(Problems::Dense { n, m, q })
}

#[cfg(test)]
mod tests {
    use crate::generate::families::islands_of_size;
    use crate::generate::Rng;
    use crate::settings::{Backend, Method, Settings};
    use crate::{Lcp, Report, Solver};

    /// Seeded problems of size n: physical islands (PSD, often singular),
    /// A Aᵀ + I (PD), a diagonally dominant non-symmetric P-matrix, and a
    /// random matrix (any status).
    fn problems(n: usize, seed: u64) -> Vec<Lcp> {
        let mut rng = Rng::new(seed);
        let mut out = islands_of_size(n, 12, seed);
        for kind in 0..3 {
            for _ in 0..12 {
                let a: Vec<f64> = (0..n * n).map(|_| rng.range(-1.0, 1.0)).collect();
                let m: Vec<f64> = (0..n * n)
                    .map(|k| {
                        let (i, j) = (k / n, k % n);
                        match kind {
                            0 => {
                                (0..n).map(|l| a[i * n + l] * a[j * n + l]).sum::<f64>()
                                    + f64::from(u8::from(i == j))
                            }
                            1 if i == j => n as f64 + rng.unit(),
                            _ => a[k],
                        }
                    })
                    .collect();
                let q = (0..n).map(|_| rng.range(-3.0, 3.0)).collect();
                out.push(Lcp { m, q });
            }
        }
        out
    }

    /// The batch as the two flat slices of a C-ordered (B, n, n) and (B, n).
    fn flat(lcps: &[Lcp]) -> (Vec<f64>, Vec<f64>) {
        let m = lcps.iter().flat_map(|l| l.m.iter().copied()).collect();
        (m, lcps.iter().flat_map(|l| l.q.iter().copied()).collect())
    }

    /// Everything a report says but its seconds, as text: f64s print as
    /// their shortest round trip, so equal text is equal bits.
    fn said(r: &Report) -> String {
        format!(
            "{:?}",
            (
                &r.islands,
                &r.scenes,
                &r.counts,
                r.statuses,
                r.max_error,
                &r.device,
                &r.choice,
                &r.fallback,
            )
        )
    }

    fn settings(method: Method, threads: usize) -> Settings {
        Settings {
            threads,
            ..Settings::new(Backend::Cpu, method)
        }
    }

    #[test]
    fn a_dense_batch_gives_the_built_batchs_report_bit_for_bit() {
        for method in [
            Method::Auto,
            Method::Lemke,
            Method::Enumeration,
            Method::Pgs,
        ] {
            for threads in [1, 2] {
                let mut a = Solver::new(settings(method, threads)).unwrap();
                let mut b = Solver::new(settings(method, threads)).unwrap();
                for n in 1..=12 {
                    let lcps = problems(n, 7 + n as u64);
                    let (m, q) = flat(&lcps);
                    let built = a.solve_lcps(&lcps).unwrap();
                    let dense = b.solve_dense(n, &m, &q).unwrap();
                    assert_eq!(said(&dense), said(&built), "{method:?}, n = {n}");
                    assert_eq!(dense.islands.len(), lcps.len());
                }
            }
        }
        // With every solution enumerated (and no statuses lost).
        let all = Settings {
            all_solutions: true,
            ..settings(Method::Enumeration, 2)
        };
        let lcps = problems(5, 3);
        let (m, q) = flat(&lcps);
        let built = Solver::new(all.clone()).unwrap().solve_lcps(&lcps);
        let dense = Solver::new(all).unwrap().solve_dense(5, &m, &q);
        assert_eq!(said(&dense.unwrap()), said(&built.unwrap()));
    }

    #[test]
    fn a_keyed_dense_batch_warm_starts_as_a_keyed_built_one() {
        let warm = Settings {
            warm_start: true,
            ..settings(Method::Auto, 2)
        };
        let (mut a, mut b) = (
            Solver::new(warm.clone()).unwrap(),
            Solver::new(warm).unwrap(),
        );
        let n = 6;
        let lcps = problems(n, 11);
        let (m, q) = flat(&lcps);
        let ids: Vec<u64> = (0..q.len() as u64).map(|k| 3 * k + 1).collect();
        let rows: Vec<Vec<u64>> = ids.chunks(n).map(<[u64]>::to_vec).collect();
        for call in 0..2 {
            let built = a.solve_lcps_keyed(&lcps, &rows).unwrap();
            let dense = b.solve_dense_keyed(n, &m, &q, &ids).unwrap();
            assert_eq!(said(&dense), said(&built), "call {call}");
            assert_eq!(dense.counts.warm_start > 0, call == 1, "{:?}", dense.counts);
        }
        let e = b.solve_dense_keyed(n, &m, &q, &ids[1..]).unwrap_err();
        assert!(e.to_string().starts_with("ids: field `len`: "), "{e}");
    }

    #[test]
    fn a_dense_batch_on_the_gpu_gives_the_built_batchs_report() {
        let Some(gpu) = crate::tests::common::gpu_settings_or_skip() else {
            return;
        };
        let s = Settings {
            gpu,
            ..Settings::new(Backend::Gpu, Method::Enumeration)
        };
        let (mut a, mut b) = (Solver::new(s.clone()).unwrap(), Solver::new(s).unwrap());
        for n in [1, 4, 8] {
            let lcps = problems(n, 5);
            let (m, q) = flat(&lcps);
            let built = a.solve_lcps(&lcps).unwrap();
            let dense = b.solve_dense(n, &m, &q).unwrap();
            assert!(dense.on_gpu(), "{}", dense.device.name);
            assert_eq!(said(&dense), said(&built), "n = {n}");
        }
    }

    #[test]
    fn bad_dense_input_is_named_as_the_built_batchs() {
        let mut s = Solver::new(settings(Method::Auto, 2)).unwrap();
        let n = 3;
        let lcps = problems(n, 1);
        let (m, q) = flat(&lcps);
        for (at_m, k, v) in [
            (true, 5 * 9 + 7, f64::NAN),
            (false, 40 * 3 + 2, f64::INFINITY),
        ] {
            let (mut m, mut q, mut bad) = (m.clone(), q.clone(), lcps.clone());
            if at_m {
                m[k] = v;
                bad[k / 9].m[k % 9] = v;
            } else {
                q[k] = v;
                bad[k / 3].q[k % 3] = v;
            }
            let want = s.solve_lcps(&bad).unwrap_err().to_string();
            assert_eq!(s.solve_dense(n, &m, &q).unwrap_err().to_string(), want);
        }
        let shape = |n, m: &[f64], q: &[f64]| {
            let mut s = Solver::new(settings(Method::Auto, 1)).unwrap();
            s.solve_dense(n, m, q).unwrap_err().to_string()
        };
        assert_eq!(
            shape(0, &[], &[]),
            "batch: field `n`: n = 0: every problem needs at least one row"
        );
        assert_eq!(
            shape(2, &m[..8], &q[..3]),
            "batch: field `q`: has 3 entries, not a multiple of n = 2"
        );
        assert_eq!(
            shape(3, &m[..17], &q[..6]),
            "batch: field `M`: has 17 entries, expected B·n² = 18 (B = 2, n = 3)"
        );
        // An empty batch is an empty report, as an empty list of problems.
        let empty = s.solve_dense(3, &[], &[]).unwrap();
        assert_eq!(said(&empty), said(&s.solve_lcps(&[]).unwrap()));
        // Enumeration refuses n > 20 on the CPU backend, naming the problem.
        let mut e = Solver::new(settings(Method::Enumeration, 2)).unwrap();
        let big = Lcp::new(vec![0.0; 21 * 21], vec![1.0; 21]).unwrap();
        let want = e.solve_lcps(&[big.clone(), big.clone()]).unwrap_err();
        let (m, q) = flat(&[big.clone(), big]);
        let got = e.solve_dense(21, &m, &q).unwrap_err();
        assert_eq!(got.to_string(), want.to_string());
    }
}
