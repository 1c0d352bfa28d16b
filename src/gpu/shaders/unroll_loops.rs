//! Loop unrolling for the friction kernels and the narrow phase's
//! manifolds (`collide`, `world_collide`) (test builds only, like the rest
//! of the composition): every `for` loop whose header line ends in
//! `// UNROLL` and whose bounds are constants once the island size is known
//! is replaced by one block per iteration with the loop variable written as
//! a literal.
//!
//! Why: llvmpipe (lavapipe) turns an access to a private array at a run-time
//! index into a per-lane gather or scatter, and keeps an array in registers
//! only when every access to it has a constant index. Unrolled here, the
//! island's W, q, μ and vectors become plain SSA values (measured in
//! BENCHMARKS.md, "GPU: cone projection iterations for friction").
//!
//! The header must read `for (var V = A; V < B; V++) { // UNROLL` with A
//! and B sums of products of unsigned literals (`3u`), enclosing loops'
//! variables (already literals by then) and the named constants given; the
//! loop's body ends at its matching brace.

use crate::Error;

/// The marker that asks for a loop to be unrolled.
const MARK: &str = "// UNROLL";

/// `src` with every marked loop unrolled (outermost first; inner loops see
/// the outer variable as a literal); `constants` are the named constants
/// the bounds may use. With `enabled` false the markers are only removed
/// (the loops stay).
pub(super) fn unroll_marked_loops(
    src: &str,
    constants: &[(&str, u64)],
    enabled: bool,
) -> Result<String, Error> {
    let mut s = src.to_string();
    while let Some(mark) = s.find(MARK) {
        let line_start = s[..mark].rfind('\n').map_or(0, |i| i + 1);
        let header = s[line_start..mark].trim();
        let (var, from, to) = parse_header(header)?;
        // The body: from the header's `{` to its matching `}`.
        let open = line_start + s[line_start..mark].rfind('{').ok_or_else(|| bad(header))?;
        let close = matching_brace(&s, open).ok_or_else(|| bad(header))?;
        if open > mark {
            return Err(bad(header));
        }
        // After the header line's marker, up to the matching brace.
        let body = &s[mark + MARK.len()..close];
        let replacement = if enabled {
            let (a, b) = (eval(&from, constants)?, eval(&to, constants)?);
            let mut out = String::new();
            for i in a..b {
                out.push_str("{\n");
                out.push_str(&replace_word(body, &var, &format!("{i}u")));
                out.push_str("}\n");
            }
            out
        } else {
            format!(
                "{}{}",
                s[line_start..mark].trim_end(),
                &s[mark + MARK.len()..=close]
            )
        };
        s = format!("{}{}{}", &s[..line_start], replacement, &s[close + 1..]);
    }
    Ok(s)
}

fn bad(header: &str) -> Error {
    Error::Gpu(format!("unroll: cannot read the loop `{header}`"))
}

/// (variable, start, bound) of `for (var V = A; V < B; V++) {`.
fn parse_header(header: &str) -> Result<(String, String, String), Error> {
    let rest = header
        .strip_prefix("for (var ")
        .ok_or_else(|| bad(header))?;
    let (var, rest) = rest.split_once(" = ").ok_or_else(|| bad(header))?;
    let (from, rest) = rest.split_once("; ").ok_or_else(|| bad(header))?;
    let rest = rest
        .strip_prefix(&format!("{var} < "))
        .ok_or_else(|| bad(header))?;
    let (to, rest) = rest.split_once("; ").ok_or_else(|| bad(header))?;
    if rest.trim() != format!("{var}++) {{") {
        return Err(bad(header));
    }
    Ok((var.to_string(), from.to_string(), to.to_string()))
}

/// The index of the `}` matching the `{` at `open`.
fn matching_brace(s: &str, open: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (i, c) in s[open..].char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(open + i);
                }
            }
            _ => {}
        }
    }
    None
}

/// `text` with every whole-word `word` replaced by `by`.
fn replace_word(text: &str, word: &str, by: &str) -> String {
    let is_ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find(word) {
        let before = rest[..at].chars().next_back();
        let after = rest[at + word.len()..].chars().next();
        out.push_str(&rest[..at]);
        if before.is_some_and(is_ident) || after.is_some_and(is_ident) {
            out.push_str(word);
        } else {
            out.push_str(by);
        }
        rest = &rest[at + word.len()..];
    }
    out.push_str(rest);
    out
}

/// The value of a sum of products of `12u` literals and named constants.
fn eval(expr: &str, constants: &[(&str, u64)]) -> Result<u64, Error> {
    let term = |t: &str| -> Result<u64, Error> {
        t.split('*').try_fold(1u64, |acc, f| {
            let f = f.trim();
            let v = match constants.iter().find(|(n, _)| *n == f) {
                Some(&(_, v)) => v,
                None => f
                    .trim_end_matches('u')
                    .parse()
                    .map_err(|_| Error::Gpu(format!("unroll: `{expr}` is not constant")))?,
            };
            Ok(acc * v)
        })
    };
    expr.split('+').try_fold(0u64, |acc, t| Ok(acc + term(t)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nested_loops_unroll_with_literal_indices() {
        let src = "a;\nfor (var r = 0u; r < N; r++) { // UNROLL\n    for (var j = 2u * r; j < 2u * r + 2u; j++) { // UNROLL\n        s += w[r * N + j];\n    }\n}\nb;\n";
        let out = unroll_marked_loops(src, &[("N", 2)], true).unwrap();
        assert!(!out.contains("for"), "{out}");
        for needle in [
            "w[0u * N + 0u]",
            "w[0u * N + 1u]",
            "w[1u * N + 2u]",
            "w[1u * N + 3u]",
        ] {
            assert!(out.contains(needle), "{needle} in {out}");
        }
        assert_eq!(out.matches("s += ").count(), 4);
        assert!(out.starts_with("a;\n") && out.ends_with("b;\n"));
        let kept = unroll_marked_loops(src, &[("N", 2)], false).unwrap();
        assert_eq!(kept.matches("for (var").count(), 2);
        assert!(!kept.contains(MARK));
    }

    #[test]
    fn a_loop_with_run_time_bounds_is_an_error() {
        let src = "for (var j = lo; j < hi; j++) { // UNROLL\n}\n";
        assert!(unroll_marked_loops(src, &[], true).is_err());
        assert_eq!(replace_word("ri + r + xr", "r", "1u"), "ri + 1u + xr");
    }
}
