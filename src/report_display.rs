//! The report in words: what `lcpbatch solve` prints on stderr.

use std::fmt;

use super::{nonzero_statuses, Report};

impl fmt::Display for Report {
    /// A few lines: device and why, islands per path, statuses, the largest
    /// error (with the island that has it) and time per phase.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "device: {} ({})", self.device.name, self.choice)?;
        if let Some(why) = &self.fallback {
            writeln!(f, "GPU trouble, solved on the CPU: {why}")?;
        }
        let paths: Vec<String> = self
            .counts
            .nonzero()
            .iter()
            .map(|(n, c)| format!("{n} {c}"))
            .collect();
        writeln!(f, "{} islands: {}", self.islands.len(), paths.join(", "))?;
        let statuses: Vec<String> = self
            .status_counts()
            .iter()
            .map(|(s, c)| format!("{s} {c}"))
            .collect();
        writeln!(f, "statuses: {}", statuses.join(", "))?;
        match self.max_error {
            Some((e, i)) => writeln!(f, "max error: {e:.3e} (island {i})")?,
            None => writeln!(f, "max error: none (no island has a solution)")?,
        }
        if !self.friction.is_empty() {
            let statuses: Vec<String> = nonzero_statuses(self.friction_statuses)
                .iter()
                .map(|(s, c)| format!("{s} {c}"))
                .collect();
            // Where they ran, in the solver's words: every path ends `choice`
            // with "friction: <method> on the CPU (why)" or "… on the GPU",
            // then its counts; the first clause is that. Wherever they ran,
            // each answer's Coulomb error was computed in f64.
            let went = self
                .choice
                .rsplit_once("friction: ")
                .map(|(_, w)| w.split(", ").next().unwrap_or(w))
                .filter(|w| !w.is_empty());
            match went {
                Some(went) => write!(
                    f,
                    "{} frictional islands ({went}; checked in f64): ",
                    self.friction.len()
                )?,
                None => write!(
                    f,
                    "{} frictional islands (checked in f64): ",
                    self.friction.len()
                )?,
            }
            writeln!(f, "{}", statuses.join(", "))?;
            match self.max_coulomb_error {
                Some((e, i)) => writeln!(f, "max Coulomb error: {e:.3e} (frictional island {i})")?,
                None => writeln!(f, "max Coulomb error: none (no frictional island solved)")?,
            }
        }
        if let Some(g) = &self.gpu {
            writeln!(
                f,
                "gpu: {} chunk(s), {} dispatch(es), {} round(s), tree {} decided / {} undecided, max error before polish {:.3e}",
                g.chunks, g.dispatches, g.rounds, g.tree_decided, g.tree_undecided, g.max_gpu_error
            )?;
        }
        let t = &self.timings;
        write!(
            f,
            "time: total {:.3} s (build {:.3}, prediction {:.3}, gpu {:.3}, validation {:.3}, solve {:.3}, impulses {:.3})",
            t.total, t.build, t.prediction, t.gpu, t.validation, t.solve, t.impulses
        )
    }
}
