//! The one composition of the WGSL that runs (test builds only): from the
//! sources in `shaders/` to the committed files in `shaders/generated/`.
//!
//! Per [`Shader`] and precision: the enumeration kernels get
//! `shaders/enumeration_basis.wgsl` prepended (WGSL has no include); the
//! lines marked `// HOST <what>` are replaced (scalar type; for the
//! specialised kernels the island size, and the tree kernel's confirmation
//! count); the placeholder functions of the specialised kernels are replaced
//! by generated straight-line code ([`super::unrolled`], [`super::tree`]).
//! Every step that cannot find what it replaces is an [`Error::Gpu`].

use super::tree::tree_pass_source;
use super::unroll_loops::unroll_marked_loops;
use super::unrolled::straight_line_solver;
use super::{Shader, FIXED_MAX_N, FRICTION_MAX_K};
use crate::cpu::enumeration_tree::{TreeSettings, TREE_MAX_N};
use crate::gpu::Precision;
use crate::Error;

const ENUMERATION_BASIS_WGSL: &str = include_str!("../../../shaders/enumeration_basis.wgsl");
const ENUMERATION_WGSL: &str = include_str!("../../../shaders/enumeration.wgsl");
const ENUMERATION_WORKGROUP_WGSL: &str =
    include_str!("../../../shaders/enumeration_workgroup.wgsl");
const ENUMERATION_TREE_WGSL: &str = include_str!("../../../shaders/enumeration_tree.wgsl");
const ENUMERATION_ALL_WGSL: &str = include_str!("../../../shaders/enumeration_all.wgsl");
const ENUMERATION_SETTLE_WGSL: &str = include_str!("../../../shaders/enumeration_settle.wgsl");
const LEMKE_WGSL: &str = include_str!("../../../shaders/lemke.wgsl");
const ASSEMBLY_WGSL: &str = include_str!("../../../shaders/assembly.wgsl");
const IMPULSES_WGSL: &str = include_str!("../../../shaders/impulses.wgsl");
const FRICTION_PROJECTED_WGSL: &str = include_str!("../../../shaders/friction_projected.wgsl");
const FRICTION_COMMON_WGSL: &str = include_str!("../../../shaders/friction_common.wgsl");
const FRICTION_PROJECTED_GLOBAL_WGSL: &str =
    include_str!("../../../shaders/friction_projected_global.wgsl");
const COLLIDE_WGSL: &str = include_str!("../../../shaders/collide.wgsl");
const COLLIDE_BOX_WGSL: &str = include_str!("../../../shaders/collide_box.wgsl");
const WORLD_STEP_WGSL: &str = include_str!("../../../shaders/world_step.wgsl");
const WORLD_COLLIDE_WGSL: &str = include_str!("../../../shaders/world_collide.wgsl");
const WORLD_BODIES_WGSL: &str = include_str!("../../../shaders/world_bodies.wgsl");
const WORLD_ASSEMBLE_WGSL: &str = include_str!("../../../shaders/world_assemble.wgsl");
const WORLD_ISLAND_WGSL: &str = include_str!("../../../shaders/world_island.wgsl");
const WORLD_SOLVE_WGSL: &str = include_str!("../../../shaders/world_solve.wgsl");
const WORLD_LEMKE_WGSL: &str = include_str!("../../../shaders/world_lemke.wgsl");
const WORLD_LEMKE_CHECK_WGSL: &str = include_str!("../../../shaders/world_lemke_check.wgsl");
const WORLD_FINISH_WGSL: &str = include_str!("../../../shaders/world_finish.wgsl");
const WORLD_FRICTION_WGSL: &str = include_str!("../../../shaders/world_friction.wgsl");
const WORLD_SWEEPS_WGSL: &str = include_str!("../../../shaders/world_sweeps.wgsl");
const WORLD_APGD_WGSL: &str = include_str!("../../../shaders/world_apgd.wgsl");

/// The line of `shaders/collide.wgsl` that `shaders/collide_box.wgsl`
/// replaces (below its pair functions line).
const COLLIDE_BOX: &str = "// BOX-BOX: shaders/collide_box.wgsl\n";
/// Where `shaders/collide.wgsl`'s own stage starts: the world step kernel
/// takes the functions above it.
const COLLIDE_STAGE: &str = "// Stage `collide_pairs`.";
/// Where `shaders/collide.wgsl`'s pair functions start: the resident
/// step's solve and frictional modules take the functions above it.
const COLLIDE_PAIRS: &str = "// Pair functions";
/// Where `shaders/lemke.wgsl`'s own kernel starts: the world step kernel
/// takes the functions above it.
const LEMKE_KERNEL: &str = "// LEMKE KERNEL";
/// Where `shaders/friction_common.wgsl`'s cone projection starts (APGD's
/// scalar steps follow it): the world step kernel takes it from there.
const CONE_PROJECTION: &str = "// Siconos' fc3d projection on";

/// Largest island (contacts) whose friction kernels come from
/// `shaders/friction_projected.wgsl` (private copies, marked loops unrolled
/// by [`unroll_marked_loops`]); larger ones from
/// `shaders/friction_projected_global.wgsl` (loops over the buffers: their
/// unrolled code compiles too slowly on lavapipe: 52 s for the k = 8 APGD
/// kernel against about 5 s at k = 4, measured).
const FRICTION_UNROLL_MAX_K: usize = 4;

/// Environment variable that makes `generated_shaders_are_committed`
/// rewrite the committed files instead of failing.
const BLESS: &str = "LCPBATCH_BLESS_SHADERS";

/// The complete text of `shader` in `precision` (F32 or F64), as committed
/// in `shaders/generated/`.
pub(super) fn compose(shader: Shader, precision: Precision) -> Result<String, Error> {
    if !COLLIDE_WGSL.contains(COLLIDE_BOX) {
        return Err(Error::Gpu(format!(
            "collide.wgsl has no `{}` line",
            COLLIDE_BOX.trim_end()
        )));
    }
    let collide = COLLIDE_WGSL.replacen(COLLIDE_BOX, COLLIDE_BOX_WGSL, 1);
    let (file, body) = match shader {
        Shader::Enumeration | Shader::Unrolled(_) => ("enumeration", ENUMERATION_WGSL),
        Shader::Workgroup => ("enumeration_workgroup", ENUMERATION_WORKGROUP_WGSL),
        Shader::Tree(_) => ("enumeration_tree", ENUMERATION_TREE_WGSL),
        Shader::AllBases => ("enumeration_all", ENUMERATION_ALL_WGSL),
        Shader::Settle => ("enumeration_settle", ENUMERATION_SETTLE_WGSL),
        Shader::Lemke => ("lemke", LEMKE_WGSL),
        Shader::Assembly => ("assembly", ASSEMBLY_WGSL),
        Shader::Impulses => ("impulses", IMPULSES_WGSL),
        Shader::FrictionProjected(k) if k <= FRICTION_UNROLL_MAX_K => {
            ("friction_projected", FRICTION_PROJECTED_WGSL)
        }
        Shader::FrictionProjected(_) => {
            ("friction_projected_global", FRICTION_PROJECTED_GLOBAL_WGSL)
        }
        Shader::Collide => ("collide", collide.as_str()),
        Shader::WorldCollide => ("world_collide", WORLD_COLLIDE_WGSL),
        Shader::WorldAssemble => ("world_assemble", WORLD_ASSEMBLE_WGSL),
        Shader::WorldSolve => ("world_solve", WORLD_SOLVE_WGSL),
        Shader::WorldLemke => ("world_lemke", WORLD_LEMKE_WGSL),
        Shader::WorldLemkeCheck => ("world_lemke_check", WORLD_LEMKE_CHECK_WGSL),
        Shader::WorldFriction | Shader::WorldFrictionApgd => {
            ("world_friction", WORLD_FRICTION_WGSL)
        }
        Shader::WorldFinish => ("world_finish", WORLD_FINISH_WGSL),
    };
    // The resident solve, frictional and finish modules start alike: the
    // functions above collide.wgsl's pair functions and lemke.wgsl's, the
    // step's header, the bodies' velocities.
    let world_head = || -> Result<String, Error> {
        Ok(format!(
            "{}\n{}\n{WORLD_STEP_WGSL}\n{WORLD_BODIES_WGSL}",
            text_before(COLLIDE_WGSL, COLLIDE_PAIRS)?,
            text_before(LEMKE_WGSL, LEMKE_KERNEL)?
        ))
    };
    let standalone = matches!(
        shader,
        Shader::Assembly | Shader::Impulses | Shader::FrictionProjected(_) | Shader::Collide
    );
    let src = match shader {
        Shader::FrictionProjected(_) => format!("{FRICTION_COMMON_WGSL}\n{body}"),
        Shader::WorldCollide => format!(
            "{}\n{WORLD_STEP_WGSL}\n{body}",
            text_before(&collide, COLLIDE_STAGE)?
        ),
        Shader::WorldSolve | Shader::WorldLemke | Shader::WorldLemkeCheck => {
            format!("{}\n{WORLD_ISLAND_WGSL}\n{body}", world_head()?)
        }
        Shader::WorldAssemble | Shader::WorldFinish => format!("{}\n{body}", world_head()?),
        Shader::WorldFriction | Shader::WorldFrictionApgd => format!(
            "{}\n{body}\n{}\n{}",
            world_head()?,
            match shader {
                Shader::WorldFriction => WORLD_SWEEPS_WGSL,
                _ => WORLD_APGD_WGSL,
            },
            text_from(FRICTION_COMMON_WGSL, CONE_PROJECTION)?
        ),
        _ if standalone => body.to_string(),
        _ => format!("{ENUMERATION_BASIS_WGSL}\n{body}"),
    };
    let ty = match precision {
        Precision::F32 => "f32",
        Precision::F64 => "f64",
        Precision::Auto => return Err(Error::Gpu("compose: precision not resolved".into())),
    };
    let s = replace_host_line(&src, "scalar", &format!("alias Scalar = {ty};"))?;
    let s = match shader {
        Shader::Unrolled(n) if (1..=FIXED_MAX_N).contains(&n) => fixed_source(&s, n)?,
        Shader::Tree(n) if (1..=TREE_MAX_N).contains(&n) => tree_source(&s, n)?,
        // The friction kernels: the island size k, and the scalar type's limits
        // (finiteness and rounding tests).
        Shader::FrictionProjected(k) if (1..=FRICTION_MAX_K).contains(&k) => {
            let s = replace_host_line(&s, "fixed_k", &format!("const FIXED_K: u32 = {k}u;"))?;
            let s = with_scalar_limits(&s, precision)?;
            let n = 3 * k as u64;
            // The vec4 counts of shaders/friction_projected.wgsl (its
            // VALUES4, APGD4, X4, SWEEPS4: the same formulas).
            let k4 = k as u64;
            let constants = [
                ("N", n),
                ("NN", n * n),
                ("FIXED_K", k4),
                ("VALUES4", (n * n + n + k4).div_ceil(4)),
                ("APGD4", (5 * n).div_ceil(4)),
                ("X4", n.div_ceil(4)),
                ("SWEEPS4", k4),
            ];
            unroll_marked_loops(&s, &constants, true)?
        }
        // The world step: Lemke's finiteness tests and the error measure's
        // epsilon (lcp_error's f64::EPSILON); the collision phase has no
        // Lemke.
        Shader::WorldAssemble
        | Shader::WorldSolve
        | Shader::WorldLemke
        | Shader::WorldLemkeCheck
        | Shader::WorldFriction
        | Shader::WorldFrictionApgd
        | Shader::WorldFinish => with_scalar_limits(&s, precision)?,
        Shader::WorldCollide => replace_host_line(
            &s,
            "scalar_epsilon",
            &format!(
                "const SCALAR_EPSILON: Scalar = {};",
                scalar_limits(precision).1
            ),
        )?,
        // Lemke: the scalar type's largest finite value (finiteness tests).
        Shader::Lemke => {
            let max = scalar_limits(precision).0;
            replace_host_line(
                &s,
                "scalar_max",
                &format!("const SCALAR_MAX: Scalar = {max};"),
            )?
        }
        Shader::Unrolled(n) | Shader::Tree(n) | Shader::FrictionProjected(n) => {
            return Err(Error::Gpu(format!(
                "{}: no kernel for n = {n}",
                shader.name()
            )))
        }
        _ => s,
    };
    // The narrow phase: every index into a manifold or a polygon a
    // constant (shaders/collide.wgsl, push_hit).
    let s = match shader {
        Shader::Collide | Shader::WorldCollide => {
            unroll_marked_loops(&s, &[("CAPACITY", 8), ("SLOTS", 4)], true)?
        }
        _ => s,
    };
    let from = match shader {
        Shader::FrictionProjected(_) => {
            format!("shaders/friction_common.wgsl + shaders/{file}.wgsl")
        }
        Shader::Collide => "shaders/collide.wgsl + shaders/collide_box.wgsl".to_string(),
        _ if standalone => format!("shaders/{file}.wgsl"),
        Shader::WorldCollide => "shaders/collide.wgsl (functions) + shaders/collide_box.wgsl + \
             shaders/world_step.wgsl + shaders/world_collide.wgsl"
            .to_string(),
        Shader::WorldSolve | Shader::WorldLemke | Shader::WorldLemkeCheck => format!(
            "shaders/collide.wgsl (functions above its pair functions) + \
             shaders/lemke.wgsl (functions) + shaders/world_step.wgsl + shaders/world_bodies.wgsl + \
             shaders/world_island.wgsl + shaders/{file}.wgsl"
        ),
        Shader::WorldAssemble | Shader::WorldFinish => format!(
            "shaders/collide.wgsl (functions above its pair functions) + \
             shaders/lemke.wgsl (functions) + shaders/world_step.wgsl + shaders/world_bodies.wgsl + \
             shaders/{file}.wgsl"
        ),
        Shader::WorldFriction | Shader::WorldFrictionApgd => format!(
            "shaders/collide.wgsl (functions above its pair functions) + \
             shaders/lemke.wgsl (functions) + shaders/world_step.wgsl + shaders/world_bodies.wgsl + \
             shaders/world_friction.wgsl + shaders/world_{}.wgsl + shaders/friction_common.wgsl \
             (project_on_cone on)",
            match shader {
                Shader::WorldFriction => "sweeps",
                _ => "apgd",
            }
        ),
        _ => format!("shaders/enumeration_basis.wgsl + shaders/{file}.wgsl"),
    };
    Ok(format!(
        "// GENERATED from {from} by src/gpu/shaders/compose.rs: do not edit.\n\
         // Regenerate: {BLESS}=1 cargo test --release generated_shaders_are_committed\n\n{s}\n"
    ))
}

/// The largest finite value and the machine epsilon of `precision`'s
/// scalar (F32 or F64; composition has already refused Auto), as WGSL
/// literals.
fn scalar_limits(precision: Precision) -> (&'static str, &'static str) {
    if precision == Precision::F64 {
        ("1.7976931348623157e308", "2.220446049250313e-16")
    } else {
        ("3.4028234663852886e38", "1.1920929e-7")
    }
}

/// `src` with its `// HOST scalar_max` and `// HOST scalar_epsilon` lines
/// set to `precision`'s largest finite value and epsilon.
fn with_scalar_limits(src: &str, precision: Precision) -> Result<String, Error> {
    let (max, eps) = scalar_limits(precision);
    let s = replace_host_line(
        src,
        "scalar_max",
        &format!("const SCALAR_MAX: Scalar = {max};"),
    )?;
    replace_host_line(
        &s,
        "scalar_epsilon",
        &format!("const SCALAR_EPSILON: Scalar = {eps};"),
    )
}

/// The text of `src` before its line `marker`.
fn text_before<'a>(src: &'a str, marker: &str) -> Result<&'a str, Error> {
    src.find(marker)
        .map(|at| &src[..at])
        .ok_or_else(|| Error::Gpu(format!("shader has no `{marker}` line")))
}

/// The text of `src` from its line `marker` on.
fn text_from<'a>(src: &'a str, marker: &str) -> Result<&'a str, Error> {
    src.find(marker)
        .map(|at| &src[at..])
        .ok_or_else(|| Error::Gpu(format!("shader has no `{marker}` line")))
}

/// Replaces the `// HOST <what>` line of `src` with `line`.
fn replace_host_line(src: &str, what: &str, line: &str) -> Result<String, Error> {
    let marker = format!("// HOST {what}");
    let mut found = false;
    let out: Vec<String> = src
        .lines()
        .map(|l| {
            if l.trim_end().ends_with(&marker) {
                found = true;
                format!("{line} {marker}")
            } else {
                l.to_string()
            }
        })
        .collect();
    if !found {
        return Err(Error::Gpu(format!("shader has no `{marker}` line")));
    }
    Ok(out.join("\n"))
}

/// Replaces the WGSL function `name` of `src` (from `fn name(` to the first
/// line that is a lone `}`) with `function`.
fn replace_function(src: &str, name: &str, function: &str) -> Result<String, Error> {
    let start = src
        .find(&format!("fn {name}("))
        .ok_or_else(|| Error::Gpu(format!("shader has no function {name}")))?;
    let end = src[start..]
        .find("\n}\n")
        .map(|e| start + e + 3)
        .ok_or_else(|| Error::Gpu(format!("function {name} has no end")))?;
    Ok(format!("{}{function}{}", &src[..start], &src[end..]))
}

/// `shaders/enumeration.wgsl` specialised to islands of exactly n contacts:
/// FIXED, FN, FNN set, and `solve_basis_fixed` replaced by
/// [`straight_line_solver`] (no loops, every array index constant).
fn fixed_source(enumeration_src: &str, n: usize) -> Result<String, Error> {
    let s = replace_host_line(enumeration_src, "fixed", "const FIXED: bool = true;")?;
    let s = replace_host_line(&s, "fixed_n", &format!("const FN: u32 = {n}u;"))?;
    let s = replace_host_line(&s, "fixed_nn", &format!("const FNN: u32 = {}u;", n * n))?;
    replace_function(&s, "solve_basis_fixed", &straight_line_solver(n))
}

/// `shaders/enumeration_tree.wgsl` for islands of exactly n contacts: FN,
/// WORDS and MAX_CONFIRMATIONS ([`TreeSettings`]' default) set, and the
/// placeholder `tree_pass` replaced by [`tree_pass_source`].
fn tree_source(tree_src: &str, n: usize) -> Result<String, Error> {
    let confirmations = TreeSettings::default().max_confirmations;
    let s = replace_host_line(
        tree_src,
        "max_confirmations",
        &format!("const MAX_CONFIRMATIONS: u32 = {confirmations}u;"),
    )?;
    let s = replace_host_line(&s, "fixed_n", &format!("const FN: u32 = {n}u;"))?;
    let s = replace_host_line(
        &s,
        "words",
        &format!("const WORDS: u32 = {}u;", (1usize << n).div_ceil(32)),
    )?;
    replace_function(&s, "tree_pass", &tree_pass_source(n))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    const PRECISIONS: [Precision; 2] = [Precision::F32, Precision::F64];

    /// The committed files are exactly what the generator makes, the table
    /// compiled into the binary holds every one of them and nothing else.
    #[test]
    fn generated_shaders_are_committed() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let bless = std::env::var(BLESS).is_ok_and(|v| v == "1");
        let mut stale = Vec::new();
        let mut expected = Vec::new();
        for shader in Shader::all() {
            for p in PRECISIONS {
                let text = compose(shader, p).unwrap_or_else(|e| panic!("{shader:?}: {e}"));
                let path = shader.path(p);
                expected.push(path.clone());
                let file = root.join(&path);
                if std::fs::read_to_string(&file).ok().as_deref() != Some(text.as_str()) {
                    if bless {
                        std::fs::write(&file, &text).unwrap();
                    } else {
                        stale.push(path);
                    }
                } else if shader.source(p).ok() != Some(text.as_str()) {
                    stale.push(format!("{path} (rebuild: the binary holds an older copy)"));
                }
            }
        }
        let mut extra: Vec<String> = std::fs::read_dir(root.join("shaders/generated"))
            .unwrap()
            .map(|e| {
                format!(
                    "shaders/generated/{}",
                    e.unwrap().file_name().to_string_lossy()
                )
            })
            .filter(|p| !expected.contains(p))
            .collect();
        extra.sort();
        assert!(
            stale.is_empty() && extra.is_empty(),
            "generated shaders out of date: {stale:?}; not generated: {extra:?}. \
             Regenerate with `{BLESS}=1 cargo test --release generated_shaders_are_committed` \
             (and delete the files not generated)"
        );
        let names: Vec<String> = Shader::all().iter().map(|s| s.name()).collect();
        let table: Vec<String> = super::super::GENERATED
            .iter()
            .map(|(n, _, _)| n.to_string())
            .collect();
        assert_eq!(names, table, "shaders::GENERATED lists every Shader::all()");
    }

    /// Every generated shader parses and validates with naga (f64 allowed).
    #[test]
    fn generated_shaders_validate_with_naga() {
        use naga::valid::{Capabilities, ValidationFlags, Validator};
        for shader in Shader::all() {
            for p in PRECISIONS {
                let src = shader.source(p).unwrap();
                let module = naga::front::wgsl::parse_str(src)
                    .unwrap_or_else(|e| panic!("{}: {}", shader.path(p), e.emit_to_string(src)));
                Validator::new(ValidationFlags::all(), Capabilities::FLOAT64)
                    .validate(&module)
                    .unwrap_or_else(|e| panic!("{}: {e:?}", shader.path(p)));
            }
        }
    }

    #[test]
    fn composition_errors_are_errors() {
        assert!(replace_host_line("fn main() {}", "scalar", "x").is_err());
        assert!(replace_function("fn main() {}", "tree_pass", "x").is_err());
        assert!(compose(Shader::Unrolled(FIXED_MAX_N + 1), Precision::F32).is_err());
        assert!(compose(Shader::Tree(0), Precision::F64).is_err());
        assert!(compose(Shader::Enumeration, Precision::Auto).is_err());
        let s = compose(Shader::Unrolled(3), Precision::F64).unwrap();
        assert!(s.contains("alias Scalar = f64; // HOST scalar"));
        assert!(s.contains("const FN: u32 = 3u; // HOST fixed_n"));
        assert!(!s.contains("_TOL"), "tolerances come from the uniform");
    }
}
