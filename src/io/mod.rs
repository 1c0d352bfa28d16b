//! File formats: scenes and LCP batches in JSON, Siconos `.dat` LCPs, and the
//! JSON output. Field names are fixed so that other tools can write and read
//! them (see the README).

pub mod siconos;

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::cpu::impulses::BodyVelocity;
use crate::lcp::{Lcp, LcpSolution, SolutionSet};
use crate::pipeline::SceneSolution;
use crate::scene::Scene;
use crate::Error;

/// What an input file holds.
#[derive(Clone, Debug, PartialEq)]
pub enum Input {
    /// One scene (`{"bodies", "contacts"}`) or many (`{"scenes": [...]}`).
    Scenes(Vec<Scene>),
    /// LCPs: a JSON batch or one Siconos `.dat` problem.
    Lcps(Vec<Lcp>),
}

/// One LCP in the JSON batch format: M as rows.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LcpRecord {
    #[serde(rename = "M")]
    pub m: Vec<Vec<f64>>,
    pub q: Vec<f64>,
}

#[derive(Deserialize)]
#[serde(untagged)]
enum JsonInput {
    Batch { problems: Vec<LcpRecord> },
    Scenes { scenes: Vec<Scene> },
    Scene(Scene),
}

/// Parses JSON text holding a scene, `{"scenes": [...]}` or
/// `{"problems": [...]}`, and checks every item. `path` names the file in errors.
pub fn parse_json(path: &str, text: &str) -> Result<Input, Error> {
    // Parse as a generic value first so that syntax errors keep their position,
    // then pick the shape by its top-level key, so that a field error names it.
    let value: serde_json::Value = serde_json::from_str(text).map_err(|e| Error::json(path, e))?;
    let shape_err = |what: &str, e: serde_json::Error| Error::Json {
        path: path.to_string(),
        line: 0,
        column: 0,
        message: format!("{what}: {e}"),
    };
    let Some(obj) = value.as_object() else {
        return Err(Error::invalid(
            path,
            "(top level)",
            "expected a JSON object",
        ));
    };
    let input = if obj.contains_key("problems") {
        let batch: BatchFile =
            serde_json::from_value(value).map_err(|e| shape_err("LCP batch", e))?;
        JsonInput::Batch {
            problems: batch.problems,
        }
    } else if obj.contains_key("scenes") {
        let s: ScenesFile = serde_json::from_value(value).map_err(|e| shape_err("scenes", e))?;
        JsonInput::Scenes { scenes: s.scenes }
    } else if obj.contains_key("bodies") || obj.contains_key("contacts") {
        JsonInput::Scene(serde_json::from_value(value).map_err(|e| shape_err("scene", e))?)
    } else {
        return Err(Error::invalid(
            path,
            "(top level)",
            "expected a key `problems` (LCP batch), `scenes` or `bodies` and `contacts` (scene)",
        ));
    };
    match input {
        JsonInput::Batch { problems } => {
            if problems.is_empty() {
                return Err(Error::invalid(path, "problems", "empty list"));
            }
            let lcps = problems
                .into_iter()
                .enumerate()
                .map(|(i, p)| {
                    Lcp::from_rows(&p.m, p.q).map_err(|e| match e {
                        Error::Invalid { field, reason, .. } => {
                            Error::invalid(format!("problem {i}"), field, reason)
                        }
                        other => other,
                    })
                })
                .collect::<Result<Vec<_>, _>>()?;
            Ok(Input::Lcps(lcps))
        }
        JsonInput::Scenes { scenes } => {
            if scenes.is_empty() {
                return Err(Error::invalid(path, "scenes", "empty list"));
            }
            for (i, s) in scenes.iter().enumerate() {
                s.validate(&format!("scene {i}"))?;
            }
            Ok(Input::Scenes(scenes))
        }
        JsonInput::Scene(scene) => {
            scene.validate("scene 0")?;
            Ok(Input::Scenes(vec![scene]))
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BatchFile {
    problems: Vec<LcpRecord>,
}

#[derive(Deserialize)]
struct ScenesFile {
    scenes: Vec<Scene>,
}

/// Reads an input file: `.dat` as Siconos, anything else as JSON.
pub fn read_input(path: &Path) -> Result<Input, Error> {
    let text = std::fs::read_to_string(path).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let name = path.display().to_string();
    if path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("dat"))
    {
        Ok(Input::Lcps(vec![siconos::parse_dat(&name, &text)?]))
    } else {
        parse_json(&name, &text)
    }
}

/// One LCP result in the output file.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct LcpOutput {
    pub status: String,
    pub z: Vec<f64>,
    pub w: Vec<f64>,
    pub error: f64,
    pub min_z: f64,
    pub min_w: f64,
    pub max_complementarity: f64,
    /// Indices i with z_i basic, when the solver works with bases.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub basis: Option<Vec<usize>>,
    pub solver: String,
    pub bases_visited: u64,
    pub pivots: u64,
    pub iterations: u64,
    /// With --all-solutions: the whole solution set and every distinct solution.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub solution_set: Option<SolutionSet>,
    #[serde(skip_serializing_if = "Vec::is_empty", default)]
    pub solutions: Vec<Vec<f64>>,
}

/// Basis mask as a list of indices.
pub fn basis_indices(mask: u32, n: usize) -> Vec<usize> {
    (0..n.min(32)).filter(|&i| mask >> i & 1 == 1).collect()
}

impl LcpOutput {
    pub fn new(solver: &str, sol: &LcpSolution) -> Self {
        let n = sol.z.len();
        LcpOutput {
            status: sol.status.name().to_string(),
            z: sol.z.clone(),
            w: sol.w.clone(),
            error: sol.residuals.error,
            min_z: sol.residuals.min_z,
            min_w: sol.residuals.min_w,
            max_complementarity: sol.residuals.max_complementarity,
            basis: sol.basis.map(|m| basis_indices(m, n)),
            solver: solver.to_string(),
            bases_visited: sol.counters.bases_visited,
            pivots: sol.counters.pivots,
            iterations: sol.counters.iterations,
            solution_set: sol.solution_set.clone(),
            solutions: crate::cpu::enumeration::distinct_solutions(&sol.all_bases)
                .into_iter()
                .map(|b| b.z.clone())
                .collect(),
        }
    }
}

/// `{"problems": [...]}`.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct LcpBatchOutput {
    pub problems: Vec<LcpOutput>,
}

/// One contact's result.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ContactOutput {
    pub impulse: f64,
}

/// One island's result.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct IslandOutput {
    pub contacts: Vec<usize>,
    pub status: String,
    pub error: f64,
    pub solver: String,
}

/// One scene's result.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct SceneOutput {
    pub contacts: Vec<ContactOutput>,
    pub bodies: Vec<BodyVelocity>,
    pub islands: Vec<IslandOutput>,
}

impl SceneOutput {
    pub fn new(sol: &SceneSolution) -> Self {
        SceneOutput {
            contacts: sol
                .impulses
                .iter()
                .map(|&impulse| ContactOutput { impulse })
                .collect(),
            bodies: sol.bodies.clone(),
            islands: sol
                .islands
                .iter()
                .map(|r| IslandOutput {
                    contacts: r.contacts.clone(),
                    status: r.solution.status.name().to_string(),
                    error: r.solution.residuals.error,
                    solver: r.solver.name().to_string(),
                })
                .collect(),
        }
    }
}

/// `{"scenes": [...]}`, also for a single scene.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ScenesOutput {
    pub scenes: Vec<SceneOutput>,
}

/// Writes `text` to `path` atomically: a temporary file beside it, renamed
/// into place, so that a failure leaves no partial output.
pub fn write_atomically(path: &Path, text: &str) -> Result<(), Error> {
    let io = |source| Error::Io {
        path: path.to_path_buf(),
        source,
    };
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let file_name = path
        .file_name()
        .ok_or_else(|| Error::invalid("-o", "path", "names no file"))?;
    let tmp = dir.join(format!(
        ".{}.tmp{}",
        file_name.to_string_lossy(),
        std::process::id()
    ));
    std::fs::write(&tmp, text).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        io(e)
    })?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        io(e)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shapes_are_recognised_and_errors_named() {
        let s = r#"{"problems":[{"M":[[2,1],[1,2]],"q":[-5,-6]}]}"#;
        assert!(matches!(parse_json("t", s).unwrap(), Input::Lcps(v) if v.len() == 1));
        let s = r#"{"problems":[{"M":[[2,1],[1]],"q":[-5,-6]}]}"#;
        let e = parse_json("t", s).unwrap_err().to_string();
        assert!(e.contains("problem 0") && e.contains("M[1]"), "{e}");
        let scene = r#"{"bodies":[{"inv_mass":1,"inv_inertia":[[1,0,0],[0,1,0],[0,0,1]],"position":[0,1,0],"velocity":[0,-1,0],"angular_velocity":[0,0,0]}],
            "contacts":[{"a":0,"b":null,"point":[0,0,0],"normal":[0,1,0],"restitution":0.5}]}"#;
        assert!(matches!(parse_json("t", scene).unwrap(), Input::Scenes(v) if v.len() == 1));
        let bad = scene.replace("\"a\":0", "\"a\":3");
        let e = parse_json("t", &bad).unwrap_err().to_string();
        assert!(e.contains("scene 0, contact 0") && e.contains("`a`"), "{e}");
        let e = parse_json("t", "{\"problems\": [").unwrap_err().to_string();
        assert!(e.contains("line 1"), "{e}");
        let e = parse_json("t", r#"{"bodies":[{"inv_mass":"x"}],"contacts":[]}"#)
            .unwrap_err()
            .to_string();
        assert!(e.contains("inv_mass") || e.contains("invalid type"), "{e}");
    }
}
