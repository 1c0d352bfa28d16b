//! Every knob of a [`crate::Solver`], its default and its check.
//!
//! One plain struct, [`Settings`], with documented public fields; the GPU's
//! are grouped in [`GpuSettings`]. [`Settings::validate`] (called by
//! [`crate::Solver::new`]) refuses a value out of range with an error that
//! names the field, e.g. `settings: pivot_tol: 2 is not in [0, 1)`.

use crate::cpu::enumeration::EnumerationSettings;
use crate::cpu::enumeration_tree::TREE_MAX_N;
use crate::cpu::lemke::LemkeSettings;
use crate::cpu::pgs::PgsSettings;
use crate::friction::{FrictionMethod, FrictionSettings};
use crate::gpu::{GpuOptions, GpuSolveSettings};
use crate::linalg::PIVOT_TOL;
use crate::Error;
use std::str::FromStr;

/// Where islands are solved.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Backend {
    /// The GPU when a hardware adapter exists (or one is named in
    /// [`GpuSettings::adapter`]), else the CPU. A software adapter
    /// (lavapipe, llvmpipe) is slower than the CPU path on every batch
    /// measured (BENCHMARKS.md), so `Auto` never picks one by itself; the
    /// report says why it chose what it chose.
    #[default]
    Auto,
    /// The CPU path in f64 over every core.
    Cpu,
    /// The GPU, software adapters included, every answer validated on the
    /// CPU in f64. On device trouble (no adapter, no f64 where f64 was asked,
    /// a device lost) the CPU solves the batch, with a warning and the reason
    /// in [`crate::Report::fallback`].
    Gpu,
}

impl Backend {
    /// `auto`, `cpu` or `gpu`.
    pub fn name(self) -> &'static str {
        match self {
            Backend::Auto => "auto",
            Backend::Cpu => "cpu",
            Backend::Gpu => "gpu",
        }
    }
}

/// The algorithm that solves an island's LCP.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// The fastest exact path (default). On the CPU: prediction (separating,
    /// single contact, warm start, predicted basis), then Lemke, whose final
    /// basis is re-solved in f64 and checked by the test every GPU answer
    /// goes through; enumeration only where that check fails (a ray, the
    /// pivot cap, or a basis invalid in f64), and above n = 20 Lemke's answer
    /// as it is. On the GPU the same: prediction, then Lemke's textbook path
    /// in a kernel (`shaders/lemke.wgsl`) whose basis gets the same f64
    /// check, the CPU path for the islands it does not settle: in f64 the
    /// CPU's answers. Where z is not unique, Auto and Enumeration may report
    /// different solutions (Lemke's basis, enumeration's fewest active
    /// contacts); where M is positive semidefinite, w is the same.
    #[default]
    Auto,
    /// Enumeration of the complementary bases (exact; fewest active contacts
    /// first, then the smallest mask), after the cheap paths of prediction
    /// (separating, single contact, warm start, predicted basis). On the CPU
    /// up to n = 20, on the GPU up to n = 16; scene islands above that go to
    /// Lemke. The GPU's enumeration kernels.
    Enumeration,
    /// Lemke's complementary pivoting with a lexicographic ratio test (exact,
    /// any n). On the GPU: the textbook path in a kernel for n ≤ 16, its
    /// basis re-solved and checked in f64 (else the CPU's Lemke); such an
    /// answer is the basis' f64 re-solve where the CPU's may keep its
    /// tableau's z (the same solution to rounding).
    Lemke,
    /// Projected Gauss–Seidel from z = 0 (iterative; CPU).
    Pgs,
}

impl Method {
    /// The name used on the command line and in output: `auto`, `enum`,
    /// `lemke`, `pgs`.
    pub fn name(self) -> &'static str {
        match self {
            Method::Auto => "auto",
            Method::Enumeration => "enum",
            Method::Lemke => "lemke",
            Method::Pgs => "pgs",
        }
    }
}

/// The value among `all` whose `name` is `s`; else an error naming `what`
/// and listing the allowed names, e.g. `method: field `method`: `x` is not
/// one of auto, enum, lemke, pgs`. The one inverse of each `name()`.
pub(crate) fn from_name<T: Copy>(
    what: &str,
    s: &str,
    all: &[T],
    name: fn(T) -> &'static str,
) -> Result<T, Error> {
    all.iter().copied().find(|&v| name(v) == s).ok_or_else(|| {
        let names: Vec<&str> = all.iter().map(|&v| name(v)).collect();
        Error::invalid(
            what,
            what,
            format!("`{s}` is not one of {}", names.join(", ")),
        )
    })
}

impl Backend {
    /// Every backend, in the order of the help texts.
    pub const ALL: [Backend; 3] = [Backend::Auto, Backend::Cpu, Backend::Gpu];
}

impl FromStr for Backend {
    type Err = Error;
    /// The backend of [`Backend::name`]; an error listing the names otherwise.
    fn from_str(s: &str) -> Result<Self, Error> {
        from_name("backend", s, &Backend::ALL, Backend::name)
    }
}

impl Method {
    /// Every method.
    pub const ALL: [Method; 4] = [
        Method::Auto,
        Method::Enumeration,
        Method::Lemke,
        Method::Pgs,
    ];
}

impl FromStr for Method {
    type Err = Error;
    /// The method of [`Method::name`] (`enum` for enumeration); an error
    /// listing the names otherwise.
    fn from_str(s: &str) -> Result<Self, Error> {
        from_name("method", s, &Method::ALL, Method::name)
    }
}

/// Floating-point type of the shaders.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Precision {
    /// f64 where the adapter has SHADER_F64, else f32.
    #[default]
    Auto,
    /// 32-bit floats (every adapter).
    F32,
    /// 64-bit floats (adapters with SHADER_F64).
    F64,
}

impl Precision {
    /// Every precision.
    pub const ALL: [Precision; 3] = [Precision::Auto, Precision::F32, Precision::F64];

    /// `auto`, `f32` or `f64`.
    pub fn name(self) -> &'static str {
        match self {
            Precision::Auto => "auto",
            Precision::F32 => "f32",
            Precision::F64 => "f64",
        }
    }
}

impl FromStr for Precision {
    type Err = Error;
    /// The precision of [`Precision::name`]; an error listing the names otherwise.
    fn from_str(s: &str) -> Result<Self, Error> {
        from_name("precision", s, &Precision::ALL, Precision::name)
    }
}

/// Which wgpu backend(s) to look for adapters on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum BackendChoice {
    /// Every backend wgpu was built with (Vulkan is preferred over GL).
    #[default]
    Auto,
    /// Vulkan (lavapipe among the software adapters).
    Vulkan,
    /// OpenGL (llvmpipe through EGL among the software adapters; no f64).
    Gl,
    /// Metal.
    Metal,
    /// Direct3D 12.
    Dx12,
}

/// The enumeration shader.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum EnumerationKernel {
    /// Per island size, whichever measured faster (`for_n`): Unrolled up to
    /// n = 7, Workgroup from n = 10, Elimination between (BENCHMARKS.md).
    #[default]
    Auto,
    /// `shaders/enumeration.wgsl`: bases by size, one elimination each, stop
    /// at the first valid one.
    Elimination,
    /// `shaders/enumeration.wgsl` specialised per island size (constant
    /// loop bounds and private-array indices) for the sizes the generated
    /// shaders cover; the elimination kernel above. Same answers as
    /// Elimination, bit for bit.
    Unrolled,
    /// `shaders/enumeration_tree.wgsl` first, on every island of n ≤
    /// [`GpuSettings::tree_max_n`]: all bases screened by principal pivots
    /// down the tree of bases, the screened ones confirmed by elimination;
    /// the islands it leaves undecided, and the larger ones, go to Auto's
    /// kernel. Auto sends only positive definite islands to it.
    Tree,
    /// `shaders/enumeration_workgroup.wgsl`: one workgroup per island, its
    /// 64 invocations solving the bases of one popcount in waves of 64
    /// consecutive masks, stopping at the first wave with a valid basis
    /// (the elimination kernel's order and choice: in f64 the same basis,
    /// z and counters). Parallelism inside an island, for few large ones.
    Workgroup,
}

impl EnumerationKernel {
    /// The name used in settings and benches.
    pub fn name(self) -> &'static str {
        match self {
            EnumerationKernel::Auto => "auto",
            EnumerationKernel::Elimination => "elimination",
            EnumerationKernel::Unrolled => "unrolled",
            EnumerationKernel::Tree => "tree",
            EnumerationKernel::Workgroup => "workgroup",
        }
    }
}

/// Settings of the GPU backend. Defaults: the best adapter on any wgpu
/// backend, f64 where the adapter has it, kernels chosen per island.
#[derive(Clone, Debug, PartialEq)]
pub struct GpuSettings {
    /// A case-insensitive part of the adapter's name (default None: the best
    /// adapter, hardware before software). Naming one makes `Backend::Auto`
    /// use it even when it is a software adapter.
    pub adapter: Option<String>,
    /// The wgpu backend to look on (default [`BackendChoice::Auto`]: all,
    /// Vulkan before GL).
    pub api: BackendChoice,
    /// Shader precision (default [`Precision::Auto`]: f64 where the adapter
    /// has SHADER_F64, else f32). [`Precision::F64`] on an adapter without
    /// it is device trouble: the CPU solves, never silently in f32.
    pub precision: Precision,
    /// The enumeration shader (default [`EnumerationKernel::Auto`]: chosen
    /// per island size and class from measurements).
    pub kernel: EnumerationKernel,
    /// Largest island the tree kernel takes (default 12; 0 turns it off).
    pub tree_max_n: usize,
    /// Split batches above this many bytes per binding (default None: the
    /// device's limit; a lower value is capped by it). For tests of the splitting.
    pub max_binding_bytes: Option<u64>,
    /// At most this many workgroups per dispatch (default None: the
    /// device's limit). For tests of the splitting.
    pub max_workgroups: Option<u32>,
    /// Loop work per invocation and enumeration round (default None: 48,000
    /// on software adapters, which end longer loops, 2²² on hardware).
    pub round_budget: Option<u32>,
}

impl Default for GpuSettings {
    fn default() -> Self {
        GpuSettings {
            adapter: None,
            api: BackendChoice::Auto,
            precision: Precision::Auto,
            kernel: EnumerationKernel::Auto,
            tree_max_n: TREE_MAX_N,
            max_binding_bytes: None,
            max_workgroups: None,
            round_budget: None,
        }
    }
}

impl GpuSettings {
    /// Defaults overridden by the environment: `LCPBATCH_GPU_ADAPTER`,
    /// `LCPBATCH_GPU_BACKEND` (auto, vulkan, gl, metal, dx12) and
    /// `LCPBATCH_GPU_PRECISION` (auto, f32, f64). A bad value is an error
    /// naming the variable.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the variable whose value is not one of those.
    pub fn from_env() -> Result<Self, Error> {
        let o = GpuOptions::from_env()?;
        Ok(GpuSettings {
            adapter: o.adapter_name,
            api: o.backend,
            precision: o.precision,
            ..GpuSettings::default()
        })
    }

    pub(crate) fn options(&self) -> GpuOptions {
        GpuOptions {
            backend: self.api,
            adapter_name: self.adapter.clone(),
            precision: self.precision,
            ..GpuOptions::default()
        }
    }
}

/// Every setting of a [`crate::Solver`]. `Settings::default()` is the
/// fastest exact path: on the CPU prediction, then Lemke checked in f64,
/// then enumeration where the check fails; on a hardware GPU enumeration;
/// every answer checked in f64.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// Where to solve (default [`Backend::Auto`]).
    pub backend: Backend,
    /// `Backend::Auto` with a GPU open: the measured costs of both paths by
    /// island size that choose, per batch, the faster one (default None:
    /// the model cached for this device and thread count, else measured
    /// once by [`crate::Solver::new`] and cached; see [`crate::CostModel`]).
    pub cost_model: Option<crate::CostModel>,
    /// The algorithm (default [`Method::Auto`]: the fastest exact path).
    pub method: Method,
    /// Visit every basis and report every solution and whether the solution
    /// set is finite (default false; method Auto or Enumeration, which then
    /// enumerates). On the GPU every basis of every island of n ≤ 16 is
    /// screened on the device and the flagged ones re-solved and decided in
    /// f64 on the CPU: the same solution sets as the CPU's enumeration.
    pub all_solutions: bool,
    /// Enumeration only: settle what needs no enumeration first (separating
    /// islands, single contacts, a warm basis, the predicted basis when M is
    /// positive definite), on both backends (default true). Same answers.
    pub predict: bool,
    /// Remember each island's basis by its contact ids and start the next
    /// call from it (default false). Scenes key contacts by
    /// [`crate::Contact::id`]; LCPs by the ids given to
    /// [`crate::Solver::solve_lcps_keyed`]. Contacts without an id are not
    /// remembered.
    pub warm_start: bool,
    /// Calls a contact id is remembered for warm start without being seen
    /// again (default 1: only the last call's ids); at least 1.
    pub warm_start_calls: usize,
    /// CPU worker threads (default 0: every core the OS reports).
    pub threads: usize,
    /// Relative pivot tolerance below which a principal submatrix is
    /// singular (default 1e-13); in [0, 1).
    pub pivot_tol: f64,
    /// Relative feasibility tolerance of a valid basis (default 1e-12); in [0, 1).
    pub feasibility_tol: f64,
    /// When no basis is feasible to `feasibility_tol`, the least infeasible
    /// one is accepted if within this (default 1e-9); in
    /// [`feasibility_tol`](Self::feasibility_tol), 1).
    pub relaxed_feasibility_tol: f64,
    /// Lemke's pivot cap (default 10,000; at least 1); reaching it gives
    /// `not_converged`.
    pub lemke_max_pivots: u64,
    /// Lemke: an entering-column entry counts as positive above this times
    /// the column's largest magnitude (default 1e-12); in [0, 1).
    pub lemke_pivot_tol: f64,
    /// PGS sweep cap (default 1000; at least 1).
    pub pgs_max_sweeps: u64,
    /// PGS stops when the error measure is at most this (default 1e-10);
    /// finite and ≥ 0.
    pub pgs_tolerance: f64,
    /// A solution is reported as `solved` (or `multiple_solutions`) only when
    /// z, w and the error measure are finite and the error is at most this
    /// (default 1e-8); otherwise its status is `numerical_failure`. In (0, 1).
    pub tolerance: f64,
    /// The algorithm for islands with friction (default
    /// [`FrictionMethod::Auto`]: NSGS then Alart–Curnier Newton). They are
    /// solved on the CPU in f64, except with [`Backend::Gpu`] and a projected
    /// method (`jacobi`, `pgs`, `apgd`): the GPU iterates islands of up to 16
    /// contacts in its precision and the CPU checks every answer in f64,
    /// polishing or re-solving it where it misses the tolerance
    /// ([`crate::Report::choice`] says where they went).
    pub friction_method: FrictionMethod,
    /// A frictional island is `solved` only when its Coulomb error (Siconos'
    /// fc3d error with De Saxcé's correction) is at most this (default 1e-8);
    /// in (0, 1).
    pub friction_tolerance: f64,
    /// Cap on a frictional island's NSGS sweeps plus Newton steps (default
    /// 1000; at least 1); reaching it gives `not_converged`.
    pub friction_max_iterations: u64,
    /// The GPU backend's settings.
    pub gpu: GpuSettings,
    /// Print device trouble on stderr, once per solver (default true: the
    /// command-line tool's `warning: GPU: …` line). A caller that reports
    /// [`crate::Report::fallback`] itself (the Python package, as a
    /// `DeviceWarning`) turns it off so that the trouble is told once.
    pub warn_on_stderr: bool,
}

impl Default for Settings {
    fn default() -> Self {
        let e = EnumerationSettings::default();
        let l = LemkeSettings::default();
        let p = PgsSettings::default();
        Settings {
            backend: Backend::Auto,
            cost_model: None,
            method: Method::Auto,
            all_solutions: false,
            predict: true,
            warm_start: false,
            warm_start_calls: 1,
            threads: 0,
            pivot_tol: PIVOT_TOL,
            feasibility_tol: e.feasibility_tol,
            relaxed_feasibility_tol: e.relaxed_feasibility_tol,
            lemke_max_pivots: l.max_pivots,
            lemke_pivot_tol: l.pivot_tol,
            pgs_max_sweeps: p.max_iterations,
            pgs_tolerance: p.tolerance,
            tolerance: 1e-8,
            friction_method: FrictionMethod::Auto,
            friction_tolerance: FrictionSettings::default().tolerance,
            friction_max_iterations: FrictionSettings::default().max_iterations,
            gpu: GpuSettings::default(),
            warn_on_stderr: true,
        }
    }
}

fn invalid(field: &str, reason: impl Into<String>) -> Error {
    Error::invalid("settings", field, reason)
}

impl Settings {
    /// Default settings on `backend` with `method`.
    pub fn new(backend: Backend, method: Method) -> Self {
        Settings {
            backend,
            method,
            ..Settings::default()
        }
    }

    /// Checks every field; the error names the first one out of range.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the first field out of range.
    pub fn validate(&self) -> Result<(), Error> {
        if let Some(m) = &self.cost_model {
            m.validate()?;
        }
        for (name, v) in [
            ("pivot_tol", self.pivot_tol),
            ("feasibility_tol", self.feasibility_tol),
            ("relaxed_feasibility_tol", self.relaxed_feasibility_tol),
            ("lemke_pivot_tol", self.lemke_pivot_tol),
        ] {
            if !(0.0..1.0).contains(&v) {
                return Err(invalid(name, format!("{v} is not in [0, 1)")));
            }
        }
        if self.relaxed_feasibility_tol < self.feasibility_tol {
            return Err(invalid(
                "relaxed_feasibility_tol",
                "must be at least feasibility_tol",
            ));
        }
        if !(self.tolerance > 0.0 && self.tolerance < 1.0) {
            return Err(invalid(
                "tolerance",
                format!("{} is not in (0, 1)", self.tolerance),
            ));
        }
        if !(self.friction_tolerance > 0.0 && self.friction_tolerance < 1.0) {
            return Err(invalid(
                "friction_tolerance",
                format!("{} is not in (0, 1)", self.friction_tolerance),
            ));
        }
        if self.friction_max_iterations == 0 {
            return Err(invalid("friction_max_iterations", "must be at least 1"));
        }
        if self.warm_start_calls == 0 {
            return Err(invalid("warm_start_calls", "must be at least 1"));
        }
        if self.lemke_max_pivots == 0 {
            return Err(invalid("lemke_max_pivots", "must be at least 1"));
        }
        if self.pgs_max_sweeps == 0 {
            return Err(invalid("pgs_max_sweeps", "must be at least 1"));
        }
        if !(self.pgs_tolerance.is_finite() && self.pgs_tolerance >= 0.0) {
            return Err(invalid(
                "pgs_tolerance",
                format!("{} is not a finite number ≥ 0", self.pgs_tolerance),
            ));
        }
        if self.all_solutions && !matches!(self.method, Method::Auto | Method::Enumeration) {
            return Err(invalid("all_solutions", "needs method Auto or Enumeration"));
        }
        if self.backend == Backend::Gpu && !self.gpu_capable() {
            return Err(invalid(
                "backend",
                "the GPU backend solves by enumeration or Lemke only (no PGS)",
            ));
        }
        if self.gpu.adapter.as_deref() == Some("") {
            return Err(invalid(
                "gpu.adapter",
                "is empty (None means the best adapter)",
            ));
        }
        if self.gpu.max_binding_bytes == Some(0) {
            return Err(invalid("gpu.max_binding_bytes", "must be positive"));
        }
        if self.gpu.max_workgroups == Some(0) {
            return Err(invalid("gpu.max_workgroups", "must be positive"));
        }
        if self.gpu.round_budget == Some(0) {
            return Err(invalid("gpu.round_budget", "must be positive"));
        }
        Ok(())
    }

    /// Whether the GPU can serve these settings (enumeration, or Lemke's
    /// textbook path: Auto and Lemke).
    pub(crate) fn gpu_capable(&self) -> bool {
        matches!(
            self.method,
            Method::Auto | Method::Enumeration | Method::Lemke
        )
    }

    pub(crate) fn enumeration(&self) -> EnumerationSettings {
        EnumerationSettings {
            all_solutions: self.all_solutions,
            pivot_tol: self.pivot_tol,
            feasibility_tol: self.feasibility_tol,
            relaxed_feasibility_tol: self.relaxed_feasibility_tol,
        }
    }

    /// The friction solvers' settings.
    pub fn friction(&self) -> FrictionSettings {
        FrictionSettings {
            method: self.friction_method,
            tolerance: self.friction_tolerance,
            max_iterations: self.friction_max_iterations,
        }
    }

    pub(crate) fn lemke(&self) -> LemkeSettings {
        LemkeSettings {
            max_pivots: self.lemke_max_pivots,
            pivot_tol: self.lemke_pivot_tol,
        }
    }

    pub(crate) fn pgs(&self) -> PgsSettings {
        PgsSettings {
            max_iterations: self.pgs_max_sweeps,
            tolerance: self.pgs_tolerance,
        }
    }

    pub(crate) fn gpu_solve(&self) -> GpuSolveSettings {
        GpuSolveSettings {
            enumeration: self.enumeration(),
            lemke: self.lemke(),
            max_binding_bytes: self.gpu.max_binding_bytes,
            max_workgroups: self.gpu.max_workgroups,
            round_budget: self.gpu.round_budget,
            // Lemke on the CPU path predicts nothing.
            predict: self.predict && self.method != Method::Lemke,
            kernel: self.gpu.kernel,
            method: self.method,
            tree_max_n: self.gpu.tree_max_n,
            tolerance: self.tolerance,
            ..GpuSolveSettings::default()
        }
    }
}

#[cfg(test)]
#[path = "settings_tests.rs"]
mod tests;
