//! lcpbatch: batched rigid-body contact problems, solved exactly.
//!
//! The path of the data: [`scene`] (bodies and contacts) → [`islands`]
//! (independent groups of contacts) → [`cpu::assembly`] (K matrices, Jacobian
//! rows, each island's LCP (M, q)) → a solver ([`cpu::enumeration`] of the
//! complementary bases, [`solvers::lemke`], [`solvers::pgs`]) → [`cpu::impulses`]
//! (velocities after the impact). [`pipeline`] runs it for whole scenes,
//! [`io`] reads and writes the file formats.

pub mod backend;
pub mod bench;
pub mod cpu;
pub mod error;
pub mod generate;
pub mod gpu;
pub mod io;
pub mod islands;
pub mod lcp;
pub mod linalg;
pub mod pipeline;
pub mod prediction;
pub mod scene;
pub mod solvers;
pub mod stress;
pub mod validation;

pub use error::Error;
pub use lcp::{Lcp, LcpSolution, Residuals, SolutionSet, Status};
pub use scene::{Body, Contact, Scene};
pub use solvers::{solve, Solver, SolverSettings};
