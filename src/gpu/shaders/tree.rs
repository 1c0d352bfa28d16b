//! Generator of the tree kernel's screen pass (`tree_pass` in
//! `shaders/enumeration_tree.wgsl`) for one island size: straight-line WGSL.
//! Used only by [`super::compose`] (tests), which writes the result to
//! `shaders/generated/`.

/// Levels of the tree written out as straight-line code in the tree kernel;
/// above that, a loop over the bases of the first n − 8 indices runs the
/// straight-line tree of the last 8 under each (code and compile time stay
/// those of n = 8).
pub(super) const TREE_INNER_LEVELS: usize = 8;

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
pub(super) fn tree_pass_source(n: usize) -> String {
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
/// names whether the subtree is live); else a pivot at most tol.tree_pivot
/// · M_dd in a live subtree leaves the island undecided.
fn pivot_tests(o: &mut String, d: usize, p: &str, live: &str, set: &str) {
    use std::fmt::Write;
    let _ = writeln!(
        o,
        "let dead{d} = semi & !({p} > tol.tree_singular * m{d}_{d});\nok = ok & !({live} & !dead{d} & !({p} > tol.tree_pivot * m{d}_{d}));\n{set} & !dead{d};"
    );
}

/// One node of [`tree_pass_source`]'s unrolled levels: depth d, the basic
/// indices in d' ∈ [prefix, d) in `mask` (those below `prefix` are `pre`'s,
/// known at run time as `b{i}`), whether the subtree is live (`live`: not
/// cut by a singular pivot), tableau entries and t named in `tab` and
/// `rhs`.
/// Eight parameters and about 90 lines on purpose: the recursion carries
/// the whole naming state of the walk (depth, prefix, mask, liveness, the
/// tableau and t names) down the tree; a struct would be rebuilt per node.
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
                format!("({} >= -tol.screen * {scale})", rhs[i])
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
