//! Shaders, bind group layouts and pipelines, and the buffer plumbing every
//! stage shares (upload, dispatch in ranges, readback).
//!
//! The WGSL files are valid on their own with `Scalar = f32`, except the
//! three enumeration kernels, whose common part (scalar type, tolerances,
//! bindings 0-6, the elimination `solve_basis`) lives once in
//! `shaders/enumeration_basis.wgsl` and is prepended to each of them
//! ([`enumeration_source`]). The host templates the sources by replacing the
//! lines marked `// HOST ...` (scalar type and tolerances) when it builds a
//! pipeline. Pipelines are built once per (precision, tolerances) and cached
//! in the [`super::GpuContext`].

use std::sync::Arc;

use wgpu::util::DeviceExt;

use super::layout::Params;
use super::{GpuContext, Precision};
use crate::cpu::enumeration_tree::{TreeSettings, TREE_MAX_N};
use crate::Error;

/// The part every enumeration kernel shares (WGSL has no include):
/// prepended to each kernel's source by [`enumeration_source`].
pub const ENUMERATION_BASIS_WGSL: &str = include_str!("../../shaders/enumeration_basis.wgsl");
pub const ENUMERATION_WGSL: &str = include_str!("../../shaders/enumeration.wgsl");
pub const ENUMERATION_GRAY_WGSL: &str = include_str!("../../shaders/enumeration_gray.wgsl");
pub const ENUMERATION_WORKGROUP_WGSL: &str =
    include_str!("../../shaders/enumeration_workgroup.wgsl");
pub const ENUMERATION_TREE_WGSL: &str = include_str!("../../shaders/enumeration_tree.wgsl");

/// Gray-code kernel tolerances in f32 (f64 uses the CPU twin's,
/// [`crate::cpu::enumeration_gray::GraySettings`]): the screen is looser
/// than the f32 feasibility tolerance (1e-4) by more than the tableau's
/// measured drift, so that every basis f32 elimination accepts is screened
/// in; a principal pivot below 1e-3 of its row is replaced by a rebuild.
pub const F32_SCREEN_TOL: f64 = 1e-3;
/// Largest island size with a specialised (constant-size) elimination kernel.
pub const FIXED_MAX_N: usize = 8;
pub const F32_TABLEAU_PIVOT_TOL: f64 = 1e-3;
/// Tree kernel in f32: a pivot T_dd at most this times M_dd leaves the
/// island to elimination (f64 uses [`crate::cpu::enumeration_tree::TreeSettings`]'s).
/// With f32's 6e-8 rounding it bounds a leaf's error near 1e-4, under the
/// screen's 1e-3.
pub const F32_TREE_PIVOT_TOL: f64 = 1e-3;
/// Tree kernel in f32, semidefinite islands: a pivot at most this times
/// M_dd is singular (f32 rounds a singular Schur complement to about 1e-7
/// of M_dd) and cuts its subtree.
pub const F32_TREE_SINGULAR_TOL: f64 = 1e-5;
pub const ASSEMBLY_WGSL: &str = include_str!("../../shaders/assembly.wgsl");
pub const IMPULSES_WGSL: &str = include_str!("../../shaders/impulses.wgsl");

/// Workgroup size of every entry point (`@workgroup_size(64)`).
pub const WORKGROUP: u32 = 64;

/// Pipelines are cached by this key.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PipelineKey {
    pub precision: Precision,
    pub pivot_tol_bits: u64,
    pub feasibility_tol_bits: u64,
    pub relaxed_tol_bits: u64,
}

/// One entry point: its explicit bind group layout and its pipeline.
pub struct Stage {
    pub layout: wgpu::BindGroupLayout,
    pub pipeline: wgpu::ComputePipeline,
}

/// Every stage's pipeline for one precision and one set of tolerances.
pub struct Pipelines {
    pub enumeration: Stage,
    /// `shaders/enumeration_gray.wgsl`: the enumeration in Gray-code order.
    pub enumeration_gray: Stage,
    /// `shaders/enumeration_workgroup.wgsl`: one workgroup per island, the
    /// bases of each popcount in waves of [`WORKGROUP`] lanes.
    pub enumeration_workgroup: Stage,
    /// `shaders/enumeration.wgsl` specialised to islands of exactly n
    /// contacts (FIXED), n = 1…[`FIXED_MAX_N`], at index n − 1; built on
    /// first use ([`Pipelines::fixed`]: 16 more shader compilations that only
    /// the Unrolled kernel needs).
    enumeration_fixed: Vec<std::sync::OnceLock<Stage>>,
    fixed_src: Vec<String>,
    /// `shaders/enumeration_tree.wgsl` for islands of exactly n contacts,
    /// n = 1…[`TREE_MAX_N`], at index n − 1; built on first use
    /// ([`Pipelines::tree`]).
    enumeration_tree: Vec<std::sync::OnceLock<Stage>>,
    /// The templated tree kernel, before [`tree_source`] specialises it.
    tree_src: String,
    pub assemble_contacts: Stage,
    pub assemble_islands: Stage,
    pub impulses: Stage,
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

/// A WGSL float literal that round-trips `v` exactly (naga parses abstract
/// floats as f64).
fn literal(v: f64) -> String {
    let s = format!("{v:e}");
    if s.contains('.') || s.contains('e') {
        s
    } else {
        format!("{s}.0")
    }
}

/// An enumeration kernel's complete source (before templating):
/// `shaders/enumeration_basis.wgsl`, then the kernel's own file.
pub fn enumeration_source(kernel: &str) -> String {
    format!("{ENUMERATION_BASIS_WGSL}\n{kernel}")
}

/// `shaders/enumeration.wgsl` (templated) specialised to islands of exactly
/// n contacts: FIXED, FN, FNN set, and `solve_basis_fixed` replaced by
/// [`straight_line_solver`] (no loops, every array index constant).
pub fn fixed_source(enumeration_src: &str, n: usize) -> Result<String, Error> {
    let s = replace_host_line(enumeration_src, "fixed", "const FIXED: bool = true;")?;
    let s = replace_host_line(&s, "fixed_n", &format!("const FN: u32 = {n}u;"))?;
    let s = replace_host_line(&s, "fixed_nn", &format!("const FNN: u32 = {}u;", n * n))?;
    replace_function(&s, "solve_basis_fixed", &straight_line_solver(n))
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

/// `solve_basis_fixed` for n contacts as straight-line WGSL: `solve_basis`'
/// elimination (shaders/enumeration_basis.wgsl) on the n×n system whose
/// nonbasic rows and columns are the identity, in the same order, on
/// scalars named by their constant indices (row swaps and skipped updates
/// become selects), so that nothing is indexed dynamically. The identity
/// rows never pivot and add exact zeros, so the answers are `solve_basis`'
/// bit for bit (`tests/gpu_gray.rs`, `unrolled_kernel_equals_elimination_kernel`).
pub fn straight_line_solver(n: usize) -> String {
    use std::fmt::Write;
    let mut o = String::new();
    let w = &mut o;
    let _ = writeln!(w, "fn solve_basis_fixed(base: u32, mask: u32) -> Scalar {{");
    let _ = writeln!(w, "    let qbase = base + FNN;");
    for r in 0..n {
        let _ = writeln!(w, "    let b{r} = ((mask >> {r}u) & 1u) == 1u;");
    }
    for r in 0..n {
        for c in 0..n {
            let other = if r == c { "1.0" } else { "0.0" };
            let cond = if r == c {
                format!("b{r}")
            } else {
                format!("b{r} && b{c}")
            };
            let _ = writeln!(
                w,
                "    var a{r}_{c} = select(Scalar({other}), values[base + {}u], {cond});",
                r * n + c
            );
        }
        let _ = writeln!(
            w,
            "    var x{r} = select(Scalar(0.0), -values[qbase + {r}u], b{r});"
        );
    }
    for c in 0..n {
        let terms: Vec<String> = (0..n).map(|r| format!("abs(a{r}_{c})")).collect();
        let mut e = "Scalar(0.0)".to_string();
        for t in terms {
            e = format!("max({e}, {t})");
        }
        let _ = writeln!(w, "    let cm{c} = {e};");
    }
    for c in 0..n {
        let _ = writeln!(w, "    {{");
        let _ = writeln!(w, "        var best = abs(a{c}_{c});");
        let _ = writeln!(w, "        var p = {c}u;");
        for r in c + 1..n {
            let _ = writeln!(
                w,
                "        {{ let v = abs(a{r}_{c}); let g = v > best; p = select(p, {r}u, g); best = select(best, v, g); }}"
            );
        }
        let _ = writeln!(
            w,
            "        if !(best > PIVOT_TOL * cm{c}) || best == Scalar(0.0) {{ return SINGULAR; }}"
        );
        for r in c + 1..n {
            let _ = writeln!(w, "        {{ let sw = p == {r}u;");
            for j in c..n {
                let _ = writeln!(
                    w,
                    "            {{ let t = a{c}_{j}; a{c}_{j} = select(a{c}_{j}, a{r}_{j}, sw); a{r}_{j} = select(a{r}_{j}, t, sw); }}"
                );
            }
            let _ = writeln!(
                w,
                "            {{ let t = x{c}; x{c} = select(x{c}, x{r}, sw); x{r} = select(x{r}, t, sw); }} }}"
            );
        }
        let _ = writeln!(w, "        let inv = Scalar(1.0) / a{c}_{c};");
        for r in c + 1..n {
            let _ = writeln!(
                w,
                "        {{ let f = a{r}_{c} * inv; let nz = f != Scalar(0.0);"
            );
            for j in c + 1..n {
                let _ = writeln!(
                    w,
                    "            a{r}_{j} = select(a{r}_{j}, a{r}_{j} - f * a{c}_{j}, nz);"
                );
            }
            let _ = writeln!(
                w,
                "            x{r} = select(x{r}, x{r} - f * x{c}, nz); }}"
            );
        }
        let _ = writeln!(w, "    }}");
    }
    for c in (0..n).rev() {
        let _ = writeln!(w, "    {{ var s = x{c};");
        for j in c + 1..n {
            let _ = writeln!(w, "        s = s - a{c}_{j} * x{j};");
        }
        let _ = writeln!(w, "        x{c} = s / a{c}_{c}; }}");
    }
    for r in 0..n {
        let _ = writeln!(w, "    fx[{r}] = x{r};");
    }
    let _ = writeln!(w, "    var zmax = Scalar(0.0);");
    for r in 0..n {
        let _ = writeln!(w, "    if b{r} {{ zmax = max(zmax, abs(x{r})); }}");
    }
    let _ = writeln!(w, "    var worst = Scalar(0.0);");
    for r in 0..n {
        let _ = writeln!(
            w,
            "    if b{r} && x{r} < Scalar(0.0) {{ worst = max(worst, -x{r} / zmax); }}"
        );
    }
    let _ = writeln!(w, "    if worst > RELAXED_TOL {{ return worst; }}");
    for i in 0..n {
        let _ = writeln!(w, "    if !b{i} {{");
        let _ = writeln!(w, "        var w = values[qbase + {i}u];");
        let _ = writeln!(w, "        var scale = abs(w);");
        for j in 0..n {
            let _ = writeln!(
                w,
                "        if b{j} {{ let t = values[base + {}u] * x{j}; w += t; scale += abs(t); }}",
                i * n + j
            );
        }
        let _ = writeln!(
            w,
            "        if w < Scalar(0.0) {{ worst = max(worst, -w / scale); if worst > RELAXED_TOL {{ return worst; }} }}"
        );
        let _ = writeln!(w, "    }}");
    }
    let _ = writeln!(w, "    return worst;");
    let _ = writeln!(w, "}}");
    o
}

/// Levels of the tree written out as straight-line code in the tree kernel;
/// above that, a loop over the bases of the first n − 8 indices runs the
/// straight-line tree of the last 8 under each (code and compile time stay
/// those of n = 8).
pub const TREE_INNER_LEVELS: usize = 8;

/// `shaders/enumeration_tree.wgsl` (templated) for islands of exactly n
/// contacts: FN and WORDS set, and the placeholder `tree_pass` replaced by
/// [`tree_pass_source`].
pub fn tree_source(tree_src: &str, n: usize) -> Result<String, Error> {
    let s = replace_host_line(tree_src, "fixed_n", &format!("const FN: u32 = {n}u;"))?;
    let s = replace_host_line(
        &s,
        "words",
        &format!("const WORDS: u32 = {}u;", (1usize << n).div_ceil(32)),
    )?;
    replace_function(&s, "tree_pass", &tree_pass_source(n))
}

/// The screen pass of `shaders/enumeration_tree.wgsl` for n contacts (n ≤
/// [`TREE_INNER_LEVELS`] + 5) as WGSL: the depth-first walk of
/// [`crate::cpu::enumeration_tree`] with the same operations in the same
/// order. The first P = n − 8 levels (none when n ≤ 8) run in a loop over
/// their 2^P bases `pre`, each pivot of the prefix under `if` (llvmpipe
/// computes it either way; P is small); the last levels are unrolled, each
/// pivot's results named by the depth that made them (`a{d}_{i}_{j}`,
/// `t{d}_{i}`) inside a block per subtree, and each leaf's screen sets bit
/// `mask` of the candidate bitmap (word `mask / 32` is a constant as long as
/// P ≤ 5).
pub fn tree_pass_source(n: usize) -> String {
    use std::fmt::Write;
    let mut o = String::new();
    let _ = writeln!(o, "fn tree_pass(base: u32, semi: bool) -> bool {{");
    // The screen's scale of w_i: |q_i| + rm{i}·Σ|z_S|, rm{i} = max_j |M_ij|.
    for i in 0..n {
        let mut rm = "Scalar(0.0)".to_string();
        for j in 0..n {
            let _ = writeln!(o, "let m{i}_{j} = values[base + {}u];", i * n + j);
            rm = format!("max({rm}, abs(m{i}_{j}))");
        }
        let _ = writeln!(o, "let rm{i} = {rm};");
    }
    for i in 0..n {
        let _ = writeln!(o, "let q{i} = values[base + {}u];", n * n + i);
        let _ = writeln!(o, "let qa{i} = abs(q{i});");
    }
    let _ = writeln!(o, "var ok = true;");
    let words = (1usize << n).div_ceil(32);
    for w in 0..words {
        let _ = writeln!(o, "var c{w} = 0u;");
    }
    let prefix = n.saturating_sub(TREE_INNER_LEVELS);
    let mut tab: Vec<String> = (0..n * n)
        .map(|k| format!("m{}_{}", k / n, k % n))
        .collect();
    let mut rhs: Vec<String> = (0..n).map(|i| format!("q{i}")).collect();
    if prefix == 0 {
        let _ = writeln!(o, "let pre = 0u;");
    } else {
        let _ = writeln!(o, "for (var pre = 0u; pre < {}u; pre++) {{", 1u32 << prefix);
        let _ = writeln!(o, "var live = true;");
        // The prefix's tableau: columns ≥ 1 and t, pivoted on each index d
        // < P that `pre` makes basic.
        for i in 0..n {
            for j in 1..n {
                let _ = writeln!(o, "var x{i}_{j} = m{i}_{j};");
                tab[i * n + j] = format!("x{i}_{j}");
            }
            let _ = writeln!(o, "var y{i} = q{i};");
            rhs[i] = format!("y{i}");
        }
        for d in 0..prefix {
            let _ = writeln!(o, "let b{d} = ((pre >> {d}u) & 1u) == 1u;");
            let _ = writeln!(o, "if b{d} {{");
            let p = &tab[d * n + d];
            pivot_tests(&mut o, d, p, "live", "live = live");
            let _ = writeln!(o, "let i{d} = Scalar(1.0) / {p};\nlet n{d} = -i{d};");
            for j in d + 1..n {
                let _ = writeln!(o, "let r{j} = {} * n{d};", tab[d * n + j]);
            }
            let _ = writeln!(o, "let tr = -{} * i{d};", rhs[d]);
            for i in (0..n).filter(|&i| i != d) {
                let _ = writeln!(o, "let f{i} = {};", tab[i * n + d]);
                for j in d + 1..n {
                    let _ = writeln!(o, "{0} = {0} + f{i} * r{j};", tab[i * n + j]);
                }
                let _ = writeln!(o, "{0} = {0} + f{i} * tr;", rhs[i]);
            }
            for j in d + 1..n {
                let _ = writeln!(o, "{} = r{j};", tab[d * n + j]);
            }
            let _ = writeln!(o, "{} = tr;\n}}", rhs[d]);
        }
    }
    let live = if prefix == 0 { "true" } else { "live" };
    tree_node(&mut o, n, prefix, prefix, 0, live, &tab, &rhs);
    if prefix > 0 {
        let _ = writeln!(o, "}}");
    }
    for w in 0..words {
        let _ = writeln!(o, "cand[{w}] = c{w};");
    }
    let _ = writeln!(o, "return ok;\n}}");
    o
}

/// The tests of a pivot `p` on d (the twin's `Walk::node`): on a
/// semidefinite island a singular pivot cuts the subtree (`{set} & !dead{d}`
/// names whether the subtree is live); else a pivot at most TREE_PIVOT_TOL
/// · M_dd in a live subtree leaves the island undecided.
fn pivot_tests(o: &mut String, d: usize, p: &str, live: &str, set: &str) {
    use std::fmt::Write;
    let _ = writeln!(
        o,
        "let dead{d} = semi & !({p} > SINGULAR_PIVOT_TOL * m{d}_{d});\nok = ok & !({live} & !dead{d} & !({p} > TREE_PIVOT_TOL * m{d}_{d}));\n{set} & !dead{d};"
    );
}

/// One node of [`tree_pass_source`]'s unrolled levels: depth d, the basic
/// indices in d' ∈ [prefix, d) in `mask` (those below `prefix` are `pre`'s,
/// known at run time as `b{i}`), whether the subtree is live (`live`: not
/// cut by a singular pivot), tableau entries and t named in `tab` and
/// `rhs`.
#[allow(clippy::too_many_arguments)]
fn tree_node(
    o: &mut String,
    n: usize,
    prefix: usize,
    d: usize,
    mask: usize,
    live: &str,
    tab: &[String],
    rhs: &[String],
) {
    use std::fmt::Write;
    if d == n {
        // The screen (the CPU twin's `Walk::screen`): a prefix index is
        // basic when its `b` is set; select(0, |t|, false) adds 0 to the sum
        // and leaves the max, as the twin's skip does.
        let _ = writeln!(o, "{{");
        let (mut zm, mut zs) = ("Scalar(0.0)".to_string(), "Scalar(0.0)".to_string());
        for i in 0..n {
            let a = format!("abs({})", rhs[i]);
            if i < prefix {
                let v = format!("select(Scalar(0.0), {a}, b{i})");
                zm = format!("max({zm}, {v})");
                zs = format!("({zs} + {v})");
            } else if mask >> i & 1 == 1 {
                zm = format!("max({zm}, {a})");
                zs = format!("({zs} + {a})");
            }
        }
        let _ = writeln!(o, "let zm = {zm};\nlet zs = {zs};");
        let tests: Vec<String> = (0..n)
            .map(|i| {
                let ws = format!("(qa{i} + rm{i} * zs)");
                let scale = if i < prefix {
                    format!("select({ws}, zm, b{i})")
                } else if mask >> i & 1 == 1 {
                    "zm".to_string()
                } else {
                    ws
                };
                format!("({} >= -SCREEN_TOL * {scale})", rhs[i])
            })
            .collect();
        let _ = writeln!(
            o,
            "c{w} = c{w} | select(0u, 1u << (pre | {low}u), {live} & {});\n}}",
            tests.join(" & "),
            w = mask / 32,
            low = mask % 32
        );
        return;
    }
    // Index d nonbasic: the same tableau.
    tree_node(o, n, prefix, d + 1, mask, live, tab, rhs);
    // Index d basic: the principal pivot on T_dd (columns > d and t).
    let _ = writeln!(o, "{{");
    let p = &tab[d * n + d];
    pivot_tests(o, d, p, live, &format!("let l{d} = {live}"));
    let _ = writeln!(o, "let i{d} = Scalar(1.0) / {p};\nlet n{d} = -i{d};");
    let mut tab2 = tab.to_vec();
    let mut rhs2 = rhs.to_vec();
    for j in d + 1..n {
        let _ = writeln!(o, "let a{d}_{d}_{j} = {} * n{d};", tab[d * n + j]);
        tab2[d * n + j] = format!("a{d}_{d}_{j}");
    }
    let _ = writeln!(o, "let t{d}_{d} = -{} * i{d};", rhs[d]);
    rhs2[d] = format!("t{d}_{d}");
    for i in (0..n).filter(|&i| i != d) {
        let f = &tab[i * n + d];
        for j in d + 1..n {
            let _ = writeln!(
                o,
                "let a{d}_{i}_{j} = {} + {f} * a{d}_{d}_{j};",
                tab[i * n + j]
            );
            tab2[i * n + j] = format!("a{d}_{i}_{j}");
        }
        let _ = writeln!(o, "let t{d}_{i} = {} + {f} * t{d}_{d};", rhs[i]);
        rhs2[i] = format!("t{d}_{i}");
    }
    tree_node(
        o,
        n,
        prefix,
        d + 1,
        mask | 1 << d,
        &format!("l{d}"),
        &tab2,
        &rhs2,
    );
    let _ = writeln!(o, "}}");
}

/// The shader source for `precision` (and tolerances where the shader has them).
pub fn template(
    src: &str,
    precision: Precision,
    tolerances: Option<(f64, f64, f64)>,
) -> Result<String, Error> {
    let ty = if precision == Precision::F64 {
        "f64"
    } else {
        "f32"
    };
    let mut s = replace_host_line(src, "scalar", &format!("alias Scalar = {ty};"))?;
    if let Some((pivot, feas, relaxed)) = tolerances {
        s = host_scalar(&s, "relaxed_tol", "RELAXED_TOL", relaxed)?;
        s = host_scalar(&s, "pivot_tol", "PIVOT_TOL", pivot)?;
        s = host_scalar(&s, "feasibility_tol", "FEASIBILITY_TOL", feas)?;
    }
    Ok(s)
}

/// Replaces the `// HOST <what>` line of `src` with the scalar constant
/// `const <name>: Scalar = <value>;` (the value exactly).
fn host_scalar(src: &str, what: &str, name: &str, value: f64) -> Result<String, Error> {
    replace_host_line(
        src,
        what,
        &format!("const {name}: Scalar = {};", literal(value)),
    )
}

fn uniform_entry(binding: u32) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

fn storage_entry(binding: u32, read_only: bool) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

/// The bindings every enumeration kernel shares (shaders/enumeration_basis.wgsl):
/// params, islands, values, results, z, unfinished, least_infeasibility.
fn enumeration_entries() -> [wgpu::BindGroupLayoutEntry; 7] {
    [
        uniform_entry(0),
        storage_entry(1, true),
        storage_entry(2, true),
        storage_entry(3, false),
        storage_entry(4, false),
        storage_entry(5, false),
        storage_entry(6, false),
    ]
}

fn stage(
    device: &wgpu::Device,
    module: &wgpu::ShaderModule,
    entry: &str,
    entries: &[wgpu::BindGroupLayoutEntry],
) -> Stage {
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(entry),
        entries,
    });
    let pl = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some(entry),
        bind_group_layouts: &[Some(&layout)],
        immediate_size: 0,
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(entry),
        layout: Some(&pl),
        module,
        entry_point: Some(entry),
        compilation_options: Default::default(),
        cache: None,
    });
    Stage { layout, pipeline }
}

impl Pipelines {
    /// The specialised elimination stage for islands of n contacts
    /// (1 ≤ n ≤ [`FIXED_MAX_N`]), built on first use.
    pub fn fixed(&self, ctx: &GpuContext, n: usize) -> &Stage {
        self.enumeration_fixed[n - 1].get_or_init(|| {
            let entries = enumeration_entries();
            let m = ctx
                .device
                .create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some("enumeration.wgsl (fixed n)"),
                    source: wgpu::ShaderSource::Wgsl(self.fixed_src[n - 1].as_str().into()),
                });
            stage(&ctx.device, &m, "main", &entries)
        })
    }

    /// The tree stage for islands of n contacts (1 ≤ n ≤ [`TREE_MAX_N`]),
    /// built on first use.
    pub fn tree(&self, ctx: &GpuContext, n: usize) -> &Stage {
        self.enumeration_tree[n - 1].get_or_init(|| {
            // The placeholder and HOST lines were checked when the
            // pipelines were built (`tree_source` at n = 1).
            let src = tree_source(&self.tree_src, n).unwrap_or_default();
            let m = ctx
                .device
                .create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some("enumeration_tree.wgsl"),
                    source: wgpu::ShaderSource::Wgsl(src.into()),
                });
            stage(&ctx.device, &m, "main", &enumeration_entries())
        })
    }

    fn build(ctx: &GpuContext, key: &PipelineKey) -> Result<Self, Error> {
        let d = &ctx.device;
        let pivot = f64::from_bits(key.pivot_tol_bits);
        let feas = f64::from_bits(key.feasibility_tol_bits);
        let relaxed = f64::from_bits(key.relaxed_tol_bits);
        let enumeration_src = template(
            &enumeration_source(ENUMERATION_WGSL),
            key.precision,
            Some((pivot, feas, relaxed)),
        )?;
        let gray = crate::cpu::enumeration_gray::GraySettings::default();
        let (screen, tab_pivot) = if key.precision == Precision::F64 {
            (gray.screen_tol, gray.pivot_tol)
        } else {
            (F32_SCREEN_TOL, F32_TABLEAU_PIVOT_TOL)
        };
        let gray_src = template(
            &enumeration_source(ENUMERATION_GRAY_WGSL),
            key.precision,
            Some((pivot, feas, relaxed)),
        )?;
        let gray_src = host_scalar(&gray_src, "screen_tol", "SCREEN_TOL", screen)?;
        let gray_src = host_scalar(&gray_src, "tableau_pivot_tol", "TAB_PIVOT_TOL", tab_pivot)?;
        let workgroup_src = template(
            &enumeration_source(ENUMERATION_WORKGROUP_WGSL),
            key.precision,
            Some((pivot, feas, relaxed)),
        )?;
        let fixed_src: Vec<String> = (1..=FIXED_MAX_N)
            .map(|n| fixed_source(&enumeration_src, n))
            .collect::<Result<_, Error>>()?;
        let tree = TreeSettings::default();
        let (tree_screen, tree_pivot, tree_singular) = if key.precision == Precision::F64 {
            (tree.screen_tol, tree.pivot_tol, tree.singular_tol)
        } else {
            (F32_SCREEN_TOL, F32_TREE_PIVOT_TOL, F32_TREE_SINGULAR_TOL)
        };
        let tree_src = template(
            &enumeration_source(ENUMERATION_TREE_WGSL),
            key.precision,
            Some((pivot, feas, relaxed)),
        )?;
        let tree_src = host_scalar(&tree_src, "screen_tol", "SCREEN_TOL", tree_screen)?;
        let tree_src = host_scalar(&tree_src, "tree_pivot_tol", "TREE_PIVOT_TOL", tree_pivot)?;
        let tree_src = host_scalar(
            &tree_src,
            "tree_singular_tol",
            "SINGULAR_PIVOT_TOL",
            tree_singular,
        )?;
        let tree_src = replace_host_line(
            &tree_src,
            "max_confirmations",
            &format!(
                "const MAX_CONFIRMATIONS: u32 = {}u;",
                tree.max_confirmations
            ),
        )?;
        tree_source(&tree_src, 1)?;
        let assembly_src = template(ASSEMBLY_WGSL, key.precision, None)?;
        let impulses_src = template(IMPULSES_WGSL, key.precision, None)?;
        ctx.scoped("building the pipelines", || {
            let module = |label: &str, src: String| {
                d.create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some(label),
                    source: wgpu::ShaderSource::Wgsl(src.into()),
                })
            };
            let enumeration = module("enumeration.wgsl", enumeration_src);
            let enumeration_gray = module("enumeration_gray.wgsl", gray_src);
            let enumeration_workgroup = module("enumeration_workgroup.wgsl", workgroup_src);
            let assembly = module("assembly.wgsl", assembly_src);
            let impulses = module("impulses.wgsl", impulses_src);
            Pipelines {
                enumeration: stage(d, &enumeration, "main", &enumeration_entries()),
                enumeration_gray: stage(
                    d,
                    &enumeration_gray,
                    "main",
                    &[enumeration_entries().as_slice(), &[storage_entry(7, false)]].concat(),
                ),
                enumeration_workgroup: stage(
                    d,
                    &enumeration_workgroup,
                    "main",
                    &enumeration_entries(),
                ),
                enumeration_fixed: (0..FIXED_MAX_N)
                    .map(|_| std::sync::OnceLock::new())
                    .collect(),
                fixed_src,
                enumeration_tree: (0..TREE_MAX_N)
                    .map(|_| std::sync::OnceLock::new())
                    .collect(),
                tree_src,
                assemble_contacts: stage(
                    d,
                    &assembly,
                    "assemble_contacts",
                    &[
                        uniform_entry(0),
                        storage_entry(1, true),
                        storage_entry(2, true),
                        storage_entry(3, true),
                        storage_entry(4, false),
                    ],
                ),
                assemble_islands: stage(
                    d,
                    &assembly,
                    "assemble_islands",
                    &[
                        uniform_entry(0),
                        storage_entry(2, true),
                        storage_entry(4, false),
                        storage_entry(5, true),
                        storage_entry(6, true),
                        storage_entry(7, false),
                    ],
                ),
                impulses: stage(
                    d,
                    &impulses,
                    "main",
                    &[
                        uniform_entry(0),
                        storage_entry(1, true),
                        storage_entry(2, true),
                        storage_entry(3, true),
                        storage_entry(4, true),
                        storage_entry(5, true),
                        storage_entry(6, false),
                    ],
                ),
            }
        })
    }
}

impl GpuContext {
    /// The pipelines for the context's precision and these tolerances,
    /// built on first use.
    pub(crate) fn pipelines(&self, tolerances: (f64, f64, f64)) -> Result<Arc<Pipelines>, Error> {
        let key = PipelineKey {
            precision: self.precision(),
            pivot_tol_bits: tolerances.0.to_bits(),
            feasibility_tol_bits: tolerances.1.to_bits(),
            relaxed_tol_bits: tolerances.2.to_bits(),
        };
        let mut cache = self
            .pipelines
            .lock()
            .map_err(|_| Error::Gpu("pipeline cache poisoned".into()))?;
        if let Some(p) = cache.get(&key) {
            return Ok(p.clone());
        }
        let p = Arc::new(Pipelines::build(self, &key)?);
        cache.insert(key, p.clone());
        Ok(p)
    }

    /// A storage buffer holding `bytes` (at least 16 bytes: empty bindings
    /// are invalid), readable by the shaders and copyable to a readback buffer.
    pub(crate) fn storage(&self, label: &str, bytes: &[u8]) -> wgpu::Buffer {
        let usage = wgpu::BufferUsages::STORAGE
            | wgpu::BufferUsages::COPY_SRC
            | wgpu::BufferUsages::COPY_DST;
        if bytes.len() < 16 {
            let mut padded = bytes.to_vec();
            padded.resize(16, 0);
            return self
                .device
                .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some(label),
                    contents: &padded,
                    usage,
                });
        }
        self.device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytes,
                usage,
            })
    }

    /// An uninitialised storage buffer of `size` bytes (rounded up to 16).
    pub(crate) fn storage_zeroed(&self, label: &str, size: u64) -> wgpu::Buffer {
        self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: size.max(16).next_multiple_of(4),
            usage: wgpu::BufferUsages::STORAGE
                | wgpu::BufferUsages::COPY_SRC
                | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        })
    }

    /// Bind groups for dispatches of a stage over items first..first+count in
    /// ranges of at most `max_groups` workgroups (the per-dimension limit),
    /// each range with its own Params uniform; `bind` makes the bind group
    /// for a Params buffer. Returns (bind group, workgroups) per range.
    /// `flags`: Params' last word (the Gray-code kernel's period and drift flag).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn ranges(
        &self,
        first: u32,
        count: u32,
        max_groups: u32,
        budget: u32,
        flags: u32,
        bind: &dyn Fn(&wgpu::Buffer) -> wgpu::BindGroup,
    ) -> Vec<(wgpu::BindGroup, u32)> {
        self.ranges_per_group(first, count, WORKGROUP, max_groups, budget, flags, bind)
    }

    /// [`Self::ranges`] with `per_group` items per workgroup (1: the
    /// workgroup kernel, one island per workgroup).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn ranges_per_group(
        &self,
        first: u32,
        count: u32,
        per_group: u32,
        max_groups: u32,
        budget: u32,
        flags: u32,
        bind: &dyn Fn(&wgpu::Buffer) -> wgpu::BindGroup,
    ) -> Vec<(wgpu::BindGroup, u32)> {
        let per_group = per_group.max(1);
        let per = max_groups.max(1) as u64 * per_group as u64;
        let mut out = Vec::new();
        let mut done = 0u64;
        while done < count as u64 {
            let this = (count as u64 - done).min(per) as u32;
            let params = Params {
                first: first + done as u32,
                count: this,
                budget,
                _pad: flags,
            };
            // Params: which slice of the table this dispatch covers.
            let ub = self
                .device
                .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some("params"),
                    contents: bytemuck::bytes_of(&params),
                    usage: wgpu::BufferUsages::UNIFORM,
                });
            out.push((bind(&ub), this.div_ceil(per_group)));
            done += this as u64;
        }
        out
    }

    /// Records one dispatch of `stage` per range.
    pub(crate) fn record(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        stage: &Stage,
        ranges: &[(wgpu::BindGroup, u32)],
    ) {
        for (bg, groups) in ranges {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("dispatch"),
                timestamp_writes: None,
            });
            pass.set_pipeline(&stage.pipeline);
            pass.set_bind_group(0, bg, &[]);
            pass.dispatch_workgroups(*groups, 1, 1);
        }
    }

    /// Records dispatches of `stage` over items first..first+count (see [`Self::ranges`]).
    pub(crate) fn dispatch_ranges(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        stage: &Stage,
        first: u32,
        count: u32,
        max_groups: u32,
        bind: &dyn Fn(&wgpu::Buffer) -> wgpu::BindGroup,
    ) {
        let r = self.ranges(first, count, max_groups, 0, 0, bind);
        self.record(encoder, stage, &r);
    }

    /// Copies each (buffer, bytes) to a mappable buffer, submits `encoder`,
    /// waits, and returns the bytes.
    pub(crate) fn submit_and_read(
        &self,
        mut encoder: wgpu::CommandEncoder,
        reads: &[(&wgpu::Buffer, u64)],
    ) -> Result<Vec<Vec<u8>>, Error> {
        let staging: Vec<(wgpu::Buffer, u64)> = reads
            .iter()
            .map(|&(src, size)| {
                let size4 = size.max(4).next_multiple_of(4);
                // Readback: MAP_READ buffers cannot be storage, so copy here.
                let dst = self.device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some("readback"),
                    size: size4,
                    usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                    mapped_at_creation: false,
                });
                encoder.copy_buffer_to_buffer(src, 0, &dst, 0, size4);
                (dst, size)
            })
            .collect();
        self.queue.submit([encoder.finish()]);
        for (dst, _) in &staging {
            dst.slice(..).map_async(wgpu::MapMode::Read, |_| {});
        }
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| Error::Gpu(format!("waiting for the GPU: {e}")))?;
        let mut out = Vec::with_capacity(staging.len());
        for (dst, size) in &staging {
            let view = dst
                .slice(..)
                .get_mapped_range()
                .map_err(|e| Error::Gpu(format!("reading back: {e}")))?;
            out.push(view[..*size as usize].to_vec());
            drop(view);
            dst.unmap();
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gpu::GpuOptions;

    #[test]
    fn templating_replaces_the_marked_lines_exactly() {
        let s = template(
            &enumeration_source(ENUMERATION_WGSL),
            Precision::F64,
            Some((1e-13, 1e-12, 1e-9)),
        )
        .unwrap();
        assert!(s.contains("alias Scalar = f64; // HOST scalar"));
        assert!(s.contains("const PIVOT_TOL: Scalar = 1e-13; // HOST pivot_tol"));
        assert!(s.contains("const RELAXED_TOL: Scalar = 1e-9; // HOST relaxed_tol"));
        assert!(template("fn main() {}", Precision::F32, None).is_err());
        assert_eq!(literal(0.5), "5e-1");
        assert_eq!(0.5f64, "5e-1".parse::<f64>().unwrap());
    }

    /// A wgpu validation error (a uniform binding of a buffer without
    /// UNIFORM usage) comes back as Error::Gpu, not as a panic.
    #[test]
    fn wgpu_validation_errors_become_error_gpu() {
        let ctx = GpuContext::new(&GpuOptions::from_env().unwrap())
            .unwrap_or_else(|e| panic!("no GPU adapter: {e}"));
        let p = ctx.pipelines((1e-13, 1e-12, 1e-9)).unwrap();
        let r = ctx.scoped("a bad bind group", || {
            let not_uniform = ctx.storage_zeroed("not uniform", 16);
            ctx.device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("bad"),
                layout: &p.enumeration.layout,
                entries: &[wgpu::BindGroupEntry {
                    binding: 0,
                    resource: not_uniform.as_entire_binding(),
                }],
            })
        });
        match r {
            Err(Error::Gpu(msg)) => assert!(msg.starts_with("a bad bind group: "), "{msg}"),
            other => panic!("expected Error::Gpu, got {other:?}"),
        }
        // The context stays usable.
        assert!(ctx.scoped("nothing", || ()).is_ok());
    }
}
