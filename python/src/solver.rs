//! `NativeSolver`: one [`lcpbatch::Solver`] (device, pipelines, warm-start
//! memory) kept between Python calls.
//!
//! Every solve releases the GIL (`py.detach`) around each chunk and checks
//! for signals (Ctrl-C) between chunks; the solver sits in a mutex so that
//! two Python threads sharing one `Solver` take turns instead of racing.

use std::ops::Range;
use std::sync::{Mutex, MutexGuard};
use std::time::Instant;

use lcpbatch::{FrictionProblem, Lcp, Report, Scene, Settings, Solver};
use numpy::{IntoPyArray, PyReadonlyArray1, PyReadonlyArray2, PyReadonlyArray3};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::{batch, friction, guard, report, scenes, settings::Args, to_py_err, worlds};

/// The library's solver behind a mutex (see the module docs).
/// Frozen (every method takes `&self`, state sits behind mutexes): the
/// XLA FFI handlers reach it without the GIL (`ffi/`).
#[pyclass(module = "lcpbatch._native", frozen)]
pub(crate) struct NativeSolver {
    solver: Mutex<Solver>,
    /// Calls now in `run_chunks` with their chunks joined (several Python
    /// threads may share the solver): the join ends when the last ends.
    joins: Mutex<usize>,
}

impl NativeSolver {
    /// The solver; a mutex poisoned by a panic (already reported as a
    /// `RuntimeError`) is taken over as it is.
    fn lock(&self) -> MutexGuard<'_, Solver> {
        self.solver.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Solves `ranges` one after the other with the GIL released, checking
    /// for Ctrl-C between them; one report ([`Self::solve_joined`]).
    fn run_chunks(
        &self,
        py: Python<'_>,
        ranges: Vec<Range<usize>>,
        solve: impl Fn(&mut Solver, Range<usize>) -> Result<Report, lcpbatch::Error> + Sync,
    ) -> PyResult<(Report, usize)> {
        let count = ranges.len();
        let chunks = self.solve_joined(ranges, |r| -> PyResult<Report> {
            let next = py.detach(|| guard(|| solve(&mut self.lock(), r).map_err(to_py_err)))?;
            py.check_signals()?;
            Ok(next)
        });
        match chunks? {
            Some(t) => Ok((t, count)),
            // An empty batch: the library's own (empty) report.
            None => Ok((
                py.detach(|| guard(|| self.lock().solve_lcps(&[]).map_err(to_py_err)))?,
                0,
            )),
        }
    }

    /// Solves `ranges` one after the other (`chunk` solves one) into one
    /// report ([`Report::append`]: the ranges are consecutive from 0, so
    /// scene indices shift by the scenes before); None for no range. The
    /// chunks are one call of the warm-start memory
    /// ([`Solver::join_warm_start_calls`]): `warm_start_calls` counts
    /// calls, and every chunk finds the ids of the calls before.
    fn solve_joined<E>(
        &self,
        ranges: Vec<Range<usize>>,
        mut chunk: impl FnMut(Range<usize>) -> Result<Report, E>,
    ) -> Result<Option<Report>, E> {
        let joined = ranges.len() > 1;
        if joined {
            self.join_chunks(true);
        }
        let chunks = (|| {
            let mut total: Option<Report> = None;
            for r in ranges {
                let next = chunk(r)?;
                match &mut total {
                    Some(t) => t.append(next),
                    None => total = Some(next),
                }
            }
            Ok(total)
        })();
        // Also after an error or Ctrl-C: the chunks solved count as the call.
        if joined {
            self.join_chunks(false);
        }
        chunks
    }

    /// For the XLA FFI handler (`ffi/`), without Python: the C-ordered
    /// batch `ms` (B·n·n), `qs` (B·n) of size n > 0 solved as
    /// [`Self::solve_dense_zw`] solves it (the same chunks, read in place,
    /// on the calling thread; no Ctrl-C check). The report, None for an
    /// empty batch.
    pub(crate) fn solve_dense_report(
        &self,
        n: usize,
        ms: &[f64],
        qs: &[f64],
    ) -> Result<Option<Report>, lcpbatch::Error> {
        let ranges = batch::chunks(std::iter::repeat_n(n, qs.len() / n));
        self.solve_joined(ranges, |r| {
            dense_chunk(&mut self.lock(), n, ms, qs, None, r)
        })
    }

    /// The C-ordered batch `ms` (B·n·n), `qs` (B·n) of size n > 0, contact
    /// ids `ids` (B·n) or None, solved in chunks where it lies
    /// ([`Solver::solve_dense`]), GIL released. The library checks every
    /// entry as it solves; a non-finite one is then named as [`batch::dense`]
    /// names it. With ids, a batch of several chunks is checked whole first:
    /// no chunk's bases are remembered before an error in a later one.
    fn dense_in_place(
        &self,
        py: Python<'_>,
        (n, ms, qs): (usize, &[f64], &[f64]),
        ids: Option<&[u64]>,
    ) -> PyResult<(Report, usize)> {
        let named = || batch::check_finite(ms, qs, n).map_err(PyValueError::new_err);
        let ranges = batch::chunks(std::iter::repeat_n(n, qs.len() / n));
        if ids.is_some() && ranges.len() > 1 {
            named()?;
        }
        let solved = self.run_chunks(py, ranges, |s, r| dense_chunk(s, n, ms, qs, ids, r));
        solved.map_err(|e| named().err().unwrap_or(e))
    }

    /// Starts (`true`) or ends a call whose chunks are one call of the
    /// warm-start memory; nested calls of other threads join the first.
    fn join_chunks(&self, join: bool) {
        let mut joins = self.joins.lock().unwrap_or_else(|p| p.into_inner());
        *joins = if join {
            *joins + 1
        } else {
            joins.saturating_sub(1)
        };
        if *joins == usize::from(join) {
            self.lock().join_warm_start_calls(join);
        }
    }

    /// The report of `lcps` (contact ids `ids` or None), solved in chunks.
    fn lcps_report(
        &self,
        py: Python<'_>,
        lcps: &[Lcp],
        ids: Option<Vec<Vec<u64>>>,
    ) -> PyResult<(Report, usize)> {
        let ranges = batch::chunks(lcps.iter().map(Lcp::n));
        self.run_chunks(py, ranges, |s, r| match &ids {
            Some(ids) => s.solve_lcps_keyed(&lcps[r.clone()], &ids[r]),
            None => s.solve_lcps(&lcps[r]),
        })
    }

    fn frictional<'py>(
        &self,
        py: Python<'py>,
        problems: Vec<FrictionProblem>,
        ids: Option<Vec<Vec<u64>>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let ranges = friction::chunks(problems.iter().map(FrictionProblem::contacts));
        let (r, count) = self.run_chunks(py, ranges, |s, r| match &ids {
            Some(ids) => s.solve_friction_keyed(&problems[r.clone()], &ids[r]),
            None => s.solve_friction(&problems[r]),
        })?;
        let d = PyDict::new(py);
        friction::problems_into(py, &d, &r.friction)?;
        d.set_item("report", report::to_dict(py, &r, count)?)?;
        Ok(d)
    }
}

#[pymethods]
impl NativeSolver {
    /// Builds the solver (opens the device), GIL released. Seventeen keyword
    /// arguments on purpose: one per setting a Python user may change.
    #[new]
    #[pyo3(signature = (backend="auto", method="auto", precision="auto", all_solutions=false,
        warm_start=false, warm_start_calls=1, tolerance=None, threads=0, adapter=None, api="auto",
        predict=true, lemke_max_pivots=None, pgs_max_sweeps=None, pgs_tolerance=None, friction_method="auto",
        friction_tolerance=None, friction_max_iterations=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        backend: &str,
        method: &str,
        precision: &str,
        all_solutions: bool,
        warm_start: bool,
        warm_start_calls: usize,
        tolerance: Option<f64>,
        threads: usize,
        adapter: Option<String>,
        api: &str,
        predict: bool,
        lemke_max_pivots: Option<u64>,
        pgs_max_sweeps: Option<u64>,
        pgs_tolerance: Option<f64>,
        friction_method: &str,
        friction_tolerance: Option<f64>,
        friction_max_iterations: Option<u64>,
    ) -> PyResult<Self> {
        let settings: Settings = Args {
            backend,
            method,
            precision,
            all_solutions,
            warm_start,
            warm_start_calls,
            tolerance,
            threads,
            adapter,
            api,
            predict,
            lemke_max_pivots,
            pgs_max_sweeps,
            pgs_tolerance,
            friction_method,
            friction_tolerance,
            friction_max_iterations,
        }
        .settings()?;
        let solver = py.detach(|| guard(|| Solver::new(settings).map_err(to_py_err)))?;
        Ok(NativeSolver {
            solver: Mutex::new(solver),
            joins: Mutex::new(0),
        })
    }

    /// Where the next batch will be solved, in words.
    fn device(&self) -> String {
        self.lock().device().name
    }

    /// "cpu", "hardware_gpu" or "software_gpu".
    fn device_kind(&self) -> &'static str {
        report::device_kind_name(self.lock().device().kind)
    }

    /// Why this device.
    fn choice(&self) -> String {
        self.lock().choice().to_string()
    }

    /// Why the CPU took over from the GPU (None: no device trouble so far).
    fn fallback(&self) -> Option<String> {
        self.lock().fallback().map(str::to_string)
    }

    /// Forgets the bases remembered for warm start.
    fn clear_warm_start(&self) {
        self.lock().clear_warm_start();
    }

    /// A dense batch: M (B, n, n), q (B, n), ids (B, n) or None.
    #[pyo3(signature = (m, q, ids=None))]
    /// C-ordered arrays are read in place by the library (GIL released);
    /// any other layout is copied once, into one problem each.
    fn solve_dense<'py>(
        &self,
        py: Python<'py>,
        m: PyReadonlyArray3<'py, f64>,
        q: PyReadonlyArray2<'py, f64>,
        ids: Option<PyReadonlyArray2<'py, u64>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let solved = match batch::dense_slices(&m, &q) {
            Some(slices) => {
                let flat = ids.as_ref().map(batch::flat_ids);
                self.dense_in_place(py, slices, flat.as_deref())?
            }
            None => {
                let lcps = batch::dense(&m, &q)?;
                self.lcps_report(py, &lcps, ids.as_ref().map(batch::dense_ids))?
            }
        };
        lcps_dict(py, solved)
    }

    /// For the differentiable adapters (`lcpbatch.jax`, `lcpbatch.torch`):
    /// a dense batch M (B, n, n), q (B, n) solved as [`Self::solve_dense`]
    /// solves it, returning only z and w (B, n), the status codes (B,) and
    /// the report's fallback. A C-ordered batch is read in place by the
    /// library (GIL released); any other is copied once, as `solve_dense`
    /// copies it.
    fn solve_dense_zw<'py>(
        &self,
        py: Python<'py>,
        m: PyReadonlyArray3<'py, f64>,
        q: PyReadonlyArray2<'py, f64>,
    ) -> PyResult<(batch::ZwArrays<'py>, Option<String>)> {
        let (b, n) = q.as_array().dim();
        let (r, _) = match batch::dense_slices(&m, &q) {
            Some(slices) => self.dense_in_place(py, slices, None)?,
            None => self.lcps_report(py, &batch::dense(&m, &q)?, None)?,
        };
        Ok((batch::zw(py, &r.islands, (b, n))?, r.fallback))
    }

    /// A ragged batch: lists of (nᵢ, nᵢ) and (nᵢ,) arrays, ids a list or None.
    #[pyo3(signature = (m, q, ids=None))]
    fn solve_ragged<'py>(
        &self,
        py: Python<'py>,
        m: Vec<PyReadonlyArray2<'py, f64>>,
        q: Vec<PyReadonlyArray1<'py, f64>>,
        ids: Option<Vec<PyReadonlyArray1<'py, u64>>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let lcps = batch::ragged(&m, &q)?;
        let solved = self.lcps_report(py, &lcps, ids.as_deref().map(batch::ragged_ids))?;
        lcps_dict(py, solved)
    }

    /// Scenes, one dict of arrays each (see `scenes.rs` for the layout).
    fn solve_scenes<'py>(
        &self,
        py: Python<'py>,
        scenes: Vec<scenes::SceneArrays<'py>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let scenes: Vec<Scene> = scenes
            .iter()
            .enumerate()
            .map(|(i, s)| s.scene(i))
            .collect::<PyResult<_>>()?;
        let ranges = scenes::chunks(&scenes);
        let (r, count) = self.run_chunks(py, ranges, |s, r| s.solve_scenes(&scenes[r]))?;
        let d = PyDict::new(py);
        scenes::scenes_into(py, &d, &scenes, &r)?;
        d.set_item("report", report::to_dict(py, &r, count)?)?;
        Ok(d)
    }

    /// A dense batch of frictional problems: W (B, 3k, 3k), q (B, 3k),
    /// mu (B, k), ids (B, k) or None.
    #[pyo3(signature = (w, q, mu, ids=None))]
    fn solve_friction_dense<'py>(
        &self,
        py: Python<'py>,
        w: PyReadonlyArray3<'py, f64>,
        q: PyReadonlyArray2<'py, f64>,
        mu: PyReadonlyArray2<'py, f64>,
        ids: Option<PyReadonlyArray2<'py, u64>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let problems = friction::dense(&w, &q, &mu)?;
        self.frictional(py, problems, ids.as_ref().map(batch::dense_ids))
    }

    /// A ragged batch of frictional problems: lists of arrays.
    #[pyo3(signature = (w, q, mu, ids=None))]
    fn solve_friction_ragged<'py>(
        &self,
        py: Python<'py>,
        w: Vec<PyReadonlyArray2<'py, f64>>,
        q: Vec<PyReadonlyArray1<'py, f64>>,
        mu: Vec<PyReadonlyArray1<'py, f64>>,
        ids: Option<Vec<PyReadonlyArray1<'py, u64>>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let problems = friction::ragged(&w, &q, &mu)?;
        self.frictional(py, problems, ids.as_deref().map(batch::ragged_ids))
    }

    /// Advances `worlds` by `steps` steps of `dt` seconds through the
    /// library's `Solver::step_worlds_for` (on the resident GPU path the
    /// states stay on the device within a call and come back at its end),
    /// in calls with the GIL released and a Ctrl-C check between them: 1
    /// step, then twice as many after a call shorter than half a second.
    /// The worlds are updated in place (after an interruption: to the last
    /// call finished, every step reported). Returns the per-step summaries
    /// of [`worlds::summaries_into`], per step `unsolved` and the seconds of
    /// `collision`, `solve`, `integrate`, and the last step's `report`.
    fn step_worlds<'py>(
        &self,
        py: Python<'py>,
        worlds: Vec<Bound<'py, worlds::NativeWorld>>,
        dt: f64,
        steps: usize,
    ) -> PyResult<Bound<'py, PyDict>> {
        let mut ws: Vec<lcpbatch::World> =
            worlds.iter().map(|w| w.borrow().world.clone()).collect();
        let (mut summaries, mut unsolved) = (Vec::with_capacity(steps), Vec::new());
        let mut timings: [Vec<f64>; 3] = Default::default();
        let mut last = None;
        let mut outcome = Ok(());
        let (mut done, mut chunk) = (0, 1);
        while done < steps {
            let n = chunk.min(steps - done);
            let start = Instant::now();
            let call = py.detach(|| {
                guard(|| {
                    let mut solver = self.lock();
                    let keep = |_, rep: lcpbatch::StepReport| {
                        summaries.push(rep.worlds);
                        unsolved.push(rep.unsolved as i64);
                        timings[0].push(rep.timings.collision);
                        timings[1].push(rep.timings.solve);
                        timings[2].push(rep.timings.integrate);
                        last = Some(rep.solve);
                    };
                    solver
                        .step_worlds_for(&mut ws, dt, n, keep)
                        .map_err(to_py_err)
                })
            });
            if let Err(e) = call.and_then(|()| py.check_signals()) {
                outcome = Err(e);
                break;
            }
            done += n;
            if start.elapsed().as_secs_f64() < 0.5 {
                chunk *= 2;
            }
        }
        for (w, state) in worlds.iter().zip(ws) {
            w.borrow_mut().world = state;
        }
        outcome?;
        let d = PyDict::new(py);
        worlds::summaries_into(py, &d, &summaries, worlds.len())?;
        d.set_item("unsolved", unsolved.into_pyarray(py))?;
        let [collision, solve, integrate] = timings;
        d.set_item("collision", collision.into_pyarray(py))?;
        d.set_item("solve", solve.into_pyarray(py))?;
        d.set_item("integrate", integrate.into_pyarray(py))?;
        let report = last.map(|r| report::to_dict(py, &r, 1)).transpose()?;
        d.set_item("report", report)?;
        Ok(d)
    }

    /// For `bench_overhead.py`: the seconds of `repeats` calls of the
    /// library's `Solver::solve_lcps` on the whole batch, timed in Rust
    /// (the problems are built before the clock starts); with `dense`,
    /// of `Solver::solve_dense` on the arrays in place (C-ordered).
    #[pyo3(signature = (m, q, repeats, dense=false))]
    fn time_solve_lcps(
        &self,
        py: Python<'_>,
        m: PyReadonlyArray3<'_, f64>,
        q: PyReadonlyArray2<'_, f64>,
        repeats: usize,
        dense: bool,
    ) -> PyResult<Vec<f64>> {
        let lcps = if dense {
            Vec::new()
        } else {
            batch::dense(&m, &q)?
        };
        let (n, ms, qs) = match (dense, batch::dense_slices(&m, &q)) {
            (true, Some(slices)) => slices,
            (true, None) => return Err(PyValueError::new_err("M, q: C-ordered, n > 0")),
            (false, _) => (0, &[][..], &[][..]),
        };
        py.detach(|| {
            guard(|| {
                let mut solver = self.lock();
                (0..repeats)
                    .map(|_| {
                        let t = Instant::now();
                        match dense {
                            true => solver.solve_dense(n, ms, qs),
                            false => solver.solve_lcps(&lcps),
                        }
                        .map_err(to_py_err)?;
                        Ok(t.elapsed().as_secs_f64())
                    })
                    .collect()
            })
        })
    }
}

/// A report's islands and the report (of `count` chunks) as the dict
/// `LcpResult` reads.
fn lcps_dict<'py>(py: Python<'py>, (r, count): (Report, usize)) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    batch::islands_into(py, &d, &r.islands)?;
    d.set_item("report", report::to_dict(py, &r, count)?)?;
    Ok(d)
}

/// Chunk `r` of the C-ordered batch `ms` (B·n·n), `qs` (B·n) of size n > 0
/// solved where it lies, keyed by `ids` (B·n) where given.
fn dense_chunk(
    s: &mut Solver,
    n: usize,
    ms: &[f64],
    qs: &[f64],
    ids: Option<&[u64]>,
    r: Range<usize>,
) -> Result<Report, lcpbatch::Error> {
    let (m, q) = (
        &ms[r.start * n * n..r.end * n * n],
        &qs[r.start * n..r.end * n],
    );
    match ids {
        Some(ids) => s.solve_dense_keyed(n, m, q, &ids[r.start * n..r.end * n]),
        None => s.solve_dense(n, m, q),
    }
}
