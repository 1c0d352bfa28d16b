//! Reader for Siconos' FrictionContact3D test files (`.dat`), exactly as
//! ../shared/conformance/siconos-fc3d/README.md describes them: whitespace
//! separated tokens d (= 3), n_c, the storage of W (0 dense, 1
//! sparse-block), size0 = size1 = 3 n_c, W (dense: the sizes again and the
//! entries column-major; sparse-block: as the LCP files, see
//! [`super::siconos`]), q (3 n_c), μ (n_c); anything after μ is ignored.
//!
//! # Telling it from an LCP `.dat`
//! An LCP file starts `n storage n n`; a FrictionContact3D file starts
//! `3 n_c storage 3n_c 3n_c`. So a file is FrictionContact3D exactly when
//! its first token is 3, its third is 0 or 1 and its fourth is three times
//! its second ([`is_fc3d`]): an LCP with n = 3 has 3 as its third token.

use super::siconos::{read_sparse_block, Tokens, MAX_DAT_N};
use crate::friction::FrictionProblem;
use crate::Error;

/// Whether the text of a `.dat` file is a FrictionContact3D problem (see
/// the module docs); false for an LCP file or one too short to tell.
pub fn is_fc3d(text: &str) -> bool {
    let t: Vec<&str> = text.split_whitespace().take(4).collect();
    let int = |i: usize| t.get(i).and_then(|s| s.parse::<usize>().ok());
    match (int(0), int(1), int(2), int(3)) {
        (Some(3), Some(nc), Some(s), Some(size0)) => s <= 1 && size0 == 3 * nc,
        _ => false,
    }
}

/// Parses the text of a FrictionContact3D `.dat` file; `path` names it in
/// errors, with the line and the field.
///
/// # Errors
/// [`Error::Dat`] naming the line and the field where the text is malformed
/// or a number not finite, or the problem's check that failed.
pub fn parse_fc3d(path: &str, text: &str) -> Result<FrictionProblem, Error> {
    let mut t = Tokens::new(path, text);
    let d = t.int("d (dimension of the contact space)", MAX_DAT_N)?;
    if d != 3 {
        return Err(t.err(format!(
            "d = {d}: only three-dimensional friction (d = 3) is read"
        )));
    }
    let nc = t.int("n_c (number of contacts)", MAX_DAT_N / 3)?;
    if nc == 0 {
        return Err(t.err("n_c = 0: no contacts".into()));
    }
    let n = 3 * nc;
    let storage = t.int("storage type of W", 1)?;
    let size0 = t.int("size0", MAX_DAT_N)?;
    let size1 = t.int("size1", MAX_DAT_N)?;
    if size0 != n || size1 != n {
        return Err(t.err(format!("W is {size0}×{size1} but 3 n_c = {n}")));
    }
    let mut w = vec![0.0; n * n];
    if storage == 0 {
        let r = t.int("size0 (repeated)", MAX_DAT_N)?;
        let c = t.int("size1 (repeated)", MAX_DAT_N)?;
        if r != n || c != n {
            return Err(t.err(format!("repeated sizes {r}×{c} differ from 3 n_c = {n}")));
        }
        for col in 0..n {
            for row in 0..n {
                w[row * n + col] = t.real(&format!("W[{row}][{col}]"))?;
            }
        }
    } else {
        read_sparse_block(&mut t, n, &mut w)?;
    }
    let mut q = Vec::with_capacity(n);
    for i in 0..n {
        q.push(t.real(&format!("q[{i}]"))?);
    }
    let mut mu = Vec::with_capacity(nc);
    for i in 0..nc {
        mu.push(t.real(&format!("mu[{i}]"))?);
    }
    FrictionProblem::new(w, q, mu).map_err(|e| t.err(e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dense_is_column_major_and_sparse_block_matches_dense() {
        // One contact, W = [[2, 0, 1], [0, 1, 0], [0, 0, 3]] column-major.
        let dense = "3\n1\n0\n3\n3\n3 3\n2 0 0\n0 1 0\n1 0 3\n-1 0.5 0\n0.3\n0";
        let p = parse_fc3d("t", dense).unwrap();
        assert_eq!(p.w, vec![2.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 3.0]);
        assert_eq!(
            (p.q.clone(), p.mu.clone()),
            (vec![-1.0, 0.5, 0.0], vec![0.3])
        );
        let block = "3 1 1 3 3\n1\n1 1\n3\n3\n2 1\n0 1\n0\n0\n2 0 0 0 1 0 1 0 3\n-1 0.5 0\n0.3";
        assert_eq!(parse_fc3d("t", block).unwrap(), p);
        assert!(is_fc3d(dense) && is_fc3d(block));
        // LCP files: n storage n n.
        assert!(!is_fc3d("3\n0\n3\n3\n3 3\n1 0 0 0 1 0 0 0 1\n-1 -1 -1"));
        assert!(!is_fc3d("2\n0\n2\n2\n2 2\n2 1 1 2\n-5 -6"));
    }

    #[test]
    fn errors_name_the_file_line_and_field() {
        let e = parse_fc3d("f.dat", "3 1 0 3 3 3 3 2 0 0 0 1 0 1 0 x")
            .unwrap_err()
            .to_string();
        assert!(e.contains("f.dat") && e.contains("W[2][2]"), "{e}");
        let e = parse_fc3d("f.dat", "3 1 0 3 3 3 3 2 0 0 0 1 0 1 0 3 -1 0 0")
            .unwrap_err()
            .to_string();
        assert!(e.contains("mu[0]") && e.contains("ends"), "{e}");
        let e = parse_fc3d("f.dat", "3 1 0 3 3 3 3 2 0 0 0 1 0 1 0 3 -1 0 0 -0.5")
            .unwrap_err()
            .to_string();
        assert!(e.contains("f.dat") && e.contains("mu[0]"), "{e}");
        let e = parse_fc3d("f.dat", "2 1 0 2 2").unwrap_err().to_string();
        assert!(e.contains("d = 2"), "{e}");
    }
}
