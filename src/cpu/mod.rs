//! The CPU path in f64: the twins of the GPU stages (`assembly`,
//! `enumeration`, `enumeration_tree`, `impulses`: each has a shader of the
//! same name in `shaders/` and computes the same thing from the same
//! inputs; they are the reference every GPU result is checked against) and
//! the solvers that run on the CPU only (`lemke`, `pgs`). `batch` spreads a
//! batch over the cores.

pub mod assembly;
pub mod batch;
pub mod enumeration;
pub mod enumeration_tree;
pub mod impulses;
pub mod lemke;
mod lemke_tableau;
pub mod pgs;
