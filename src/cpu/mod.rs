//! CPU twins of the GPU stages, in f64: each file here has a shader of the
//! same name in `shaders/` and computes the same thing from the same inputs.
//! They are the reference every GPU result is checked against, and the CPU
//! path itself. (`batch` spreads a batch over the cores.)

pub mod assembly;
pub mod batch;
pub mod enumeration;
pub mod enumeration_tree;
pub mod impulses;
