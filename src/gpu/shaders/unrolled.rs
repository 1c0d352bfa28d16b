//! Generator of the specialised elimination (`solve_basis_fixed`) of
//! `shaders/enumeration.wgsl` for one island size: straight-line WGSL. Used
//! only by [`super::compose`] (tests), which writes the result to
//! `shaders/generated/`.

/// `solve_basis_fixed` for n contacts as straight-line WGSL: `solve_basis`'
/// elimination (shaders/enumeration_basis.wgsl) on the n×n system whose
/// nonbasic rows and columns are the identity, in the same order, on
/// scalars named by their constant indices (row swaps and skipped updates
/// become selects), so that nothing is indexed dynamically. The identity
/// rows never pivot and add exact zeros, so the answers are `solve_basis`'
/// bit for bit (`src/tests/gpu_unrolled.rs`, `unrolled_kernel_equals_elimination_kernel`).
/// Long (about 120 lines) on purpose: it writes one WGSL function top to
/// bottom, each block emitting one phase of the elimination in order;
/// split, the phases would have to pass the naming scheme around.
pub(super) fn straight_line_solver(n: usize) -> String {
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
            "        if !(best > tol.pivot * cm{c}) || best == Scalar(0.0) {{ return SINGULAR; }}"
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
    let _ = writeln!(w, "    if worst > tol.relaxed {{ return worst; }}");
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
            "        if w < Scalar(0.0) {{ worst = max(worst, -w / scale); if worst > tol.relaxed {{ return worst; }} }}"
        );
        let _ = writeln!(w, "    }}");
    }
    let _ = writeln!(w, "    return worst;");
    let _ = writeln!(w, "}}");
    o
}
