//! Friction in the file formats: the JSON batch of frictional problems
//! (`{"friction_problems": [{"W": [[…]], "q": […], "mu": […]}]}`) and the
//! JSON output of frictional problems and of scenes with friction.

use serde::{Deserialize, Serialize};

use crate::friction::FrictionProblem;
use crate::report::{ContactImpulse, FrictionIslandReport};
use crate::Error;

/// One frictional problem in the JSON batch format: W as rows (3k × 3k,
/// interleaved per contact: normal, t₁, t₂), q (3k) and μ (k).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FrictionRecord {
    /// W, row by row.
    #[serde(rename = "W")]
    pub w: Vec<Vec<f64>>,
    /// q.
    pub q: Vec<f64>,
    /// μ per contact.
    pub mu: Vec<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FrictionFile {
    friction_problems: Vec<FrictionRecord>,
}

/// Parses `{"friction_problems": [...]}` (its top-level key decided the
/// shape) and checks every problem; errors name the file, or the problem
/// and its field.
pub(super) fn parse_friction_json(
    path: &str,
    value: serde_json::Value,
) -> Result<Vec<FrictionProblem>, Error> {
    let file = FrictionFile::deserialize(&value).map_err(|e| {
        // Name the problem and the field (a misspelt key as unknown, not its
        // correct spelling as missing); serde's words where that finds nothing.
        let fields: [(&str, bool, super::FieldCheck); 3] = [
            ("W", true, super::rows),
            ("q", true, super::numbers),
            ("mu", true, super::numbers),
        ];
        super::check_problems(path, &value, "friction_problems", &fields)
            .unwrap_or_else(|| Error::invalid(path, "friction_problems", e.to_string()))
    })?;
    if file.friction_problems.is_empty() {
        return Err(Error::invalid(path, "friction_problems", "empty list"));
    }
    file.friction_problems
        .into_iter()
        .enumerate()
        .map(|(i, p)| {
            let item = format_args!("problem {i}");
            let n = p.q.len();
            if let Some(r) = p.w.iter().position(|row| row.len() != n) {
                return Err(Error::invalid(
                    item,
                    format!("W[{r}]"),
                    format!(
                        "has {} entries, expected 3k = {n} (the length of q)",
                        p.w[r].len()
                    ),
                ));
            }
            let problem = FrictionProblem {
                w: p.w.into_iter().flatten().collect(),
                q: p.q,
                mu: p.mu,
            };
            problem.validate(&item)?;
            Ok(problem)
        })
        .collect()
}

/// One frictional problem's (or island's) result in the output.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct FrictionOutput {
    /// The scene's contact indices in the order of the problem's contacts
    /// (absent for a batch of problems).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub contacts: Option<Vec<usize>>,
    /// The status's snake_case name: `solved`, `not_converged` or `numerical_failure`.
    pub status: String,
    /// The reactions, 3k, interleaved (normal, t₁, t₂ per contact).
    pub r: Vec<f64>,
    /// u = W r + q.
    pub u: Vec<f64>,
    /// Siconos' fc3d error (Coulomb, De Saxcé's correction).
    pub coulomb_error: f64,
    /// The cone complementarity residual ‖r − P_K(r − u)‖, normalised alike.
    pub cone_error: f64,
    /// max_i max(0, ‖r_t,i‖ − μ_i r_n,i).
    pub cone_violation: f64,
    /// max_i |r_i · ũ_i|.
    pub complementarity: f64,
    /// max_i max(0, −u_n,i).
    pub dual_cone_violation: f64,
    /// NSGS sweeps plus Newton steps.
    pub iterations: u64,
    /// The friction method: `auto`, `nsgs` or `newton`.
    pub solver: String,
}

impl FrictionOutput {
    /// The output of one frictional island (`contacts` only for scenes).
    pub fn of(isl: &FrictionIslandReport) -> Self {
        let s = &isl.solution;
        FrictionOutput {
            contacts: isl.scene.map(|_| isl.contacts.clone()),
            status: s.status.name().to_string(),
            r: s.r.clone(),
            u: s.u.clone(),
            coulomb_error: s.residuals.coulomb_error,
            cone_error: s.residuals.cone_error,
            cone_violation: s.residuals.cone_violation,
            complementarity: s.residuals.complementarity,
            dual_cone_violation: s.residuals.dual_cone_violation,
            iterations: s.iterations,
            solver: s.method.name().to_string(),
        }
    }
}

/// `{"friction_problems": [...]}`: one entry per problem, in the input's order.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct FrictionBatchOutput {
    /// One entry per problem.
    pub friction_problems: Vec<FrictionOutput>,
}

impl FrictionBatchOutput {
    /// The output of a frictional batch's report.
    pub fn of(report: &crate::Report) -> Self {
        FrictionBatchOutput {
            friction_problems: report.friction.iter().map(FrictionOutput::of).collect(),
        }
    }
}

/// A contact's frictional output: its [`ContactImpulse`].
pub type ContactFrictionOutput = ContactImpulse;
