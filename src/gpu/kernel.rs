//! Kernel choice: which enumeration shader runs islands of each size, the
//! tree kernel's route per island, and the loop-work budget per round.

use super::batch::GpuSolveSettings;
use super::shaders::FIXED_MAX_N;
use super::GpuContext;
use crate::cpu::enumeration_tree::TREE_MAX_N;
use crate::lcp::Lcp;
use crate::prediction::{is_positive_definite, is_positive_semidefinite};
use crate::settings::Method;

pub use crate::settings::EnumerationKernel;

impl EnumerationKernel {
    /// The kernel that runs islands of n contacts.
    /// For [`EnumerationKernel::Tree`]: the kernel after the tree (the tree
    /// itself is chosen per island, [`KernelPlan::tree_for`]).
    pub fn for_n(self, n: usize) -> EnumerationKernel {
        match self {
            EnumerationKernel::Auto | EnumerationKernel::Tree => {
                if WORKGROUP_FROM_N.is_some_and(|w| n >= w) {
                    EnumerationKernel::Workgroup
                } else if n <= UNROLLED_UP_TO_N {
                    EnumerationKernel::Unrolled
                } else {
                    EnumerationKernel::Elimination
                }
            }
            EnumerationKernel::Unrolled if n > FIXED_MAX_N => EnumerationKernel::Elimination,
            k => k,
        }
    }
}

/// Auto: the specialised straight-line elimination kernel up to this island
/// size (on lavapipe 1.14–1.97× the looped kernel's islands/s at n = 1…7,
/// 1.07–1.15× at n = 8: not clearly faster there; BENCHMARKS.md).
pub const UNROLLED_UP_TO_N: usize = 7;
/// Auto: the workgroup kernel (one workgroup per island) from this island
/// size on. On lavapipe (2 cores, 128 islands of one size per batch) it
/// measured 0.70–0.75× the per-island elimination kernel's islands/s at
/// n = 8, 0.94× (f64) and 1.39× (f32) at n = 9, and was faster in every
/// run from n = 10 on: 1.02–1.10× at 10, 1.2–1.7× at 11…16 (BENCHMARKS.md).
/// Its 64 lanes solve bases of one size side by side, where the per-island
/// kernel's lanes diverge (each island stops at a different basis).
pub const WORKGROUP_FROM_N: Option<usize> = Some(10);
/// Auto: positive definite and semidefinite islands of n ≤
/// [`GpuSolveSettings::tree_max_n`] go to the tree kernel first (on lavapipe
/// 2–25× the islands/s of Auto's other kernels at n = 6…12 on definite
/// islands, 17–33× end to end on resting stacks; BENCHMARKS.md). Its first dispatch per size
/// compiles for 1.5 s (n = 6) to 9 s (n = 12) on lavapipe without Mesa's
/// shader cache, once per process.
pub const AUTO_TREE: bool = true;

/// Loop work per invocation and round on software adapters: llvmpipe ends
/// every loop of an invocation after about 65,535 iterations in all.
pub const SOFTWARE_ROUND_BUDGET: u32 = 48_000;
/// Loop work per invocation and round on hardware (bounds one dispatch's time).
pub const HARDWARE_ROUND_BUDGET: u32 = 1 << 22;

/// Loop work per invocation and round for this adapter and these settings.
pub(crate) fn round_budget(ctx: &GpuContext, settings: &GpuSolveSettings) -> u32 {
    let default = if ctx.adapter_info().software {
        SOFTWARE_ROUND_BUDGET
    } else {
        HARDWARE_ROUND_BUDGET
    };
    settings.round_budget.unwrap_or(default).max(1)
}

/// Which enumeration shader runs per size, and its per-round parameters.
#[derive(Clone, Copy, Debug)]
pub struct KernelPlan {
    /// Loop work per invocation and round.
    pub budget: u32,
    pub kernel: EnumerationKernel,
    /// Largest island for the tree kernel (≤ [`TREE_MAX_N`]).
    pub tree_max_n: usize,
    /// Every island to the Lemke kernel (`shaders/lemke.wgsl`) instead of
    /// the enumeration kernels: methods Auto and Lemke.
    pub lemke: bool,
}

impl KernelPlan {
    pub(crate) fn new(ctx: &GpuContext, settings: &GpuSolveSettings) -> Self {
        KernelPlan {
            budget: round_budget(ctx, settings),
            kernel: settings.kernel,
            tree_max_n: settings.tree_max_n.min(TREE_MAX_N),
            lemke: settings.method != Method::Enumeration,
        }
    }

    /// Does this island go to the tree kernel first, and how? Only when n ≤
    /// `tree_max_n` (and never with [`Self::lemke`]). Positive definite M (every pivot of the tree exists):
    /// [`TreeRoute::Definite`]; symmetric positive semidefinite M (resting
    /// contacts): [`TreeRoute::Semidefinite`]; both tested on the CPU in
    /// O(n³). Auto ([`AUTO_TREE`]) routes only these;
    /// [`EnumerationKernel::Tree`] sends the others too, as Definite.
    /// `definite`: whether M is positive definite, when the caller knows
    /// (prediction tests it; else it is tested here).
    pub fn tree_for(&self, lcp: &Lcp, definite: Option<bool>) -> TreeRoute {
        if self.lemke
            || lcp.n() > self.tree_max_n
            || !matches!(
                self.kernel,
                EnumerationKernel::Tree | EnumerationKernel::Auto
            )
            || (self.kernel == EnumerationKernel::Auto && !AUTO_TREE)
        {
            return TreeRoute::Off;
        }
        if definite.unwrap_or_else(|| is_positive_definite(lcp)) {
            TreeRoute::Definite
        } else if is_positive_semidefinite(lcp) {
            TreeRoute::Semidefinite
        } else if self.kernel == EnumerationKernel::Tree {
            TreeRoute::Definite
        } else {
            TreeRoute::Off
        }
    }
}

/// How an island goes through the tree kernel (`shaders/enumeration_tree.wgsl`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum TreeRoute {
    /// Not at all: Auto's kernel for its size.
    #[default]
    Off,
    /// A pivot at most the tree pivot tolerance leaves the island undecided.
    Definite,
    /// M is symmetric positive semidefinite: a pivot singular to working
    /// precision cuts its subtree (no basis below it is nonsingular).
    Semidefinite,
}
