//! What the phases read of the [`Solver`](super::Solver) ([`SolverView`]).

use super::device::cpu_device;
use crate::report::{Device, IslandReport, Report, SceneReport};
use crate::settings::Settings;
use crate::warm::Warm;

/// What the phases (free functions in the modules of `src/solver/`) read
/// of the [`Solver`](super::Solver), borrowed for one phase: the settings,
/// the thread count, the warm-start memory, and the words every report
/// carries (why this device, why the CPU took over). The solver itself
/// stays with the conductor (its methods in `mod.rs`), which alone opens
/// or drops the device and records into the warm-start memory.
#[derive(Clone, Copy)]
pub(super) struct SolverView<'a> {
    pub(super) settings: &'a Settings,
    pub(super) threads: usize,
    pub(super) warm: &'a Warm,
    pub(super) choice: &'a str,
    pub(super) fallback: Option<&'a str>,
}

impl SolverView<'_> {
    /// The report of `islands` (already through
    /// [`check_solution`](super::check_solution)) and `scenes` on `device`,
    /// with the solver's choice and fallback reason.
    pub(super) fn report(
        &self,
        islands: Vec<IslandReport>,
        scenes: Vec<SceneReport>,
        device: Device,
    ) -> Report {
        let mut r = Report::new(islands, scenes, device, self.choice.to_string());
        r.fallback = self.fallback.map(str::to_string);
        r
    }

    /// The CPU path as a device.
    pub(super) fn cpu_device(&self) -> Device {
        cpu_device(self.threads)
    }

    /// The warm basis remembered for an island's contact ids (None without
    /// `settings.warm_start` or without ids).
    pub(super) fn warm_basis(&self, ids: &[u64]) -> Option<u32> {
        if !self.settings.warm_start || ids.is_empty() {
            return None;
        }
        self.warm.bases.basis(ids.iter().map(|&id| Some(id)))
    }
}
