//! Reader for the Siconos numerics LCP test files (`.dat`).
//!
//! Whitespace-separated tokens: n, storage (0 dense, 1 sparse-block), size0,
//! size1, then
//! - dense: size0 size1 again and size0·size1 values of M in column-major
//!   order (each text line of a square file is a column of M);
//! - sparse-block: nbblocks, blocknumber0, blocknumber1, the cumulative block
//!   sizes of the block rows (blocknumber0 entries) and block columns
//!   (blocknumber1 entries), filled1, filled2, index1_data (filled1 block-row
//!   pointers), index2_data (filled2 block columns), then for every block its
//!   number and its values in column-major order;
//!
//! then q (n values). Anything after q is ignored (the files keep comments there).

use crate::lcp::Lcp;
use crate::Error;

/// Largest n accepted, so that a corrupt header cannot ask for terabytes.
pub const MAX_DAT_N: usize = 10_000;

pub(super) struct Tokens<'a> {
    path: &'a str,
    it: std::iter::Peekable<Box<dyn Iterator<Item = (usize, &'a str)> + 'a>>,
}

impl<'a> Tokens<'a> {
    pub(super) fn new(path: &'a str, text: &'a str) -> Self {
        let it: Box<dyn Iterator<Item = (usize, &'a str)> + 'a> = Box::new(
            text.lines()
                .enumerate()
                .flat_map(|(l, line)| line.split_whitespace().map(move |t| (l + 1, t))),
        );
        Tokens {
            path,
            it: it.peekable(),
        }
    }

    pub(super) fn err(&self, message: String) -> Error {
        Error::Dat {
            path: self.path.to_string(),
            message,
        }
    }

    fn next(&mut self, what: &str) -> Result<(usize, &'a str), Error> {
        self.it
            .next()
            .ok_or_else(|| self.err(format!("file ends before {what}")))
    }

    pub(super) fn int(&mut self, what: &str, max: usize) -> Result<usize, Error> {
        let (line, t) = self.next(what)?;
        let v: usize = t.parse().map_err(|_| {
            self.err(format!(
                "line {line}: {what}: expected a non-negative integer, found `{t}`"
            ))
        })?;
        if v > max {
            return Err(self.err(format!("line {line}: {what} = {v} exceeds the limit {max}")));
        }
        Ok(v)
    }

    pub(super) fn real(&mut self, what: &str) -> Result<f64, Error> {
        let (line, t) = self.next(what)?;
        let v: f64 = t.parse().map_err(|_| {
            self.err(format!(
                "line {line}: {what}: expected a number, found `{t}`"
            ))
        })?;
        if !v.is_finite() {
            return Err(self.err(format!("line {line}: {what}: `{t}` is not a finite number")));
        }
        Ok(v)
    }
}

/// Parses the text of a .dat file; `path` names it in errors.
///
/// # Errors
/// [`Error::Dat`] naming the line and the field where the text is malformed
/// or a number not finite.
pub fn parse_dat(path: &str, text: &str) -> Result<Lcp, Error> {
    let mut t = Tokens::new(path, text);
    let n = t.int("n", MAX_DAT_N)?;
    if n == 0 {
        return Err(t.err("n = 0: empty problem".into()));
    }
    let storage = t.int("storage type", 1)?;
    let size0 = t.int("size0", MAX_DAT_N)?;
    let size1 = t.int("size1", MAX_DAT_N)?;
    if size0 != n || size1 != n {
        return Err(t.err(format!("M is {size0}×{size1} but n = {n}")));
    }
    let mut m = vec![0.0; n * n];
    if storage == 0 {
        let r = t.int("size0 (repeated)", MAX_DAT_N)?;
        let c = t.int("size1 (repeated)", MAX_DAT_N)?;
        if r != n || c != n {
            return Err(t.err(format!("repeated sizes {r}×{c} differ from n = {n}")));
        }
        for col in 0..n {
            for row in 0..n {
                m[row * n + col] = t.real(&format!("M[{row}][{col}]"))?;
            }
        }
    } else {
        read_sparse_block(&mut t, n, &mut m)?;
    }
    let mut q = Vec::with_capacity(n);
    for i in 0..n {
        q.push(t.real(&format!("q[{i}]"))?);
    }
    Lcp::new(m, q)
}

/// Reads a sparse-block matrix (n × n, row-major into `m`); FrictionContact3D
/// files store W the same way.
pub(super) fn read_sparse_block(t: &mut Tokens, n: usize, m: &mut [f64]) -> Result<(), Error> {
    let nbblocks = t.int("nbblocks", n * n)?;
    let bn0 = t.int("blocknumber0", n)?;
    let bn1 = t.int("blocknumber1", n)?;
    let cumulative = |t: &mut Tokens, count: usize, what: &str| -> Result<Vec<usize>, Error> {
        let mut v = Vec::with_capacity(count);
        for i in 0..count {
            let s = t.int(&format!("{what}[{i}]"), n)?;
            if v.last().is_some_and(|&p| s <= p) {
                return Err(t.err(format!(
                    "{what} must increase, found {s} after {}",
                    v.last().unwrap()
                )));
            }
            v.push(s);
        }
        if v.last() != Some(&n) {
            return Err(t.err(format!("{what} must end at n = {n}")));
        }
        Ok(v)
    };
    let rows = cumulative(t, bn0, "blocksize0")?;
    let cols = cumulative(t, bn1, "blocksize1")?;
    let filled1 = t.int("filled1", n + 1)?;
    let filled2 = t.int("filled2", n * n)?;
    if filled1 != bn0 + 1 {
        return Err(t.err(format!(
            "filled1 = {filled1}, expected blocknumber0 + 1 = {}",
            bn0 + 1
        )));
    }
    if filled2 != nbblocks {
        return Err(t.err(format!(
            "filled2 = {filled2}, expected nbblocks = {nbblocks}"
        )));
    }
    let mut index1 = Vec::with_capacity(filled1);
    for i in 0..filled1 {
        index1.push(t.int(&format!("index1_data[{i}]"), nbblocks)?);
    }
    if index1[0] != 0 || index1[bn0] != nbblocks || index1.windows(2).any(|w| w[1] < w[0]) {
        return Err(t.err("index1_data must rise from 0 to nbblocks".into()));
    }
    let mut index2 = Vec::with_capacity(filled2);
    for i in 0..filled2 {
        index2.push(t.int(&format!("index2_data[{i}]"), bn1.saturating_sub(1))?);
    }
    let start = |v: &[usize], b: usize| if b == 0 { 0 } else { v[b - 1] };
    for br in 0..bn0 {
        for k in index1[br]..index1[br + 1] {
            let number = t.int("block number", nbblocks)?;
            if number != k {
                return Err(t.err(format!("block number {number}, expected {k}")));
            }
            let bc = index2[k];
            let (r0, r1) = (start(&rows, br), rows[br]);
            let (c0, c1) = (start(&cols, bc), cols[bc]);
            for c in c0..c1 {
                for r in r0..r1 {
                    m[r * n + c] = t.real(&format!("block {k}, M[{r}][{c}]"))?;
                }
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dense_is_column_major_and_block_matches_dense() {
        let dense = "2\n0\n2\n2\n2 2\n2 1\n3 4\n-5 -6\ncomment";
        let lcp = parse_dat("t", dense).unwrap();
        assert_eq!(lcp.m, vec![2.0, 3.0, 1.0, 4.0]);
        assert_eq!(lcp.q, vec![-5.0, -6.0]);
        let block = "2\n1\n2\n2\n1\n1\n1\n2\n2\n2\n1\n0 1\n0\n0\n2 1 3 4\n-5 -6";
        assert_eq!(parse_dat("t", block).unwrap(), lcp);
    }

    #[test]
    fn errors_name_the_place() {
        let e = parse_dat("f.dat", "2\n0\n2\n2\n2 2\n2 x\n")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("f.dat") && e.contains("line 6") && e.contains("M[1][0]"),
            "{e}"
        );
        let e = parse_dat("f.dat", "2\n0\n2\n2\n2 2\n2 1 3 4\n-5")
            .unwrap_err()
            .to_string();
        assert!(e.contains("q[1]"), "{e}");
        let e = parse_dat("f.dat", "999999999\n0").unwrap_err().to_string();
        assert!(e.contains("limit"), "{e}");
        assert!(parse_dat("f.dat", "2\n0\n2\n2\n2 2\n2 1 3 nan\n-5 -6").is_err());
    }
}
