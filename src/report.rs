//! What a [`crate::Solver`] call found: one [`Report`] type for LCP batches
//! and scene batches, on every backend.
//!
//! Per island (an LCP of the batch, or a contact island of a scene): the
//! status, z, w, the error measure, the basis and the path that settled it
//! ([`IslandReport`]). Per batch: counts per path ([`PathCounts`]) and per
//! status, the largest error and which island has it, time per phase
//! ([`Timings`]), where it ran and why ([`Report::device`],
//! [`Report::choice`]) and the reason the CPU took over, if it did
//! ([`Report::fallback`]).

use std::fmt;
use std::ops::AddAssign;

pub use crate::cpu::impulses::BodyVelocity;
use crate::friction::{FrictionMethod, FrictionSolution};
use crate::gpu::Precision;
use crate::lcp::{LcpSolution, Status};
use crate::settings::Method;
use crate::short_vec::ShortVec;

/// How an island was settled.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum SolvePath {
    /// q ≥ 0: no impulse needed (prediction).
    Separating,
    /// n = 1, closed form (prediction).
    SingleContact,
    /// The basis remembered from the previous call was still valid.
    WarmStart,
    /// The basis of the approaching contacts was valid and M positive definite.
    PredictedBasis,
    /// Enumerated on the GPU; its z passed the f64 check (accepted) or its
    /// basis is valid in f64 (polished), or its "no solution" was
    /// confirmed on the CPU.
    EnumeratedGpu,
    /// Lemke's textbook path on the GPU (`shaders/lemke.wgsl`); its basis
    /// re-solved and checked in f64 as the CPU path checks Lemke's.
    LemkeGpu,
    /// Enumerated on the GPU, but the answer failed the f64 check: the CPU
    /// enumeration solved it (also: an island the GPU's Lemke could not
    /// settle and the CPU path's Lemke did not either).
    Repaired,
    /// Enumerated on the CPU.
    EnumeratedCpu,
    /// Lemke on the CPU: asked for, or an island too large to enumerate.
    Lemke,
    /// Projected Gauss–Seidel on the CPU.
    Pgs,
    /// The problem failed its checks (status `invalid_input`).
    Invalid,
}

impl SolvePath {
    /// Every path, in the order of the variants (Python's path codes).
    pub const ALL: [SolvePath; 11] = [
        SolvePath::Separating,
        SolvePath::SingleContact,
        SolvePath::WarmStart,
        SolvePath::PredictedBasis,
        SolvePath::EnumeratedGpu,
        SolvePath::LemkeGpu,
        SolvePath::Repaired,
        SolvePath::EnumeratedCpu,
        SolvePath::Lemke,
        SolvePath::Pgs,
        SolvePath::Invalid,
    ];

    /// The snake_case name used in reports.
    pub fn name(self) -> &'static str {
        match self {
            SolvePath::Separating => "separating",
            SolvePath::SingleContact => "single_contact",
            SolvePath::WarmStart => "warm_start",
            SolvePath::PredictedBasis => "predicted_basis",
            SolvePath::EnumeratedGpu => "enumerated_gpu",
            SolvePath::LemkeGpu => "lemke_gpu",
            SolvePath::Repaired => "repaired",
            SolvePath::EnumeratedCpu => "enumerated_cpu",
            SolvePath::Lemke => "lemke",
            SolvePath::Pgs => "pgs",
            SolvePath::Invalid => "invalid",
        }
    }

    /// Settled by prediction, before either backend enumerates.
    pub fn is_prediction(self) -> bool {
        matches!(
            self,
            SolvePath::Separating
                | SolvePath::SingleContact
                | SolvePath::WarmStart
                | SolvePath::PredictedBasis
        )
    }
}

impl fmt::Display for SolvePath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One island's (or one LCP's) result.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct IslandReport {
    /// The scene it belongs to (None for an LCP batch).
    pub scene: Option<usize>,
    /// The scene's contact indices in the order of the LCP's rows (for an
    /// LCP batch: 0..n). Inline up to [`crate::short_vec::SHORT_INLINE`] contacts, as
    /// the solution's z and w: a batch of small islands allocates nothing
    /// per island.
    pub contacts: ShortVec<usize>,
    /// The algorithm whose answer this is (enumeration hands islands beyond
    /// its size limit to Lemke).
    pub method: Method,
    /// How it was settled.
    pub path: SolvePath,
    /// Status, z, w, residuals (the error measure), basis and counters, all in f64.
    pub solution: LcpSolution,
}

impl IslandReport {
    /// The status of the solve.
    pub fn status(&self) -> Status {
        self.solution.status
    }

    /// The Siconos error measure ‖z − max(0, z − w)‖ / ‖q‖.
    pub fn error(&self) -> f64 {
        self.solution.residuals.error
    }
}

/// One scene after the impact.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct SceneReport {
    /// Normal impulse of every contact, in the scene's order.
    pub impulses: Vec<f64>,
    /// Velocities of every body after the impulses.
    pub bodies: Vec<BodyVelocity>,
    /// Its islands: indices into [`Report::islands`].
    pub islands: std::ops::Range<usize>,
    /// Scenes with friction (any contact with μ > 0): per contact the
    /// impulse vector and its parts, and the scene's frictional islands.
    /// None for a frictionless scene, whose output is unchanged. For a scene
    /// with friction, `impulses` holds the normal parts and `islands` is empty.
    pub friction: Option<SceneFriction>,
}

/// A scene's frictional results.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct SceneFriction {
    /// One per contact, in the scene's order.
    pub contacts: Vec<ContactImpulse>,
    /// Its islands: indices into [`Report::friction`].
    pub islands: std::ops::Range<usize>,
}

/// One contact's impulse with friction.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ContactImpulse {
    /// The impulse on body a (world frame): r_n n + r_t₁ t₁ + r_t₂ t₂; body b
    /// receives the opposite.
    pub impulse: [f64; 3],
    /// Its normal part r_n ≥ 0.
    pub normal: f64,
    /// Its tangential part in the contact's frame: (r_t₁, r_t₂), with
    /// ‖(r_t₁, r_t₂)‖ ≤ μ r_n.
    pub tangential: [f64; 2],
    /// The tangential part in the world frame: r_t₁ t₁ + r_t₂ t₂.
    pub tangential_impulse: [f64; 3],
    /// The frame (t₁, t₂) the parts refer to.
    pub tangents: [[f64; 3]; 2],
    /// The local velocity after the impulse (u_n, u_t₁, u_t₂), restitution
    /// included in u_n as in the LCP's w.
    pub velocity: [f64; 3],
}

/// One frictional island's (or one [`crate::FrictionProblem`]'s) result.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct FrictionIslandReport {
    /// The scene it belongs to (None for a batch of problems).
    pub scene: Option<usize>,
    /// The scene's contact indices in the order of the problem's contacts
    /// (for a batch of problems: 0..k).
    pub contacts: Vec<usize>,
    /// Whether it started from the last call's impulses (warm start by ids).
    pub warm_started: bool,
    /// Status, r, u, residuals (Coulomb error and the others), iterations, method.
    pub solution: FrictionSolution,
}

impl FrictionIslandReport {
    /// The status of the solve.
    pub fn status(&self) -> Status {
        self.solution.status
    }
    /// The Coulomb error (Siconos' fc3d error with De Saxcé's correction).
    pub fn error(&self) -> f64 {
        self.solution.residuals.coulomb_error
    }
    /// The method that solved it.
    pub fn method(&self) -> FrictionMethod {
        self.solution.method
    }
}

/// Islands per path, and what validation did to the GPU's answers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
#[non_exhaustive]
pub struct PathCounts {
    /// q ≥ 0: no impulse.
    pub separating: usize,
    /// One contact, closed form.
    pub single_contact: usize,
    /// The basis remembered from the last call was valid.
    pub warm_start: usize,
    /// The basis of the approaching contacts was valid, M positive definite.
    pub predicted_basis: usize,
    /// Enumerated on the GPU and confirmed in f64 (`accepted` +
    /// `polished` + GPU "no solution" confirmed on the CPU).
    pub enumerated_gpu: usize,
    /// Settled by the GPU's Lemke kernel, its basis checked in f64.
    pub lemke_gpu: usize,
    /// Enumerated on the CPU.
    pub enumerated_cpu: usize,
    /// Lemke on the CPU (asked for, or too large to enumerate).
    pub lemke: usize,
    /// Projected Gauss–Seidel.
    pub pgs: usize,
    /// Failed their checks.
    pub invalid: usize,
    /// GPU answers kept as the GPU gave them: its z passed the f64 check
    /// (w = M z + q recomputed in f64 from the input: signs,
    /// complementarity, the error measure within tolerance); f64 shaders
    /// on LCP batches (a scene's islands assembled on the device are
    /// re-solved on the CPU's assembly: polished).
    pub accepted: usize,
    /// GPU answers whose basis was re-solved in f64 and valid there (z, w
    /// recomputed in f64): where the check of the GPU's own z failed, and
    /// every answer of an f32 shader.
    pub polished: usize,
    /// GPU answers that failed in f64 and were re-solved on the CPU.
    pub repaired: usize,
    /// Islands the GPU backend handed to the CPU because they are too large
    /// for its kernels (n > 16), or its Lemke kernel could not settle them,
    /// solved by Lemke on the CPU.
    pub cpu_fallback: usize,
}

impl PathCounts {
    fn add(&mut self, path: SolvePath) {
        let c = match path {
            SolvePath::Separating => &mut self.separating,
            SolvePath::SingleContact => &mut self.single_contact,
            SolvePath::WarmStart => &mut self.warm_start,
            SolvePath::PredictedBasis => &mut self.predicted_basis,
            SolvePath::EnumeratedGpu => &mut self.enumerated_gpu,
            SolvePath::LemkeGpu => &mut self.lemke_gpu,
            SolvePath::Repaired => &mut self.repaired,
            SolvePath::EnumeratedCpu => &mut self.enumerated_cpu,
            SolvePath::Lemke => &mut self.lemke,
            SolvePath::Pgs => &mut self.pgs,
            SolvePath::Invalid => &mut self.invalid,
        };
        *c += 1;
    }

    /// (name, count) of every count, in a fixed order (the order of the
    /// report's text and of Python's `counts`).
    pub fn named(&self) -> [(&'static str, usize); 14] {
        [
            ("separating", self.separating),
            ("single_contact", self.single_contact),
            ("warm_start", self.warm_start),
            ("predicted_basis", self.predicted_basis),
            ("enumerated_gpu", self.enumerated_gpu),
            ("lemke_gpu", self.lemke_gpu),
            ("accepted", self.accepted),
            ("polished", self.polished),
            ("repaired", self.repaired),
            ("enumerated_cpu", self.enumerated_cpu),
            ("lemke", self.lemke),
            ("cpu_fallback", self.cpu_fallback),
            ("pgs", self.pgs),
            ("invalid", self.invalid),
        ]
    }

    /// (name, count) of every non-zero count, in the order of [`Self::named`].
    pub fn nonzero(&self) -> Vec<(&'static str, usize)> {
        self.named().into_iter().filter(|(_, c)| *c > 0).collect()
    }
}

impl AddAssign for PathCounts {
    /// Every count summed (the one place that lists them for a merge).
    fn add_assign(&mut self, b: PathCounts) {
        self.separating += b.separating;
        self.single_contact += b.single_contact;
        self.warm_start += b.warm_start;
        self.predicted_basis += b.predicted_basis;
        self.enumerated_gpu += b.enumerated_gpu;
        self.lemke_gpu += b.lemke_gpu;
        self.enumerated_cpu += b.enumerated_cpu;
        self.lemke += b.lemke;
        self.pgs += b.pgs;
        self.invalid += b.invalid;
        self.accepted += b.accepted;
        self.polished += b.polished;
        self.repaired += b.repaired;
        self.cpu_fallback += b.cpu_fallback;
    }
}

/// Seconds per phase of one call (0 for a phase that did not run).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct Timings {
    /// Scenes: checks, islands and assembly (on the GPU path, the CPU's f64
    /// assembly that validation uses).
    pub build: f64,
    /// Prediction on the CPU (before the GPU; on the CPU path it is part of `solve`).
    pub prediction: f64,
    /// GPU: upload, dispatch and readback (assembly, enumeration, impulses).
    pub gpu: f64,
    /// Checking the GPU's answers in f64.
    pub validation: f64,
    /// CPU solves (prediction included on the CPU path; the GPU path's
    /// Lemke fallbacks are in its total only).
    pub solve: f64,
    /// Scenes: velocities after the impulses.
    pub impulses: f64,
    /// The whole call.
    pub total: f64,
}

impl Timings {
    /// (name, seconds) of every phase, in a fixed order (that of Python's
    /// `timings`).
    pub fn named(&self) -> [(&'static str, f64); 7] {
        [
            ("build", self.build),
            ("prediction", self.prediction),
            ("gpu", self.gpu),
            ("validation", self.validation),
            ("solve", self.solve),
            ("impulses", self.impulses),
            ("total", self.total),
        ]
    }
}

impl AddAssign for Timings {
    /// Every phase's seconds summed.
    fn add_assign(&mut self, b: Timings) {
        self.build += b.build;
        self.prediction += b.prediction;
        self.gpu += b.gpu;
        self.validation += b.validation;
        self.solve += b.solve;
        self.impulses += b.impulses;
        self.total += b.total;
    }
}

/// What kind of device solved the batch.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DeviceKind {
    /// The CPU path in f64.
    Cpu,
    /// A hardware GPU.
    HardwareGpu,
    /// A software adapter (lavapipe, llvmpipe, WARP).
    SoftwareGpu,
}

/// Where the batch was solved.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct Device {
    /// CPU, hardware GPU or software adapter.
    pub kind: DeviceKind,
    /// The adapter in words (name, backend, device type, how chosen,
    /// precision), or `cpu (N threads)`.
    pub name: String,
    /// Shader precision on the GPU; F64 on the CPU.
    pub precision: Precision,
}

/// GPU-only figures of a batch.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct GpuFigures {
    /// Parts the batch was split into under the device's limits.
    pub chunks: usize,
    /// Compute dispatches.
    pub dispatches: usize,
    /// Enumeration rounds (see `shaders/enumeration.wgsl`).
    pub rounds: usize,
    /// Islands the tree kernel decided, and those it left to elimination.
    pub tree_decided: usize,
    /// Islands the tree kernel left to the elimination kernel.
    pub tree_undecided: usize,
    /// Largest error measure of the GPU's own z, before the f64 polish.
    pub max_gpu_error: f64,
    /// Scenes: largest relative deviation of the GPU's impulse stage from
    /// its f64 twin.
    pub max_velocity_deviation: f64,
    /// Seconds of the GPU phase's parts, as the host sees them: planning
    /// the chunks (sorting by size, the tree kernel's routes), writing M
    /// and q into the device's buffers, the kernels (submission to the end
    /// of the last round, waits included) and reading the answers back.
    pub pack_seconds: f64,
    /// See [`Self::pack_seconds`].
    pub upload_seconds: f64,
    /// See [`Self::pack_seconds`].
    pub kernel_seconds: f64,
    /// See [`Self::pack_seconds`].
    pub readback_seconds: f64,
    /// Seconds the device itself ran the kernels, from GPU timestamps
    /// (per submission, its first dispatch's start to its last one's end,
    /// summed over submissions and chunks); None where the adapter has no
    /// `TIMESTAMP_QUERY`. Beside [`Self::kernel_seconds`] it says how much
    /// of the host's wait was the kernels themselves.
    pub kernel_device_seconds: Option<f64>,
    /// Seconds of the f64 check of the GPU's answers (each answer's z
    /// checked, its basis re-solved where that fails, on every thread; wall time of the passes,
    /// [`Self::repair_seconds`] left out). LCP batches only.
    pub check_seconds: f64,
    /// Seconds of the repairs in the check: answers the check rejected,
    /// solved again by the CPU path (the threads' seconds on them divided
    /// by the threads: their share of the passes' wall time).
    pub repair_seconds: f64,
    /// Seconds making the batch's report: each island's record (before the
    /// passes) and the counts (after). LCP batches only.
    pub report_seconds: f64,
    /// Of the host's seconds above (packing, upload, check), those spent
    /// while a chunk was on the device: hidden behind the kernels where the
    /// device is not the host's own cores.
    pub overlapped_seconds: f64,
}

impl AddAssign for GpuFigures {
    /// Counts summed, the largest deviations kept (`f64::max`: a NaN on one
    /// side gives the other).
    fn add_assign(&mut self, b: GpuFigures) {
        self.chunks += b.chunks;
        self.dispatches += b.dispatches;
        self.rounds += b.rounds;
        self.tree_decided += b.tree_decided;
        self.tree_undecided += b.tree_undecided;
        self.max_gpu_error = self.max_gpu_error.max(b.max_gpu_error);
        self.max_velocity_deviation = self.max_velocity_deviation.max(b.max_velocity_deviation);
        self.pack_seconds += b.pack_seconds;
        self.upload_seconds += b.upload_seconds;
        self.kernel_seconds += b.kernel_seconds;
        self.readback_seconds += b.readback_seconds;
        self.kernel_device_seconds = match (self.kernel_device_seconds, b.kernel_device_seconds) {
            (Some(a), Some(b)) => Some(a + b),
            (a, b) => a.or(b),
        };
        self.check_seconds += b.check_seconds;
        self.repair_seconds += b.repair_seconds;
        self.report_seconds += b.report_seconds;
        self.overlapped_seconds += b.overlapped_seconds;
    }
}

/// Everything a call found; see the module docs.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Report {
    /// One per LCP (in the caller's order), or per island of each scene
    /// (scene by scene, islands in the order of [`crate::Scene`]'s contact graph).
    pub islands: Vec<IslandReport>,
    /// Scene batches only: one per scene (empty for LCP batches).
    pub scenes: Vec<SceneReport>,
    /// Islands per path.
    pub counts: PathCounts,
    /// Islands per status, in the order of [`Status::ALL`].
    pub statuses: [usize; Status::ALL.len()],
    /// Largest error measure over islands whose status is a solution, and
    /// the index of that island in `islands` (None when there is none).
    pub max_error: Option<(f64, usize)>,
    /// Seconds per phase.
    pub timings: Timings,
    /// Where the batch was solved.
    pub device: Device,
    /// Why this device: the backend asked for and what was found.
    pub choice: String,
    /// Why the CPU took over from the GPU (None: no device trouble).
    pub fallback: Option<String>,
    /// GPU figures when the GPU solved the batch.
    pub gpu: Option<GpuFigures>,
    /// One per frictional problem (in the caller's order) or per island of
    /// each scene with friction (scene by scene); empty without friction.
    pub friction: Vec<FrictionIslandReport>,
    /// Frictional islands per status, in the order of [`Status::ALL`].
    pub friction_statuses: [usize; Status::ALL.len()],
    /// Largest Coulomb error over solved frictional islands and the index of
    /// that island in `friction` (None when there is none).
    pub max_coulomb_error: Option<(f64, usize)>,
}

impl Report {
    /// Counts per path (from the islands' paths alone: the GPU's
    /// `accepted`, `polished` and `cpu_fallback` start at 0), per status and the
    /// largest error from `islands`.
    pub(crate) fn new(
        islands: Vec<IslandReport>,
        scenes: Vec<SceneReport>,
        device: Device,
        choice: String,
    ) -> Self {
        Self::new_on(islands, scenes, device, choice, 1)
    }

    /// [`Report::new`], the islands counted on up to `threads` threads.
    pub(crate) fn new_on(
        islands: Vec<IslandReport>,
        scenes: Vec<SceneReport>,
        device: Device,
        choice: String,
        threads: usize,
    ) -> Self {
        let (counts, (statuses, max_error)) = count_islands(&islands, threads);
        Report {
            islands,
            scenes,
            counts,
            statuses,
            max_error,
            timings: Timings::default(),
            device,
            choice,
            fallback: None,
            gpu: None,
            friction: Vec::new(),
            friction_statuses: [0; Status::ALL.len()],
            max_coulomb_error: None,
        }
    }

    /// Sets the frictional islands, their counts per status and the largest
    /// Coulomb error.
    pub(crate) fn set_friction(&mut self, friction: Vec<FrictionIslandReport>) {
        (self.friction_statuses, self.max_coulomb_error) =
            tally(friction.iter().map(|i| (i.status(), i.error())));
        self.friction = friction;
    }

    /// Appends `other` (the next part of one batch): its islands, scenes
    /// and frictional islands after this report's, their scene indices and
    /// island ranges shifted past this report's, counts, statuses, timings
    /// and GPU figures summed, the largest errors (NaN wins) with their
    /// index in the whole batch. The device and choice become `other`'s
    /// (the last part's), the fallback reason stays the first one.
    pub fn append(&mut self, mut other: Report) {
        let (islands, scenes, friction) =
            (self.islands.len(), self.scenes.len(), self.friction.len());
        for isl in &mut other.islands {
            isl.scene = isl.scene.map(|s| s + scenes);
        }
        for isl in &mut other.friction {
            isl.scene = isl.scene.map(|s| s + scenes);
        }
        for s in &mut other.scenes {
            s.islands = s.islands.start + islands..s.islands.end + islands;
            if let Some(f) = &mut s.friction {
                f.islands = f.islands.start + friction..f.islands.end + friction;
            }
        }
        self.counts += other.counts;
        add_tally(
            (&mut self.statuses, &mut self.max_error),
            (other.statuses, other.max_error),
            islands,
        );
        add_tally(
            (&mut self.friction_statuses, &mut self.max_coulomb_error),
            (other.friction_statuses, other.max_coulomb_error),
            friction,
        );
        self.timings += other.timings;
        match (&mut self.gpu, other.gpu) {
            (Some(a), Some(b)) => *a += b,
            (a, b) => *a = a.or(b),
        }
        self.fallback = self.fallback.take().or(other.fallback);
        self.device = other.device;
        self.choice = other.choice;
        self.islands.append(&mut other.islands);
        self.scenes.append(&mut other.scenes);
        self.friction.append(&mut other.friction);
    }

    /// Appends one scene with its islands and frictional islands: their
    /// scene index becomes the scene's, its ranges point at them, their
    /// paths, statuses and largest errors are added.
    pub(crate) fn push_scene(
        &mut self,
        mut scene: SceneReport,
        mut islands: Vec<IslandReport>,
        mut friction: Vec<FrictionIslandReport>,
    ) {
        let (k, first, first_friction) =
            (self.scenes.len(), self.islands.len(), self.friction.len());
        islands.iter().for_each(|i| self.counts.add(i.path));
        islands.iter_mut().for_each(|i| i.scene = Some(k));
        friction.iter_mut().for_each(|i| i.scene = Some(k));
        let lcp = tally(islands.iter().map(|i| (i.status(), i.error())));
        add_tally((&mut self.statuses, &mut self.max_error), lcp, first);
        let fr = tally(friction.iter().map(|i| (i.status(), i.error())));
        let friction_tally = (&mut self.friction_statuses, &mut self.max_coulomb_error);
        add_tally(friction_tally, fr, first_friction);
        scene.islands = first..first + islands.len();
        if let Some(f) = &mut scene.friction {
            f.islands = first_friction..first_friction + friction.len();
        }
        self.islands.append(&mut islands);
        self.friction.append(&mut friction);
        self.scenes.push(scene);
    }

    /// Merges `other`, a scene batch solved beside this one, scene by scene:
    /// the merged scene k is `other`'s next where `from_other[k]`, else this
    /// report's next. What [`Self::append`] adds up is added up; each scene
    /// keeps its islands and frictional islands in order (ranges renumbered,
    /// empty where it has none) and the largest errors are found anew.
    pub(crate) fn merge_scenes(&mut self, other: Report, from_other: &[bool]) {
        let mut next = [0, self.scenes.len()];
        self.append(other);
        let mut order = vec![0; from_other.len()];
        for (k, &o) in from_other.iter().enumerate() {
            order[next[usize::from(o)]] = k;
            next[usize::from(o)] += 1;
        }
        let at = |s: Option<usize>| s.map(|s| order[s]);
        self.islands.iter_mut().for_each(|i| i.scene = at(i.scene));
        self.friction.iter_mut().for_each(|i| i.scene = at(i.scene));
        // Stable sorts: already in order where nothing moves.
        self.islands.sort_by_key(|i| i.scene);
        self.friction.sort_by_key(|i| i.scene);
        let mut scenes: Vec<_> = order.iter().zip(std::mem::take(&mut self.scenes)).collect();
        scenes.sort_by_key(|s| *s.0);
        let (mut first, mut first_friction) = (0, 0);
        for (_, mut s) in scenes {
            s.islands = first..first + s.islands.len();
            first = s.islands.end;
            if let Some(f) = &mut s.friction {
                f.islands = first_friction..first_friction + f.islands.len();
                first_friction = f.islands.end;
            }
            self.scenes.push(s);
        }
        (self.statuses, self.max_error) =
            tally(self.islands.iter().map(|i| (i.status(), i.error())));
        let friction = std::mem::take(&mut self.friction);
        self.set_friction(friction);
    }

    /// (status, count) of every status that occurs, in [`Status::ALL`] order.
    pub fn status_counts(&self) -> Vec<(Status, usize)> {
        nonzero_statuses(self.statuses)
    }

    /// Whether the GPU solved the batch.
    pub fn on_gpu(&self) -> bool {
        self.device.kind != DeviceKind::Cpu
    }
}

#[path = "report_display.rs"]
mod display;
#[path = "report_tally.rs"]
mod tally;
use tally::{add_tally, count_islands, nonzero_statuses, tally};
